/* Independent brute-force oracles and polygon generators for the 2D flintstone tests. */
#ifndef HAL2_ORACLE_H
#define HAL2_ORACLE_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fl_test.h"

/* A polygon under construction: rings appended one at a time, each its own polygon unless
 * `hole` is set (then it joins the previous polygon). */
typedef struct test_poly {
    fl_polygon pg;
    size_t cap;
} test_poly;

static inline void tp_init(test_poly *t)
{
    memset(t, 0, sizeof *t);
    t->cap = 16;
    t->pg.xy = malloc(2 * t->cap * sizeof(double));
    t->pg.ring_start = malloc(sizeof(size_t));
    t->pg.polygon_start = malloc(sizeof(size_t));
    t->pg.ring_start[0] = t->pg.polygon_start[0] = 0;
}

static inline void tp_add_ring(test_poly *t, const double *xy, size_t n, int hole)
{
    fl_polygon *p = &t->pg;
    while (p->vertex_count + n > t->cap)
        t->cap *= 2;
    p->xy = realloc(p->xy, 2 * t->cap * sizeof(double));
    memcpy(p->xy + 2 * p->vertex_count, xy, 2 * n * sizeof(double));
    p->vertex_count += n;
    p->ring_count++;
    p->ring_start = realloc(p->ring_start, (p->ring_count + 1) * sizeof(size_t));
    p->ring_start[p->ring_count] = p->vertex_count;
    if (!hole) {
        p->polygon_count++;
        p->polygon_start = realloc(p->polygon_start, (p->polygon_count + 1) * sizeof(size_t));
    }
    p->polygon_start[p->polygon_count] = p->ring_count;
}

/* A random star-shaped ring around (cx, cy): sorted random angles, radii in [r/2, 3r/2]. */
static inline void star_ring(double *xy, size_t n, double cx, double cy, double r,
                             unsigned long long *rng)
{
    double *ang = malloc(n * sizeof(double));
    for (size_t k = 0; k < n; k++)
        ang[k] = 6.283185307179586 * ((double)k + 0.9 * fl_test_rand01(rng)) / n;
    for (size_t k = 0; k < n; k++) {
        double rad = r * (0.5 + fl_test_rand01(rng));
        xy[2 * k] = cx + rad * cos(ang[k]);
        xy[2 * k + 1] = cy + rad * sin(ang[k]);
    }
    free(ang);
}

/* A comb with `teeth` teeth on integer coordinates: base y in [0, 2], teeth up to y = 10. */
static inline size_t comb_ring(double *xy, int teeth)
{
    size_t n = 0;
#define PUT(x, y) (xy[2 * n] = (x), xy[2 * n + 1] = (y), n++)
    PUT(0, 0);
    PUT(4.0 * teeth, 0);
    for (int t = teeth - 1; t >= 0; t--) {
        PUT(4.0 * t + 4, 10);
        PUT(4.0 * t + 2, 10);
        PUT(4.0 * t + 2, 2);
        PUT(4.0 * t, 2);
    }
#undef PUT
    return n;
}

static inline int oracle_on_segment(const double *a, const double *b, const double *x)
{
    return fl_orient2d(a, b, x) == 0 && fmin(a[0], b[0]) <= x[0] && x[0] <= fmax(a[0], b[0]) &&
           fmin(a[1], b[1]) <= x[1] && x[1] <= fmax(a[1], b[1]);
}

/* Brute-force even-odd test over every edge: boundary when on an edge (exact), else the parity
 * of half-open crossings of the rightward ray. */
static inline int oracle_where(const fl_polygon *p, const double *x)
{
    int parity = 0;
    for (size_t r = 0; r < p->ring_count; r++)
        for (size_t v = p->ring_start[r]; v < p->ring_start[r + 1]; v++) {
            size_t w = v + 1 == p->ring_start[r + 1] ? p->ring_start[r] : v + 1;
            const double *a = p->xy + 2 * v, *b = p->xy + 2 * w;
            if (oracle_on_segment(a, b, x)) return FL_HAL2_BOUNDARY;
            if ((a[1] > x[1]) != (b[1] > x[1])) {
                int o = fl_orient2d(a, b, x);
                parity ^= b[1] > a[1] ? o > 0 : o < 0;
            }
        }
    return parity ? FL_HAL2_INSIDE : FL_HAL2_OUTSIDE;
}

