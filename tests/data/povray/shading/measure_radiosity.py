# Radiosity (docs/povray-lighting.md, "Radiosity"): how the gathered light enters the surface colour,
# what ambient and emission do in 3.7 and legacy scenes, recursion_limit, highlights and reflection
# in the gathered light, gray_threshold. The environment is a sphere of radius 100 around the scene
# (uniform radiance), so every gathering ray brings the same light and the values are exact.
from pv import ORTHO, fmt, render

HEAD36 = '#version 3.6;\nglobal_settings { assumed_gamma 1.0 %s }\n'


def sky(plane, env, env_pigment='rgb 1'):
    return ORTHO + ('plane { -z, 0 pigment { rgb 1 } finish { %s } }\n'
                    'sphere { 0, 100 pigment { %s } finish { %s } }\n') % (plane, env_pigment, env)


def show(name, got, want):
    err = max(abs(a - b) for a, b in zip(got, want))
    print('%-58s povray %s  model %s  %s' % (name, fmt(got), fmt(want), 'ok' if err < 3e-4 else 'DIFF %.5f' % err))


R = 'radiosity { count 200 }'
EM = 'ambient 0 diffuse 0 emission .5'
# E = L under uniform radiance L; the surface shows diffuse·C·brightness·E.
show('no radiosity', render(sky('ambient 0 diffuse .6', EM)), [0] * 3)
show('diffuse .6 under emission .5', render(sky('ambient 0 diffuse .6', EM), R), [.3] * 3)
show('diffuse .3', render(sky('ambient 0 diffuse .3', EM), R), [.15] * 3)
show('brightness 2', render(sky('ambient 0 diffuse .6', EM), 'radiosity { count 200 brightness 2 }'), [.6] * 3)
show('pigment .5', render(sky('ambient 0 diffuse .6', EM).replace('rgb 1 } finish { ambient 0 diffuse .6',
                                                                   'rgb .5 } finish { ambient 0 diffuse .6'), R), [.15] * 3)
# 3.7: the finish's ambient neither shows nor lights others; emission does both.
show('3.7 plane ambient .2', render(sky('ambient .2 diffuse .6', EM), R), [.3] * 3)
show('3.7 plane ambient .2, ambient_light .5', render(sky('ambient .2 diffuse .6', EM), R + ' ambient_light .5'), [.3] * 3)
show('3.7 plane emission .2', render(sky('ambient 0 emission .2 diffuse .6', EM), R), [.5] * 3)
show('3.7 sky ambient .5 (no emission)', render(sky('ambient 0 diffuse .6', 'ambient .5 diffuse 0'), R), [0] * 3)
# Legacy scenes: ambient·ambient_light stays and lights others like emission.
show('3.6 sky ambient .5', render(sky('ambient 0 diffuse .6', 'ambient .5 diffuse 0'), head=HEAD36 % R), [.3] * 3)
show('3.6 plane ambient .2 diffuse 0', render(sky('ambient .2 diffuse 0', 'ambient .5 diffuse 0'), head=HEAD36 % R), [.2] * 3)
show('3.6 ambient_light .5', render(sky('ambient .2 diffuse .6', 'ambient .5 diffuse 0'),
                                    head=HEAD36 % (R + ' ambient_light .5')), [.25] * 3)
# recursion_limit n inside a closed sphere of emission e, diffuse ρ: e·(1 + ρ + … + ρ^n).
for n, want in ((1, .75), (2, .875), (3, .9375)):
    for fin in ('ambient 0 diffuse .5 emission .5', 'ambient .2 diffuse .5 emission .5'):
        show('recursion_limit %d, %s' % (n, fin),
             render(ORTHO + 'sphere { 0, 100 pigment { rgb 1 } finish { %s } }\n' % fin,
                    'radiosity { count 200 recursion_limit %d }' % n), [want] * 3)
