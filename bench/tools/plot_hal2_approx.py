#!/usr/bin/env python3
"""Error against size of the 2D approximations (docs/hal.md, "Against GEOS"; cf. thesis Fig. 7.6).

Reads the APPROX lines of bench/eval_hal2.c and bench/peers/geos_hal2.c (key=value fields) and
writes an SVG with log-log axes: x = vertices of the approximation (summed over the rings),
y = measured error (largest distance from an original vertex to the approximation, relative to
each ring's bounding-box diagonal, maximum over the rings). Three series: flintstone adaptive,
flintstone by level, Douglas-Peucker (GEOSSimplify). Points with zero error (the original
polygon) have no place on a log axis and are left out. Python 3 standard library only.

    plot_hal2_approx.py [APPROX_LINES...] > out.svg     (reads stdin when no file is given)
"""
import math
import sys

SERIES = [  # method, label, colour, marker
    ("flintstone-adaptive", "flintstone, adaptive (error bound)", "#1f77b4", "circle"),
    ("flintstone-level", "flintstone, by level", "#d62728", "square"),
    ("geos-douglas-peucker", "Douglas\u2013Peucker (GEOSSimplify)", "#2ca02c", "triangle"),
]
W, H = 740, 480
LEFT, RIGHT, TOP, BOTTOM = 80, 40, 40, 60


def parse(lines):
    """{method: [(vertices, error), ...]} from the APPROX lines; the first line of a
    (method, parameter) wins, so several rounds of the same run plot once."""
    data, seen = {}, set()
    for line in lines:
        words = line.split()
        if not words or words[0] != "APPROX":
            continue
        f = dict(w.split("=", 1) for w in words[1:] if "=" in w)
        key = (f.get("method"), f.get("fraction"), f.get("level"))
        if key in seen or "vertices" not in f or "measured" not in f:
            continue
        seen.add(key)
        data.setdefault(f["method"], []).append((int(f["vertices"]), float(f["measured"])))
        if "original" in f:
            data["original"] = int(f["original"])
    return data


def decades(lo, hi):
    """Powers of ten covering [lo, hi]."""
    return math.floor(math.log10(lo)), math.ceil(math.log10(hi))


def esc(s):
    return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def marker(kind, x, y, colour):
    if kind == "circle":
        return f'<circle cx="{x:.1f}" cy="{y:.1f}" r="3.5" fill="{colour}"/>'
    if kind == "square":
        return f'<rect x="{x - 3.2:.1f}" y="{y - 3.2:.1f}" width="6.4" height="6.4" fill="{colour}"/>'
    return (f'<path d="M{x:.1f},{y - 4.5:.1f} L{x + 4:.1f},{y + 3:.1f} L{x - 4:.1f},{y + 3:.1f} Z"'
            f' fill="{colour}"/>')


def svg(data):
    pts = [p for m, _, _, _ in SERIES for p in data.get(m, []) if p[0] > 0 and p[1] > 0]
    if not pts:
        raise SystemExit("plot_hal2_approx: no APPROX lines with positive vertices and error")
    x0, x1 = decades(min(p[0] for p in pts), max(p[0] for p in pts))
    y0, y1 = decades(min(p[1] for p in pts), max(p[1] for p in pts))
    pw, ph = W - LEFT - RIGHT, H - TOP - BOTTOM
    original = f" ({data['original']:,} vertices)".replace(",", "\u2009") if "original" in data else ""

    def sx(v):
        return LEFT + (math.log10(v) - x0) / (x1 - x0) * pw

    def sy(v):
        return TOP + (y1 - math.log10(v)) / (y1 - y0) * ph

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" '
           f'viewBox="0 0 {W} {H}" font-family="sans-serif" font-size="12">',
           f'<rect width="{W}" height="{H}" fill="white"/>',
           f'<text x="{W / 2}" y="22" text-anchor="middle" font-size="13">Approximation error '
           f'against size, the 20 largest world-atlas countries-50m rings{original}</text>']
    for e in range(x0, x1 + 1):  # decade grid, labels, minor ticks
        x = sx(10 ** e)
        out.append(f'<line x1="{x:.1f}" y1="{TOP}" x2="{x:.1f}" y2="{TOP + ph}" stroke="#ddd"/>')
        out.append(f'<text x="{x:.1f}" y="{TOP + ph + 18}" text-anchor="middle">{10 ** e:g}</text>')
        for k in range(2, 10):
            if e < x1:
                xm = sx(k * 10 ** e)
                out.append(f'<line x1="{xm:.1f}" y1="{TOP + ph}" x2="{xm:.1f}" y2="{TOP + ph - 4}" '
                           'stroke="#888"/>')
    for e in range(y0, y1 + 1):
        y = sy(10 ** e)
        out.append(f'<line x1="{LEFT}" y1="{y:.1f}" x2="{LEFT + pw}" y2="{y:.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{LEFT - 6}" y="{y + 4:.1f}" text-anchor="end">{10.0 ** e:g}</text>')
        for k in range(2, 10):
            if e < y1:
                ym = sy(k * 10 ** e)
                out.append(f'<line x1="{LEFT}" y1="{ym:.1f}" x2="{LEFT + 4}" y2="{ym:.1f}" '
                           'stroke="#888"/>')
    out.append(f'<rect x="{LEFT}" y="{TOP}" width="{pw}" height="{ph}" fill="none" stroke="black"/>')
    out.append(f'<text x="{LEFT + pw / 2}" y="{H - 18}" text-anchor="middle">vertices of the '
               'approximation (all 20 rings)</text>')
    out.append(f'<text transform="translate(22,{TOP + ph / 2}) rotate(-90)" text-anchor="middle">'
               'measured error / bounding-box diagonal (max over rings)</text>')
    for method, label, colour, kind in SERIES:
        p = sorted(q for q in data.get(method, []) if q[0] > 0 and q[1] > 0)
        if not p:
            continue
        path = " ".join(f"{'M' if i == 0 else 'L'}{sx(v):.1f},{sy(e):.1f}"
                        for i, (v, e) in enumerate(p))
        out.append(f'<path d="{path}" fill="none" stroke="{colour}" stroke-width="1.5"/>')
        out.extend(marker(kind, sx(v), sy(e), colour) for v, e in p)
    lx, ly = LEFT + pw - 250, TOP + 14  # legend, top right (the curves fall to the bottom right)
    out.append(f'<rect x="{lx - 8}" y="{ly - 12}" width="250" height="{18 * len(SERIES) + 6}" '
               'fill="white" stroke="#888"/>')
    for i, (_, label, colour, kind) in enumerate(SERIES):
        y = ly + 18 * i
        out.append(f'<line x1="{lx}" y1="{y}" x2="{lx + 24}" y2="{y}" stroke="{colour}" '
                   'stroke-width="1.5"/>')
        out.append(marker(kind, lx + 12, y, colour))
        out.append(f'<text x="{lx + 32}" y="{y + 4}">{esc(label)}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main():
    lines = []
    if len(sys.argv) > 1:
        for path in sys.argv[1:]:
            with open(path, encoding="utf-8") as f:
                lines.extend(f)
    else:
        lines = sys.stdin.readlines()
    sys.stdout.write(svg(parse(lines)))


if __name__ == "__main__":
    main()
