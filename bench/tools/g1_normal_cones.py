#!/usr/bin/env python3
"""Which vertices of a closed OFF mesh admit a normal satisfying the G1 orientation condition of
thesis §9.6 (every incident triangle projects counter-clockwise on the tangent plane, i.e.
n . c_i > 0 for the unit triangle normals c_i), independently of the library (docs/smooth.md,
"hand.off" and "Auto"). Such an n exists iff the maximin cosine max_n min_i n . c_i is > 0
(Gordan); the optimum has equal cosines to one, two or three of the c_i, so every such
candidate is tried. Polygons are fanned from their first vertex, as the reader does.
usage: g1_normal_cones.py MESH.off [COUNT]   prints the COUNT vertices with the narrowest cone."""
import itertools
import math
import sys


def read_off(path):
    toks = []
    for line in open(path):
        toks += line.split('#')[0].split()
    assert toks[0].startswith('OFF')
    nv, nf = int(toks[1]), int(toks[2])
    i = 4
    verts = [tuple(map(float, toks[i + 3 * k:i + 3 * k + 3])) for k in range(nv)]
    i += 3 * nv
    tris = []
    for _ in range(nf):
        n = int(toks[i])
        poly = list(map(int, toks[i + 1:i + 1 + n]))
        tris += [(poly[0], poly[k], poly[k + 1]) for k in range(1, n - 1)]
        i += 1 + n
    return verts, tris


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def unit(a):
    length = math.sqrt(dot(a, a))
    return (a[0] / length, a[1] / length, a[2] / length) if length > 0 else None


def maximin(normals):
    cands = list(normals)
    for a, b in itertools.combinations(normals, 2):
        cands.append(unit((a[0] + b[0], a[1] + b[1], a[2] + b[2])))
    for a, b, c in itertools.combinations(normals, 3):
        u = unit(cross(sub(a, b), sub(a, c)))
        if u:
            cands += [u, (-u[0], -u[1], -u[2])]
    return max(min(dot(c, n) for c in normals) for n in cands if n)


def main():
    verts, tris = read_off(sys.argv[1])
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 10
    star = {}
    for t in tris:
        for v in t:
            star.setdefault(v, []).append(t)
    res = []
    for v, ts in star.items():
        normals = [unit(cross(sub(verts[t[1]], verts[t[0]]), sub(verts[t[2]], verts[t[0]])))
                   for t in ts]
        normals = [n for n in normals if n]
        res.append((maximin(normals) if normals else -2.0, v, len(ts)))
    res.sort()
    for best, v, k in res[:count]:
        print('vertex %d: %d triangles, maximin cosine %.6g (%s, %.4g degrees)' %
              (v, k, best, 'valid normal exists' if best > 0 else 'NO valid normal',
               math.degrees(math.asin(max(-1.0, min(1.0, best))))))


main()
