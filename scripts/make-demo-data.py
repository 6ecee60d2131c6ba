#!/usr/bin/env python3
"""Regenerates the bundled demo inputs in data/demo/ (our own synthetic shapes, no third-party
data). Deterministic: the same files every run."""
import math
import random
from pathlib import Path

out = Path(__file__).resolve().parent.parent / "data" / "demo"
out.mkdir(parents=True, exist_ok=True)
rng = random.Random(20261123)

# A torus (R=2, r=0.75) as a closed, oriented triangle mesh of genus 1: 32 x 16 quads.
nu, nv, R, r = 32, 16, 2.0, 0.75
verts, faces = [], []
for i in range(nu):
    u = 2 * math.pi * i / nu
    for j in range(nv):
        v = 2 * math.pi * j / nv
        verts.append(((R + r * math.cos(v)) * math.cos(u), (R + r * math.cos(v)) * math.sin(u), r * math.sin(v)))
idx = lambda i, j: (i % nu) * nv + (j % nv)
for i in range(nu):
    for j in range(nv):
        a, b, c, d = idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)
        faces += [(a, b, c), (a, c, d)]
with open(out / "torus.off", "w") as f:
    f.write("OFF\n# torus R=2 r=0.75, 32x16 quads split in two, outward oriented\n")
    f.write(f"{len(verts)} {len(faces)} 0\n")
    for p in verts:
        f.write("%.17g %.17g %.17g\n" % p)
    for t in faces:
        f.write("3 %d %d %d\n" % t)

# A leaf-like closed curve in 2D, sampled unevenly: scattered points of an object's boundary.
with open(out / "leaf.xy", "w") as f:
    f.write("# 160 points sampled on a closed leaf-shaped curve (unordered)\n")
    pts = []
    for k in range(160):
        t = 2 * math.pi * (k + 0.4 * rng.random()) / 160
        rad = 1.0 + 0.35 * math.cos(3 * t) + 0.1 * math.sin(7 * t)
        pts.append((rad * math.cos(t) * 1.4, rad * math.sin(t)))
    rng.shuffle(pts)
    for p in pts:
        f.write("%.9f %.9f\n" % p)

# A peanut-shaped closed surface in 3D, sampled at 1500 random points (unordered).
with open(out / "peanut.xyz", "w") as f:
    f.write("# 1500 points sampled on a peanut-shaped closed surface\n")
    for _ in range(1500):
        z = rng.uniform(-1, 1)
        phi = rng.uniform(0, 2 * math.pi)
        s = math.sqrt(1 - z * z)
        x, y = s * math.cos(phi), s * math.sin(phi)
        scale = 1.0 + 0.45 * math.cos(2 * math.acos(max(-1, min(1, x))))
        f.write("%.9f %.9f %.9f\n" % (2.0 * x, scale * 0.8 * y, scale * 0.8 * z))

# Ground truth for the demo's distance checks: the leaf curve densely and in order, and the
# peanut surface as a fine mesh (an icosphere, subdivided 4 times, mapped like the samples).
with open(out / "leaf-truth.xy", "w") as f:
    f.write("# the leaf curve of leaf.xy, 2000 points in order (a closed polygon)\n")
    for k in range(2000):
        t = 2 * math.pi * k / 2000
        rad = 1.0 + 0.35 * math.cos(3 * t) + 0.1 * math.sin(7 * t)
        f.write("%.9f %.9f\n" % (rad * math.cos(t) * 1.4, rad * math.sin(t)))

g = (1 + math.sqrt(5)) / 2
ico_v = [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), (0, -1, g), (0, 1, g), (0, -1, -g),
         (0, 1, -g), (g, 0, -1), (g, 0, 1), (-g, 0, -1), (-g, 0, 1)]
ico_f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
sv = [tuple(c / math.sqrt(sum(x * x for x in v)) for c in v) for v in ico_v]
sf = list(ico_f)
for _ in range(4):
    mid = {}
    def midpoint(a, b):
        key = (min(a, b), max(a, b))
        if key not in mid:
            m = [(sv[a][k] + sv[b][k]) / 2 for k in range(3)]
            n = math.sqrt(sum(c * c for c in m))
            sv.append(tuple(c / n for c in m))
            mid[key] = len(sv) - 1
        return mid[key]
    nf = []
    for a, b, c in sf:
        ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
        nf += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
    sf = nf
with open(out / "peanut-truth.off", "w") as f:
    f.write("OFF\n# the peanut surface of peanut.xyz: a 4x subdivided icosphere mapped the same way\n")
    f.write(f"{len(sv)} {len(sf)} 0\n")
    for x, y, z in sv:
        scale = 1.0 + 0.45 * math.cos(2 * math.acos(max(-1, min(1, x))))
        f.write("%.9g %.9g %.9g\n" % (2.0 * x, scale * 0.8 * y, scale * 0.8 * z))
    for t in sf:
        f.write("3 %d %d %d\n" % t)
