# Layered and patterned textures in POV-Ray 3.7 measured against the model of
# docs/povray-lighting.md ("Layered textures", "Patterned textures"): each layer lit with its own
# finish and normal and filtered by the layers above, reflections per layer (not filtered; traced
# when max(R)·grey(above) reaches adc_bailout), the transmitted ray through all layers, shadows
# through every layer, conserve_energy per layer, texture maps blending whole textures.
# Orthographic camera along +z, a plane facing it, a parallel light straight on (N·L = 1).
import math, os, sys
sys.dont_write_bytecode = True  # no __pycache__ in the checkout
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pv import render, ORTHO, row

LIGHT = 'light_source { <0,0,-10>, rgb 1 parallel point_at 0 }\n'
C = (1, .5, .25)
FILTER = 'texture { pigment { rgbf <1,.5,.25,.5> } finish { ambient 0 diffuse 0 %s } }'


def plane(textures, bg='rgb 0', light=LIGHT):
    return render(ORTHO + light + 'background { %s }\nplane { -z, 0 %s }' % (bg, textures))


def mul(a, b):
    return [x * y for x, y in zip(a, b)]


through = [.5 * c for c in C]  # f·C of the filter layer
row('white diffuse .8 under a filter layer', plane('texture { pigment { rgb 1 } finish { ambient 0 diffuse .8 } } ' + FILTER % ''),
    [.8 * t for t in through])
row('phong .6 on the filter layer over a dull one',
    plane('texture { pigment { rgb 1 } finish { ambient 0 diffuse 0 } } ' + FILTER % 'phong .6'), [.6] * 3)
row('phong 1 on the bottom, filtered', plane('texture { pigment { rgb 1 } finish { ambient 0 diffuse 0 phong 1 } } ' + FILTER % ''),
    through)
row('three layers, ambient 1 each',
    plane('texture { pigment { rgb <.2,.4,.8> } finish { ambient 1 diffuse 0 } } '
          'texture { pigment { rgbf <1,.5,.25,.5> } finish { ambient 1 diffuse 0 } } '
          'texture { pigment { rgbt <.5,1,.5,.6> } finish { ambient 1 diffuse 0 } }'),
    [.4 * a + .6 * .5 * b + .6 * t * c for a, b, t, c in zip((.5, 1, .5), C, through, (.2, .4, .8))])
tilt = math.atan(2 / 15)
row('normal on the bottom layer only',
    plane('texture { pigment { rgb 1 } normal { gradient x 1 } finish { ambient 0 diffuse .5 } } '
          'texture { pigment { rgbt <1,1,1,.5> } finish { ambient 0 diffuse 0 phong .3 phong_size 10 } }', 'rgb 0'),
    [.25 * math.cos(tilt) + .3] * 3)
row('normal on the top layer only',
    plane('texture { pigment { rgb 1 } finish { ambient 0 diffuse .5 } } '
          'texture { pigment { rgbt <1,1,1,.5> } normal { gradient x 1 } finish { ambient 0 diffuse 0 phong .3 phong_size 10 } }'),
    [.25 + .3 * math.cos(2 * tilt) ** 10] * 3)
bg = (1, .8, .6)
row('reflection per layer, the lower one unfiltered',
    plane('texture { pigment { rgb .5 } finish { ambient 1 diffuse 0 reflection .3 } } ' + FILTER % 'reflection .2',
          'rgb <1,.8,.6>'),
    [.5 * t + .3 * b + .2 * b for t, b in zip(through, bg)])
for tr, traced in (('.02', True), ('.01', False)):
    row('bottom reflection .3 under transmit %s (traced: %s)' % (tr, traced),
        plane('texture { pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection .3 } } '
              'texture { pigment { rgbt <1,.5,.25,%s> } finish { ambient 0 diffuse 0 } }' % tr, 'rgb <1,.8,.6>', light=''),
        [.3 * b if traced else 0 for b in bg], tol=3e-3)
row('conserve_energy on the top layer',
    plane('texture { pigment { rgb <.2,.4,.8> } finish { ambient 1 diffuse 0 } } ' + FILTER % 'reflection .4 conserve_energy',
          'rgb <.2,.4,.6>', light=''),
    [.4 * b + .6 * t * c for b, t, c in zip((.2, .4, .6), through, (.2, .4, .8))])
row('shadow through a two-layer pane (two surfaces)',
    render(ORTHO + LIGHT + 'plane { -z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n'
           'box { <-5,-5,-2>, <5,5,-1.5> texture { pigment { rgbt <.2,.4,.8,.5> } } '
           'texture { pigment { rgbf <1,.5,.25,.5> } } no_image }'),
    [(.5 * t) ** 2 for t in through])
row('a layer starts from the default finish (no light)',
    plane('texture { pigment { rgb <.2,.4,.8> } finish { ambient 1 diffuse 0 } } texture { pigment { rgbf <1,.5,.25,.5> } }',
          light=''),
    [.5 * .1 * c + t * b for c, t, b in zip(C, through, (.2, .4, .8))])
# Texture maps: both textures shaded in full, blended (value .825 at the centre pixel, x = .125).
A = 'pigment { rgb <.2,.4,.6> } finish { ambient 0 diffuse .5 phong .2 }'
B = 'pigment { rgbf <1,.5,.25,.6> } finish { ambient 1 diffuse 0 reflection .3 }'
sa = [.5 * c + .2 for c in (.2, .4, .6)]
sb = [.4 * c + .3 * b + .6 * c * b for c, b in zip(C, bg)]
row('gradient texture_map between two finishes',
    plane('texture { gradient x texture_map { [0 %s] [1 %s] } translate .3*x }' % (A, B), 'rgb <1,.8,.6>'),
    [min(1, .175 * a + .825 * b) for a, b in zip(sa, sb)])
