/* 3D Delaunay triangulation: validity on random and degenerate input, checked by
 * fl_dt3_verify and by independent brute force (exact empty sphere, hull, volume, Euler). */
#include <string.h>

#include "dt3_check.h"
#include "fl_test.h"

static double *random_points(size_t n, unsigned long long seed, int shape)
{
    double *p = malloc(3 * n * sizeof *p);
    for (size_t i = 0; i < n; i++) {
        double *q = p + 3 * i;
        do {
            for (int k = 0; k < 3; k++)
                q[k] = 2.0 * fl_test_rand01(&seed) - 1.0;
        } while (shape == 1 && q[0] * q[0] + q[1] * q[1] + q[2] * q[2] > 1.0);
        if (shape == 2) { /* Gaussian clusters around 8 centres */
            double g[3];
            for (int k = 0; k < 3; k++) {
                double u = fl_test_rand01(&seed) + 1e-300, v = fl_test_rand01(&seed);
                g[k] = sqrt(-2.0 * log(u)) * cos(6.283185307179586 * v);
            }
            for (int k = 0; k < 3; k++)
                q[k] = (double)((i >> k) & 1) * 10.0 + 0.3 * g[k];
        }
    }
    return p;
}

static double *grid_points(int a, int b, int c, size_t *n)
{
    *n = (size_t)a * b * c;
    double *p = malloc(3 * *n * sizeof *p), *q = p;
    for (int i = 0; i < a; i++)
        for (int j = 0; j < b; j++)
            for (int k = 0; k < c; k++, q += 3) {
                q[0] = i;
                q[1] = j;
                q[2] = k;
            }
    return p;
}

static double total_volume(const double *p, const fl_dt3 *dt)
{
    double v = 0;
    for (size_t t = 0; t < dt->tet_count; t++) {
        const uint32_t *q = dt->tet + 4 * t;
        v += dt3c_volume(p + 3 * q[0], p + 3 * q[1], p + 3 * q[2], p + 3 * q[3]);
    }
    return v;
}

/* Volume enclosed by the hull faces (divergence theorem): with the faces counterclockwise from
 * outside, the cone from the origin over each face is positively oriented when the origin is
 * behind the face. */
static double hull_volume(const double *p, const fl_dt3 *dt)
{
    static const double origin[3] = {0, 0, 0};
    double v = 0;
    for (size_t h = 0; h < dt->hull_face_count; h++) {
        const uint32_t *f = dt->hull_faces + 3 * h;
        v += dt3c_volume(p + 3 * f[0], p + 3 * f[1], p + 3 * f[2], origin);
    }
    return v;
}

static void check_valid(const double *p, size_t n, const fl_dt3 *dt)
{
    fl_error err;
    CHECK_STATUS(fl_dt3_verify(p, dt, &err), FL_OK, &err);
    CHECK_EQ_INT(dt->point_count, n);
    double tv = total_volume(p, dt), hv = hull_volume(p, dt);
    CHECK_NEAR(tv, hv, 1e-9 * (fabs(hv) + 1));
    for (size_t t = 0; t < dt->tet_count; t++) {
        const uint32_t *q = dt->tet + 4 * t;
        CHECK(fl_orient3d(p + 3 * q[0], p + 3 * q[1], p + 3 * q[2], p + 3 * q[3]) > 0);
    }
}

static void build_ok(const double *p, size_t n, fl_dt3 *dt)
{
    fl_error err;
    CHECK_STATUS(fl_dt3_build(p, n, NULL, dt, &err), FL_OK, &err);
    check_valid(p, n, dt);
}

static void test_dt3_valid_and_empty_spheres_on_random_shapes(void)
{
    for (int shape = 0; shape < 3; shape++) {
        size_t n = 400;
        double *p = random_points(n, 11 + (unsigned long long)shape, shape);
        fl_dt3 dt;
        build_ok(p, n, &dt);
        CHECK_EQ_INT(dt.unique_count, n);
        CHECK_EQ_INT(dt3c_empty_sphere_violations(p, 3, n, dt.tet, dt.tet_count, 0), 0);
        fl_dt3_free(&dt);
        free(p);
    }
}

