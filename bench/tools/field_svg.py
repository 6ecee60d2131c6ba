#!/usr/bin/env python3
"""Draws a distance-field PLY written by `flintstone hausdorff -o FIELD.ply` as an SVG: an
orthographic view along one axis, triangles painted back to front, each filled with the colour
of its mean vertex distance (blue low, red high, as the PLY's own colours), with a colour bar.

usage: field_svg.py FIELD.ply OUT.svg [view axis x|y|z, default y] [up axis, default z]"""
import sys


def colour(t):
    t = min(1.0, max(0.0, t))
    r, g, b = (0, 2 * t, 1 - 2 * t) if t < 0.5 else (2 * t - 1, 2 - 2 * t, 0)
    return "#%02x%02x%02x" % (round(255 * r), round(255 * g), round(255 * b))


def main():
    src, dst = sys.argv[1], sys.argv[2]
    axes = {"x": 0, "y": 1, "z": 2}
    view = axes[sys.argv[3] if len(sys.argv) > 3 else "y"]
    up = axes[sys.argv[4] if len(sys.argv) > 4 else "z"]
    right = 3 - view - up
    with open(src) as f:
        lines = f.read().split("\n")
    nv = nf = 0
    lo = hi = None
    i = 0
    while lines[i] != "end_header":
        w = lines[i].split()
        if w[:2] == ["element", "vertex"]:
            nv = int(w[2])
        if w[:2] == ["element", "face"]:
            nf = int(w[2])
        if w[:1] == ["comment"] and "blue" in w:
            lo, hi = float(w[w.index("blue") + 1]), float(w[w.index("red") + 1])
        i += 1
    i += 1
    pts, dist = [], []
    for k in range(nv):
        x, y, z, d = map(float, lines[i + k].split()[:4])
        pts.append((x, y, z))
        dist.append(d)
    i += nv
    faces = [tuple(map(int, lines[i + k].split()[1:4])) for k in range(nf)]
    if lo is None or not hi > lo:
        lo, hi = min(dist), max(dist)
    xs = [p[right] for p in pts]
    ys = [p[up] for p in pts]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    W = 640
    s = (W - 40) / max(x1 - x0, y1 - y0)
    H = int((y1 - y0) * s) + 80
    faces.sort(key=lambda f: -sum(pts[v][view] for v in f))
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d">' % (W, H),
           '<rect width="100%" height="100%" fill="white"/>']
    for f in faces:
        t = (sum(dist[v] for v in f) / 3 - lo) / (hi - lo)
        c = colour(t)
        p = " ".join("%.1f,%.1f" % (20 + (pts[v][right] - x0) * s, 20 + (y1 - pts[v][up]) * s)
                     for v in f)
        out.append('<polygon points="%s" fill="%s" stroke="%s" stroke-width="0.3"/>' % (p, c, c))
    for k in range(100):
        out.append('<rect x="%.1f" y="%d" width="4.3" height="12" fill="%s"/>'
                   % (120 + 4 * k, H - 40, colour(k / 99)))
    out.append('<text x="20" y="%d" font-size="12" font-family="sans-serif">%.4g</text>'
               % (H - 30, lo))
    out.append('<text x="530" y="%d" font-size="12" font-family="sans-serif">%.4g</text>'
               % (H - 30, hi))
    out.append("</svg>")
    with open(dst, "w") as f:
        f.write("\n".join(out) + "\n")


main()
