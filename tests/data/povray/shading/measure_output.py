# What POV-Ray 3.7 writes for a working-space colour c: sRGB(c^assumed_gamma); legacy scenes
# without assumed_gamma, and assumed_gamma srgb, write c as it is (docs/povray-lighting.md).
# Values are the 16-bit PPM's, not decoded; the 8-bit PNG holds round(255·v).
import os, sys
sys.dont_write_bytecode = True  # no __pycache__ in the checkout
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pv import render, fmt, ORTHO


def srgb(c):
    return 12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055


body = ORTHO + 'plane { -z, 0 pigment { rgb <.2,.5,.9> } finish { ambient 1 diffuse 0 } }'
for head, gamma in (('#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n', 1.0),
                    ('#version 3.7;\nglobal_settings { assumed_gamma 1.8 }\n', 1.8),
                    ('#version 3.7;\nglobal_settings { assumed_gamma 2.2 }\n', 2.2),
                    ('#version 3.7;\n', 1.0),
                    ('#version 3.6;\nglobal_settings { assumed_gamma 1.0 }\n', 1.0),
                    ('#version 3.6;\n', 0),
                    ('', 0),
                    ('#version 3.7;\nglobal_settings { assumed_gamma srgb }\n', 0)):
    got = render(body, head=head, raw=True)
    want = [srgb(c ** gamma) if gamma else c for c in (.2, .5, .9)]
    err = max(abs(a - b) for a, b in zip(got, want))
    print('%-56r povray %s (8-bit %s)  model %s  %s' % (head, fmt(got), [round(255 * v) for v in got], fmt(want),
                                                        'ok' if err < 2e-5 else 'DIFF %.5f' % err))
