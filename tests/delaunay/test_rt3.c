/* Regular (weighted Delaunay) triangulation: validity, the power criterion against brute force,
 * hidden balls against an independent location, and agreement with the Delaunay triangulation
 * when all weights are equal. */
#include <string.h>

#include "dt3_check.h"
#include "fl_test.h"

static double *random_balls(size_t n, unsigned long long seed, double wmax)
{
    double *p = malloc(4 * n * sizeof *p);
    for (size_t i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++)
            p[4 * i + k] = 2.0 * fl_test_rand01(&seed) - 1.0;
        p[4 * i + 3] = wmax * fl_test_rand01(&seed);
    }
    return p;
}

static void build_ok(const double *p, size_t n, fl_rt3 *rt)
{
    fl_error err;
    CHECK_STATUS(fl_rt3_build(p, n, NULL, rt, &err), FL_OK, &err);
    CHECK_STATUS(fl_rt3_verify(p, rt, &err), FL_OK, &err);
    for (size_t t = 0; t < rt->tet_count; t++) {
        const uint32_t *q = rt->tet + 4 * t;
        CHECK(fl_orient3d(p + 4 * q[0], p + 4 * q[1], p + 4 * q[2], p + 4 * q[3]) > 0);
    }
}

/* Brute force: the tetrahedron containing the centre of ball h (exact orientations over all
 * tetrahedra), or SIZE_MAX. */
static size_t containing_tet(const double *p, const fl_rt3 *rt, uint32_t h)
{
    for (size_t t = 0; t < rt->tet_count; t++) {
        const uint32_t *q = rt->tet + 4 * t;
        int k = 0;
        for (; k < 4; k++) {
            const double *c[4] = {p + 4 * q[0], p + 4 * q[1], p + 4 * q[2], p + 4 * q[3]};
            c[k] = p + 4 * (size_t)h;
            if (fl_orient3d(c[0], c[1], c[2], c[3]) < 0) break;
        }
        if (k == 4) return t;
    }
    return SIZE_MAX;
}

/* No ball, hidden or not, is below the lifted hyperplane of any tetrahedron; every hidden ball is
 * above the lifted tetrahedron over its centre (strictly unless ties are possible: a lifted point
 * exactly on the lower hull may be left out, as the perturbation decides); vertices + hidden +
 * duplicates = n. */
static void check_against_brute_force(const double *p, size_t n, const fl_rt3 *rt, int strict)
{
    CHECK_EQ_INT(dt3c_empty_sphere_violations(p, 4, n, rt->tet, rt->tet_count, 1), 0);
    for (size_t i = 0; i < rt->hidden_count; i++) {
        uint32_t h = rt->hidden[i];
        size_t t = containing_tet(p, rt, h);
        CHECK(t != SIZE_MAX);
        if (t == SIZE_MAX) continue;
        const uint32_t *q = rt->tet + 4 * t;
        CHECK(fl_insphere_weighted(p + 4 * q[0], p + 4 * q[1], p + 4 * q[2], p + 4 * q[3],
                                   p + 4 * (size_t)h) < (strict ? 0 : 1));
    }
    size_t dups = 0;
    for (size_t i = 0; i < n; i++)
        dups += rt->duplicate_of[i] != i;
    CHECK_EQ_INT(rt->vertex_count + rt->hidden_count + dups, n);
}

static void test_rt3_power_criterion_and_hidden_balls_by_brute_force(void)
{
    const double wmax[] = {0.001, 0.05, 0.5};
    for (int trial = 0; trial < 3; trial++) {
        size_t n = 400;
        double *p = random_balls(n, 21 + (unsigned long long)trial, wmax[trial]);
        fl_rt3 rt;
        build_ok(p, n, &rt);
        check_against_brute_force(p, n, &rt, 1);
        if (trial == 2) /* heavy balls among light ones: many are hidden */
            CHECK(rt.hidden_count > 20);
        fl_rt3_free(&rt);
        free(p);
    }
}

/* Light balls inserted first and then hidden by heavy ones exercise the removal of existing
 * vertices: the light balls come from a fine grid, the heavy ones sit between them. */
