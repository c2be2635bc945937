# Lights and fog in POV-Ray 3.7: no_shadow, shadowless lights, spotlights, cylindrical lights,
# light fading, constant and ground fog (filter, transmit, several fogs), looks_like. Each row
# prints povray's value beside the model's (docs/povray-lighting.md); tests/pov_lights_test.cpp
# checks Rays against these numbers.
import math, os, sys
sys.dont_write_bytecode = True  # no __pycache__ in the checkout
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pv import render, fmt, ORTHO, row as pv_row


def row(name, got, want):
    pv_row(name, got, want, tol=1e-4)  # povray's 16-bit values at a few points of a strip


FLOOR = 'plane { -z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n'
# A 64×2 strip of the floor: pixel i at x = −1 + (i + .5)/32, y = 1/64.
STRIP = 'camera { orthographic location -3*z look_at 0 right 2*x up 0.0625*y }\n'
Y = 0.015625


def smooth(s):
    return s * s * (3 - 2 * s)


def spot(c, radius, falloff, tightness):
    cr, cf = math.cos(math.radians(radius)), math.cos(math.radians(falloff))
    k = 1 if c >= cr else 0 if c <= cf else smooth((c - cf) / (cr - cf))
    return k * c ** tightness


def strip(light, model, pixels=range(32, 64, 4), z=1):
    got = render(STRIP + FLOOR + 'light_source { %s }\n' % light, W=64, H=2, pts=[(i, 0) for i in pixels])
    for i, v in zip(pixels, got):
        x = -1 + (i + 0.5) / 32
        r = math.hypot(x, Y)
        c = z / math.hypot(r, z)  # cosine at the light and N·L of a point light
        row('%s  x %.3f' % (light[:44], x), [v[0]], [model(r, c)])


# Shadows: no_shadow objects cast none, also transparent ones and a union's children.
L60 = 'light_source { <0.866025,0,-0.5>*100, rgb 1 }\n'
for pig in ('rgb <.5,.6,.7>', 'rgbf <.5,.6,.7,.5>', 'rgbt <.5,.6,.7,.5>'):
    got = render(ORTHO + L60 + FLOOR + 'box { <1,-5,-1.01>, <5,5,-1> pigment { %s } finish { ambient 0 diffuse 0 } no_shadow }' % pig)
    row('no_shadow box of ' + pig, got, render(ORTHO + L60 + FLOOR))
got = render(ORTHO + L60 + FLOOR + 'union { box { <1,-5,-1.01>, <5,5,-1> } sphere { <3,0,-5>, 0.1 } pigment { rgb 1 } no_shadow }')
row('no_shadow union', got, render(ORTHO + L60 + FLOOR))

# Shadowless lights: diffuse only (no phong, no specular), nothing blocks them.
F = 'plane { -z, 0 pigment { rgb <.5,.6,.7> } finish { ambient 0 diffuse 0.5 %s } }\n'
WALL = 'box { <-5,-5,-2.01>, <5,5,-2> pigment { rgb 1 } finish { ambient 0 diffuse 0 } no_image }\n'
for fin, extra in (('', ''), ('phong 1', ''), ('specular 1', ''), ('', WALL)):
    got = render(ORTHO + 'light_source { <0,0,-100>, rgb 1 shadowless }\n' + F % fin + extra)
    row('shadowless light, %s%s' % (fin or 'diffuse', ' behind a wall' if extra else ''), got, (.25, .3, .35))

# Spotlights: 3s² − 2s³ between the cones (s over the cosines), times cos^tightness.
strip('<0,0,-1>, rgb 1 spotlight point_at 0 radius 10 falloff 30', lambda r, c: c * spot(c, 10, 30, 0))
strip('<0,0,-1>, rgb 1 spotlight point_at 0 radius 10 falloff 40 tightness 10', lambda r, c: c * spot(c, 10, 40, 10))
strip('<0,0,-1>, rgb 1 spotlight point_at 0', lambda r, c: c * spot(c, 30, 45, 0))
strip('<0,0,-1>, rgb 1 spotlight point_at 0 radius 20 falloff 10', lambda r, c: c * spot(c, 20, 10, 0))
# Cylindrical lights: radius and falloff are distances from the axis; light along the axis.
strip('<0,0,-1>, rgb 1 cylinder point_at 0 radius 0.3 falloff 0.6',
      lambda r, c: 1 if r <= .3 else 0 if r >= .6 else smooth((.6 - r) / .3))
strip('<0,0,-3>, rgb 1 cylinder point_at 0 radius 0.3 falloff 0.6',
      lambda r, c: 1 if r <= .3 else 0 if r >= .6 else smooth((.6 - r) / .3), z=3)
strip('<0,0,-1>, rgb 1 cylinder point_at 0 radius 0.3 falloff 0.6 tightness 3',
      lambda r, c: (1 if r <= .3 else 0 if r >= .6 else smooth((.6 - r) / .3)) * max(0, 1 - r / .6) ** 3)
# ... and cast shadows along the axis (a strip at x .1 .. .2 shades x .1 .. .2 only).
got = render(STRIP + FLOOR + 'box { <0.1,-1,-1.01>, <0.2,1,-1> pigment { rgb 1 } no_image }\n'
             'light_source { <0,0,-2>, rgb 1 cylinder point_at 0 radius 0.9 falloff 1 }', W=64, H=2,
             pts=[(i, 0) for i in range(32, 64)])
print('cylinder shadow at x:', ' '.join('%.2f' % (-1 + (i + 32.5) / 32) for i, v in enumerate(got) if v[0] < 0.01))

