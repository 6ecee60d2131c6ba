/* Flintstone trees: structure (Fig. 7.5, Thm. 7.2), the root on the smallest enclosing disc,
 * the flintstones of Def. 7.3 checked with exact predicates, widths (Def. 7.4) against the
 * circumcircle, and approximations whose certified error bounds the true deviation. */
#include "hal2_oracle.h"

static void build_or_fail(const fl_polygon *p, fl_hal2 *h)
{
    fl_error err;
    CHECK_STATUS(fl_hal2_build(p, NULL, h, &err), FL_OK, &err);
}

static void random_stars(test_poly *t, unsigned long long seed, size_t n)
{
    double *xy = malloc(2 * n * sizeof(double));
    unsigned long long rng = seed;
    tp_init(t);
    star_ring(xy, n, 0, 0, 10, &rng);
    tp_add_ring(t, xy, n, 0);
    star_ring(xy, n / 3 + 3, 0.5, -0.3, 2, &rng); /* a hole */
    tp_add_ring(t, xy, n / 3 + 3, 1);
    free(xy);
}

/* Infix order of each tree is its ring, every non-root vertex is one node's split vertex, and
 * there are (count - 2) nodes a ring. */
static void test_hal2_tree_infix_order_is_the_ring(void)
{
    for (unsigned long long seed = 1; seed <= 20; seed++) {
        test_poly t;
        fl_hal2 h;
        random_stars(&t, seed, 5 + seed * 7);
        build_or_fail(&t.pg, &h);
        size_t expect = 0;
        for (size_t r = 0; r < t.pg.ring_count; r++)
            expect += h.rings[r].count - 2;
        CHECK_EQ_INT(h.node_count, expect);
        int *seen = calloc(t.pg.vertex_count, sizeof(int));
        for (size_t r = 0; r < t.pg.ring_count; r++) {
            seen[h.rings[r].root[0]]++;
            seen[h.rings[r].root[1]]++;
        }
        for (size_t k = 0; k < h.node_count; k++) {
            const fl_hal2_node *nd = &h.nodes[k];
            seen[nd->q]++;
            /* ring offsets: q strictly between p and s; children cover p..q and q..s */
            const fl_hal2_ring *rg = NULL;
            for (size_t r = 0; r < t.pg.ring_count; r++)
                if (nd->p >= h.rings[r].first && nd->p < h.rings[r].first + h.rings[r].count)
                    rg = &h.rings[r];
            uint32_t n = rg->count, oq = (nd->q - nd->p + n) % n, os = (nd->s - nd->p + n) % n;
            if (os == 0) os = n;
            CHECK(oq > 0 && oq < os && os == nd->edges);
            for (int c = 0; c < 2; c++) {
                uint32_t a = c ? nd->q : nd->p, b = c ? nd->s : nd->q;
                uint32_t span = (b - a + n) % n;
                if (nd->child[c] < 0) {
                    CHECK_EQ_INT(span, 1);
                } else {
                    const fl_hal2_node *ch = &h.nodes[nd->child[c]];
                    CHECK(ch->p == a && ch->s == b && ch->level == nd->level + 1);
                }
            }
        }
        for (size_t v = 0; v < t.pg.vertex_count; v++)
            CHECK_EQ_INT(seen[v], 1);
        free(seen);
        fl_hal2_free(&h);
        fl_polygon_free(&t.pg);
    }
}

/* Brute-force smallest enclosing circle: the smallest diametral or circum-circle containing
 * every point (with a relative tolerance for the containment of the floating circle). */
static double brute_sbd(const double *xy, size_t n, double c[2])
{
    double best = INFINITY;
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++)
            for (size_t k = j; k < n; k++) {
                const double *a = xy + 2 * i, *b = xy + 2 * j, *d = xy + 2 * k;
                double cx, cy;
                if (k == j) {
                    cx = (a[0] + b[0]) / 2, cy = (a[1] + b[1]) / 2;
                } else {
                    double bx = b[0] - a[0], by = b[1] - a[1], dx = d[0] - a[0], dy = d[1] - a[1];
                    double den = 2 * (bx * dy - by * dx);
                    if (den == 0) continue;
                    cx = a[0] + (dy * (bx * bx + by * by) - by * (dx * dx + dy * dy)) / den;
                    cy = a[1] + (bx * (dx * dx + dy * dy) - dx * (bx * bx + by * by)) / den;
                }
                double r = hypot(a[0] - cx, a[1] - cy);
                if (r >= best) continue;
                int ok = 1;
                for (size_t m = 0; m < n && ok; m++)
                    ok = hypot(xy[2 * m] - cx, xy[2 * m + 1] - cy) <= r * (1 + 1e-12);
                if (ok) best = r, c[0] = cx, c[1] = cy;
            }
    return best;
}

