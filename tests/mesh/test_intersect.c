/* The exact segment/triangle predicates of src/mesh/intersect.c against an independent GMP
 * oracle (tests/mesh/gmp_oracle.h), on random input and on grid input that is full of
 * touching, collinear and coplanar cases. */
#include "fl_test.h"
#include "gmp_oracle.h"
#include "mesh/intersect.h"

/* Random point: on a small integer grid (degenerate on purpose) or uniform in [0,1)^3. */
static void random_point(unsigned long long *rng, int grid, double *p, int dim)
{
    for (int k = 0; k < dim; k++)
        p[k] = grid ? (double)(fl_test_rand_u64(rng) % (unsigned)grid) : fl_test_rand01(rng);
}

static void random_triangle(unsigned long long *rng, int grid, double t[3][3])
{
    do {
        for (int i = 0; i < 3; i++)
            random_point(rng, grid, t[i], 3);
    } while (!q_triangle_proper(t[0], t[1], t[2]));
}

static void test_segments2_agree_with_rational_oracle(void)
{
    unsigned long long rng = 1;
    int mismatches = 0, hits = 0;
    for (int n = 0; n < 20000; n++) {
        double p[4][2];
        for (int i = 0; i < 4; i++)
            random_point(&rng, n % 2 ? 4 : 0, p[i], 2);
        int m = fl_segments_intersect2(p[0], p[1], p[2], p[3]);
        int o = oracle_segments2(p[0], p[1], p[2], p[3]);
        mismatches += m != o;
        hits += o;
    }
    CHECK_EQ_INT(mismatches, 0);
    CHECK(hits > 1000);
}

static void test_segment_triangle_agrees_with_rational_oracle(void)
{
    unsigned long long rng = 2;
    int mismatches = 0, hits = 0;
    for (int n = 0; n < 6000; n++) {
        int grid = n % 3 == 0 ? 0 : 3;
        double t[3][3], a[3], b[3];
        random_triangle(&rng, grid, t);
        random_point(&rng, grid, a, 3);
        random_point(&rng, grid, b, 3);
        if (n % 3 == 2) a[2] = b[2] = t[0][2] = t[1][2] = t[2][2] = 1.0; /* coplanar */
        if (n % 3 == 2 && !q_triangle_proper(t[0], t[1], t[2])) continue;
        int m = fl_segment_triangle_intersect(a, b, t[0], t[1], t[2]);
        int o = oracle_segment_triangle(a, b, t[0], t[1], t[2]);
        mismatches += m != o;
        hits += o;
    }
    CHECK_EQ_INT(mismatches, 0);
    CHECK(hits > 500);
}

/* fl_triangles_intersect against the oracle, also under all vertex rotations, reversal and
 * swapping the triangles (the answer must not depend on the order). */
static int tri_tri_mismatches(unsigned long long seed, int grid, int coplanar, int count, int *hits)
{
    unsigned long long rng = seed;
    int mismatches = 0;
    for (int n = 0; n < count; n++) {
        double t1[3][3], t2[3][3];
        random_triangle(&rng, grid, t1);
        random_triangle(&rng, grid, t2);
        if (coplanar) {
            for (int i = 0; i < 3; i++)
                t1[i][2] = t2[i][2] = 0.5;
            if (!q_triangle_proper(t1[0], t1[1], t1[2]) || !q_triangle_proper(t2[0], t2[1], t2[2]))
                continue;
        }
        const double *a[3] = {t1[0], t1[1], t1[2]}, *b[3] = {t2[0], t2[1], t2[2]};
        int o = oracle_triangles(a, b);
        *hits += o;
        for (int rot = 0; rot < 6; rot++) {
            int r = rot % 3, rev = rot >= 3;
            const double *p = a[r], *q = a[(r + (rev ? 2 : 1)) % 3],
                         *s = a[(r + (rev ? 1 : 2)) % 3];
            mismatches += fl_triangles_intersect(p, q, s, b[0], b[1], b[2]) != o;
            mismatches +=
                fl_triangles_intersect(b[r], b[(r + 1) % 3], b[(r + 2) % 3], s, q, p) != o;
        }
    }
    return mismatches;
}

static void test_triangles_random_in_unit_cube_agree_with_oracle(void)
{
    int hits = 0;
    CHECK_EQ_INT(tri_tri_mismatches(3, 0, 0, 1500, &hits), 0);
    CHECK(hits > 100);
}

static void test_triangles_on_integer_grid_agree_with_oracle(void)
{
    int hits = 0;
    CHECK_EQ_INT(tri_tri_mismatches(4, 3, 0, 3000, &hits), 0);
    CHECK(hits > 1000);
}

static void test_coplanar_triangles_agree_with_oracle(void)
{
    int hits = 0;
    CHECK_EQ_INT(tri_tri_mismatches(5, 4, 1, 1500, &hits), 0);
    CHECK_EQ_INT(tri_tri_mismatches(6, 0, 1, 500, &hits), 0);
    CHECK(hits > 300);
}

/* Touching configurations decided exactly: a vertex on a face, an edge on an edge, and the
 * same configurations moved off by one unit in the last place. */
static void test_touching_triangles_count_and_near_misses_do_not(void)
{
    double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0};
    double p[3] = {0.25, 0.25, 0}, q[3] = {0.25, 0.25, 1}, r[3] = {1, 1, 1};
    CHECK(fl_triangles_intersect(a, b, c, p, q, r)); /* p lies in abc */
    p[2] = 0x1p-1074;                                /* lifted by the smallest positive double */
    CHECK(!fl_triangles_intersect(a, b, c, p, q, r));
    double e[3] = {0.5, 0.5, -1}, f[3] = {0.5, 0.5, 1}, g[3] = {2, 2, 0};
    CHECK(fl_triangles_intersect(a, b, c, e, f, g)); /* edge ef crosses edge bc at (.5,.5,0) */
    e[0] = f[0] = nextafter(0.5, 1.0);
    CHECK(!fl_triangles_intersect(a, b, c, e, f, g));
    CHECK(oracle_triangles((const double *const[]){a, b, c}, (const double *const[]){e, f, g}) ==
          0);
}

static void test_degenerate_triangle_is_decided_exactly(void)
{
    double a[3] = {0.1, 0.2, 0.3}, b[3] = {0.2, 0.4, 0.6}, c[3] = {0.4, 0.8, 1.2};
    /* b = 2a and c = 4a exactly (scaling by a power of two): collinear */
    CHECK(fl_triangle_degenerate(a, b, c));
    double d[3] = {0.3, 0.6, 0.9}; /* 0.3 is not 3 * 0.1 in binary: not collinear */
    CHECK_EQ_INT(fl_triangle_degenerate(a, b, d), !q_triangle_proper(a, b, d));
    CHECK(!fl_triangle_degenerate(a, b, d));
    CHECK(fl_triangle_degenerate(a, a, d));
}

FL_TEST_MAIN(FL_TEST_CASE(test_segments2_agree_with_rational_oracle),
             FL_TEST_CASE(test_segment_triangle_agrees_with_rational_oracle),
             FL_TEST_CASE(test_triangles_random_in_unit_cube_agree_with_oracle),
             FL_TEST_CASE(test_triangles_on_integer_grid_agree_with_oracle),
             FL_TEST_CASE(test_coplanar_triangles_agree_with_oracle),
             FL_TEST_CASE(test_touching_triangles_count_and_near_misses_do_not),
             FL_TEST_CASE(test_degenerate_triangle_is_decided_exactly))
