# The curve behind `metallic`: with a parallel light at angle a from the normal of a plane facing
# an orthographic camera, `phong 1 phong_size 1 metallic 1` on pigment C gives
# cos(a)·(1 + (1 − F)·(C − 1)); F is solved from the red channel (C = 0.5) and compared with
# F(x) = 0.014567225/(x − 1.12)² − 0.011612903, x = a/90° (clamped to [0, 1]).
import math, sys, os
sys.dont_write_bytecode = True  # no __pycache__ in the checkout
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pv import render, ORTHO


def fit(x):
    return min(1.0, max(0.0, 0.014567225 / (x - 1.12) ** 2 - 0.011612903))


for a in (0, 10, 20, 30, 40, 50, 60, 70, 75, 80, 85, 88):
    r = math.radians(a)
    L = (math.sin(r), 0, -math.cos(r))
    v = render(ORTHO + 'light_source { <%f,%f,%f>*10, rgb 1 parallel point_at 0 }\n' % L +
               'plane { -z, 0 pigment { rgb <.5,.6,.7> } finish { ambient 0 diffuse 0 phong 1 phong_size 1 metallic 1 } }')
    tint = v[0] / math.cos(r)
    F = 1 - (tint - 1) / (0.5 - 1)
    print('angle %2d  F measured %.5f  fitted %.5f' % (a, F, fit(a / 90)))
