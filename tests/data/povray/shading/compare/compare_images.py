# Compares two 8-bit PPM images of the same size: mean and largest channel difference, and how
# many pixels differ by more than 2 and 8 levels. With a third argument, also writes a PNG of the
# two side by side and their difference times 8, each scaled up 2×.
import os, struct, sys, zlib
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
from pv import read_ppm

w, h, _, a = read_ppm(sys.argv[1])
_, _, _, b = read_ppm(sys.argv[2])
a, b = a[:w * h * 3], b[:w * h * 3]
d = [abs(x - y) for x, y in zip(a, b)]
worst = [max(d[3 * i:3 * i + 3]) for i in range(w * h)]
print('mean abs diff %.3f, max %d; pixels off by more than 2: %d of %d, more than 8: %d'
      % (sum(d) / len(d), max(d), sum(1 for x in worst if x > 2), w * h, sum(1 for x in worst if x > 8)))
if len(sys.argv) > 3:
    diff = bytes(min(255, 8 * x) for x in d)
    rows = []
    for y in range(h):
        row = b''
        for img in (a, b, diff):
            line = img[y * w * 3:(y + 1) * w * 3]
            row += b''.join(line[3 * x:3 * x + 3] * 2 for x in range(w))
        rows += [b'\0' + row] * 2

    def chunk(t, data):
        return struct.pack('>I', len(data)) + t + data + struct.pack('>I', zlib.crc32(t + data) & 0xffffffff)
    open(sys.argv[3], 'wb').write(b'\x89PNG\r\n\x1a\n' +
                                  chunk(b'IHDR', struct.pack('>IIBBBBB', 6 * w, 2 * h, 8, 2, 0, 0, 0)) +
                                  chunk(b'IDAT', zlib.compress(b''.join(rows), 9)) + chunk(b'IEND', b''))