static void test_dt3_valid_on_ten_thousand_points(void)
{
    for (int shape = 0; shape < 3; shape++) {
        size_t n = 10000;
        double *p = random_points(n, 5 + (unsigned long long)shape, shape);
        fl_dt3 dt;
        build_ok(p, n, &dt);
        /* Random points in general position: about 6.5 tetrahedra a point (Dwyer). */
        CHECK(dt.tet_count > 6 * n && dt.tet_count < 7 * n);
        fl_dt3_free(&dt);
        free(p);
    }
}

static void test_dt3_empty_sphere_on_integer_grid(void)
{
    size_t n;
    double *p = grid_points(6, 5, 4, &n);
    fl_dt3 dt;
    build_ok(p, n, &dt);
    CHECK_EQ_INT(dt3c_empty_sphere_violations(p, 3, n, dt.tet, dt.tet_count, 0), 0);
    CHECK_NEAR(total_volume(p, &dt), 5.0 * 4.0 * 3.0, 1e-9);
    fl_dt3_free(&dt);
    free(p);

    p = grid_points(10, 10, 10, &n);
    build_ok(p, n, &dt);
    CHECK_NEAR(total_volume(p, &dt), 729.0, 1e-9);
    /* Each of the 6 square facets (81 unit squares) is split into 2 triangles a square. */
    CHECK_EQ_INT(dt.hull_face_count, 6 * 81 * 2);
    fl_dt3_free(&dt);
    free(p);
}

/* All integer points on the sphere x^2 + y^2 + z^2 = 15^2: every tetrahedron is cospherical. */
static void test_dt3_cospherical_integer_points(void)
{
    size_t n = 0;
    double *p = malloc(3 * 4000 * sizeof *p);
    for (int x = -15; x <= 15; x++)
        for (int y = -15; y <= 15; y++)
            for (int z = -15; z <= 15; z++)
                if (x * x + y * y + z * z == 225) {
                    p[3 * n] = x;
                    p[3 * n + 1] = y;
                    p[3 * n + 2] = z;
                    n++;
                }
    CHECK_EQ_INT(n, 150); /* r_3(225) */
    fl_dt3 dt;
    build_ok(p, n, &dt);
    CHECK_EQ_INT(dt.unique_count, n);
    CHECK_EQ_INT(dt3c_empty_sphere_violations(p, 3, n, dt.tet, dt.tet_count, 0), 0);
    /* Every point is on the hull, and the hull is a triangulated sphere: F = 2V - 4. */
    CHECK_EQ_INT(dt.hull_face_count, 2 * n - 4);
    fl_dt3_free(&dt);
    free(p);
}

/* Triangles ijk with every other point strictly on one side (O(n^4)); each must be one of dt's
 * hull faces. Returns how many there are. */
static size_t brute_force_hull_faces(const double *p, size_t n, const fl_dt3 *dt)
{
    size_t count = 0;
    for (uint32_t i = 0; i < n; i++)
        for (uint32_t j = i + 1; j < n; j++)
            for (uint32_t k = j + 1; k < n; k++) {
                int pos = 0, neg = 0;
                for (size_t l = 0; l < n; l++) {
                    int s = fl_orient3d(p + 3 * i, p + 3 * j, p + 3 * k, p + 3 * l);
                    pos += s > 0;
                    neg += s < 0;
                }
                if ((size_t)(pos + neg) != n - 3 || (pos && neg)) continue;
                count++;
                int found = 0;
                for (size_t h = 0; h < dt->hull_face_count; h++) {
                    const uint32_t *f = dt->hull_faces + 3 * h;
                    int m = (f[0] == i || f[1] == i || f[2] == i) +
                            (f[0] == j || f[1] == j || f[2] == j) +
                            (f[0] == k || f[1] == k || f[2] == k);
                    found |= m == 3;
                }
                CHECK_MSG(found, "brute-force hull triangle %u %u %u is missing", i, j, k);
            }
    return count;
}

