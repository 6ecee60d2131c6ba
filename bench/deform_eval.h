/* The deforming-mesh closest-point evaluation (docs/sweep.md, "Deforming mesh against CGAL";
 * issue #9's third workload), shared by ours (bench/closest_deform.c) and the CGAL peer
 * (bench/peers/cgal_closest_deform.cpp) so that both see bit-identical frames and queries.
 * C11 and C++17. The mesh is PREFIX.mesh of bench/closest_eval.h.
 *
 * Frame f (0 <= f < F) moves every vertex along x by a sine wave travelling along y:
 *     x += a sin(k (y - ymin) + 2 pi f / F),  a = 1% of the bounding-box diagonal,
 * k = two periods over the y extent. Per frame Q queries: one random walk with steps of 0.1% of
 * the diagonal in a uniformly random direction, kept inside the bounding box grown by 10% (a step
 * that would leave it is reflected), continuing from frame to frame. Everything is computed with
 * +, *, sqrt and sin of the same libm, in the same order on both sides. */
#ifndef FL_BENCH_DEFORM_EVAL_H
#define FL_BENCH_DEFORM_EVAL_H

#include <math.h>
#include <stdint.h>

#include "closest_eval.h"

#define DE_PI 3.14159265358979323846

typedef struct de_setup {
    double lo[3], hi[3], diag, amplitude, wavenumber;
    double walk[3];     /* the walk's current point */
    uint64_t rng;
} de_setup;

static double de_uniform(de_setup *s)
{
    s->rng ^= s->rng << 13;
    s->rng ^= s->rng >> 7;
    s->rng ^= s->rng << 17;
    return (double)(s->rng >> 11) * 0x1p-53;
}

/* Bounding box, wave parameters, and the walk's start: vertex 0 of the rest mesh. */
static void de_init(de_setup *s, const ce_mesh *m)
{
    for (int k = 0; k < 3; k++) {
        s->lo[k] = m->xyz[k];
        s->hi[k] = m->xyz[k];
    }
    for (uint64_t i = 0; i < m->v; i++)
        for (int k = 0; k < 3; k++) {
            double c = m->xyz[3 * i + k];
            s->lo[k] = c < s->lo[k] ? c : s->lo[k];
            s->hi[k] = c > s->hi[k] ? c : s->hi[k];
        }
    double d2 = 0;
    for (int k = 0; k < 3; k++) d2 += (s->hi[k] - s->lo[k]) * (s->hi[k] - s->lo[k]);
    s->diag = sqrt(d2);
    s->amplitude = 0.01 * s->diag;
    double ey = s->hi[1] - s->lo[1];
    s->wavenumber = ey > 0 ? 2 * (2 * DE_PI) / ey : 0;
    for (int k = 0; k < 3; k++) s->walk[k] = m->xyz[k];
    s->rng = 0x9e3779b97f4a7c15ull;
}

/* The vertices of frame f of `frames` into out (3 * m->v doubles). */
static void de_frame(const de_setup *s, const ce_mesh *m, int f, int frames, double *out)
{
    double phase = 2 * DE_PI * (double)f / (double)frames;
    for (uint64_t i = 0; i < m->v; i++) {
        const double *p = m->xyz + 3 * i;
        out[3 * i] = p[0] + s->amplitude * sin(s->wavenumber * (p[1] - s->lo[1]) + phase);
        out[3 * i + 1] = p[1];
        out[3 * i + 2] = p[2];
    }
}

/* The next n points of the walk into q (3 * n doubles). */
static void de_walk(de_setup *s, double *q, uint64_t n)
{
    double step = 0.001 * s->diag;
    for (uint64_t i = 0; i < n; i++) {
        double d[3], len2;
        do { /* a uniform direction: rejection in the unit ball */
            for (int k = 0; k < 3; k++) d[k] = 2 * de_uniform(s) - 1;
            len2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        } while (len2 > 1 || len2 < 1e-6);
        double scale = step / sqrt(len2);
        for (int k = 0; k < 3; k++) {
            double grow = 0.1 * (s->hi[k] - s->lo[k]), x = s->walk[k] + scale * d[k];
            if (x < s->lo[k] - grow || x > s->hi[k] + grow) x = s->walk[k] - scale * d[k];
            s->walk[k] = x;
            q[3 * i + k] = x;
        }
    }
}

/* Squared distance from p to triangle (a, b, c): Ericson, Real-Time Collision Detection §5.1.5,
 * region by region; the brute-force reference of the benchmark. */
static double de_point_triangle2(const double *p, const double *a, const double *b,
                                 const double *c)
{
    double ab[3], ac[3], ap[3], bp[3], cp[3], x[3];
    for (int k = 0; k < 3; k++) {
        ab[k] = b[k] - a[k];
        ac[k] = c[k] - a[k];
        ap[k] = p[k] - a[k];
        bp[k] = p[k] - b[k];
        cp[k] = p[k] - c[k];
    }
#define DE_DOT(u, w) ((u)[0] * (w)[0] + (u)[1] * (w)[1] + (u)[2] * (w)[2])
    double d1 = DE_DOT(ab, ap), d2 = DE_DOT(ac, ap), d3 = DE_DOT(ab, bp), d4 = DE_DOT(ac, bp);
    double d5 = DE_DOT(ab, cp), d6 = DE_DOT(ac, cp);
    double va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2;
    double u = 0, w = 0; /* x = a + u ab + w ac */
    if (d1 <= 0 && d2 <= 0) {
    } else if (d3 >= 0 && d4 <= d3) {
        u = 1;
    } else if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        u = d1 / (d1 - d3);
    } else if (d6 >= 0 && d5 <= d6) {
        w = 1;
    } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        w = d2 / (d2 - d6);
    } else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        u = 1 - w;
    } else {
        double den = 1 / (va + vb + vc);
        u = vb * den;
        w = vc * den;
    }
#undef DE_DOT
    double r = 0;
    for (int k = 0; k < 3; k++) {
        x[k] = a[k] + u * ab[k] + w * ac[k] - p[k];
        r += x[k] * x[k];
    }
    return r;
}

#endif
