# Reflection in POV-Ray 3.7: plain and coloured, variable {min, max} with falloff, fresnel (the
# interior's ior, from outside and inside), exponent, metallic, conserve_energy. A plane facing an
# orthographic camera, turned about y, reflects the background; docs/povray-lighting.md.
import math, os, sys
sys.dont_write_bytecode = True  # no __pycache__ in the checkout
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pv import render, fmt, ORTHO, row

C = (0.5, 0.6, 0.7)
B = (0.2, 0.5, 0.9)
BG = 'background { rgb <.2,.5,.9> }\n'



def fresnel(cosi, eta):
    s2 = eta * eta * (1 - cosi * cosi)
    if s2 >= 1:
        return 1.0
    ct = math.sqrt(1 - s2)
    rs = (eta * cosi - ct) / (eta * cosi + ct)
    rp = (cosi - eta * ct) / (cosi + eta * ct)
    return 0.5 * (rs * rs + rp * rp)


def metal_curve(c):
    x = math.acos(max(-1, min(1, c))) / (math.pi / 2)
    return min(1, max(0, 0.014567225 / (x - 1.12) ** 2 - 0.011612903))


def plane(finish, tilt=0, pigment='rgb <.5,.6,.7>', interior='', normal='-z'):
    return render(ORTHO + BG + 'plane { %s, 0 rotate y*%g pigment { %s } finish { ambient 0 diffuse 0 %s } %s }'
                  % (normal, tilt, pigment, finish, interior))


row('reflection .4 with ambient 1 (adds, takes nothing)',
    render(ORTHO + BG + 'plane { -z, 0 pigment { rgb <.5,.6,.7> } finish { ambient 1 diffuse 0 reflection .4 } }'),
    [min(1, c + .4 * b) for c, b in zip(C, B)])
row('reflection <.4,.2,.1>', plane('reflection <.4,.2,.1>'), [r * b for r, b in zip((.4, .2, .1), B)])
for tilt in (0, 30, 60, 80):
    cs = math.cos(math.radians(tilt))
    row('reflection {.1, .9} at %d' % tilt, plane('reflection {.1, .9}', tilt), [(.1 + .8 * (1 - cs)) * b for b in B])
    row('reflection {.1, .9 falloff 2} at %d' % tilt, plane('reflection {.1, .9 falloff 2}', tilt),
        [(.1 + .8 * (1 - cs) ** 2) * b for b in B])
    row('reflection {0, 1 fresnel} ior 1.5 at %d' % tilt,
        plane('reflection {0, 1 fresnel}', tilt, interior='interior { ior 1.5 }'), [fresnel(cs, 1 / 1.5) * b for b in B])
    row('reflection {.4 metallic 1} at %d' % tilt, plane('reflection {.4 metallic 1}', tilt),
        [.4 * (1 + (1 - metal_curve(cs)) * (c - 1)) * b for c, b in zip(C, B)])
for tilt in (0, 20, 35):
    cs = math.cos(math.radians(tilt))
    row('fresnel seen from inside (eta 1.5) at %d' % tilt,
        plane('reflection {0, 1 fresnel}', tilt, interior='interior { ior 1.5 }', normal='z'),
        [fresnel(cs, 1.5) * b for b in B])
row('reflection {.2, .8 fresnel} ior 1.5 at 0', plane('reflection {.2, .8 fresnel}', 0, interior='interior { ior 1.5 }'),
    [(.2 + .6 * .04) * b for b in B])
row('reflection {1 fresnel} (one value: min 0) at 60', plane('reflection {1 fresnel}', 60, interior='interior { ior 1.5 }'),
    [fresnel(.5, 1 / 1.5) * b for b in B])
row('reflection {.5 falloff 2} (one value: constant) at 60', plane('reflection {.5 falloff 2}', 60), [.5 * b for b in B])
for e in (.5, 2):
    row('reflection {.4 exponent %g}' % e, plane('reflection {.4 exponent %g}' % e), [.4 * b ** (1 / e) for b in B])
# conserve_energy: filter and transmit times 1 - reflection (per channel, metallic included, not
# the exponent); the surface's own colour is untouched.
row('rgbft .3 .4, reflection .4', plane('reflection .4', pigment='rgbft <.5,.6,.7,.3,.4>'),
    [.4 * b + (.3 * c + .4) * b for c, b in zip(C, B)])
row('rgbft .3 .4, reflection <.4,.2,.1> conserve_energy',
    plane('reflection <.4,.2,.1> conserve_energy', pigment='rgbft <.5,.6,.7,.3,.4>'),
    [r * b + (1 - r) * (.3 * c + .4) * b for r, c, b in zip((.4, .2, .1), C, B)])
for tilt in (0, 60):
    cs = math.cos(math.radians(tilt))
    R = [.4 * (1 + (1 - metal_curve(cs)) * (c - 1)) for c in C]
    row('rgbt .5, reflection {.4 metallic 1} conserve at %d' % tilt,
        plane('reflection {.4 metallic 1} conserve_energy', tilt, pigment='rgbt <.5,.6,.7,.5>'),
        [r * b + (1 - r) * .5 * b for r, b in zip(R, B)])
row('rgbt .2, reflection {.3 exponent .5} conserve',
    plane('reflection {.3 exponent .5} conserve_energy', pigment='rgbt <.5,.6,.7,.2>'),
    [.3 * b * b + .7 * .2 * b for b in B])
row('ambient 1, reflection .4 conserve (own colour kept)',
    render(ORTHO + 'plane { -z, 0 pigment { rgb <.5,.6,.7> } finish { ambient 1 diffuse 0 reflection .4 conserve_energy } }'), C)