static void test_rt3_later_balls_hide_earlier_vertices(void)
{
    size_t n = 0;
    double *p = malloc(4 * 600 * sizeof *p);
    for (int i = 0; i < 8; i++)
        for (int j = 0; j < 8; j++)
            for (int k = 0; k < 8; k++, n++) {
                double *q = p + 4 * n;
                q[0] = i;
                q[1] = j;
                q[2] = k;
                q[3] = 0;
            }
    unsigned long long seed = 5;
    for (int h = 0; h < 40; h++, n++) {
        double *q = p + 4 * n;
        for (int k = 0; k < 3; k++)
            q[k] = 1.0 + 5.0 * fl_test_rand01(&seed);
        q[3] = 1.5 + fl_test_rand01(&seed);
    }
    fl_rt3 rt;
    build_ok(p, n, &rt);
    check_against_brute_force(p, n, &rt, 1);
    size_t grid_hidden = 0;
    for (size_t i = 0; i < rt.hidden_count; i++)
        grid_hidden += rt.hidden[i] < 512;
    CHECK(grid_hidden > 10);
    fl_rt3_free(&rt);
    free(p);
}

static void sorted_tets(const uint32_t *tet, size_t nt, uint32_t *out)
{
    for (size_t t = 0; t < nt; t++) {
        uint32_t *q = out + 4 * t;
        memcpy(q, tet + 4 * t, 4 * sizeof *q);
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 3 - i; j++)
                if (q[j] > q[j + 1]) {
                    uint32_t x = q[j];
                    q[j] = q[j + 1];
                    q[j + 1] = x;
                }
    }
}

static int cmp_quad(const void *a, const void *b)
{
    return memcmp(a, b, 4 * sizeof(uint32_t));
}

/* With equal weights the power test is the in-sphere test. The perturbation is the same, so even
 * on the degenerate grid the two triangulations are the same set of tetrahedra. */
static void test_rt3_equal_weights_give_the_delaunay_triangulation(void)
{
    for (int trial = 0; trial < 2; trial++) {
        size_t n = trial == 0 ? 300 : 125;
        double *p = random_balls(n, 77, 0), *xyz = malloc(3 * n * sizeof *xyz);
        for (size_t i = 0; i < n; i++) {
            if (trial == 1) {
                p[4 * i] = (double)(i % 5);
                p[4 * i + 1] = (double)(i / 5 % 5);
                p[4 * i + 2] = (double)(i / 25);
            }
            p[4 * i + 3] = trial == 0 ? 0.0 : 2.5; /* zero weights, then another constant */
            memcpy(xyz + 3 * i, p + 4 * i, 3 * sizeof *xyz);
        }
        fl_rt3 rt;
        fl_dt3 dt;
        fl_error err;
        build_ok(p, n, &rt);
        CHECK_STATUS(fl_dt3_build(xyz, n, NULL, &dt, &err), FL_OK, &err);
        CHECK_EQ_INT(rt.hidden_count, 0);
        CHECK_EQ_INT(rt.tet_count, dt.tet_count);
        if (rt.tet_count == dt.tet_count) {
            uint32_t *a = malloc(4 * rt.tet_count * sizeof *a),
                     *b = malloc(4 * dt.tet_count * sizeof *b);
            sorted_tets(rt.tet, rt.tet_count, a);
            sorted_tets(dt.tet, dt.tet_count, b);
            qsort(a, rt.tet_count, 4 * sizeof *a, cmp_quad);
            qsort(b, dt.tet_count, 4 * sizeof *b, cmp_quad);
            CHECK(memcmp(a, b, 4 * rt.tet_count * sizeof *a) == 0);
            free(a);
            free(b);
        }
        fl_rt3_free(&rt);
        fl_dt3_free(&dt);
        free(p);
        free(xyz);
    }
}

static void test_rt3_coincident_centres(void)
{
    size_t n = 100;
    double *p = random_balls(n, 3, 0.01);
    memcpy(p + 4 * 50, p + 4 * 10, 4 * sizeof *p); /* the same ball twice: a duplicate */
    memcpy(p + 4 * 60, p + 4 * 11, 3 * sizeof *p); /* a heavier ball at ball 11's centre */
    p[4 * 60 + 3] = p[4 * 11 + 3] + 0.001;
    fl_rt3 rt;
    build_ok(p, n, &rt);
    check_against_brute_force(p, n, &rt, 1);
    CHECK(rt.duplicate_of[50] == 10 || rt.duplicate_of[10] == 50);
    int hidden11 = 0;
    for (size_t i = 0; i < rt.hidden_count; i++)
        hidden11 |= rt.hidden[i] == 11;
    CHECK(hidden11);
    fl_rt3_free(&rt);
    free(p);
}

