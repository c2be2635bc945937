# max_trace_level and adc_bailout in POV-Ray 3.7 (docs/povray-lighting.md): two facing mirrors
# (ambient .1, reflection .5) with an orthographic camera between them; stacks of thin clear boxes.
import os, sys
sys.dont_write_bytecode = True  # no __pycache__ in the checkout
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pv import render, fmt, row

CAM = 'camera { orthographic location -1*z look_at 0 right x up y }\n'



def mirrors(gs, refl='.5', bg='rgb 1'):
    return render(CAM + 'background { %s }\n' % bg +
                  'plane { -z, 0 pigment { rgb 1 } finish { ambient .1 diffuse 0 reflection %s } }\n' % refl +
                  'plane { z, -2 pigment { rgb 1 } finish { ambient .1 diffuse 0 reflection %s } }\n' % refl, gs=gs)


def series(terms, r=.5):
    return .1 * sum(r ** k for k in range(terms))


# The camera ray is level 1; a surface at level max_trace_level sends no further ray.
for mtl in (1, 2, 3, 5):
    row('mirrors, max_trace_level %d' % mtl, mirrors('max_trace_level %d adc_bailout 0' % mtl), [series(mtl)] * 3)
# A ray is traced when its weight (product of max(reflection) along the way) is at least adc_bailout.
for adc, terms in ((.3, 2), (.2, 3), (.1, 4), (.05, 5), (.02, 6)):
    row('mirrors, adc_bailout %g' % adc, mirrors('max_trace_level 20 adc_bailout %g' % adc), [series(terms)] * 3)
    row('mirrors, reflection <.5,.2,.2>, adc_bailout %g' % adc,
        mirrors('max_trace_level 20 adc_bailout %g' % adc, refl='<.5,.2,.2>'),
        [series(terms), series(terms, .2), series(terms, .2)])


def boxes(gs, n, pigment='rgbt 1', finish='ambient 0 diffuse 0', interior=''):
    return render(CAM + 'background { rgb 1 }\n' + ''.join(
        'box { <-5,-5,%g>, <5,5,%g> pigment { %s } finish { %s } %s }\n' % (.1 * k, .1 * k + .01, pigment, finish, interior)
        for k in range(n)), gs=gs)


# Passing straight through (ior 1) keeps the level; each refraction adds one.
for n in (1, 2, 4):
    for mtl in (1, 2):
        row('%d clear boxes, ior 1, max_trace_level %d' % (n, mtl), boxes('max_trace_level %d adc_bailout 0' % mtl, n),
            [1 if mtl >= 2 else 0] * 3)
    for mtl in (2 * n, 2 * n + 1):
        row('%d clear boxes, ior 1.5, max_trace_level %d' % (n, mtl),
            boxes('max_trace_level %d adc_bailout 0' % mtl, n, interior='interior { ior 1.5 }'),
            [1 if mtl > 2 * n else 0] * 3)


# Transmitted rays carry the weight too (3 boxes of rgbt .5 with ambient .2: each surface keeps .1).
def stack(adc, surfaces=6):
    def at(k):
        c = .1
        if .5 ** (k + 1) >= adc:
            c += .5 * (at(k + 1) if k + 1 < surfaces else 1.0)
        return c
    return at(0)


for adc in (0, .3, .2, .1, .05):
    row('3 boxes rgbt .5 ambient .2, adc_bailout %g' % adc,
        boxes('max_trace_level 20 adc_bailout %g' % adc, 3, 'rgbt <1,1,1,.5>', 'ambient .2 diffuse 0'), [stack(adc)] * 3)
