# Filter, transmit, refraction, total internal reflection and interior fading of POV-Ray 3.7,
# measured against the model of docs/povray-lighting.md.
import math, os, sys
sys.dont_write_bytecode = True  # no __pycache__ in the checkout
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pv import render, fmt, ORTHO, HEAD, row

C = (0.5, 0.6, 0.7)
B = (0.2, 0.5, 0.9)
BG = 'background { rgb <.2,.5,.9> }\n'



# A pane (ambient 1) over the background: (1 - f - t)·C + (f·C + t)·B.
for (f, t) in ((.5, 0), (0, .5), (.3, .4)):
    got = render(ORTHO + BG + 'plane { -z, 0 pigment { rgbft <.5,.6,.7,%g,%g> } finish { ambient 1 diffuse 0 } }' % (f, t))
    row('pane rgbft f %g t %g, ambient 1' % (f, t), got, [(1 - f - t) * c + (f * c + t) * b for c, b in zip(C, B)])
# Legacy scenes: 1 - (f·max(C) + t).
for head, w in (('#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n', .4),
                ('#version 3.6;\nglobal_settings { assumed_gamma 1.0 }\n', .45),
                ('global_settings { assumed_gamma 1.0 }\n', .45)):
    got = render(ORTHO + 'plane { -z, 0 pigment { rgbft <.2,.6,.9,.5,.1> } finish { ambient 1 diffuse 0 } }', head=head)
    row('own colour share, %s' % head.split('\n')[0][:14], got, [w * c for c in (.2, .6, .9)])
# Diffuse is weighted by the opacity, highlights are not.
L60 = 'light_source { <0.866025,0,-0.5>*10, rgb 1 parallel point_at 0 }\n'
row('diffuse .8 on rgbft .3 .4 at 60', render(ORTHO + L60 + 'plane { -z, 0 pigment { rgbft <.5,.6,.7,.3,.4> } finish { ambient 0 diffuse .8 } }'),
    [.3 * .8 * .5 * c for c in C])
row('phong 1 size 1 on rgbft .3 .4 at 60', render(ORTHO + L60 + 'plane { -z, 0 pigment { rgbft <.5,.6,.7,.3,.4> } finish { ambient 0 diffuse 0 phong 1 phong_size 1 } }'),
    [.5] * 3)
row('emission 1 on rgbf .5', render(ORTHO + 'plane { -z, 0 pigment { rgbf <.5,.6,.7,.5> } finish { emission 1 ambient 0 diffuse 0 } }'),
    [.5 * c for c in C])
# Both surfaces of a box filter: (f·C)² B.
row('box rgbf .5: two surfaces', render(ORTHO + BG + 'box { <-5,-5,0>, <5,5,1> pigment { rgbf <.5,.6,.7,.5> } finish { ambient 0 diffuse 0 } }'),
    [(.5 * c) ** 2 * b for c, b in zip(C, B)])
# ior 1.5 without reflection: no automatic Fresnel loss.
row('clear pane ior 1.5 at 60 deg', render(ORTHO + BG + 'plane { -z, 0 rotate y*60 pigment { rgbt 1 } finish { ambient 0 diffuse 0 } interior { ior 1.5 } }'), B)
# Seen from inside (plane { z, 0 } holds the camera): total internal reflection beyond 41.8 deg
# replaces reflection and transmission by one reflected ray of full weight.
for fin in ('ambient 0 diffuse 0', 'ambient 1 diffuse 0', 'ambient 0 diffuse 0 reflection .3',
            'ambient 0 diffuse 0 reflection {.3 metallic 1}', 'ambient 0 diffuse 0 reflection .3 conserve_energy'):
    got = render(ORTHO + BG + 'plane { z, 0 rotate y*60 pigment { rgbf <.5,.6,.7,.5> } finish { %s } interior { ior 1.5 } }' % fin)
    amb = 1 if 'ambient 1' in fin else 0
    row('inside, TIR, rgbf .5, ' + fin, got, [min(1, amb * .5 * c + b) for c, b in zip(C, B)])
got = render(ORTHO + BG + 'plane { z, 0 pigment { rgbf <.5,.6,.7,.5> } finish { ambient 0 diffuse 0 reflection .3 } interior { ior 1.5 } }')
row('inside, normal incidence, rgbf .5, reflection .3', got, [.5 * c * b + .3 * b for c, b in zip(C, B)])
# Fading through a slab of depth d: a + (1 - a)·fade_color, a = 1/(1 + (d/fd)^p); p >= 1000: exp.
for p in (1, 2, 3, 1000):
    for d in (0.5, 1, 2, 4):
        got = render(ORTHO + 'background { rgb 1 }\nbox { <-5,-5,0>, <5,5,%g> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } interior { fade_distance 2 fade_power %g fade_color <.5,.2,0> } }' % (d, p))
        if p >= 1000:
            want = [math.exp(-(1 - fc) * d / 2) for fc in (.5, .2, 0)]
        else:
            a = 1 / (1 + (d / 2) ** p)
            want = [a + (1 - a) * fc for fc in (.5, .2, 0)]
        row('fade power %g depth %g' % (p, d), got, want)
# The camera inside a fading interior: its ray fades; the totally reflected ray does not.
for tilt, d in ((0, 3.0), (60, 3 - 0.866025 * 0.125 * 2)):
    got = render(ORTHO + 'background { rgb .5 }\nplane { z, 0 rotate y*%g pigment { rgbt 1 } finish { ambient 0 diffuse 0 } interior { ior 1.5 fade_distance 1 fade_power 1001 } }' % tilt)
    row('camera inside, fading, tilt %d' % tilt, got, [.5 * math.exp(-d)] * 3)
# Rays reflected inside an interior do not fade (slab, reflection .4, background .3).
for mtl in (2, 3, 4, 10):
    got = render(ORTHO + 'background { rgb .3 }\nbox { <-5,-5,0>, <5,5,1> pigment { rgbt 1 } finish { ambient 0 diffuse 0 reflection .4 } interior { fade_distance 1 fade_power 1001 } }',
                 gs='max_trace_level %d adc_bailout 0' % mtl)

    def seen(level, which):  # which: 'out' (front, from outside), 'in' (a face from inside)
        if level >= mtl:
            return 0
        if which == 'out':
            return .4 * .3 + math.exp(-1) * seen(level, 'in')
        return .3 + .4 * seen(level + 1, 'in')
    row('slab, internal reflections, max_trace_level %d' % mtl, got, [seen(1, 'out')] * 3)
# Nor does a ray reflected by a mirror inside a fading interior (only the way in fades: e^-2).
got = render(ORTHO + 'background { rgb 1 }\nbox { <-50,-50,-2>, <50,50,4> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } '
             'interior { fade_distance 1 fade_power 1001 } }\nplane { -z, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 } }')
row('mirror inside a fading box, normal incidence', got, [math.exp(-2)] * 3)
