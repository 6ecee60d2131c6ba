/* Our side of the 2D flintstone evaluation (bench/hal2_eval.h): build time, the approximation
 * curve (adaptive and by level, certified and measured error), point-inclusion throughput
 * against a brute-force crossing test, and boundary-intersection detection between rings.
 *   eval_hal2 RINGS.xy ANSWERS_PREFIX [RINGS=20] [QUERIES=1000000] [PAIR_RINGS=300]
 * Writes ANSWERS_PREFIX.inside (one byte a query: 1 inside, 0 outside, 2 on the boundary) and
 * ANSWERS_PREFIX.pairs (one byte a ring pair: 1 when the boundaries meet) for the workload to
 * compare with GEOS's. */
#define _POSIX_C_SOURCE 200809L
#include <time.h>

#include "flintstone.h"
#include "hal2_eval.h"

/* Queries a ring whose answers are checked against the exact brute force (untimed). */
#define H2_EXACT 10000

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static fl_status build(const h2_ring *r, fl_hal2 *hal, fl_error *err)
{
    size_t rs[2] = {0, r->n}, ps[2] = {0, 1};
    fl_polygon p = {r->n, r->xy, 1, rs, 1, ps};
    return fl_hal2_build(&p, NULL, hal, err);
}

/* The plain crossing-number test a user would write, in floating point. */
static int brute_inside(const h2_ring *r, const double *q)
{
    int in = 0;
    for (size_t i = 0, j = r->n - 1; i < r->n; j = i++) {
        const double *a = r->xy + 2 * i, *b = r->xy + 2 * j;
        if ((a[1] > q[1]) != (b[1] > q[1]) &&
            q[0] < (b[0] - a[0]) * (q[1] - a[1]) / (b[1] - a[1]) + a[0])
            in = !in;
    }
    return in;
}

/* The exact brute force of the tests (tests/hal/hal2_oracle.h): boundary when on an edge,
 * else the parity of half-open crossings, every decision by fl_orient2d. */
static int exact_on_segment(const double *a, const double *b, const double *x)
{
    return fl_orient2d(a, b, x) == 0 && fmin(a[0], b[0]) <= x[0] && x[0] <= fmax(a[0], b[0]) &&
           fmin(a[1], b[1]) <= x[1] && x[1] <= fmax(a[1], b[1]);
}

static int exact_where(const h2_ring *r, const double *x)
{
    int parity = 0;
    for (size_t i = 0, j = r->n - 1; i < r->n; j = i++) {
        const double *a = r->xy + 2 * j, *b = r->xy + 2 * i;
        if (exact_on_segment(a, b, x)) return FL_HAL2_BOUNDARY;
        if ((a[1] > x[1]) != (b[1] > x[1])) {
            int o = fl_orient2d(a, b, x);
            parity ^= b[1] > a[1] ? o > 0 : o < 0;
        }
    }
    return parity ? FL_HAL2_INSIDE : FL_HAL2_OUTSIDE;
}

