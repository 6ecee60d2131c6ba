/* Independent brute-force distances for the sweep tests, in long double: the plane projection
 * with an inside test by orientation signs, else the nearest edge. It shares no code with
 * src/sweep (which uses Voronoi-region barycentrics in double). */
#ifndef SWEEP_ORACLE_H
#define SWEEP_ORACLE_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

typedef long double ld;

static inline ld oracle_segment(const double *p, const double *a, const double *b)
{
    ld ab[3], ap[3], len2 = 0, s = 0;
    for (int c = 0; c < 3; c++) {
        ab[c] = (ld)b[c] - a[c];
        ap[c] = (ld)p[c] - a[c];
        len2 += ab[c] * ab[c];
        s += ab[c] * ap[c];
    }
    ld t = len2 > 0 ? s / len2 : 0;
    if (t < 0) t = 0;
    if (t > 1) t = 1;
    ld d2 = 0;
    for (int c = 0; c < 3; c++) {
        ld x = ap[c] - t * ab[c];
        d2 += x * x;
    }
    return sqrtl(d2);
}

static inline void oracle_cross(const ld *u, const ld *v, ld *w)
{
    w[0] = u[1] * v[2] - u[2] * v[1];
    w[1] = u[2] * v[0] - u[0] * v[2];
    w[2] = u[0] * v[1] - u[1] * v[0];
}

static inline ld oracle_triangle(const double *p, const double *a, const double *b, const double *c)
{
    ld best = oracle_segment(p, a, b);
    ld e = oracle_segment(p, b, c);
    if (e < best) best = e;
    e = oracle_segment(p, c, a);
    if (e < best) best = e;
    const double *v[3] = {a, b, c};
    ld ab[3], ac[3], n[3], n2 = 0, h = 0;
    for (int k = 0; k < 3; k++) {
        ab[k] = (ld)b[k] - a[k];
        ac[k] = (ld)c[k] - a[k];
    }
    oracle_cross(ab, ac, n);
    for (int k = 0; k < 3; k++) {
        n2 += n[k] * n[k];
        h += n[k] * ((ld)p[k] - a[k]);
    }
    if (!(n2 > 0)) return best;
    /* p projects inside iff ((t - s) x (p - s)) . n > 0 for every edge st (p and its projection
     * differ by a multiple of n, which leaves that sign unchanged). Only a clear inside counts:
     * a sign within rounding of zero goes to the edges, which is exact when the projection is on
     * an edge and off by at most the rounding when it is just inside. Found by fuzz_sweep: a
     * sliver 1e-300 wide whose edge differences round to parallel gave sign 0 and the plane
     * distance 8 instead of the edge distance 12.3. */
    ld nn = sqrtl(n2);
    for (int i = 0; i < 3; i++) {
        const double *s = v[i], *t = v[(i + 1) % 3];
        ld st[3], sp[3], w[3], sign = 0, lst = 0, lsp = 0;
        for (int k = 0; k < 3; k++) {
            st[k] = (ld)t[k] - s[k];
            sp[k] = (ld)p[k] - s[k];
            lst += st[k] * st[k];
            lsp += sp[k] * sp[k];
        }
        oracle_cross(st, sp, w);
        for (int k = 0; k < 3; k++)
            sign += w[k] * n[k];
        if (!(sign > 1e-15L * sqrtl(lst) * sqrtl(lsp) * nn)) return best;
    }
    ld hp = fabsl(h) / sqrtl(n2);
    return hp < best ? hp : best;
}

static inline const double *oracle_vertex(const double *xyz, const uint32_t *tri, size_t t, int k)
{
    return xyz + 3 * (size_t)tri[3 * t + k];
}

static inline ld oracle_mesh_element(const double *xyz, const uint32_t *tri, size_t t,
                                     const double *p)
{
    return oracle_triangle(p, oracle_vertex(xyz, tri, t, 0), oracle_vertex(xyz, tri, t, 1),
                           oracle_vertex(xyz, tri, t, 2));
}

/* Polyline segment i of n points (dimension 3 layout), closing segment included. */
static inline ld oracle_polyline_element(const double *xyz, size_t n, size_t i, const double *p)
{
    return oracle_segment(p, xyz + 3 * i, xyz + 3 * ((i + 1) % n));
}

#endif /* SWEEP_ORACLE_H */
