# Shadows in POV-Ray 3.7: through transparent objects (filter·C + transmit per surface crossed,
# fading inside interiors; the light at a point seen through a fading interior divided by the
# viewing ray's fade), parallel lights' shadow plane, area lights shaded from their centre. A white floor facing an orthographic camera; docs/povray-lighting.md.
import math, os, sys
sys.dont_write_bytecode = True  # no __pycache__ in the checkout
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pv import render, fmt, ORTHO, row

C = (0.5, 0.6, 0.7)
L60 = 'light_source { <0.866025,0,-0.5>*100, rgb 1 parallel point_at 0 }\n'
FLOOR = 'plane { -z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n'



# A thin box beside the view, crossed twice by the floor's shadow ray (cos 60 = .5 unshadowed).
for pig, tint in (('rgb <.5,.6,.7>', (0, 0, 0)), ('rgbf <.5,.6,.7,.5>', [.5 * c for c in C]),
                  ('rgbt <.5,.6,.7,.5>', (.5, .5, .5)), ('rgbft <.5,.6,.7,.3,.4>', [.3 * c + .4 for c in C])):
    got = render(ORTHO + L60 + FLOOR + 'box { <1,-5,-1.01>, <5,5,-1> pigment { %s } finish { ambient 0 diffuse 0 } }' % pig)
    row('shadow through a thin box of ' + pig, got, [.5 * t * t for t in tint])
got = render(ORTHO + L60 + FLOOR + 'box { <1,-5,-1.01>, <5,5,-1> pigment { rgbt <.5,.6,.7,.5> } finish { ambient 0 diffuse 0 reflection .5 conserve_energy } interior { ior 1.5 } }')
row('... rgbt .5 with ior 1.5, reflection, conserve', got, [.125] * 3)
# Fading along the shadow ray inside a thick box: the centre pixel's point is x = 0.125, the ray
# enters the top (z = -1) and leaves the side x = 5.
d = (5 - 0.125) / 0.866025 - 2
for p, want in ((1, [.5 * (a + (1 - a) * fc) for a in [1 / (1 + d / 2)] for fc in (.5, .2, 0)]),
                (1001, [.5 * math.exp(-(1 - fc) * d / 2) for fc in (.5, .2, 0)])):
    got = render(ORTHO + L60 + FLOOR + 'box { <1,-5,-3>, <5,5,-1> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } interior { fade_distance 2 fade_power %g fade_color <.5,.2,0> } }' % p)
    row('shadow fading through a thick box, power %g' % p, got, want)
# The floor inside a clear fading box whose front is 1 or 2 in front of it (V, the viewing ray's
# length inside): the light is faded over the shadow ray's length inside (S, up to where it leaves
# the box, 0 when it reaches the light's plane first) and divided by the fade over V, so the
# floor's value is 0.2·cos·fade(S) whatever V.
def fade(d, p):
    return math.exp(-d) if p >= 1000 else 1 / (1 + d ** p)


for p in (1001, 1, 2):
    for zf, side in ((-1, 50), (-2, 50), (-2, 1)):
        for ang in (0, 37, 60, 80):
            a = math.radians(ang)
            box = ('box { <-50,-50,%g>, <%g,50,2> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } '
                   'interior { fade_distance 1 fade_power %g } }\n' % (zf, side, p))
            got = render(ORTHO + 'light_source { <%f,0,%f>*10, rgb 1 parallel point_at 0 }\n' % (math.sin(a), -math.cos(a)) +
                         box + FLOOR.replace('rgb 1', 'rgb .2'))
            S = min((side - 0.125) / math.sin(a) if ang else 1e9, -zf / math.cos(a))
            if S > 10:  # the light's plane is 10 away
                S = 0
            row('floor in a fading box (power %g), front %g side %g, light %d' % (p, -zf, side, ang), got,
                [.2 * math.cos(a) * fade(S, p)] * 3)
for p in (1, 2):
    box = ('box { <-50,-50,-2>, <50,50,2> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } '
           'interior { fade_distance 1 fade_power %g } }\n' % p)
    got = render(ORTHO + 'light_source { <0,0,-1>, rgb 1 }\n' + box + FLOOR.replace('rgb 1', 'rgb .2'))
    row('floor and point light inside a fading box (power %g)' % p, got, [.2 / math.sqrt(1 + 2 * .125 ** 2)] * 3)
# A 45-degree mirror inside the fading box sends the view to a wall inside it: the wall's light is
# faded over its shadow ray's path only (neither the way in nor the reflected ray counts).
x0 = 0.125
got = render(ORTHO + 'box { <-50,-50,-2>, <50,50,4> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } '
             'interior { fade_distance 1 fade_power 1001 } }\n'
             'box { <-0.5,-0.5,0>, <0.5,0.5,0.1> rotate y*45 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 } }\n'
             'plane { x, -2 pigment { rgb .2 } finish { ambient 0 diffuse 1 } }\n'
             'light_source { <0.6,0,-0.8>*10, rgb 1 parallel point_at 0 }\n')
row('wall seen in a mirror inside a fading box', got, [.2 * .6 * math.exp(-(2 - x0) / .8)] * 3)
# Outside the interior the fade of the way there counts as usual (a floor behind a fading slab).
got = render(ORTHO + 'box { <-1,-50,-2>, <1,50,-1> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } '
             'interior { fade_distance 1 fade_power 1001 } }\n' + FLOOR.replace('rgb 1', 'rgb .2') +
             'light_source { <0.8,0,-0.6>*10, rgb 1 parallel point_at 0 }\n')
row('floor behind a fading slab, light beside it', got, [.2 * .6 * math.exp(-1)] * 3)
# Parallel lights: no shadows from beyond the plane through the light across its direction.
for dist in (2, 4, 100):
    got = render(ORTHO + 'light_source { <0.866025,0,-0.5>*%g, rgb 1 parallel point_at 0 }\n' % dist + FLOOR +
                 'box { <1,-5,-3.01>, <8,5,-3> pigment { rgb 0 } }')
    row('parallel light %g away, occluder 6 away' % dist, got, [.5 if dist < 6 else 0] * 3)
got = render(ORTHO + 'light_source { <0.866025,0,-0.5>*-2, rgb 1 parallel point_at <0.866025,0,-0.5>*-4 }\n' + FLOOR)
row('point beyond the parallel light\'s plane: lit', got, [.5] * 3)
# Area lights: the shading direction is the centre's (samples at x = -4, +4 would give 0.447).
P = (0.125, -0.125, 0)
toc = [0 - P[0], 0 - P[1], -2]
cosc = 2 / math.sqrt(sum(t * t for t in toc))
for n in (2, 3):
    got = render(ORTHO + 'light_source { <0,0,-2>, rgb 1 area_light <8,0,0>, <0,1,0>, %d, 1 }\n' % n + FLOOR)
    row('area light %dx1, 8 wide, 2 above' % n, got, [cosc] * 3)
# Shadow rays are not limited by max_trace_level or adc_bailout (20 thin boxes, rgbt .9; the ray
# crosses the first 19).
s = ORTHO + L60 + FLOOR + ''.join('box { <1,-5,%g>, <5,5,%g> pigment { rgbt <1,1,1,.9> } finish { ambient 0 diffuse 0 } }\n'
                                  % (-1 - 0.1 * k - 0.01, -1 - 0.1 * k) for k in range(20))
for gs in ('max_trace_level 1 adc_bailout 0.05', 'max_trace_level 5'):
    row('shadow through 19 thin boxes, ' + gs, render(s, gs=gs), [.5 * .9 ** 38] * 3)