static void test_hal2_root_is_on_smallest_enclosing_disc(void)
{
    for (unsigned long long seed = 1; seed <= 30; seed++) {
        unsigned long long rng = seed * 77;
        size_t n = 3 + seed % 25;
        double xy[2 * 30], c[2];
        star_ring(xy, n, seed, -2.0 * seed, 1 + seed % 4, &rng);
        test_poly t;
        tp_init(&t);
        tp_add_ring(&t, xy, n, 0);
        fl_hal2 h;
        build_or_fail(&t.pg, &h);
        double r = brute_sbd(xy, n, c);
        const fl_hal2_ring *rg = &h.rings[0];
        CHECK_NEAR(sqrt(rg->disc[2]), r, 1e-9 * r);
        for (int k = 0; k < 2; k++) {
            const double *v = xy + 2 * rg->root[k];
            CHECK_NEAR(hypot(v[0] - c[0], v[1] - c[1]), r, 1e-9 * r);
        }
        fl_hal2_free(&h);
        fl_polygon_free(&t.pg);
    }
}

/* Def. 7.3 with HAL Thm. 1: the circle through v_p, v_s and the split vertex v_q holds every
 * vertex of v_p..v_s (exact fl_incircle), the stored discs hold them too, and the width is
 * R + h of that circle (Def. 7.4), computed here from the circumcentre. */
static void test_hal2_flintstones_hold_their_polylines(void)
{
    for (unsigned long long seed = 1; seed <= 10; seed++) {
        test_poly t;
        fl_hal2 h;
        random_stars(&t, seed * 31, 60);
        build_or_fail(&t.pg, &h);
        const double *xy = t.pg.xy;
        for (size_t k = 0; k < h.node_count; k++) {
            const fl_hal2_node *nd = &h.nodes[k];
            CHECK(nd->kind == FL_HAL2_TWO_DISCS || nd->kind == FL_HAL2_DISC_HALFPLANE);
            const double *a = xy + 2 * nd->p, *b = xy + 2 * nd->s, *q = xy + 2 * nd->q;
            int o = fl_orient2d(a, b, q);
            CHECK(o != 0);
            size_t ring = 0;
            while (t.pg.ring_start[ring + 1] <= nd->p)
                ring++;
            size_t v = nd->p;
            for (uint32_t e = 0; e <= nd->edges; e++) {
                CHECK(fl_incircle(a, b, q, xy + 2 * v) * o >= 0);
                for (int d = 0; d < (nd->kind == FL_HAL2_TWO_DISCS ? 2 : 1); d++) {
                    const double *c = nd->disc[d];
                    double d2 = pow(xy[2 * v] - c[0], 2) + pow(xy[2 * v + 1] - c[1], 2);
                    CHECK(d2 <= c[2] * (1 + 1e-14));
                }
                v = ring_next(&t.pg, v);
            }
            double bx = b[0] - a[0], by = b[1] - a[1], dx = q[0] - a[0], dy = q[1] - a[1];
            double den = 2 * (bx * dy - by * dx);
            double cx = a[0] + (dy * (bx * bx + by * by) - by * (dx * dx + dy * dy)) / den;
            double cy = a[1] + (bx * (dx * dx + dy * dy) - dx * (bx * bx + by * by)) / den;
            double R = hypot(a[0] - cx, a[1] - cy), len = hypot(bx, by);
            double toward_q = o * (bx * (cy - a[1]) - by * (cx - a[0])) / len;
            CHECK_NEAR(nd->width[0], R + toward_q, 1e-7 * (R + len));
            CHECK(nd->width[0] >= nd->width[1]);
        }
        fl_hal2_free(&h);
        fl_polygon_free(&t.pg);
    }
}