static int exact_segments_meet(const double *a, const double *b, const double *c, const double *d)
{
    if (fmax(a[0], b[0]) < fmin(c[0], d[0]) || fmax(c[0], d[0]) < fmin(a[0], b[0]) ||
        fmax(a[1], b[1]) < fmin(c[1], d[1]) || fmax(c[1], d[1]) < fmin(a[1], b[1]))
        return 0;
    int o1 = fl_orient2d(a, b, c), o2 = fl_orient2d(a, b, d);
    int o3 = fl_orient2d(c, d, a), o4 = fl_orient2d(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return 1;
    return exact_on_segment(a, b, c) || exact_on_segment(a, b, d) || exact_on_segment(c, d, a) ||
           exact_on_segment(c, d, b);
}

/* Do the boundaries of rings a and b meet: all edge pairs, exact. */
static int exact_rings_meet(const h2_ring *a, const h2_ring *b)
{
    for (size_t i = 0; i < a->n; i++)
        for (size_t j = 0; j < b->n; j++)
            if (exact_segments_meet(a->xy + 2 * i, a->xy + 2 * ((i + 1) % a->n), b->xy + 2 * j,
                                    b->xy + 2 * ((j + 1) % b->n)))
                return 1;
    return 0;
}

static void approximation(const h2_set *s, size_t k, fl_hal2 *hals)
{
    fl_error err;
    for (size_t f = 0; f < H2_FRACTIONS; f++) {
        size_t vertices = 0, original = 0;
        double measured = 0, certified = 0, t = 0;
        for (size_t i = 0; i < k; i++) {
            double d = h2_diagonal(&s->rings[i]), e;
            fl_polygon a;
            double t0 = now();
            if (fl_hal2_approximate_error(&hals[i], h2_fractions[f] * d, &a, &e, NULL, &err))
                exit(1);
            t += now() - t0;
            vertices += a.vertex_count;
            original += s->rings[i].n;
            measured = fmax(measured, h2_error(&s->rings[i], a.xy, a.vertex_count) / d);
            certified = fmax(certified, e / d);
            fl_polygon_free(&a);
        }
        printf("APPROX method=flintstone-adaptive fraction=%g vertices=%zu original=%zu "
               "measured=%.3e certified=%.3e seconds=%.6f\n",
               h2_fractions[f], vertices, original, measured, certified, t);
    }
    /* Every level until all 20 rings are back to their original vertices (hal.depth). */
    uint32_t depth = 0;
    for (size_t i = 0; i < k; i++)
        depth = hals[i].depth > depth ? hals[i].depth : depth;
    for (uint32_t level = 0; level <= depth; level++) {
        size_t vertices = 0;
        double measured = 0, certified = 0;
        for (size_t i = 0; i < k; i++) {
            double d = h2_diagonal(&s->rings[i]), e;
            fl_polygon a;
            if (fl_hal2_approximate_level(&hals[i], level, &a, &e, &err)) exit(1);
            vertices += a.vertex_count;
            measured = fmax(measured, h2_error(&s->rings[i], a.xy, a.vertex_count) / d);
            certified = fmax(certified, e / d);
            fl_polygon_free(&a);
        }
        printf(
            "APPROX method=flintstone-level level=%u vertices=%zu measured=%.3e certified=%.3e\n",
            level, vertices, measured, certified);
    }
}

static void inclusion(const h2_set *s, size_t k, fl_hal2 *hals, size_t total, const char *prefix)
{
    size_t m = total / k, inside = 0, boundary = 0, brute_m = m < 2000 ? m : 2000;
    double t = 0, tb = 0;
    size_t brute_disagree = 0, exact_m = m < H2_EXACT ? m : H2_EXACT, exact_disagree = 0;
    char path[1024];
    snprintf(path, sizeof path, "%s.inside", prefix);
    FILE *out = fopen(path, "wb");
    uint8_t *where = malloc(m);
    fl_error err;
    for (size_t i = 0; i < k; i++) {
        double *q = h2_queries(&s->rings[i], i, m);
        double t0 = now();
        if (fl_hal2_contains(&hals[i], q, m, where, &err)) exit(1);
        t += now() - t0;
        t0 = now();
        int acc = 0;
        for (size_t j = 0; j < brute_m; j++)
            acc += brute_inside(&s->rings[i], q + 2 * j) << (j & 7);
        tb += now() - t0;
        for (size_t j = 0; j < m; j++) {
            inside += where[j] == FL_HAL2_INSIDE;
            boundary += where[j] == FL_HAL2_BOUNDARY;
            if (j < brute_m && where[j] != FL_HAL2_BOUNDARY &&
                (where[j] == FL_HAL2_INSIDE) != brute_inside(&s->rings[i], q + 2 * j))
                brute_disagree++;
        }
        for (size_t j = 0; j < exact_m; j++) /* untimed: the answers, exactly */
            exact_disagree += where[j] != exact_where(&s->rings[i], q + 2 * j);
        fwrite(where, 1, m, out);
        free(q);
        if (acc == -1) puts(""); /* keeps the brute-force loop from being optimised away */
    }
    fclose(out);
    free(where);
    printf("INSIDE method=flintstone queries=%zu seconds=%.6f inside=%zu boundary=%zu "
           "exact_checked=%zu exact_disagreements=%zu\n",
           m * k, t, inside, boundary, exact_m * k, exact_disagree);
    printf("INSIDE method=brute-force queries=%zu seconds=%.6f per_query_scaled=%.6f "
           "disagreements_with_flintstone=%zu\n",
           brute_m * k, tb, tb / (double)(brute_m * k) * (double)(m * k), brute_disagree);
}

static void intersection(const h2_set *s, size_t k, const fl_hal2 *hals, const char *prefix)
{
    uint32_t *p;
    size_t n = h2_pairs(s, k, &p), meeting = 0;
    char path[1024];
    snprintf(path, sizeof path, "%s.pairs", prefix);
    FILE *out = fopen(path, "wb");
    fl_error err;
    double t0 = now();
    uint8_t *ans = malloc(n + 1);
    for (size_t i = 0; i < n; i++) {
        fl_hal2_pairs pairs;
        if (fl_hal2_intersect(&hals[p[2 * i]], &hals[p[2 * i + 1]], 1, &pairs, &err)) exit(1);
        ans[i] = pairs.count > 0;
        meeting += ans[i];
        fl_hal2_pairs_free(&pairs);
    }
    double t = now() - t0;
    size_t exact_disagree = 0; /* untimed: every pair against all edge pairs, exact */
    for (size_t i = 0; i < n; i++)
        exact_disagree += ans[i] != exact_rings_meet(&s->rings[p[2 * i]], &s->rings[p[2 * i + 1]]);
    fwrite(ans, 1, n, out);
    fclose(out);
    free(ans);
    free(p);
    printf(
        "INTERSECT method=flintstone pairs=%zu meeting=%zu seconds=%.6f exact_disagreements=%zu\n",
        n, meeting, t, exact_disagree);
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr,
                "usage: eval_hal2 RINGS.xy ANSWERS_PREFIX [RINGS] [QUERIES] [PAIR_RINGS]\n");
        return 2;
    }
    size_t k = argc > 3 ? (size_t)atol(argv[3]) : 20;
    size_t queries = argc > 4 ? (size_t)atol(argv[4]) : 1000000;
    size_t kp = argc > 5 ? (size_t)atol(argv[5]) : 300;
    h2_set s;
    if (h2_load(argv[1], k > kp ? k : kp, &s)) return 1;
    if (k > s.count) k = s.count;
    if (kp > s.count) kp = s.count;
    size_t nb = k > kp ? k : kp, vertices = 0;
    fl_hal2 *hals = calloc(nb, sizeof *hals);
    fl_error err;
    double t0 = now();
    for (size_t i = 0; i < nb; i++) {
        if (build(&s.rings[i], &hals[i], &err)) {
            fprintf(stderr, "ring %zu: %s\n", i, err.message);
            return 1;
        }
        vertices += s.rings[i].n;
    }
    printf("BUILD method=flintstone rings=%zu vertices=%zu seconds=%.6f\n", nb, vertices,
           now() - t0);
    approximation(&s, k, hals);
    inclusion(&s, k, hals, queries, argv[2]);
    intersection(&s, kp, hals, argv[2]);
    for (size_t i = 0; i < nb; i++)
        fl_hal2_free(&hals[i]);
    free(hals);
    h2_free(&s);
    return 0;
}
