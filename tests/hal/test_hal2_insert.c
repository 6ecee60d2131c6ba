/* Dynamic insertion (thesis §7.5): after every insertion the repaired forest must be a valid
 * flintstone forest of the new polygon — infix order, Def. 7.3 flintstones checked exactly,
 * discs holding their polylines — and its queries must equal brute force on the new polygon. */
#include "hal2_oracle.h"

/* Every node: the polyline v_p..v_s lies in the circles through v_p, v_s and v_q (and v_r),
 * inside the stored discs, and the children partition it; every vertex is used once. */
static void check_forest(const fl_hal2 *h)
{
    const fl_polygon *pg = &h->polygon;
    int *seen = calloc(pg->vertex_count, sizeof(int));
    size_t expect = 0;
    for (size_t r = 0; r < pg->ring_count; r++) {
        const fl_hal2_ring *rg = &h->rings[r];
        CHECK(rg->first == pg->ring_start[r] && rg->count == pg->ring_start[r + 1] - rg->first);
        expect += rg->count - 2;
        seen[rg->root[0]]++;
        seen[rg->root[1]]++;
    }
    CHECK_EQ_INT(h->node_count, expect);
    for (size_t k = 0; k < h->node_count; k++) {
        const fl_hal2_node *nd = &h->nodes[k];
        seen[nd->q]++;
        CHECK(nd->kind != FL_HAL2_DISC);
        const double *a = pg->xy + 2 * nd->p, *b = pg->xy + 2 * nd->s;
        size_t v = nd->p;
        for (uint32_t e = 0; e <= nd->edges; e++) {
            const double *x = pg->xy + 2 * v;
            if (nd->kind != FL_HAL2_SEGMENT) {
                const double *q = pg->xy + 2 * nd->q, *r = pg->xy + 2 * nd->r;
                CHECK(fl_incircle(a, b, q, x) * fl_orient2d(a, b, q) >= 0);
                CHECK(fl_incircle(a, b, r, x) * fl_orient2d(a, b, r) >= 0);
            }
            double d2 = pow(x[0] - nd->disc[0][0], 2) + pow(x[1] - nd->disc[0][1], 2);
            CHECK(d2 <= nd->disc[0][2] * (1 + 1e-14));
            v = ring_next(pg, v);
        }
        CHECK(v == ring_next(pg, nd->s));
    }
    for (size_t v = 0; v < pg->vertex_count; v++)
        CHECK_EQ_INT(seen[v], 1);
    free(seen);
}

static void check_queries_and_certificate(const fl_hal2 *h, unsigned long long *rng)
{
    const fl_polygon *pg = &h->polygon;
    size_t n = 300 + pg->vertex_count;
    double *q = malloc(2 * n * sizeof(double));
    uint8_t *where = malloc(n);
    for (size_t k = 0; k < 600; k++)
        q[k] = -25 + 50 * fl_test_rand01(rng);
    memcpy(q + 600, pg->xy, 2 * pg->vertex_count * sizeof(double));
    fl_error err;
    CHECK_STATUS(fl_hal2_contains(h, q, n, where, &err), FL_OK, &err);
    size_t bad = 0;
    for (size_t k = 0; k < n; k++)
        bad += where[k] != oracle_where(pg, q + 2 * k);
    CHECK_EQ_INT(bad, 0);
    fl_polygon ap;
    double e;
    CHECK_STATUS(fl_hal2_approximate_level(h, 3, &ap, &e, &err), FL_OK, &err);
    CHECK(oracle_deviation(pg, &ap) <= e);
    fl_polygon_free(&ap);
    free(q);
    free(where);
}

static void test_hal2_insertion_keeps_a_valid_forest(void)
{
    unsigned long long rng = 42;
    double xy[2 * 40];
    test_poly t;
    tp_init(&t);
    star_ring(xy, 40, 0, 0, 10, &rng);
    tp_add_ring(&t, xy, 40, 0);
    star_ring(xy, 12, 1, 0, 2, &rng);
    tp_add_ring(&t, xy, 12, 1);
    fl_hal2 h;
    fl_error err;
    CHECK_STATUS(fl_hal2_build(&t.pg, NULL, &h, &err), FL_OK, &err);
    for (int step = 0; step < 150; step++) {
        size_t nv = h.polygon.vertex_count;
        uint32_t after = (uint32_t)(fl_test_rand_u64(&rng) % nv);
        const double *a = h.polygon.xy + 2 * after;
        const double *b = h.polygon.xy + 2 * ring_next(&h.polygon, after);
        /* near the edge, pushed in or out; every 25th step far outside (a new root) */
        double f = step % 25 == 24 ? 3.0 : 0.8 + 0.4 * fl_test_rand01(&rng);
        double x[2] = {f * (a[0] + b[0]) / 2, f * (a[1] + b[1]) / 2};
        double expect_x = x[0], expect_y = x[1];
        CHECK_STATUS(fl_hal2_insert(&h, after, x, &err), FL_OK, &err);
        CHECK_EQ_INT(h.polygon.vertex_count, nv + 1);
        CHECK(h.polygon.xy[2 * (after + 1)] == expect_x &&
              h.polygon.xy[2 * (after + 1) + 1] == expect_y);
        check_forest(&h);
        if (step % 10 == 0) check_queries_and_certificate(&h, &rng);
    }
    double bad[2] = {NAN, 0};
    CHECK_STATUS(fl_hal2_insert(&h, 0, bad, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_hal2_insert(&h, (uint32_t)h.polygon.vertex_count, bad, &err), FL_ERR_USAGE,
                 &err);
    fl_hal2_free(&h);
    fl_polygon_free(&t.pg);
}

/* Inserting collinear points into a collinear run keeps segment flintstones valid. */
static void test_hal2_insertion_into_collinear_run(void)
{
    double sq[] = {0, 0, 8, 0, 8, 8, 0, 8};
    test_poly t;
    tp_init(&t);
    tp_add_ring(&t, sq, 4, 0);
    fl_hal2 h;
    fl_error err;
    CHECK_STATUS(fl_hal2_build(&t.pg, NULL, &h, &err), FL_OK, &err);
    for (int k = 1; k < 8; k++) { /* vertices (k, 0) along the bottom edge, in order */
        double x[2] = {k, 0};
        CHECK_STATUS(fl_hal2_insert(&h, (uint32_t)(k - 1), x, &err), FL_OK, &err);
        check_forest(&h);
    }
    unsigned long long rng = 3;
    check_queries_and_certificate(&h, &rng);
    fl_hal2_free(&h);
    fl_polygon_free(&t.pg);
}

FL_TEST_MAIN(FL_TEST_CASE(test_hal2_insertion_keeps_a_valid_forest),
             FL_TEST_CASE(test_hal2_insertion_into_collinear_run))