static inline int oracle_segments_meet(const double *a, const double *b, const double *c,
                                       const double *d)
{
    int o1 = fl_orient2d(a, b, c), o2 = fl_orient2d(a, b, d);
    int o3 = fl_orient2d(c, d, a), o4 = fl_orient2d(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return 1;
    return oracle_on_segment(a, b, c) || oracle_on_segment(a, b, d) || oracle_on_segment(c, d, a) ||
           oracle_on_segment(c, d, b);
}

static inline size_t ring_next(const fl_polygon *p, size_t v)
{
    for (size_t r = 0; r < p->ring_count; r++)
        if (v + 1 == p->ring_start[r + 1]) return p->ring_start[r];
    return v + 1;
}

/* Distance from x to segment ab. */
static inline double seg_dist(const double *a, const double *b, const double *x)
{
    double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((x[0] - a[0]) * dx + (x[1] - a[1]) * dy) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(x[0] - a[0] - t * dx, x[1] - a[1] - t * dy);
}

/* Largest distance of an original vertex to the approximating polygon (all its edges). */
static inline double oracle_deviation(const fl_polygon *orig, const fl_polygon *approx)
{
    double worst = 0;
    for (size_t v = 0; v < orig->vertex_count; v++) {
        double best = INFINITY;
        for (size_t e = 0; e < approx->vertex_count; e++)
            best = fmin(best, seg_dist(approx->xy + 2 * e, approx->xy + 2 * ring_next(approx, e),
                                       orig->xy + 2 * v));
        worst = fmax(worst, best);
    }
    return worst;
}

/* Builds both trees, runs fl_hal2_intersect with and without the early exit and checks them
 * against every edge pair by the exact oracle: the same pairs in the same order, the early exit
 * reporting a real pair exactly when one exists. Returns the number of meeting pairs. */
static inline size_t check_hal2_intersection(const fl_polygon *a, const fl_polygon *b)
{
    fl_hal2 ha, hb;
    fl_error err;
    CHECK_STATUS(fl_hal2_build(a, NULL, &ha, &err), FL_OK, &err);
    CHECK_STATUS(fl_hal2_build(b, NULL, &hb, &err), FL_OK, &err);
    fl_hal2_pairs all, first;
    CHECK_STATUS(fl_hal2_intersect(&ha, &hb, 0, &all, &err), FL_OK, &err);
    CHECK_STATUS(fl_hal2_intersect(&ha, &hb, 1, &first, &err), FL_OK, &err);
    size_t k = 0, mismatches = 0;
    for (size_t i = 0; i < a->vertex_count; i++)
        for (size_t j = 0; j < b->vertex_count; j++) {
            if (!oracle_segments_meet(a->xy + 2 * i, a->xy + 2 * ring_next(a, i), b->xy + 2 * j,
                                      b->xy + 2 * ring_next(b, j)))
                continue;
            if (k >= all.count || all.pairs[2 * k] != i || all.pairs[2 * k + 1] != j) mismatches++;
            k++;
        }
    CHECK_EQ_INT(all.count, k);
    CHECK_EQ_INT(mismatches, 0);
    CHECK_EQ_INT(first.count, k > 0);
    if (first.count == 1) /* the early exit reports a real pair */
        CHECK(oracle_segments_meet(
            a->xy + 2 * first.pairs[0], a->xy + 2 * ring_next(a, first.pairs[0]),
            b->xy + 2 * first.pairs[1], b->xy + 2 * ring_next(b, first.pairs[1])));
    fl_hal2_pairs_free(&all);
    fl_hal2_pairs_free(&first);
    fl_hal2_free(&ha);
    fl_hal2_free(&hb);
    return k;
}

/* Builds the tree of p and checks fl_hal2_contains on the n queries q against oracle_where. */
static inline void check_hal2_contains(const fl_polygon *p, const double *q, size_t n)
{
    fl_hal2 h;
    fl_error err;
    CHECK_STATUS(fl_hal2_build(p, NULL, &h, &err), FL_OK, &err);
    uint8_t *where = malloc(n + 1);
    CHECK_STATUS(fl_hal2_contains(&h, q, n, where, &err), FL_OK, &err);
    size_t bad = 0;
    for (size_t k = 0; k < n; k++)
        if (where[k] != oracle_where(p, q + 2 * k) && bad++ < 5)
            fprintf(stderr, "query (%.17g, %.17g): hal %d, brute force %d\n", q[2 * k],
                    q[2 * k + 1], where[k], oracle_where(p, q + 2 * k));
    CHECK_EQ_INT(bad, 0);
    free(where);
    fl_hal2_free(&h);
}

#endif /* HAL2_ORACLE_H */
