/* Hierarchical point inclusion and intersection (thesis §7.4, Lemma 6.1) against brute force
 * over every edge with exact predicates: identical answers, also for points on vertices, on
 * edges, on chords and on flintstone boundaries, and for touching or overlapping edges. */
#include "hal2_oracle.h"

/* Queries that stress the boundaries: every vertex, its ulp neighbours, edge midpoints, and for
 * every node the chord's midpoint, the discs' centres and points on the discs' circles. */
static double *tricky_queries(const fl_polygon *p, size_t *count)
{
    fl_hal2 h;
    fl_error err;
    CHECK_STATUS(fl_hal2_build(p, NULL, &h, &err), FL_OK, &err);
    size_t cap = 8 * p->vertex_count + 12 * h.node_count + 8, n = 0;
    double *q = malloc(2 * cap * sizeof(double));
/* (derived points that overflow are skipped: queries must be finite) */
#define ADD(x, y)                                                                                  \
    do {                                                                                           \
        double x_ = (x), y_ = (y);                                                                 \
        if (isfinite(x_) && isfinite(y_)) q[2 * n] = x_, q[2 * n + 1] = y_, n++;                   \
    } while (0)
    for (size_t v = 0; v < p->vertex_count; v++) {
        const double *a = p->xy + 2 * v, *b = p->xy + 2 * ring_next(p, v);
        ADD(a[0], a[1]);
        ADD(nextafter(a[0], INFINITY), a[1]);
        ADD(a[0], nextafter(a[1], -INFINITY));
        ADD((a[0] + b[0]) / 2, (a[1] + b[1]) / 2);
        ADD(a[0] + (b[0] - a[0]) / 3, a[1] + (b[1] - a[1]) / 3);
    }
    for (size_t k = 0; k < h.node_count; k++) {
        const fl_hal2_node *nd = &h.nodes[k];
        const double *a = p->xy + 2 * nd->p, *b = p->xy + 2 * nd->s;
        ADD((a[0] + b[0]) / 2, (a[1] + b[1]) / 2);
        for (int d = 0; d < 2; d++) {
            const double *c = nd->disc[d];
            double r = sqrt(c[2]);
            ADD(c[0], c[1]);
            ADD(c[0] + r, c[1]);
            ADD(c[0], c[1] - r);
            ADD(c[0] - r * 0.6, c[1] + r * 0.8);
        }
    }
#undef ADD
    fl_hal2_free(&h);
    *count = n;
    return q;
}

static void check_random_and_tricky(const fl_polygon *p, unsigned long long seed, size_t n,
                                    double lo, double hi)
{
    unsigned long long rng = seed;
    double *q = malloc(2 * n * sizeof(double));
    for (size_t k = 0; k < 2 * n; k++)
        q[k] = lo + (hi - lo) * fl_test_rand01(&rng);
    check_hal2_contains(p, q, n);
    free(q);
    size_t m;
    q = tricky_queries(p, &m);
    check_hal2_contains(p, q, m);
    free(q);
}

static void test_hal2_inclusion_matches_brute_force_on_random_stars_with_holes(void)
{
    for (unsigned long long seed = 1; seed <= 4; seed++) {
        unsigned long long rng = seed;
        size_t n = 200 * seed;
        double *xy = malloc(2 * n * sizeof(double));
        test_poly t;
        tp_init(&t);
        star_ring(xy, n, 0, 0, 10, &rng);
        tp_add_ring(&t, xy, n, 0);
        star_ring(xy, n / 4, 1, 0, 2.5, &rng);
        tp_add_ring(&t, xy, n / 4, 1);
        star_ring(xy, 30, 40, 3, 5, &rng); /* a second polygon */
        tp_add_ring(&t, xy, 30, 0);
        check_random_and_tricky(&t.pg, seed, seed == 1 ? 10000 : 2500, -16, 47);
        free(xy);
        fl_polygon_free(&t.pg);
    }
}

static void test_hal2_inclusion_matches_brute_force_on_comb_and_collinear_grid(void)
{
    double xy[2 * 200];
    test_poly t;
    tp_init(&t);
    size_t n = comb_ring(xy, 12);
    tp_add_ring(&t, xy, n, 0);
    n = 0; /* a hole in the comb's base: 6 x 1 rectangle with integer vertices on its sides */
    for (int x = 1; x <= 7; x++)
        xy[2 * n] = x, xy[2 * n + 1] = 0.5, n++;
    for (int x = 7; x >= 1; x--)
        xy[2 * n] = x, xy[2 * n + 1] = 1.5, n++;
    tp_add_ring(&t, xy, n, 1);
    check_random_and_tricky(&t.pg, 7, 3000, -1, 50);
    /* every point of the half-integer grid: many lie exactly on edges and vertices */
    size_t m = 0;
    double *q = malloc(2 * 102 * 26 * sizeof(double));
    for (int i = -2; i < 100; i++)
        for (int j = -2; j < 24; j++)
            q[2 * m] = i / 2.0, q[2 * m + 1] = j / 2.0, m++;
    check_hal2_contains(&t.pg, q, m);
    free(q);
    fl_polygon_free(&t.pg);
}