static void check_approximation(const fl_polygon *orig, const fl_polygon *ap, double error)
{
    CHECK_EQ_INT(ap->ring_count, orig->ring_count);
    double dev = oracle_deviation(orig, ap);
    CHECK_MSG(dev <= error, "deviation %.17g > certified %.17g", dev, error);
}

static void test_hal2_level_approximations_are_certified_and_end_at_original(void)
{
    fl_error err;
    for (unsigned long long seed = 1; seed <= 6; seed++) {
        test_poly t;
        fl_hal2 h;
        random_stars(&t, seed * 5, 150);
        build_or_fail(&t.pg, &h);
        size_t prev = 0;
        for (uint32_t level = 0; level <= h.depth + 1; level++) {
            fl_polygon ap;
            double e = -1;
            CHECK_STATUS(fl_hal2_approximate_level(&h, level, &ap, &e, &err), FL_OK, &err);
            if (level == 0) CHECK_EQ_INT(ap.vertex_count, 2 * t.pg.ring_count);
            CHECK(ap.vertex_count >= prev);
            prev = ap.vertex_count;
            check_approximation(&t.pg, &ap, e);
            if (level >= h.depth) {
                CHECK_EQ_INT(ap.vertex_count, t.pg.vertex_count);
                CHECK(memcmp(ap.xy, t.pg.xy, 2 * ap.vertex_count * sizeof(double)) == 0);
                CHECK(e == 0);
            }
            fl_polygon_free(&ap);
        }
        fl_hal2_free(&h);
        fl_polygon_free(&t.pg);
    }
}

static void test_hal2_adaptive_approximation_meets_the_bound(void)
{
    fl_error err;
    test_poly t;
    fl_hal2 h;
    random_stars(&t, 99, 400);
    build_or_fail(&t.pg, &h);
    size_t prev = 0;
    const double bounds[] = {20, 5, 1, 0.3, 0.1, 0.01, 0};
    for (size_t k = 0; k < sizeof bounds / sizeof bounds[0]; k++) {
        fl_polygon ap;
        double e = -1;
        uint32_t level = 0;
        CHECK_STATUS(fl_hal2_approximate_error(&h, bounds[k], &ap, &e, &level, &err), FL_OK, &err);
        CHECK(e <= bounds[k] || (bounds[k] == 0 && e == 0));
        CHECK(level <= h.depth);
        CHECK(ap.vertex_count >= prev);
        prev = ap.vertex_count;
        check_approximation(&t.pg, &ap, e);
        if (bounds[k] == 0) CHECK_EQ_INT(ap.vertex_count, t.pg.vertex_count);
        fl_polygon_free(&ap);
    }
    fl_polygon ap;
    CHECK_STATUS(fl_hal2_approximate_error(&h, -1, &ap, NULL, NULL, &err), FL_ERR_USAGE, &err);
    fl_hal2_free(&h);
    fl_polygon_free(&t.pg);
}

/* A comb and collinear runs: vertices on the chord are handled (segment flintstones) and the
 * approximations stay certified. */
static void test_hal2_comb_and_collinear_runs_are_certified(void)
{
    fl_error err;
    double xy[2 * 400];
    test_poly t;
    tp_init(&t);
    size_t n = comb_ring(xy, 20);
    tp_add_ring(&t, xy, n, 0);
    n = 0; /* a 12 x 8 rectangle with a vertex at every integer point of its boundary */
    for (int x = 0; x < 12; x++)
        xy[2 * n] = 100 + x, xy[2 * n + 1] = 0, n++;
    for (int y = 0; y < 8; y++)
        xy[2 * n] = 112, xy[2 * n + 1] = y, n++;
    for (int x = 12; x > 0; x--)
        xy[2 * n] = 100 + x, xy[2 * n + 1] = 8, n++;
    for (int y = 8; y > 0; y--)
        xy[2 * n] = 100, xy[2 * n + 1] = y, n++;
    tp_add_ring(&t, xy, n, 0);
    fl_hal2 h;
    build_or_fail(&t.pg, &h);
    int segments = 0;
    for (size_t k = 0; k < h.node_count; k++)
        segments += h.nodes[k].kind == FL_HAL2_SEGMENT;
    CHECK(segments > 0);
    for (uint32_t level = 0; level <= h.depth; level++) {
        fl_polygon ap;
        double e;
        CHECK_STATUS(fl_hal2_approximate_level(&h, level, &ap, &e, &err), FL_OK, &err);
        check_approximation(&t.pg, &ap, e);
        fl_polygon_free(&ap);
    }
    fl_hal2_free(&h);
    fl_polygon_free(&t.pg);
}

