/* The keys that order the removable boundary edges: the γ-indicator of thesis Def. 5.1 and the
 * two comparison methods of §4.3.3 / §4.3.4 (compared in §5.6). Keys are constructions
 * (floating point) that only order the deletions; whether a deletion is allowed is decided
 * combinatorially elsewhere. */
#include <math.h>

#include "reconstruct/constrict2_internal.h"

/* Def. 5.1: R(a,b,c) = r(a,b) / (1 - |c0|) with r = |ab|/2, and by the sine rule
 * r / R = sin θ for the angle θ at c, so |c0| = 1 - sin θ. The sign (eq. 5.1) is positive when
 * the circumcentre lies on c's side of ab, i.e. when θ is acute, and negative when obtuse.
 * sin and cos come from the cross and dot products of the two sides at c, which stay accurate
 * for thin triangles where an angle from acos would not. */
double c2_gamma_indicator(const double *a, const double *b, const double *c)
{
    double ux = a[0] - c[0], uy = a[1] - c[1], vx = b[0] - c[0], vy = b[1] - c[1];
    int e; /* an exact power-of-two rescaling keeps the products below from overflowing */
    frexp(fmax(fmax(fabs(ux), fabs(uy)), fmax(fabs(vx), fabs(vy))), &e);
    if (e > -1000 && e < 1000) {
        /* Multiplying by 2^-e (a normal number here) rounds exactly as ldexp does (exact, or
         * one correct rounding when the result is subnormal) and saves four libm calls on the
         * hot path of constriction; the keys, and so the results, are bit for bit the same. */
        double scale = ldexp(1.0, -e);
        ux *= scale, uy *= scale, vx *= scale, vy *= scale;
    } else {
        ux = ldexp(ux, -e), uy = ldexp(uy, -e), vx = ldexp(vx, -e), vy = ldexp(vy, -e);
    }
    double lu = hypot(ux, uy), lv = hypot(vx, vy);
    if (!(lu > 0 && lv > 0)) return 1;
    double sin_t = fabs(ux * vy - uy * vx) / lu / lv;
    double cos_t = (ux * vx + uy * vy) / lu / lv;
    if (sin_t > 1) sin_t = 1;
    return cos_t >= 0 ? 1 - sin_t : sin_t - 1;
}

/* γ = 1 - sin θ with θ acute (cos θ >= 0), so γ >= bar when sin θ <= 1 - bar: checked as
 * cross² <= ((1 - bar)² / 2)·|u|²|v|², half the true bound, so the rounding of these few
 * products (relative 1e-15) cannot turn a "yes" wrong. The squares are only trusted in a range
 * where they neither overflow nor lose precision to underflow; outside it (and for NaN, where
 * every comparison is false) the answer is 0. The dot product's sign is the one
 * c2_gamma_indicator sees: its rescaling by a power of two is exact in this range, and the
 * dot product is then most of |u||v| (cos² > 1/2), far from its rounding error. */
int c2_gamma_at_least(const double *a, const double *b, const double *c, double bar)
{
    double ux = a[0] - c[0], uy = a[1] - c[1], vx = b[0] - c[0], vy = b[1] - c[1];
    double dot = ux * vx + uy * vy;
    if (!(dot > 0)) return 0; /* obtuse (negative key): the common case on the hot path */
    double lu2 = ux * ux + uy * uy, lv2 = vx * vx + vy * vy, cross = ux * vy - uy * vx;
    const double lo = 0x1p-400, hi = 0x1p400, s = 1 - bar;
    if (!(lu2 > lo && lu2 < hi && lv2 > lo && lv2 < hi)) return 0;
    return cross * cross <= 0.5 * s * s * (lu2 * lv2);
}

/* Eq. 4.1 in 2D ("face area" is edge length): the two edges that join the boundary minus the
 * one that leaves it, relative to the perimeter; small when the boundary barely moves. */
static double area_change(const double *a, const double *b, const double *c)
{
    double ab = hypot(a[0] - b[0], a[1] - b[1]);
    double bc = hypot(b[0] - c[0], b[1] - c[1]);
    double ca = hypot(c[0] - a[0], c[1] - a[1]);
    double sum = ab + bc + ca;
    return sum > 0 ? (bc + ca - ab) / sum : 0;
}

/* The circumcentre, computed relative to a in a frame scaled by a power of two so that the
 * third-degree products can neither overflow nor underflow; power-of-two scaling is exact, so
 * the result scales exactly with the input (the skeleton key stays scale independent). */
static void circumcentre(const double *a, const double *b, const double *c, double *out)
{
    double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
    int e;
    frexp(fmax(fmax(fabs(bx), fabs(by)), fmax(fabs(cx), fabs(cy))), &e);
    bx = ldexp(bx, -e), by = ldexp(by, -e), cx = ldexp(cx, -e), cy = ldexp(cy, -e);
    double d = 2 * (bx * cy - by * cx);
    double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    out[0] = a[0] + ldexp((cy * b2 - by * c2) / d, e);
    out[1] = a[1] + ldexp((bx * c2 - cx * b2) / d, e);
}

/* §4.3.4: the Voronoi skeleton of a triangulated polygon is the tree of its triangles' Voronoi
 * vertices (circumcentres) joined across interior edges. Deleting face t removes its Voronoi
 * vertex and the skeleton edges to its living neighbours; the greedy constriction deletes the
 * face that takes the most skeleton length with it, so the tree left at the end is short. */
static double skeleton_removed(const c2_state *s, uint32_t t)
{
    const uint32_t *v = s->tri + 3 * (size_t)t;
    double cc[2], nc[2], sum = 0;
    circumcentre(c2_pt(s, v[0]), c2_pt(s, v[1]), c2_pt(s, v[2]), cc);
    for (int k = 0; k < 3; k++) {
        uint32_t u = s->adj[3 * (size_t)t + k];
        if (u == C2_NONE) continue;
        const uint32_t *w = s->tri + 3 * (size_t)u;
        circumcentre(c2_pt(s, w[0]), c2_pt(s, w[1]), c2_pt(s, w[2]), nc);
        double len = hypot(cc[0] - nc[0], cc[1] - nc[1]);
        sum += isfinite(len) ? len : HUGE_VAL;
    }
    return sum;
}

double c2_key(const c2_state *s, uint32_t a, uint32_t b, uint32_t c, uint32_t t)
{
    const double *pa = c2_pt(s, a), *pb = c2_pt(s, b), *pc = c2_pt(s, c);
    switch (s->criterion) {
    case FL_RECONSTRUCT2_AREA_CHANGE:
        return area_change(pa, pb, pc);
    case FL_RECONSTRUCT2_VORONOI_SKELETON:
        if (t != C2_NONE) return -skeleton_removed(s, t);
        return c2_gamma_indicator(pa, pb, pc);
    case FL_RECONSTRUCT2_GAMMA:
    default:
        return c2_gamma_indicator(pa, pb, pc);
    }
}