static void test_rt3_orthogonal_balls(void)
{
    size_t n = 300;
    double *p = random_balls(n, 8, 0.05);
    fl_rt3_options opt = {0};
    opt.want_ortho = 1;
    fl_rt3 rt;
    fl_error err;
    CHECK_STATUS(fl_rt3_build(p, n, &opt, &rt, &err), FL_OK, &err);
    for (size_t t = 0; t < rt.tet_count; t++) {
        const double *o = rt.ortho + 4 * t;
        for (int k = 0; k < 4; k++) {
            const double *b = p + 4 * rt.tet[4 * t + k];
            double d2 = (b[0] - o[0]) * (b[0] - o[0]) + (b[1] - o[1]) * (b[1] - o[1]) +
                        (b[2] - o[2]) * (b[2] - o[2]);
            /* orthogonal: |z_b - z_o|^2 = w_b + w_o (skin paper §2.1) */
            CHECK_NEAR(d2, b[3] + o[3], 1e-7 * (d2 + fabs(b[3]) + fabs(o[3])));
        }
    }
    fl_rt3_free(&rt);
    free(p);
}

static void test_rt3_bad_input(void)
{
    fl_rt3 rt;
    fl_error err;
    double p[16] = {0, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, INFINITY};
    CHECK_STATUS(fl_rt3_build(p, 4, NULL, &rt, &err), FL_ERR_INPUT, &err);
    CHECK(strstr(err.message, "weight") != NULL);
    p[15] = 1;
    p[12] = p[13] = 1; /* (1,1,0): all four in the plane z = 0 */
    p[14] = 0;
    CHECK_STATUS(fl_rt3_build(p, 4, NULL, &rt, &err), FL_ERR_ALGORITHM, &err);
    CHECK(strstr(err.message, "coplanar") != NULL);
    CHECK(rt.tet == NULL);
}

/* Balls on a 5x5x5 grid with weights 0 or 1: many lifted points are coplanar, so ties in the
 * power test are everywhere; the result must still satisfy the exact power criterion. */
static void test_rt3_power_criterion_on_grid_with_integer_weights(void)
{
    size_t n = 125;
    double *p = malloc(4 * n * sizeof *p);
    unsigned long long seed = 99;
    for (size_t i = 0; i < n; i++) {
        p[4 * i] = (double)(i % 5);
        p[4 * i + 1] = (double)(i / 5 % 5);
        p[4 * i + 2] = (double)(i / 25);
        p[4 * i + 3] = (double)(fl_test_rand_u64(&seed) & 1);
    }
    fl_rt3 rt;
    build_ok(p, n, &rt);
    check_against_brute_force(p, n, &rt, 0);
    CHECK(rt.hidden_count > 0);
    fl_rt3_free(&rt);
    free(p);
}

/* Many small random subsets of the 3x3x3 grid with weights 0, 1 or 2 (repeated centres included):
 * either a correct regular triangulation or a clean error. */
static void test_rt3_random_subsets_of_a_small_grid(void)
{
    unsigned long long seed = 77;
    double p[4 * 30];
    for (int trial = 0; trial < 300; trial++) {
        size_t n = 4 + (size_t)(fl_test_rand_u64(&seed) % 27);
        for (size_t i = 0; i < 4 * n; i++)
            p[i] = (double)(fl_test_rand_u64(&seed) % 3);
        fl_rt3 rt;
        fl_error err;
        fl_status st = fl_rt3_build(p, n, NULL, &rt, &err);
        if (st == FL_OK) {
            CHECK_STATUS(fl_rt3_verify(p, &rt, &err), FL_OK, &err);
            check_against_brute_force(p, n, &rt, 0);
        } else {
            CHECK_MSG(st == FL_ERR_ALGORITHM || st == FL_ERR_INPUT, "trial %d: %s", trial,
                      err.message);
        }
        fl_rt3_free(&rt);
    }
}

FL_TEST_MAIN(FL_TEST_CASE(test_rt3_power_criterion_and_hidden_balls_by_brute_force),
             FL_TEST_CASE(test_rt3_later_balls_hide_earlier_vertices),
             FL_TEST_CASE(test_rt3_equal_weights_give_the_delaunay_triangulation),
             FL_TEST_CASE(test_rt3_coincident_centres), FL_TEST_CASE(test_rt3_orthogonal_balls),
             FL_TEST_CASE(test_rt3_bad_input),
             FL_TEST_CASE(test_rt3_power_criterion_on_grid_with_integer_weights),
             FL_TEST_CASE(test_rt3_random_subsets_of_a_small_grid))
