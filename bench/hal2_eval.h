/* The 2D flintstone evaluation (docs/hal.md, "Against GEOS"), shared by our program
 * (bench/eval_hal2.c) and the GEOS peer (bench/peers/geos_hal2.c) so both get the same rings,
 * the same queries and the same error measurement. C11.
 *
 * Input: the rings of a .xy file (npm world-atlas countries-50m.xy, bench/get-data.sh); the
 * `count` rings with the most vertices (closing repeat dropped) are the test polygons, each
 * ring its own polygon. Queries: uniform in each ring's bounding box, a fixed xorshift stream.
 * Error of an approximation: the largest distance from an original vertex to the approximating
 * ring (brute force over its edges); for polylines that is the one-sided Hausdorff distance
 * from the original boundary to the approximation, the quantity both methods bound. */
#ifndef FL_BENCH_HAL2_EVAL_H
#define FL_BENCH_HAL2_EVAL_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct h2_ring {
    size_t n;
    double *xy;
    double lo[2], hi[2];
} h2_ring;

typedef struct h2_set {
    size_t count;
    h2_ring *rings;
} h2_set;

static int h2_by_size(const void *a, const void *b)
{
    size_t x = ((const h2_ring *)a)->n, y = ((const h2_ring *)b)->n;
    return (x < y) - (x > y);
}

static void h2_push(h2_set *s, size_t *cap, const double *xy, size_t n)
{
    if (n > 1 && xy[0] == xy[2 * (n - 1)] && xy[1] == xy[2 * (n - 1) + 1]) n--;
    if (n < 4) return;
    if (s->count == *cap)
        s->rings = realloc(s->rings, (*cap = *cap ? 2 * *cap : 256) * sizeof *s->rings);
    h2_ring *r = &s->rings[s->count++];
    r->n = n;
    r->xy = malloc(2 * n * sizeof(double));
    memcpy(r->xy, xy, 2 * n * sizeof(double));
    r->lo[0] = r->lo[1] = INFINITY;
    r->hi[0] = r->hi[1] = -INFINITY;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 2; k++) {
            r->lo[k] = fmin(r->lo[k], xy[2 * i + k]);
            r->hi[k] = fmax(r->hi[k], xy[2 * i + k]);
        }
}

/* Loads the `count` largest rings of path (all when count is 0); 0 on success. */
static int h2_load(const char *path, size_t count, h2_set *s)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        fprintf(stderr, "cannot open %s\n", path);
        return 1;
    }
    memset(s, 0, sizeof *s);
    size_t cap = 0, n = 0, bcap = 4096;
    double *buf = malloc(2 * bcap * sizeof(double));
    char line[256];
    while (fgets(line, sizeof line, f)) {
        double x, y;
        if (line[0] == '#') continue;
        if (sscanf(line, "%lf %lf", &x, &y) == 2) {
            if (n == bcap) buf = realloc(buf, 2 * (bcap *= 2) * sizeof(double));
            buf[2 * n] = x;
            buf[2 * n + 1] = y;
            n++;
        } else if (n) {
            h2_push(s, &cap, buf, n);
            n = 0;
        }
    }
    if (n) h2_push(s, &cap, buf, n);
    free(buf);
    fclose(f);
    qsort(s->rings, s->count, sizeof *s->rings, h2_by_size);
    if (count && count < s->count) {
        for (size_t i = count; i < s->count; i++)
            free(s->rings[i].xy);
        s->count = count;
    }
    return 0;
}

static void h2_free(h2_set *s)
{
    for (size_t i = 0; i < s->count; i++)
        free(s->rings[i].xy);
    free(s->rings);
}

static double h2_diagonal(const h2_ring *r)
{
    return hypot(r->hi[0] - r->lo[0], r->hi[1] - r->lo[1]);
}

/* m queries uniform in the ring's bounding box, from the stream seeded by the ring's index. */
static double *h2_queries(const h2_ring *r, size_t index, size_t m)
{
    uint64_t x = 0x243f6a8885a308d3ull ^ (index * 0x9e3779b97f4a7c15ull);
    double *q = malloc(2 * m * sizeof(double));
    for (size_t i = 0; i < 2 * m; i++) {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        double u = (double)(x >> 11) * 0x1p-53;
        int k = (int)(i & 1);
        q[i] = r->lo[k] + u * (r->hi[k] - r->lo[k]);
    }
    return q;
}

static double h2_point_segment(const double *p, const double *a, const double *b)
{
    double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

/* Largest distance from a vertex of r to the closed ring approx (m vertices). Brute force over
 * the edges, but each vertex starts at the edge nearest to the previous vertex: consecutive
 * vertices usually share it, so the scan stops at once when the vertex cannot raise the maximum
 * (the result is the same in any order). */
static double h2_error(const h2_ring *r, const double *approx, size_t m)
{
    double worst = 0;
    size_t start = 0;
    for (size_t i = 0; i < r->n; i++) {
        double best = INFINITY;
        for (size_t t = 0, j = start; t < m && best > worst; t++, j = j + 1 == m ? 0 : j + 1) {
            double d = h2_point_segment(r->xy + 2 * i, approx + 2 * j, approx + 2 * ((j + 1) % m));
            if (d < best) {
                best = d;
                start = j;
            }
        }
        if (best > worst && best < INFINITY) worst = best;
    }
    return worst;
}

/* Pairs of rings (i < j) among the first k whose bounding boxes overlap. */
static size_t h2_pairs(const h2_set *s, size_t k, uint32_t **out)
{
    size_t n = 0, cap = 256;
    uint32_t *p = malloc(2 * cap * sizeof *p);
    for (size_t i = 0; i < k && i < s->count; i++)
        for (size_t j = i + 1; j < k && j < s->count; j++) {
            const h2_ring *a = &s->rings[i], *b = &s->rings[j];
            if (a->hi[0] < b->lo[0] || b->hi[0] < a->lo[0] || a->hi[1] < b->lo[1] ||
                b->hi[1] < a->lo[1])
                continue;
            if (n == cap) p = realloc(p, 2 * (cap *= 2) * sizeof *p);
            p[2 * n] = (uint32_t)i;
            p[2 * n + 1] = (uint32_t)j;
            n++;
        }
    *out = p;
    return n;
}

/* The tolerances of the approximation curve, as fractions of each ring's bbox diagonal: the
 * table of docs/hal.md uses 0.1, 0.03, ..., 0.0003; the others fill in the plot
 * (bench/tools/plot_hal2_approx.py). */
static const double h2_fractions[] = {0.3,   0.2,   0.1,   0.05,   0.03,   0.02,   0.01,  0.005,
                                      0.003, 0.002, 0.001, 0.0005, 0.0003, 0.0002, 0.0001};
#define H2_FRACTIONS (sizeof h2_fractions / sizeof h2_fractions[0])

#endif