# Gathering rays see the lights (direct .25 at the wall) but no highlights.
lit = ORTHO + 'light_source { 0, rgb .5 }\nsphere { 0, 100 pigment { rgb 1 } finish { %s } }\n'
show('lit wall, gathered', render(lit % 'ambient 0 diffuse .5', 'radiosity { count 400 recursion_limit 1 }'), [.375] * 3)
show('lit wall with phong .5 size 1 (camera highlight .25)',
     render(lit % 'ambient 0 diffuse .5 phong .5 phong_size 1', 'radiosity { count 400 recursion_limit 1 }'), [.625] * 3)
# They see reflections too: .50545 (without reflection in the gathered light it would be .4686).
print('lit wall with reflection .2, gathered:', fmt(render(lit % 'ambient 0 diffuse .5 reflection .2',
                                                          'radiosity { count 400 recursion_limit 1 }')))
# gray_threshold g: (1 − g)·c + g·grey(c), grey = .297 r + .589 g + .114 b.
for g in (0, .5, 1):
    c = [.5, .2, .1]
    grey = .297 * c[0] + .589 * c[1] + .114 * c[2]
    show('gray_threshold %g' % g, render(sky('ambient 0 diffuse 1', 'ambient 0 diffuse 0 emission <.5,.2,.1>'),
                                         'radiosity { count 200 gray_threshold %g }' % g),
         [(1 - g) * v + g * grey for v in c])
# Gathering rays see area lights as points at their centre; the light sits in the ceiling's plane
# (radiosity/cornell.pov's lights do), which must not block its shadow rays. A ceiling lit only by
# the floor: .10530 with a point light and with a 20×20 area light of 8×8 samples; the floor .29464.
CEIL = ('light_source { <27.8,54.88,27.95> color 1 fade_power 2 fade_distance 30 %s }\n'
        'plane { y, 0 pigment { rgb 1 } finish { diffuse .75 ambient 0 } }\n'
        'plane { -y, -54.88 pigment { rgb 1 } finish { diffuse .75 ambient 0 } }\n')
UP = 'camera { orthographic location <12,20,40> look_at <12,54,40> right x*1 up z*1 }\n'
DOWN = 'camera { orthographic location <12,20,40> look_at <12,0,40> right x*1 up z*1 }\n'
RC = 'radiosity { pretrace_start 0.04 pretrace_end 0.01 count 200 recursion_limit 1 nearest_count 10 error_bound 0.5 }'
print('floor under a light in the ceiling plane:', fmt(render(DOWN + CEIL % '')))
print('ceiling, point light:', fmt(render(UP + CEIL % '', RC)))
print('ceiling, area light 20x20 8x8:', fmt(render(UP + CEIL % 'area_light 20*x, 20*z, 8, 8', RC)))
# A 10x10 board 10.88 below the light shades the floor: .06491 for the point and the area light alike.
BOARD = 'box { <22.8,44,22.95>, <32.8,44.1,32.95> pigment { rgb 1 } finish { diffuse 0 ambient 0 } }\n'
UP2 = 'camera { orthographic location <10,40,10> look_at <10,54,10> right x*1 up z*1 }\n'
print('shaded ceiling, point light:', fmt(render(UP2 + CEIL % '' + BOARD, RC)))
print('shaded ceiling, area light 20x20 8x8:', fmt(render(UP2 + CEIL % 'area_light 20*x, 20*z, 8, 8' + BOARD, RC)))
# Lights: a declared light with modifiers after it; negative spotlight angles (measure_lights.py's floor).
FLOOR = ORTHO + 'plane { -z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n'
print('declared light translated:', fmt(render(FLOOR + '#declare SP = light_source { <0,0,-10>, rgb 1 fade_power 2 fade_distance 4 }\n'
                                               'light_source { SP translate <1,0,0> }\n')))
for spot in ('radius -90 falloff 90', 'radius -60 falloff 90', 'radius 10 falloff -80'):
    print('spotlight %s, 60 degrees off:' % spot, fmt(render(FLOOR + 'light_source { <0,0,-10>, rgb 1 spotlight tightness 0 '
                                                               'point_at <17.32,0,0> %s }\n' % spot)))
