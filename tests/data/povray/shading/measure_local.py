# Local lighting of POV-Ray 3.7 measured against the model of docs/povray-lighting.md: ambient and
# emission, diffuse with brilliance, the second diffuse value, double_illuminate, phong, specular
# and metallic highlights. Orthographic camera along +z, a plane facing it, parallel lights.
import math, os, sys
sys.dont_write_bytecode = True  # no __pycache__ in the checkout
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pv import render, fmt, ORTHO, row

C = (0.5, 0.6, 0.7)
PIG = 'rgb <.5,.6,.7>'



def rot_y(v, deg):
    a = math.radians(deg)
    c, s = math.cos(a), math.sin(a)
    return (c * v[0] + s * v[2], v[1], -s * v[0] + c * v[2])


def lit(L, finish, extra='', tilt=0, lc='rgb 1', gs=''):
    return render(ORTHO + 'light_source { <%f,%f,%f>*10, %s parallel point_at 0 }\n' % (L + (lc,)) +
                  'plane { -z, 0 rotate y*%g pigment { %s } finish { %s } %s }' % (tilt, PIG, finish, extra), gs=gs)


def front(deg):
    a = math.radians(deg)
    return (math.sin(a), 0.0, -math.cos(a))


def metal_curve(c):
    x = math.acos(max(-1, min(1, c))) / (math.pi / 2)
    return min(1, max(0, 0.014567225 / (x - 1.12) ** 2 - 0.011612903))


row('ambient <.3,.2,.1>, ambient_light <1,2,.5>',
    render(ORTHO + 'plane { -z, 0 pigment { %s } finish { ambient <.3,.2,.1> diffuse 0 } }' % PIG,
           gs='ambient_light <1,2,.5>'), [a * l * c for a, l, c in zip((.3, .2, .1), (1, 2, .5), C)])
row('emission <.3,.2,.1> + ambient .2, light .5',
    render(ORTHO + 'plane { -z, 0 pigment { %s } finish { emission <.3,.2,.1> ambient .2 diffuse 0 } }' % PIG,
           gs='ambient_light .5'), [(e + .2 * .5) * c for e, c in zip((.3, .2, .1), C)])
for ang in (0, 30, 60):
    for b in (1, 2.5):
        row('diffuse .8 brilliance %g at %d deg' % (b, ang), lit(front(ang), 'ambient 0 diffuse .8 brilliance %g' % b),
            [.8 * math.cos(math.radians(ang)) ** b * c for c in C])
row('light rgb <3,2,.5> at 60 deg', lit(front(60), 'ambient 0 diffuse .8', lc='rgb <3,2,.5>'),
    [min(1, l * .8 * .5 * c) for l, c in zip((3, 2, .5), C)])
behind = rot_y((0, 0, 1), 60)  # 120 deg from the facing normal
row('light behind, diffuse .8', lit(behind, 'ambient 0 diffuse .8'), (0, 0, 0))
row('light behind, diffuse .8, .3 brilliance 2', lit(behind, 'ambient 0 diffuse .8, .3 brilliance 2'),
    [.3 * .25 * c for c in C])
row('light behind, double_illuminate', lit(behind, 'ambient 0 diffuse .8, .3', 'double_illuminate'),
    [.8 * .5 * c for c in C])
for ang in (0, 10, 20):
    row('phong .7 phong_size 20 at %d deg' % ang, lit(front(ang), 'ambient 0 diffuse 0 phong .7 phong_size 20'),
        [.7 * math.cos(math.radians(ang)) ** 20] * 3)
    row('specular .7 roughness .02 at %d deg' % ang, lit(front(ang), 'ambient 0 diffuse 0 specular .7 roughness .02'),
        [.7 * math.cos(math.radians(ang / 2)) ** 50] * 3)
# metallic: the curve's angle is that of the light (N.L), seen on a plane turned 40 deg
N = rot_y((0, 0, -1), 40)
V = (0, 0, -1)
for off in (-10, 10, 25):
    L = rot_y(N, off)
    nl = sum(a * b for a, b in zip(N, L))
    R = [2 * nl * n - l for n, l in zip(N, L)]
    rv = sum(a * b for a, b in zip(R, V))
    H = [l + v for l, v in zip(L, V)]
    hn = math.sqrt(sum(h * h for h in H))
    nh = sum(n * h / hn for n, h in zip(N, H))
    tint = [1 + (1 - metal_curve(nl)) * (c - 1) for c in C]
    row('phong metallic, plane 40, light %+d' % off, lit(L, 'ambient 0 diffuse 0 phong 1 phong_size 1 metallic', tilt=40),
        [rv * t for t in tint])
    row('specular metallic, plane 40, light %+d' % off,
        lit(L, 'ambient 0 diffuse 0 specular 1 roughness 1 metallic', tilt=40), [nh * t for t in tint])
row('metallic .5 phong at 60', lit(front(60), 'ambient 0 diffuse 0 phong 1 phong_size 1 metallic .5'),
    [.5 * (1 + .5 * (1 - metal_curve(.5)) * (c - 1)) for c in C])
# highlights from behind: only with double_illuminate, with the viewer's normal
back30 = (0.5, 0, math.sqrt(.75))
row('specular, light behind', lit(back30, 'ambient 0 diffuse 0 specular 1 roughness 1'), (0, 0, 0))
row('specular, light behind, double_illuminate',
    lit(back30, 'ambient 0 diffuse 0 specular 1 roughness 1', 'double_illuminate'), [0.25882] * 3)
row('phong, light behind, double_illuminate',
    lit(back30, 'ambient 0 diffuse 0 phong 1 phong_size 1', 'double_illuminate'), (0, 0, 0))
row('specular + diffuse back only, light behind', lit(back30, 'ambient 0 diffuse 0, .5 specular 1 roughness 1'),
    [.5 * math.sqrt(.75) * c for c in C])