/* The vertices of the hull faces are exactly the points on the hull boundary (brute force), and
 * every hull face supports the point set. Random and grid (coplanar facets) sets. */
static void test_dt3_hull_matches_brute_force(void)
{
    for (int trial = 0; trial < 3; trial++) {
        size_t n = 28;
        double *p = trial < 2 ? random_points(n, 100 + (unsigned long long)trial, trial)
                              : grid_points(3, 3, 3, &n);
        fl_dt3 dt;
        build_ok(p, n, &dt);
        char *on = calloc(n, 1);
        for (size_t h = 0; h < dt.hull_face_count; h++) {
            const uint32_t *f = dt.hull_faces + 3 * h;
            for (size_t i = 0; i < n; i++)
                CHECK(fl_orient3d(p + 3 * f[0], p + 3 * f[1], p + 3 * f[2], p + 3 * i) >= 0);
            on[f[0]] = on[f[1]] = on[f[2]] = 1;
        }
        for (size_t i = 0; i < n; i++)
            CHECK_EQ_INT(on[i], dt3c_on_hull(p, 3, n, i));
        if (trial < 2) /* general position: the hull triangles themselves are unique */
            CHECK_EQ_INT(dt.hull_face_count, brute_force_hull_faces(p, n, &dt));
        free(on);
        fl_dt3_free(&dt);
        free(p);
    }
}

/* V - E + F - T = 1, counted here with a quadratic edge search on a small set. */
static void test_dt3_euler_relation_of_the_ball(void)
{
    size_t n;
    double *p = grid_points(4, 3, 3, &n);
    fl_dt3 dt;
    build_ok(p, n, &dt);
    size_t ne = 0, cap = 6 * dt.tet_count;
    uint32_t(*e)[2] = malloc(cap * sizeof *e);
    for (size_t t = 0; t < dt.tet_count; t++)
        for (int i = 0; i < 4; i++)
            for (int j = i + 1; j < 4; j++) {
                uint32_t a = dt.tet[4 * t + i], b = dt.tet[4 * t + j], lo = a < b ? a : b,
                         hi = a < b ? b : a;
                size_t k = 0;
                while (k < ne && !(e[k][0] == lo && e[k][1] == hi))
                    k++;
                if (k == ne) {
                    e[ne][0] = lo;
                    e[ne][1] = hi;
                    ne++;
                }
            }
    size_t faces = (4 * dt.tet_count + dt.hull_face_count) / 2;
    CHECK_EQ_INT((long long)n - (long long)ne + (long long)faces - (long long)dt.tet_count, 1);
    free(e);
    fl_dt3_free(&dt);
    free(p);
}