/* Twenty integer points exactly on the circle of radius 25: the smallest enclosing disc is
 * that circle and the root pair must be a diameter (length 50), "the two vertices that are
 * farthest apart" (§7.2.2). Repeated vertices (zero-length edges) are accepted. */
static void test_hal2_cocircular_root_is_a_diameter(void)
{
    static const int pts[][2] = {{25, 0},  {24, 7},   {20, 15},   {15, 20},   {7, 24},
                                 {0, 25},  {-7, 24},  {-15, 20},  {-20, 15},  {-24, 7},
                                 {-25, 0}, {-24, -7}, {-20, -15}, {-15, -20}, {-7, -24},
                                 {0, -25}, {7, -24},  {15, -20},  {20, -15},  {24, -7}};
    double xy[2 * 24];
    size_t n = 0;
    for (size_t k = 0; k < 20; k++) {
        xy[2 * n] = pts[k][0], xy[2 * n + 1] = pts[k][1], n++;
        if (k % 7 == 3) xy[2 * n] = pts[k][0], xy[2 * n + 1] = pts[k][1], n++; /* repeat */
    }
    for (size_t rot = 0; rot < n; rot += 5) {
        double ring[2 * 24];
        for (size_t k = 0; k < n; k++) {
            ring[2 * k] = xy[2 * ((k + rot) % n)];
            ring[2 * k + 1] = xy[2 * ((k + rot) % n) + 1];
        }
        test_poly t;
        tp_init(&t);
        tp_add_ring(&t, ring, n, 0);
        fl_hal2 h;
        build_or_fail(&t.pg, &h);
        const double *a = ring + 2 * h.rings[0].root[0], *b = ring + 2 * h.rings[0].root[1];
        CHECK(hypot(a[0] - b[0], a[1] - b[1]) == 50);
        CHECK_NEAR(h.rings[0].disc[2], 625, 1e-9);
        CHECK_EQ_INT(h.node_count, n - 2);
        fl_hal2_free(&h);
        fl_polygon_free(&t.pg);
    }
}

static void test_hal2_bad_input_is_rejected(void)
{
    fl_error err;
    fl_hal2 h;
    double xy[6] = {0, 0, 1, 0, 0, 1};
    size_t rs[2] = {0, 2}, ps[2] = {0, 1};
    fl_polygon p = {2, xy, 1, rs, 1, ps};
    CHECK_STATUS(fl_hal2_build(&p, NULL, &h, &err), FL_ERR_INPUT, &err);
    rs[1] = 3;
    p.vertex_count = 3;
    xy[3] = NAN;
    CHECK_STATUS(fl_hal2_build(&p, NULL, &h, &err), FL_ERR_INPUT, &err);
    xy[3] = 0;
    rs[1] = 4;
    CHECK_STATUS(fl_hal2_build(&p, NULL, &h, &err), FL_ERR_INPUT, &err);
    rs[1] = 3;
    CHECK_STATUS(fl_hal2_build(NULL, NULL, &h, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_hal2_build(&p, NULL, &h, &err), FL_OK, &err);
    CHECK_EQ_INT(h.node_count, 1);
    fl_hal2_free(&h);
    fl_hal2_free(&h); /* freeing twice is a no-op */
}

FL_TEST_MAIN(FL_TEST_CASE(test_hal2_tree_infix_order_is_the_ring),
             FL_TEST_CASE(test_hal2_root_is_on_smallest_enclosing_disc),
             FL_TEST_CASE(test_hal2_flintstones_hold_their_polylines),
             FL_TEST_CASE(test_hal2_level_approximations_are_certified_and_end_at_original),
             FL_TEST_CASE(test_hal2_adaptive_approximation_meets_the_bound),
             FL_TEST_CASE(test_hal2_comb_and_collinear_runs_are_certified),
             FL_TEST_CASE(test_hal2_cocircular_root_is_a_diameter),
             FL_TEST_CASE(test_hal2_bad_input_is_rejected))
