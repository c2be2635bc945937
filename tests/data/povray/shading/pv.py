# Black-box measurement harness for POV-Ray 3.7's lighting (docs/povray-lighting.md): renders a
# tiny scene with the installed `povray` to a 16-bit PPM and returns the pixels' working-space
# values (sRGB decoded; scenes use assumed_gamma 1, so working space = linear).
# Needs POV-Ray; the renders go to $POVSHADE_SCRATCH (default: build-scratch/ in the checkout).
import os, subprocess, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SCRATCH = os.environ.get('POVSHADE_SCRATCH', os.path.join(HERE, '../../../../build-scratch'))
HEAD = '#version 3.7;\nglobal_settings { assumed_gamma 1.0 %s }\n'
# Orthographic camera looking along +z: the view ray is (0,0,1), V = (0,0,-1).
ORTHO = 'camera { orthographic location -3*z look_at 0 right x up y }\n'


def srgb_decode(v):
    return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4


def read_ppm(path):
    data = open(path, 'rb').read()
    toks, i = [], 0
    while len(toks) < 4:
        while data[i:i + 1].isspace():
            i += 1
        if data[i:i + 1] == b'#':
            while data[i:i + 1] != b'\n':
                i += 1
            continue
        j = i
        while not data[j:j + 1].isspace():
            j += 1
        toks.append(data[i:j])
        i = j
    w, h, mx = int(toks[1]), int(toks[2]), int(toks[3])
    return w, h, mx, data[i + 1:]


def render(body, gs='', W=4, H=4, pts=None, raw=False, head=None):
    """Renders HEAD (with global settings gs) + body; returns the decoded pixel(s) at pts
    (default: the centre pixel). raw: the encoded values (0..1) instead."""
    os.makedirs(SCRATCH, exist_ok=True)
    d = tempfile.mkdtemp(dir=SCRATCH)
    src = (HEAD % gs if head is None else head) + body
    f = os.path.join(d, 's.pov')
    open(f, 'w').write(src)
    o = os.path.join(d, 's.ppm')
    r = subprocess.run(['povray', '+I' + f, '+O' + o, '+FP16', '+W%d' % W, '+H%d' % H, '-D', '-A',
                        'Work_Threads=1', '+L/usr/share/povray-3.7/include'], capture_output=True, text=True)
    if r.returncode != 0 or not os.path.exists(o):
        raise SystemExit(r.stderr[-2000:])
    w, h, mx, px = read_ppm(o)
    for name in ('s.pov', 's.ppm'):
        os.remove(os.path.join(d, name))
    os.rmdir(d)
    if pts is None:
        pts = [(w // 2, h // 2)]
    out = []
    for (x, y) in pts:
        k = (y * w + x) * 3
        v = [(px[2 * (k + c)] << 8 | px[2 * (k + c) + 1]) / mx for c in range(3)]
        out.append(v if raw else [srgb_decode(c) for c in v])
    return out[0] if len(out) == 1 else out


def fmt(v):
    return ' '.join('%.5f' % c for c in v)


def row(name, got, want, tol=3e-5):
    """Prints a measured value beside the model's, ending in ok or DIFF and the largest difference."""
    got, want = list(got), list(want)
    err = max(abs(a - b) for a, b in zip(got, want))
    print('%-58s povray %s  model %s  %s' % (name, fmt(got), fmt(want), 'ok' if err < tol else 'DIFF %.5f' % err))
