#!/usr/bin/env python3
"""Zebra (reflection-line) render of a .bez surface (thesis §8.4), pure Python, PNG out.

usage: zebra.py IN.bez OUT.png [density] [size]

Every patch is sampled on a density-segment grid; points and exact normals come from the
control net (de Casteljau). Triangles are rasterised with a z-buffer; the normal is
interpolated per pixel and the stripe is the parity of floor(k * r_y), r the reflected view
ray. Stripes bend where the normal field bends and break where it jumps (C0 only)."""
import math, struct, sys, zlib

def read_bez(path):
    tok = [l.split('#')[0].split() for l in open(path)]
    tok = [t for t in tok if t]
    n = int(tok[1][1]); pats = []
    for p in range(n):
        rows = tok[2 + 11 * p + 1: 2 + 11 * p + 11]
        pats.append([tuple(map(float, r)) for r in rows])
    return pats

IDX = {}
for i in range(4):
    for j in range(4 - i):
        IDX[(3, i, j)] = (3 - i) * (4 - i) // 2 + (3 - i - j)

def idx(n, i, j):
    return (n - i) * (n - i + 1) // 2 + (n - i - j)

def evaluate(c, u, v, w):
    a = list(c)
    for n in (3, 2):
        b = [None] * ((n) * (n + 1) // 2)
        for i in range(n):
            for j in range(n - i):
                p, q, r = a[idx(n, i + 1, j)], a[idx(n, i, j + 1)], a[idx(n, i, j)]
                b[idx(n - 1, i, j)] = tuple(u * p[d] + v * q[d] + w * r[d] for d in range(3))
        a = b
    pt = tuple(u * a[0][d] + v * a[1][d] + w * a[2][d] for d in range(3))
    e1 = [a[0][d] - a[2][d] for d in range(3)]; e2 = [a[1][d] - a[2][d] for d in range(3)]
    nn = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0])
    l = math.sqrt(sum(x * x for x in nn)) or 1
    return pt, tuple(x / l for x in nn)

def rot(p, ax, ay):
    x, y, z = p
    x, z = x * math.cos(ay) + z * math.sin(ay), -x * math.sin(ay) + z * math.cos(ay)
    y, z = y * math.cos(ax) - z * math.sin(ax), y * math.sin(ax) + z * math.cos(ax)
    return (x, y, z)

def main():
    src, out = sys.argv[1], sys.argv[2]
    N = int(sys.argv[3]) if len(sys.argv) > 3 else 6
    S = int(sys.argv[4]) if len(sys.argv) > 4 else 360
    pats = read_bez(src); tris = []
    for c in pats:
        g = {}
        for a in range(N + 1):
            for b in range(N + 1 - a):
                p, n = evaluate(c, a / N, b / N, (N - a - b) / N)
                g[(a, b)] = (rot(p, 0.6, 0.5), rot(n, 0.6, 0.5))
        for a in range(N):
            for b in range(N - a):
                tris.append((g[(a, b)], g[(a + 1, b)], g[(a, b + 1)]))
                if a + b + 2 <= N:
                    tris.append((g[(a + 1, b)], g[(a + 1, b + 1)], g[(a, b + 1)]))
    xs = [v[0][0] for t in tris for v in t]; ys = [v[0][1] for t in tris for v in t]
    cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    sc = 0.92 * S / max(max(xs) - min(xs), max(ys) - min(ys))
    zb = [[-1e300] * S for _ in range(S)]; img = [[(255, 255, 255)] * S for _ in range(S)]
    for t in tris:
        P = [((v[0][0] - cx) * sc + S / 2, S / 2 - (v[0][1] - cy) * sc, v[0][2]) for v in t]
        den = (P[1][0] - P[0][0]) * (P[2][1] - P[0][1]) - (P[2][0] - P[0][0]) * (P[1][1] - P[0][1])
        if abs(den) < 1e-12: continue
        x0, x1 = max(0, int(min(p[0] for p in P))), min(S - 1, int(max(p[0] for p in P)) + 1)
        y0, y1 = max(0, int(min(p[1] for p in P))), min(S - 1, int(max(p[1] for p in P)) + 1)
        for y in range(y0, y1 + 1):
            for x in range(x0, x1 + 1):
                px, py = x + 0.5, y + 0.5
                l1 = ((P[1][0] - px) * (P[2][1] - py) - (P[2][0] - px) * (P[1][1] - py)) / den
                l2 = ((P[2][0] - px) * (P[0][1] - py) - (P[0][0] - px) * (P[2][1] - py)) / den
                l3 = 1 - l1 - l2
                if l1 < -1e-9 or l2 < -1e-9 or l3 < -1e-9: continue
                z = l1 * P[0][2] + l2 * P[1][2] + l3 * P[2][2]
                if z <= zb[y][x]: continue
                zb[y][x] = z
                n = [l1 * t[0][1][d] + l2 * t[1][1][d] + l3 * t[2][1][d] for d in range(3)]
                ln = math.sqrt(sum(a * a for a in n)) or 1
                n = [a / ln for a in n]
                if n[2] < 0: n = [-a for a in n]
                r = [2 * n[2] * n[d] for d in range(3)]; r[2] -= 1  # reflect view (0,0,-1)
                stripe = int(math.floor(9 * (r[1] + 0.3 * r[0]))) & 1
                shade = 0.55 + 0.45 * n[2]
                v = int(255 * shade) if stripe else int(40 * shade)
                img[y][x] = (v, v, int(min(255, v + 20)))
    raw = b''.join(b'\x00' + bytes(c for px in row for c in px) for row in img)
    def chunk(k, d): return struct.pack('>I', len(d)) + k + d + struct.pack('>I', zlib.crc32(k + d) & 0xffffffff)
    png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', S, S, 8, 2, 0, 0, 0))
    png += chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b'')
    open(out, 'wb').write(png)

main()
