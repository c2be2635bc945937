#!/usr/bin/env python3
"""Measures POV-Ray camera rays (Rays tests/pov_camera_test.cpp): renders a direction-encoding scene with
POV-Ray and prints the unit view direction at pixels. Needs povray; writes m.pov and m.ppm here.
usage: measure.py 'CAMERA BODY' W H x,y [x,y ...]   (x,y pixel indices, y from the top)
mode 'hit': colour encodes the hit point on the plane z=Z (x,y in [-S/2,S/2])."""
import subprocess, sys, math, os
cam, W, H = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
pts = [tuple(int(t) for t in a.split(',')) for a in sys.argv[4:]]
mode = os.environ.get('MODE', 'dir')
S = float(os.environ.get('S', '20')); Z = float(os.environ.get('Z', '10'))
if mode == 'dir':
    f = lambda e: "function { 0.5+0.5*(%s)/sqrt(x*x+y*y+z*z) }" % e
    obj = "sphere { 0, 1000 hollow"
else:
    f = lambda e: "function { %s }" % {"x": "x/%g+0.5" % S, "y": "y/%g+0.5" % S, "z": "0"}[e]
    obj = "plane { z, %g" % Z
scene = """#version 3.7;
global_settings { assumed_gamma 1 }
background { rgb 0 }
camera { %s }
%s texture { pigment { average pigment_map {
  [1 %s color_map { [0 rgb 0] [1 rgb <3,0,0>] }]
  [1 %s color_map { [0 rgb 0] [1 rgb <0,3,0>] }]
  [1 %s color_map { [0 rgb 0] [1 rgb <0,0,3>] }] } }
  finish { ambient 1 diffuse 0 emission 0 } } }
""" % (cam, obj, f("x"), f("y"), f("z"))
open('m.pov', 'w').write(scene)
r = subprocess.run(['povray', '+Im.pov', '+Om.ppm', '+FP16', 'File_Gamma=1.0', '+W%d' % W, '+H%d' % H, '-D', '-A',
                    'Work_Threads=2', '-GA'], capture_output=True, text=True)
if r.returncode: print(r.stderr[-2000:]); sys.exit(1)
data = open('m.ppm', 'rb').read()
# parse header
parts = []; i = 0
while len(parts) < 4:
    while data[i:i+1].isspace() or data[i:i+1] == b'#':
        if data[i:i+1] == b'#':
            while data[i:i+1] != b'\n': i += 1
        else: i += 1
    j = i
    while not data[j:j+1].isspace(): j += 1
    parts.append(data[i:j]); i = j
i += 1
w, h, mx = int(parts[1]), int(parts[2]), int(parts[3])
def px(x, y):
    o = i + (y * w + x) * 6
    return [int.from_bytes(data[o+2*k:o+2*k+2], 'big') / mx for k in range(3)]
for (x, y) in pts:
    c = px(x, y)
    if mode == 'dir':
        d = [2 * v - 1 for v in c]
        print("%d,%d: %s |d|=%.4f" % (x, y, " ".join("%+.5f" % v for v in d), math.sqrt(sum(v*v for v in d))))
    else:
        print("%d,%d: hit %+.4f %+.4f  (raw %s)" % (x, y, (c[0]-0.5)*S, (c[1]-0.5)*S, " ".join("%.4f" % v for v in c)))
