#!/usr/bin/env python3
"""Turns one AOV file written by `rays render --aov` (OUTPUT.NAME.pfm) into a small PNG for the
docs (docs/aov.md). Python standard library only. Usage: aov_png.py KIND IN.pfm OUT.png
KIND: depth (near white, far dark — the 90th percentile and beyond 15 % grey —, background black), normal (n*0.5+0.5), albedo (clamped),
objectid / materialid (a fixed colour per id, background black), coverage (lines black on white),
edgetype (white, each line pixel coloured by its lowest EdgeType bit, EDGE_COLOURS)."""
import struct
import sys
import zlib


def read_pfm(path):
    data = open(path, 'rb').read()
    parts = data.split(b'\n', 3)
    kind, size, scale = parts[0].strip(), parts[1].split(), float(parts[2])
    w, h = int(size[0]), int(size[1])
    n = 3 if kind == b'PF' else 1
    fmt = ('<' if scale < 0 else '>') + 'f' * (w * h * n)
    vals = struct.unpack(fmt, parts[3][:w * h * n * 4])
    rows = [vals[(h - 1 - y) * w * n:(h - y) * w * n] for y in range(h)]  # top row first
    return w, h, n, rows


def write_png(path, w, h, rows):
    raw = b''.join(b'\0' + bytes(r) for r in rows)
    def chunk(t, d):
        return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
    png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0))
    png += chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b'')
    open(path, 'wb').write(png)


# The EdgeType bits of docs/edges.md: silhouette, occlusion, intersection, crease, material,
# shadow, reflection.
EDGE_COLOURS = [(0, 0, 0), (230, 120, 0), (210, 0, 0), (0, 90, 220), (150, 0, 170), (110, 110, 110), (0, 150, 60)]


def edge_colour(v):
    bits = int(v)
    for b, c in enumerate(EDGE_COLOURS):
        if bits & (1 << b):
            return c
    return (255, 255, 255)


def byte(v):
    return max(0, min(255, int(round(v * 255))))


def id_colour(i):
    if i < 0:
        return (0, 0, 0)
    h = (int(i) * 2654435761) & 0xffffffff  # Knuth's multiplicative hash: neighbours differ
    return (64 + (h >> 24) % 192, 64 + (h >> 16) % 192, 64 + (h >> 8) % 192)


def main():
    kind, src, dst = sys.argv[1:4]
    w, h, n, rows = read_pfm(src)
    out = []
    if kind == 'depth':
        # Nearest to the 90th percentile of the hits: a ground plane reaching the horizon would
        # otherwise squeeze everything near into one grey.
        finite = sorted(v for r in rows for v in r if v != float('inf'))
        lo, hi = (finite[0], finite[int(0.9 * (len(finite) - 1))]) if finite else (0, 1)
        for r in rows:
            line = []
            for v in r:
                g = 0 if v == float('inf') else byte(1 - 0.85 * min(1, (v - lo) / max(hi - lo, 1e-9)))
                line += [g, g, g]
            out.append(line)
    elif kind in ('objectid', 'materialid'):
        out = [[c for v in r for c in id_colour(v)] for r in rows]
    elif kind == 'edgetype':
        out = [[c for v in r for c in edge_colour(v)] for r in rows]
    elif kind == 'coverage':
        out = [[byte(1 - v) for v in r for _ in range(3)] for r in rows]
    elif kind == 'normal':
        out = [[byte(0.5 * v + 0.5) if any(r[i - i % 3:i - i % 3 + 3]) else 0 for i, v in enumerate(r)] for r in rows]
    else:  # albedo and anything else of 3 channels
        out = [[byte(v) for v in r] for r in rows]
    write_png(dst, w, h, out)


main()
