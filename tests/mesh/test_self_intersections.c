/* Self-intersection counts of fl_mesh_check against brute force (every pair, same exact
 * pair test) and against the independent GMP oracle; the rules for triangles that share
 * vertices on hand-made configurations. */
#include "fl_test.h"
#include "gmp_oracle.h"
#include "mesh/mesh_internal.h"
#include "mesh_fixtures.h"

static size_t count_by_check(const fl_mesh *m)
{
    fl_mesh_report r;
    fl_error err;
    CHECK_STATUS(fl_mesh_check(m, NULL, &r, &err), FL_OK, &err);
    size_t n = r.self_intersections;
    fl_mesh_report_free(&r);
    return n;
}

/* All pairs of proper triangles, decided by the same pair test: checks the box tree misses
 * nothing. */
static size_t count_brute_force(const fl_mesh *m)
{
    size_t n = 0;
    for (uint32_t a = 0; a < m->triangle_count; a++) {
        if (fl_mesh_triangle_degenerate(m, a)) continue;
        for (uint32_t b = a + 1; b < m->triangle_count; b++)
            if (!fl_mesh_triangle_degenerate(m, b))
                n += (size_t)fl_mesh_triangles_intersect(m, a, b);
    }
    return n;
}

static const double *vx(const fl_mesh *m, uint32_t t, int k)
{
    return m->xyz + 3 * (size_t)m->tri[3 * (size_t)t + (size_t)k];
}

/* Oracle for pairs that share no vertex index (GMP, independent formulation). */
static size_t count_oracle_disjoint_pairs(const fl_mesh *m, uint32_t a0, uint32_t a1, uint32_t b0,
                                          uint32_t b1)
{
    size_t n = 0;
    for (uint32_t a = a0; a < a1; a++)
        for (uint32_t b = b0 > a + 1 ? b0 : a + 1; b < b1; b++) {
            const double *t1[3] = {vx(m, a, 0), vx(m, a, 1), vx(m, a, 2)};
            const double *t2[3] = {vx(m, b, 0), vx(m, b, 1), vx(m, b, 2)};
            n += (size_t)oracle_triangles(t1, t2);
        }
    return n;
}

static void test_interpenetrating_cubes_match_brute_force_and_oracle(void)
{
    fl_mesh m = fx_concat(fx_cube(0, 0, 0, 1), fx_cube(0.5, 0.25, 0.75, 1));
    size_t n = count_by_check(&m);
    CHECK(n > 0);
    CHECK_EQ_INT(n, count_brute_force(&m));
    /* pairs within one cube only share vertices and do not overlap: all come from across */
    CHECK_EQ_INT(n, count_oracle_disjoint_pairs(&m, 0, 12, 12, 24));
    fl_mesh_free(&m);
}