/* Huge (products overflow) and tiny (products underflow) coordinates: the floating discs lose
 * their meaning but only prune less; the exact answers must not change. */
static void test_hal2_inclusion_is_exact_for_extreme_scales(void)
{
    const double scales[] = {1e200, 1e-300, 1e150};
    for (size_t k = 0; k < 3; k++) {
        unsigned long long rng = 5 + k;
        double xy[2 * 120];
        test_poly t;
        tp_init(&t);
        star_ring(xy, 120, 0, 0, 10, &rng);
        for (size_t i = 0; i < 240; i++)
            xy[i] *= scales[k];
        tp_add_ring(&t, xy, 120, 0);
        check_random_and_tricky(&t.pg, k, 500, -16 * scales[k], 16 * scales[k]);
        fl_polygon_free(&t.pg);
    }
}

static void test_hal2_inclusion_rejects_non_finite_queries(void)
{
    double xy[6] = {0, 0, 1, 0, 0, 1}, q[2] = {NAN, 0};
    size_t rs[2] = {0, 3}, ps[2] = {0, 1};
    fl_polygon p = {3, xy, 1, rs, 1, ps};
    fl_hal2 h;
    fl_error err;
    uint8_t w;
    CHECK_STATUS(fl_hal2_build(&p, NULL, &h, &err), FL_OK, &err);
    CHECK_STATUS(fl_hal2_contains(&h, q, 1, &w, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_hal2_contains(&h, NULL, 1, &w, &err), FL_ERR_USAGE, &err);
    fl_hal2_free(&h);
}

static void test_hal2_intersection_matches_all_pairs_on_random_stars(void)
{
    for (unsigned long long seed = 1; seed <= 12; seed++) {
        unsigned long long rng = seed * 1000;
        double xy[2 * 300];
        test_poly a, b;
        tp_init(&a);
        tp_init(&b);
        star_ring(xy, 100 + seed * 10, 0, 0, 10, &rng);
        tp_add_ring(&a, xy, 100 + seed * 10, 0);
        star_ring(xy, 20, 1, 1, 2, &rng);
        tp_add_ring(&a, xy, 20, 1);
        /* from far apart (no pair) to overlapping */
        double off = 40.0 - 3.0 * (double)seed;
        star_ring(xy, 150, off, 0.5 * off, 9, &rng);
        tp_add_ring(&b, xy, 150, 0);
        check_hal2_intersection(&a.pg, &b.pg);
        fl_polygon_free(&a.pg);
        fl_polygon_free(&b.pg);
    }
}

/* Touching vertices and collinear overlapping edges on integer coordinates. */
static void test_hal2_intersection_counts_touching_and_overlapping_edges(void)
{
    double xy[2 * 200];
    test_poly a, b;
    tp_init(&a);
    tp_init(&b);
    size_t n = comb_ring(xy, 10);
    tp_add_ring(&a, xy, n, 0);
    /* a rectangle whose bottom lies along the comb's tooth tips (y = 10) and whose left side
     * passes through the comb's base corner x = 0 */
    double r[] = {0, 10, 40, 10, 40, 14, 0, 14};
    tp_add_ring(&b, r, 4, 0);
    double s[] = {6, 2, 7, 1, 8, 2, 7, 3}; /* a diamond touching the base edge y = 2 at x=6..8 */
    tp_add_ring(&b, s, 4, 0);
    check_hal2_intersection(&a.pg, &b.pg);
    check_hal2_intersection(&a.pg, &a.pg); /* a polygon against itself: every edge meets its
                                         neighbours */
    fl_polygon_free(&a.pg);
    fl_polygon_free(&b.pg);
}

FL_TEST_MAIN(FL_TEST_CASE(test_hal2_inclusion_matches_brute_force_on_random_stars_with_holes),
             FL_TEST_CASE(test_hal2_inclusion_matches_brute_force_on_comb_and_collinear_grid),
             FL_TEST_CASE(test_hal2_inclusion_is_exact_for_extreme_scales),
             FL_TEST_CASE(test_hal2_inclusion_rejects_non_finite_queries),
             FL_TEST_CASE(test_hal2_intersection_matches_all_pairs_on_random_stars),
             FL_TEST_CASE(test_hal2_intersection_counts_touching_and_overlapping_edges))