static void test_dt3_four_and_five_points(void)
{
    const double p[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
    fl_dt3 dt;
    build_ok(p, 4, &dt);
    CHECK_EQ_INT(dt.tet_count, 1);
    CHECK_EQ_INT(dt.hull_face_count, 4);
    for (int k = 0; k < 4; k++)
        CHECK_EQ_INT(dt.adj[k], UINT32_MAX);
    fl_dt3_free(&dt);
    /* (1,1,1) is outside the first tetrahedron and cospherical with it (all five lie on the
     * sphere of centre (1/2,1/2,1/2)): either split is Delaunay, the hull has 6 faces. */
    build_ok(p, 5, &dt);
    CHECK(dt.tet_count == 2 || dt.tet_count == 3);
    CHECK_EQ_INT(dt.hull_face_count, 6);
    fl_dt3_free(&dt);
}

static void test_dt3_duplicates_are_merged_and_reported(void)
{
    size_t n = 200;
    double *p = random_points(n, 7, 0);
    memcpy(p + 3 * 150, p + 3 * 3, 3 * sizeof *p);
    memcpy(p + 3 * 151, p + 3 * 3, 3 * sizeof *p);
    memcpy(p + 3 * 199, p + 3 * 20, 3 * sizeof *p);
    fl_dt3 dt;
    build_ok(p, n, &dt);
    CHECK_EQ_INT(dt.unique_count, n - 3);
    size_t dups = 0;
    for (size_t i = 0; i < n; i++) {
        uint32_t r = dt.duplicate_of[i];
        CHECK(r < n && memcmp(p + 3 * r, p + 3 * i, 3 * sizeof *p) == 0);
        CHECK_EQ_INT(dt.duplicate_of[r], r);
        dups += r != i;
    }
    CHECK_EQ_INT(dups, 3);
    CHECK(dt.duplicate_of[150] == dt.duplicate_of[3] && dt.duplicate_of[151] == dt.duplicate_of[3]);
    fl_dt3_free(&dt);
    free(p);
}

static void check_fails(const double *p, size_t n, fl_status want, const char *word)
{
    fl_dt3 dt;
    fl_error err;
    memset(&dt, 0xff, sizeof dt);
    CHECK_STATUS(fl_dt3_build(p, n, NULL, &dt, &err), want, &err);
    CHECK_MSG(strstr(err.message, word) != NULL, "message '%s' lacks '%s'", err.message, word);
    CHECK(dt.tet == NULL && dt.tet_count == 0 && dt.duplicate_of == NULL);
    fl_dt3_free(&dt);
}

static void test_dt3_lower_dimensional_input_is_a_clear_error(void)
{
    size_t n;
    double *p = grid_points(5, 4, 1, &n);
    check_fails(p, n, FL_ERR_ALGORITHM, "coplanar");
    free(p);
    double line[15];
    for (int i = 0; i < 5; i++) {
        line[3 * i] = i;
        line[3 * i + 1] = 2 * i;
        line[3 * i + 2] = -i;
    }
    check_fails(line, 5, FL_ERR_ALGORITHM, "collinear");
    const double few[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 0};
    check_fails(few, 5, FL_ERR_INPUT, "at least 4 distinct");
    const double nan[] = {0, 0, 0, 1, 0, 0, 0, NAN, 0, 0, 0, 1};
    check_fails(nan, 4, FL_ERR_INPUT, "NaN");
}

/* A 10x10 planar grid plus an apex: a cone over the planar Delaunay triangulation, which has
 * 2n - b - 2 triangles for n points with b on the boundary (Euler). */
static void test_dt3_coplanar_points_plus_one(void)
{
    size_t n;
    double *p = grid_points(10, 10, 1, &n);
    p = realloc(p, 3 * (n + 1) * sizeof *p);
    p[3 * n] = 4.5;
    p[3 * n + 1] = 3.25;
    p[3 * n + 2] = 7;
    fl_dt3 dt;
    build_ok(p, n + 1, &dt);
    CHECK_EQ_INT(dt.tet_count, 2 * 100 - 36 - 2);
    fl_dt3_free(&dt);
    free(p);
}

static void test_dt3_circumcenters_are_equidistant(void)
{
    size_t n = 500;
    double *p = random_points(n, 3, 1);
    fl_dt3_options opt = {0};
    opt.want_circumcenters = 1;
    fl_dt3 dt;
    fl_error err;
    CHECK_STATUS(fl_dt3_build(p, n, &opt, &dt, &err), FL_OK, &err);
    for (size_t t = 0; t < dt.tet_count; t++) {
        const double *c = dt.circumcenters + 3 * t;
        double r[4];
        for (int k = 0; k < 4; k++) {
            const double *q = p + 3 * dt.tet[4 * t + k];
            r[k] = sqrt((q[0] - c[0]) * (q[0] - c[0]) + (q[1] - c[1]) * (q[1] - c[1]) +
                        (q[2] - c[2]) * (q[2] - c[2]));
        }
        for (int k = 1; k < 4; k++)
            CHECK_NEAR(r[k], r[0], 1e-6 * r[0]);
    }
    fl_dt3_free(&dt);
    free(p);
}

static int cancel_at_half(void *user, const char *stage, double fraction)
{
    (void)stage;
    ++*(int *)user;
    return fraction >= 0.5;
}

static void test_dt3_progress_reports_and_cancels(void)
{
    size_t n = 50000;
    double *p = random_points(n, 9, 0);
    int calls = 0;
    fl_dt3_options opt = {cancel_at_half, &calls, 0};
    fl_dt3 dt;
    fl_error err;
    CHECK_STATUS(fl_dt3_build(p, n, &opt, &dt, &err), FL_ERR_ALGORITHM, &err);
    CHECK(strstr(err.message, "cancelled") != NULL);
    CHECK(calls >= 2);
    CHECK(dt.tet == NULL);
    free(p);
}

/* A triangulation assembled by hand: tetrahedra (reoriented to be positive), adjacency and hull
 * faces by brute-force face matching. */
static void assemble(const double *p, size_t n, const uint32_t *tets, size_t nt, fl_dt3 *dt)
{
    static const int face[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};
    memset(dt, 0, sizeof *dt);
    dt->point_count = dt->unique_count = n;
    dt->duplicate_of = malloc(n * sizeof(uint32_t));
    for (size_t i = 0; i < n; i++)
        dt->duplicate_of[i] = (uint32_t)i;
    dt->tet_count = nt;
    dt->tet = malloc(4 * nt * sizeof(uint32_t));
    dt->adj = malloc(4 * nt * sizeof(uint32_t));
    dt->hull_faces = malloc(12 * nt * sizeof(uint32_t));
    memcpy(dt->tet, tets, 4 * nt * sizeof(uint32_t));
    for (size_t t = 0; t < nt; t++) {
        uint32_t *q = dt->tet + 4 * t;
        if (fl_orient3d(p + 3 * q[0], p + 3 * q[1], p + 3 * q[2], p + 3 * q[3]) < 0) {
            uint32_t x = q[0];
            q[0] = q[1];
            q[1] = x;
        }
    }
    for (size_t t = 0; t < nt; t++)
        for (int k = 0; k < 4; k++) {
            dt->adj[4 * t + k] = UINT32_MAX;
            for (size_t u = 0; u < nt; u++) {
                int shared = 0;
                for (int i = 0; i < 4; i++)
                    for (int j = 0; j < 4; j++)
                        shared += i != k && dt->tet[4 * t + i] == dt->tet[4 * u + j];
                if (u != t && shared == 3) dt->adj[4 * t + k] = (uint32_t)u;
            }
            if (dt->adj[4 * t + k] != UINT32_MAX) continue;
            for (int i = 0; i < 3; i++)
                dt->hull_faces[3 * dt->hull_face_count + i] = dt->tet[4 * t + face[k][i]];
            dt->hull_face_count++;
        }
}

/* Five points whose Delaunay triangulation is two tetrahedra on triangle abc; the three
 * tetrahedra around edge de fill the same hull but are not Delaunay. Verify must see it, and
 * also a flipped tetrahedron, broken adjacency and a point left out. */
static void test_dt3_verify_rejects_broken_triangulations(void)
{
    const double p[] = {0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, 5, 1, 1, -5, 1, 1, 1};
    const uint32_t two[] = {0, 1, 2, 3, 0, 1, 2, 4};
    const uint32_t three[] = {3, 4, 0, 1, 3, 4, 1, 2, 3, 4, 2, 0};
    fl_dt3 dt, built;
    fl_error err;
    assemble(p, 5, two, 2, &dt);
    CHECK_STATUS(fl_dt3_verify(p, &dt, &err), FL_OK, &err);
    CHECK_STATUS(fl_dt3_build(p, 5, NULL, &built, &err), FL_OK, &err);
    CHECK_EQ_INT(built.tet_count, 2);
    fl_dt3_free(&built);
    uint32_t x = dt.tet[0];
    dt.tet[0] = dt.tet[1];
    dt.tet[1] = x;
    CHECK_STATUS(fl_dt3_verify(p, &dt, &err), FL_ERR_ALGORITHM, &err);
    CHECK(strstr(err.message, "oriented") != NULL);
    fl_dt3_free(&dt);

    assemble(p, 5, three, 3, &dt);
    CHECK_EQ_INT(dt.hull_face_count, 6);
    CHECK_STATUS(fl_dt3_verify(p, &dt, &err), FL_ERR_ALGORITHM, &err);
    CHECK(strstr(err.message, "inside the circumsphere") != NULL);
    dt.adj[0] = dt.adj[0] == UINT32_MAX ? 1 : UINT32_MAX;
    CHECK_STATUS(fl_dt3_verify(p, &dt, &err), FL_ERR_ALGORITHM, &err);
    fl_dt3_free(&dt);

    assemble(p, 6, two, 2, &dt); /* point 5 = (1,1,1) is inside but not a vertex */
    CHECK_STATUS(fl_dt3_verify(p, &dt, &err), FL_ERR_ALGORITHM, &err);
    CHECK(strstr(err.message, "should be vertices") != NULL);
    fl_dt3_free(&dt);
}

/* Are all n points in one plane (exact, brute force over triples)? */
static int all_coplanar(const double *p, size_t n)
{
    for (size_t a = 0; a < n; a++)
        for (size_t b = 0; b < n; b++)
            for (size_t c = 0; c < n; c++)
                for (size_t d = 0; d < n; d++)
                    if (fl_orient3d(p + 3 * a, p + 3 * b, p + 3 * c, p + 3 * d) != 0) return 0;
    return 1;
}

/* Many small random subsets (with repeats) of the 3x3x3 grid: as degenerate as input gets. Each
 * either triangulates correctly (verify, brute-force empty spheres, volume) or fails with the
 * right error for the right reason. */
static void test_dt3_random_subsets_of_a_small_grid(void)
{
    unsigned long long seed = 2024;
    double p[3 * 30];
    for (int trial = 0; trial < 300; trial++) {
        size_t n = 4 + (size_t)(fl_test_rand_u64(&seed) % 27);
        for (size_t i = 0; i < 3 * n; i++)
            p[i] = (double)(fl_test_rand_u64(&seed) % 3);
        fl_dt3 dt;
        fl_error err;
        fl_status st = fl_dt3_build(p, n, NULL, &dt, &err);
        if (st == FL_OK) {
            check_valid(p, n, &dt);
            CHECK_EQ_INT(dt3c_empty_sphere_violations(p, 3, n, dt.tet, dt.tet_count, 0), 0);
        } else if (st == FL_ERR_ALGORITHM) {
            CHECK_MSG(all_coplanar(p, n), "trial %d: %s", trial, err.message);
        } else {
            CHECK_EQ_INT(st, FL_ERR_INPUT);
            CHECK(strstr(err.message, "at least 4 distinct") != NULL);
        }
        fl_dt3_free(&dt);
    }
}

FL_TEST_MAIN(FL_TEST_CASE(test_dt3_valid_and_empty_spheres_on_random_shapes),
             FL_TEST_CASE(test_dt3_valid_on_ten_thousand_points),
             FL_TEST_CASE(test_dt3_empty_sphere_on_integer_grid),
             FL_TEST_CASE(test_dt3_cospherical_integer_points),
             FL_TEST_CASE(test_dt3_hull_matches_brute_force),
             FL_TEST_CASE(test_dt3_euler_relation_of_the_ball),
             FL_TEST_CASE(test_dt3_four_and_five_points),
             FL_TEST_CASE(test_dt3_duplicates_are_merged_and_reported),
             FL_TEST_CASE(test_dt3_lower_dimensional_input_is_a_clear_error),
             FL_TEST_CASE(test_dt3_coplanar_points_plus_one),
             FL_TEST_CASE(test_dt3_circumcenters_are_equidistant),
             FL_TEST_CASE(test_dt3_progress_reports_and_cancels),
             FL_TEST_CASE(test_dt3_verify_rejects_broken_triangulations),
             FL_TEST_CASE(test_dt3_random_subsets_of_a_small_grid))