static void test_kept_pairs_are_the_intersecting_pairs(void)
{
    fl_mesh m = fx_concat(fx_cube(0, 0, 0, 1), fx_cube(0.5, 0.25, 0.75, 1));
    fl_mesh_pairs p;
    fl_error err;
    CHECK_STATUS(fl_mesh_self_intersections(&m, 3, NULL, NULL, &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.count, 3);
    CHECK_EQ_INT(p.total, count_by_check(&m));
    for (size_t i = 0; i < p.count; i++)
        CHECK(p.pairs[2 * i] < p.pairs[2 * i + 1] &&
              fl_mesh_triangles_intersect(&m, p.pairs[2 * i], p.pairs[2 * i + 1]));
    fl_mesh_pairs_free(&p);
    /* keep all: exactly the brute-force set, each pair once */
    CHECK_STATUS(fl_mesh_self_intersections(&m, (size_t)-1, NULL, NULL, &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.count, p.total);
    int seen[24][24] = {{0}};
    for (size_t i = 0; i < p.count; i++)
        seen[p.pairs[2 * i]][p.pairs[2 * i + 1]]++;
    int ok = 1;
    for (uint32_t a = 0; a < 24; a++)
        for (uint32_t b = a + 1; b < 24; b++)
            ok &= seen[a][b] == fl_mesh_triangles_intersect(&m, a, b);
    CHECK(ok);
    fl_mesh_pairs_free(&p);
    CHECK(p.pairs == NULL);
    m.tri[0] = 99;
    CHECK_STATUS(fl_mesh_self_intersections(&m, 3, NULL, NULL, &p, &err), FL_ERR_INPUT, &err);
    fl_mesh_free(&m);
}

static void test_random_soup_matches_oracle(void)
{
    unsigned long long rng = 11;
    for (int grid = 0; grid <= 4; grid += 4) {
        size_t nt = 120;
        fl_mesh m = fx_mesh_alloc(3 * nt, nt);
        for (size_t t = 0; t < nt; t++) {
            double c[3];
            for (int k = 0; k < 3; k++)
                c[k] = fl_test_rand01(&rng);
            for (int i = 0; i < 3; i++) {
                double *p = m.xyz + 9 * t + 3 * (size_t)i;
                do {
                    for (int k = 0; k < 3; k++)
                        p[k] = grid ? (double)(fl_test_rand_u64(&rng) % (unsigned)grid)
                                    : c[k] + 0.3 * (fl_test_rand01(&rng) - 0.5);
                } while (0);
                m.tri[3 * t + (size_t)i] = (uint32_t)(3 * t + (size_t)i);
            }
        }
        /* the oracle only judges proper triangles: drop the others by making them repeat */
        size_t proper = 0;
        for (size_t t = 0; t < nt; t++) {
            if (q_triangle_proper(m.xyz + 9 * t, m.xyz + 9 * t + 3, m.xyz + 9 * t + 6)) {
                proper++;
                continue;
            }
            m.tri[3 * t + 1] = m.tri[3 * t];
        }
        fl_mesh_report r;
        fl_error err;
        CHECK_STATUS(fl_mesh_check(&m, NULL, &r, &err), FL_OK, &err);
        CHECK_EQ_INT(r.degenerate_faces, nt - proper);
        size_t oracle = 0;
        for (uint32_t a = 0; a < nt; a++)
            for (uint32_t b = a + 1; b < nt; b++)
                if (m.tri[3 * a] != m.tri[3 * a + 1] && m.tri[3 * b] != m.tri[3 * b + 1])
                    oracle += count_oracle_disjoint_pairs(&m, a, a + 1, b, b + 1);
        CHECK_EQ_INT(r.self_intersections, oracle);
        CHECK(oracle > 10);
        fl_mesh_report_free(&r);
        fl_mesh_free(&m);
    }
}

static void test_linked_tori_match_brute_force(void)
{
    fl_mesh a = fx_torus(2, 0.5, 24, 10), b = fx_torus(2, 0.5, 24, 10);
    for (size_t i = 0; i < b.vertex_count; i++) { /* rotate into the xz plane, shift by R */
        double *p = b.xyz + 3 * i, y = p[1];
        p[1] = p[2], p[2] = y, p[0] += 2.0;
    }
    fl_mesh m = fx_concat(a, b);
    size_t n = count_by_check(&m);
    CHECK_EQ_INT(n, count_brute_force(&m));
    CHECK(n == 0); /* linked like a chain, the tubes do not touch */
    for (size_t i = m.vertex_count / 2; i < m.vertex_count; i++)
        m.xyz[3 * i] -= 1.3;
    n = count_by_check(&m);
    CHECK(n > 0);
    CHECK_EQ_INT(n, count_brute_force(&m));
    fl_mesh_free(&m);
}

static size_t pair_count(const double *xyz, size_t nv, const uint32_t *tri, size_t nt)
{
    fl_mesh m = fx_from_arrays(xyz, nv, tri, nt);
    size_t n = count_by_check(&m);
    CHECK_EQ_INT(n, count_brute_force(&m));
    fl_mesh_free(&m);
    return n;
}

static void test_shared_vertex_counts_only_beyond_it(void)
{
    /* v=0, a, b in the plane z = 0; other triangles through v */
    static const double xyz[] = {0,  0,  0,   2,  0,   0, 0, 2,
                                 0,  1,  0.5, -1, 0.5, 1, 1, /* 3,4: cd pierces vab */
                                 -1, -1, 1,   -1, -2,  1,    /* 5,6: touches only at v */
                                 3,  1,  0,   1,  3,   0,    /* 7,8: coplanar, ab crosses it */
                                 -1, 0,  0,   -1, -1,  0};   /* 9,10: coplanar, outside */
    CHECK_EQ_INT(pair_count(xyz, 11, (const uint32_t[]){0, 1, 2, 0, 3, 4}, 2), 1);
    CHECK_EQ_INT(pair_count(xyz, 11, (const uint32_t[]){0, 1, 2, 0, 5, 6}, 2), 0);
    CHECK_EQ_INT(pair_count(xyz, 11, (const uint32_t[]){0, 1, 2, 0, 7, 8}, 2), 1);
    CHECK_EQ_INT(pair_count(xyz, 11, (const uint32_t[]){0, 1, 2, 0, 9, 10}, 2), 0);
}

static void test_shared_edge_counts_only_coplanar_fold_over(void)
{
    static const double xyz[] = {0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0, 0.2, 3, 0, 0.5, 1, 1};
    const uint32_t flat[] = {0, 1, 2, 1, 0, 3}, fold[] = {0, 1, 2, 1, 0, 4},
                   bent[] = {0, 1, 2, 1, 0, 5}, twice[] = {0, 1, 2, 2, 1, 0};
    CHECK_EQ_INT(pair_count(xyz, 6, flat, 2), 0);
    CHECK_EQ_INT(pair_count(xyz, 6, fold, 2), 1);
    CHECK_EQ_INT(pair_count(xyz, 6, bent, 2), 0);
    CHECK_EQ_INT(pair_count(xyz, 6, twice, 2), 1); /* the same face twice */
}

/* Pairs sharing one vertex on a small grid: the count equals the oracle's "segment ab meets
 * vcd or segment cd meets vab" (see fl_triangles_meet_beyond_vertex for why). */
static void test_random_shared_vertex_pairs_match_oracle(void)
{
    unsigned long long rng = 21;
    int mismatches = 0, hits = 0;
    for (int n = 0; n < 3000; n++) {
        double xyz[15];
        for (int i = 0; i < 15; i++)
            xyz[i] = (double)(fl_test_rand_u64(&rng) % 3);
        if (!q_triangle_proper(xyz, xyz + 3, xyz + 6) || !q_triangle_proper(xyz, xyz + 9, xyz + 12))
            continue;
        fl_mesh m = fx_from_arrays(xyz, 5, (const uint32_t[]){0, 1, 2, 0, 3, 4}, 2);
        int o = oracle_segment_triangle(xyz + 3, xyz + 6, xyz, xyz + 9, xyz + 12) ||
                oracle_segment_triangle(xyz + 9, xyz + 12, xyz, xyz + 3, xyz + 6);
        mismatches += fl_mesh_triangles_intersect(&m, 0, 1) != o;
        hits += o;
        fl_mesh_free(&m);
    }
    CHECK_EQ_INT(mismatches, 0);
    CHECK(hits > 100);
}

static void test_closed_meshes_have_no_self_intersections(void)
{
    fl_mesh t = fx_torus(3, 1, 40, 20);
    CHECK_EQ_INT(count_by_check(&t), 0);
    fl_mesh_free(&t);
    fl_mesh c = fx_concat(fx_cube(0, 0, 0, 1), fx_cube(1, 0, 0, 1)); /* face to face */
    CHECK_EQ_INT(count_by_check(&c), count_brute_force(&c));
    CHECK(count_by_check(&c) > 0); /* the touching faces count: they share no vertex index */
    fl_mesh_free(&c);
}

/* The naive floating-point cross product (b - a) x (c - a) is the zero vector. */
static int naive_collinear(const double *a, const double *b, const double *c)
{
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    return u[1] * v[2] - u[2] * v[1] == 0 && u[2] * v[0] - u[0] * v[2] == 0 &&
           u[0] * v[1] - u[1] * v[0] == 0;
}

/* Degenerate faces: a repeated index, and points on the line through (0.1, 0.2, 0.3) where
 * floating point gets collinearity wrong both ways: {0.1, 0.2, 0.4}-multiples are exactly
 * collinear (powers of two) but their rounded cross product is not zero; with the
 * 0.5-multiple it is zero although the points are not collinear. Expected per the GMP normal. */
static void test_degenerate_faces_counted_exactly(void)
{
    static const double xyz[] = {0.1, 0.2, 0.3, 0.2, 0.4, 0.6, 0.4, 0.8, 1.2,
                                 0.3, 0.6, 0.9, 1,   1,   1,   0.5, 1.0, 1.5};
    static const uint32_t tri[] = {0, 1, 2, 0, 1, 3, 0, 0, 4, 0, 1, 4, 1, 2, 3, 0, 1, 5};
    CHECK(!naive_collinear(xyz, xyz + 3, xyz + 6) && !q_triangle_proper(xyz, xyz + 3, xyz + 6));
    CHECK(naive_collinear(xyz, xyz + 3, xyz + 15) && q_triangle_proper(xyz, xyz + 3, xyz + 15));
    fl_mesh m = fx_from_arrays(xyz, 6, tri, 6);
    size_t expect = 0;
    for (size_t t = 0; t < 6; t++) {
        const uint32_t *f = tri + 3 * t;
        expect += f[0] == f[1] || f[1] == f[2] || f[0] == f[2] ||
                  !q_triangle_proper(xyz + 3 * f[0], xyz + 3 * f[1], xyz + 3 * f[2]);
    }
    fl_mesh_report r;
    fl_error err;
    CHECK_STATUS(fl_mesh_check(&m, NULL, &r, &err), FL_OK, &err);
    CHECK_EQ_INT(r.degenerate_faces, expect);
    CHECK_EQ_INT(expect, 2);
    fl_mesh_report_free(&r);
    fl_mesh_free(&m);
}

FL_TEST_MAIN(FL_TEST_CASE(test_interpenetrating_cubes_match_brute_force_and_oracle),
             FL_TEST_CASE(test_kept_pairs_are_the_intersecting_pairs),
             FL_TEST_CASE(test_random_soup_matches_oracle),
             FL_TEST_CASE(test_linked_tori_match_brute_force),
             FL_TEST_CASE(test_shared_vertex_counts_only_beyond_it),
             FL_TEST_CASE(test_shared_edge_counts_only_coplanar_fold_over),
             FL_TEST_CASE(test_random_shared_vertex_pairs_match_oracle),
             FL_TEST_CASE(test_closed_meshes_have_no_self_intersections),
             FL_TEST_CASE(test_degenerate_faces_counted_exactly))