# Light fading: 2/(1 + (d/fade_distance)^fade_power).
for fd, fp in ((1, 2), (0.5, 1), (1, 0)):
    strip('<0,0,-2>, rgb 1 fade_distance %g fade_power %g' % (fd, fp),
          lambda r, c: c * 2 / (1 + (math.hypot(r, 2) / fd) ** fp), pixels=range(32, 64, 8), z=2)

# Fog: a wall of ambient 1 at distance 3.
WALLC, FC = (.5, .6, .7), (.2, .4, .8)
AMB = 'plane { -z, 0 pigment { rgb <.5,.6,.7> } finish { ambient 1 diffuse 0 } }\n'


def fogged(behind, fogs, d):
    keep, add = [1, 1, 1], [0, 0, 0]
    for depth, col, f, t in fogs:
        a = max(math.exp(-depth(d) / 2), t) if depth(d) < math.inf else t
        keep = [k * a * (1 - f + f * c) for k, c in zip(keep, col)]
        add = [s + (1 - a) * c for s, c in zip(add, col)]
    return [k * b + s for k, b, s in zip(keep, behind, add)]


for col, f, t in ((FC, 0, 0), (FC, .5, 0), (FC, 0, .3), (FC, .5, .3), (FC, 0, .1)):
    c = 'rgbft <%g,%g,%g,%g,%g>' % (col + (f, t))
    row('fog %s, the wall' % c, render(ORTHO + AMB + 'fog { distance 2 color %s }' % c),
        fogged(WALLC, [(lambda d: d, col, f, t)], 3))
    row('fog %s, the background' % c, render(ORTHO + 'background { rgb <1,.5,.25> } fog { distance 2 color %s }' % c),
        fogged((1, .5, .25), [(lambda d: d, col, f, t)], math.inf))
row('two fogs', render(ORTHO + AMB + 'fog { distance 2 color rgb <.2,.4,.8> } fog { distance 4 color rgb <1,0,0> }'),
    fogged(WALLC, [(lambda d: d, FC, 0, 0), (lambda d: d / 2, (1, 0, 0), 0, 0)], 3))
row('fog on a reflected ray (3 + 4)', render(ORTHO + 'plane { -z, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 } }\n'
                                             'plane { z, -4 pigment { rgb <.5,.6,.7> } finish { ambient 1 diffuse 0 } }\n'
                                             'fog { distance 2 color rgb <.2,.4,.8> }'),
    fogged(WALLC, [(lambda d: d, FC, 0, 0)], 7))
row('fog distance 0: no fog', render(ORTHO + AMB + 'fog { distance 0 color rgb 1 }'), WALLC)


# Ground fog: density 1 up to the offset, 1/(1 + ((h − offset)/alt)²) above (the manual's formula
# read with the square on the ratio), integrated along the ray.
def ground(off, alt):
    def integral(h):
        return h - off if h <= off else alt * math.atan((h - off) / alt)
    return integral


for off, alt in ((-1.125, 1), (-0.625, 0.5), (0, 1), (-3.125, 0.5)):
    u = -0.125 - off
    rho = 1 if u <= 0 else 1 / (1 + (u / alt) ** 2)
    got = render(ORTHO + AMB + 'fog { fog_type 2 fog_offset %g fog_alt %g distance 2 color rgb <.2,.4,.8> }' % (off, alt))
    row('ground fog, level ray, offset %g alt %g' % (off, alt), got, fogged(WALLC, [(lambda d: d * rho, FC, 0, 0)], 3))
for turn in ('up x', 'rotate -90*z'):
    got = render(ORTHO + AMB + 'fog { fog_type 2 fog_offset 0 fog_alt 1 %s distance 2 color rgb <.2,.4,.8> }' % turn)
    row('ground fog, ' + turn, got, fogged(WALLC, [(lambda d: d / (1 + 0.125 ** 2), FC, 0, 0)], 3))
SLANT = 'camera { orthographic location <0,3,-3> look_at 0 right x up y }\nplane { y, 0 pigment { rgb <.5,.6,.7> } finish { ambient 1 diffuse 0 } }\n'
for off, alt in ((0, 1), (1, 1), (1, 0.5), (-1, 2)):
    P = ground(off, alt)
    d = math.sqrt(18)
    got = render(SLANT + 'fog { fog_type 2 fog_offset %g fog_alt %g distance 2 color rgb <.2,.4,.8> }' % (off, alt), W=1, H=1)
    row('ground fog, slanted ray, offset %g alt %g' % (off, alt), got,
        fogged(WALLC, [(lambda dd: (P(3) - P(0)) / 3 * dd, FC, 0, 0)], d))

# looks_like: the object is moved to the light and casts no shadow.
got = render(ORTHO + FLOOR + 'light_source { <0.5,0,-1>, rgb 1 looks_like { sphere { 0, 0.2 pigment { rgb <1,0,0> } '
             'finish { ambient 1 diffuse 0 } } } }', W=8, H=8, pts=[(6, 3), (5, 3), (1, 1)])
row('looks_like sphere at the light, pixel (6,3)', got[0], (1, 0, 0))
for (i, j), g in zip(((5, 3), (1, 1)), got[1:]):
    x, y = -0.5 + (i + .5) / 8, 0.5 - (j + .5) / 8
    v = 1 / math.sqrt((x - .5) ** 2 + y ** 2 + 1)
    row('looks_like: the floor unshadowed, pixel (%d,%d)' % (i, j), g, (v, v, v))
