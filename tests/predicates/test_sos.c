/* The symbolically perturbed predicates: agreement with a symbolic evaluation of the perturbed
 * determinant (GMP, Leibniz expansion over polynomials in eps, see oracle.h), nonzero results,
 * antisymmetry under swapping (point, index) pairs, and that brute-force Delaunay / regular
 * triangulations built from them on highly degenerate point sets are triangulations. */
#include <math.h>
#include <stdint.h>

#include "fl_test.h"
#include "predicates/oracle.h"

enum { O2, O3, IC, IS, ICW, ISW, KINDS };
typedef struct kind {
    const char *name;
    int dim, lifted, weighted;
} kind;
static const kind kinds[KINDS] = {
    {"orient2d_sos", 2, 0, 0},          {"orient3d_sos", 3, 0, 0},
    {"incircle_sos", 2, 1, 0},          {"insphere_sos", 3, 1, 0},
    {"incircle_weighted_sos", 2, 1, 1}, {"insphere_weighted_sos", 3, 1, 1},
};

static int npoints(int k)
{
    return kinds[k].dim + 1 + kinds[k].lifted;
}

static int call_sos(int k, double p[5][4], const uint32_t *i)
{
    switch (k) {
    case O2:
        return fl_orient2d_sos(p[0], p[1], p[2], i[0], i[1], i[2]);
    case O3:
        return fl_orient3d_sos(p[0], p[1], p[2], p[3], i[0], i[1], i[2], i[3]);
    case IC:
        return fl_incircle_sos(p[0], p[1], p[2], p[3], i[0], i[1], i[2], i[3]);
    case IS:
        return fl_insphere_sos(p[0], p[1], p[2], p[3], p[4], i[0], i[1], i[2], i[3], i[4]);
    case ICW:
        return fl_incircle_weighted_sos(p[0], p[1], p[2], p[3], i[0], i[1], i[2], i[3]);
    default:
        return fl_insphere_weighted_sos(p[0], p[1], p[2], p[3], p[4], i[0], i[1], i[2], i[3], i[4]);
    }
}

static int oracle_sos(int k, double p[5][4], const uint32_t *idx)
{
    const double *q[5] = {p[0], p[1], p[2], p[3], p[4]};
    if (!kinds[k].lifted) return oracle_orient_sos(q, idx, kinds[k].dim);
    return oracle_lift_sos(q, idx, kinds[k].dim, kinds[k].weighted);
}

static int rand_int(unsigned long long *s, int lo, int hi)
{
    return lo + (int)(fl_test_rand_u64(s) % (unsigned long long)(hi - lo + 1));
}

/* Distinct indices: small, consecutive, or anywhere in the uint32 range. */
static void random_indices(unsigned long long *s, uint32_t *idx, int n)
{
    int style = rand_int(s, 0, 2);
    for (int i = 0; i < n; i++) {
        for (;;) {
            uint32_t v = style == 0   ? (uint32_t)rand_int(s, 0, 9)
                         : style == 1 ? UINT32_MAX - (uint32_t)rand_int(s, 0, 9)
                                      : (uint32_t)fl_test_rand_u64(s);
            int dup = 0;
            for (int j = 0; j < i; j++)
                dup |= idx[j] == v;
            if (!dup) {
                idx[i] = v;
                break;
            }
        }
    }
}

/* Highly degenerate inputs: values from {-1, 0, 1} (coincident, collinear, coplanar,
 * cocircular points galore), the 12 integer points of the circle of radius 5, the
 * permutations of (+-1, +-2, +-2) on the sphere of radius 3, lifted points on a plane. */
static void gen_degenerate(int k, double p[5][4], unsigned long long *s)
{
    static const int circle[12][2] = {{3, 4},   {4, 3},   {-3, 4}, {-4, 3}, {3, -4}, {4, -3},
                                      {-3, -4}, {-4, -3}, {5, 0},  {-5, 0}, {0, 5},  {0, -5}};
    int dim = kinds[k].dim, style = rand_int(s, 0, 2);
    int alpha[3] = {rand_int(s, -3, 3), rand_int(s, -3, 3), rand_int(s, -3, 3)};
    for (int i = 0; i < npoints(k); i++) {
        for (int j = 0; j < 4; j++)
            p[i][j] = rand_int(s, -1, 1);
        if (style == 1 && dim == 2) {
            const int *c = circle[rand_int(s, 0, 11)];
            p[i][0] = c[0];
            p[i][1] = c[1];
        } else if (style == 1) {
            int v[3] = {1, 2, 2}, perm = rand_int(s, 0, 2);
            for (int j = 0; j < 3; j++)
                p[i][j] = (rand_int(s, 0, 1) ? -1 : 1) * v[(j + perm) % 3];
        }
        if (kinds[k].weighted && style == 2) { /* lifted points on the plane alpha.x */
            double w = 0;
            for (int j = 0; j < dim; j++)
                w += p[i][j] * p[i][j] - alpha[j] * p[i][j];
            p[i][dim] = w;
        }
    }
}

static void test_sos_matches_symbolic_expansion_of_perturbed_determinant(void)
{
    for (int k = 0; k < KINDS; k++) {
        unsigned long long seed = 0xabc0ull + (unsigned long long)k;
        long cases = 0, mismatches = 0, unperturbed_zero = 0;
        for (int c = 0; c < 3000; c++) {
            double p[5][4];
            uint32_t idx[5];
            gen_degenerate(k, p, &seed);
            random_indices(&seed, idx, npoints(k));
            const double *q[5] = {p[0], p[1], p[2], p[3], p[4]};
            unperturbed_zero +=
                oracle_sign(q, kinds[k].dim, kinds[k].lifted, kinds[k].weighted) == 0;
            int got = call_sos(k, p, idx), want = oracle_sos(k, p, idx);
            cases++;
            if (got != want && mismatches++ < 5)
                fprintf(stderr, "%s case %d: got %d, symbolic %d\n", kinds[k].name, c, got, want);
        }
        printf("  %-22s %ld cases (%ld degenerate before perturbation), %ld mismatches\n",
               kinds[k].name, cases, unperturbed_zero, mismatches);
        CHECK_EQ_INT(mismatches, 0);
        CHECK(unperturbed_zero > cases / 4);
    }
}

/* Orientation SoS is never 0 for distinct indices, even for coincident points; the lift SoS
 * is 0 exactly when all points are collinear (2D) / coplanar (3D). */
static void test_sos_is_zero_only_when_documented(void)
{
    for (int k = 0; k < KINDS; k++) {
        unsigned long long seed = 0xdef0ull + (unsigned long long)k;
        long zeros = 0, bad = 0;
        for (int c = 0; c < 4000; c++) {
            double p[5][4];
            uint32_t idx[5];
            gen_degenerate(k, p, &seed);
            random_indices(&seed, idx, npoints(k));
            int s = call_sos(k, p, idx), flat = 1;
            if (kinds[k].lifted) { /* all points on one line / plane? */
                int n = npoints(k);
                for (int drop = 0; drop < n; drop++) {
                    const double *o[4];
                    for (int r = 0, m = 0; r < n; r++)
                        if (r != drop) o[m++] = p[r];
                    int orient = kinds[k].dim == 2 ? fl_orient2d(o[0], o[1], o[2])
                                                   : fl_orient3d(o[0], o[1], o[2], o[3]);
                    flat &= orient == 0;
                }
            } else {
                flat = 0;
            }
            zeros += s == 0;
            bad += (s == 0) != flat;
        }
        printf("  %-22s zero results: %ld (all on a line/plane), wrong: %ld\n", kinds[k].name,
               zeros, bad);
        CHECK_EQ_INT(bad, 0);
    }
}

/* Swapping two arguments together with their indices flips the sign. */
static void test_sos_flips_sign_when_two_points_swap_with_their_indices(void)
{
    for (int k = 0; k < KINDS; k++) {
        unsigned long long seed = 0x5a5a0ull + (unsigned long long)k;
        long bad = 0;
        for (int c = 0; c < 5000; c++) {
            double p[5][4];
            uint32_t idx[5];
            gen_degenerate(k, p, &seed);
            random_indices(&seed, idx, npoints(k));
            int before = call_sos(k, p, idx);
            int i = rand_int(&seed, 0, npoints(k) - 1), j = rand_int(&seed, 0, npoints(k) - 2);
            j += j >= i;
            double t[4];
            memcpy(t, p[i], sizeof t);
            memcpy(p[i], p[j], sizeof t);
            memcpy(p[j], t, sizeof t);
            uint32_t ti = idx[i];
            idx[i] = idx[j];
            idx[j] = ti;
            bad += call_sos(k, p, idx) != -before;
        }
        CHECK_EQ_INT(bad, 0);
    }
}

/* A point on the circle through a ccw triangle, with a higher index than its corners, is
 * inside (in conflict). With a lower index, the heaviest corner c decides: lowering its lift
 * lowers the plane at d when d's barycentric coordinate for c is positive (d on c's side of
 * line ab), which leaves d outside; otherwise d is inside. */
static void test_incircle_sos_puts_later_cocircular_point_inside(void)
{
    double a[2] = {5, 0}, b[2] = {0, 5}, c[2] = {-5, 0}, d[2] = {3, -4}, d2[2] = {4, 3};
    CHECK_EQ_INT(fl_incircle(a, b, c, d), 0);
    CHECK_EQ_INT(fl_incircle(a, b, c, d2), 0);
    CHECK_EQ_INT(fl_incircle_sos(a, b, c, d, 1, 2, 3, 4), 1);
    CHECK_EQ_INT(fl_incircle_sos(a, b, c, d2, 1, 2, 3, 4), 1);
    CHECK_EQ_INT(fl_orient2d(a, b, d), fl_orient2d(a, b, c)); /* d on c's side of ab */
    CHECK_EQ_INT(fl_incircle_sos(a, b, c, d, 1, 2, 3, 0), -1);
    CHECK_EQ_INT(fl_orient2d(a, b, d2), -fl_orient2d(a, b, c)); /* d2 across ab */
    CHECK_EQ_INT(fl_incircle_sos(a, b, c, d2, 1, 2, 3, 0), 1);
    double e[3] = {1, 2, 2}, f[3] = {2, 1, -2}, g[3] = {-2, 2, -1}, h[3] = {2, -2, 1};
    double x[3] = {-1, -2, -2};
    int o = fl_orient3d(e, f, g, h);
    CHECK(o != 0);
    CHECK_EQ_INT(fl_insphere(e, f, g, h, x), 0);
    CHECK_EQ_INT(fl_insphere_sos(e, f, g, h, x, 1, 2, 3, 4, 9), o);
}

/* Four cocircular points a, b, c, d in ccw order: the diagonal ac is locally Delaunay when d is
 * outside circle(abc) and b outside circle(acd); bd when a is outside circle(bcd) and c outside
 * circle(bda). Under the perturbation exactly one diagonal qualifies, for every index order. */
static void test_exactly_one_diagonal_of_cocircular_quadrilateral_is_delaunay(void)
{
    /* the 12 integer points of x^2 + y^2 = 25 in ccw order */
    static const double ring[12][2] = {{5, 0},  {4, 3},   {3, 4},   {0, 5},  {-3, 4}, {-4, 3},
                                       {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
    unsigned long long seed = 4242;
    long quads = 0, bad = 0;
    for (int i = 0; i < 12; i++)
        for (int j = i + 1; j < 12; j++)
            for (int k = j + 1; k < 12; k++)
                for (int l = k + 1; l < 12; l++) {
                    const double *a = ring[i], *b = ring[j], *c = ring[k], *d = ring[l];
                    uint32_t x[4];
                    random_indices(&seed, x, 4);
                    int ac = fl_incircle_sos(a, b, c, d, x[0], x[1], x[2], x[3]) < 0 &&
                             fl_incircle_sos(a, c, d, b, x[0], x[2], x[3], x[1]) < 0;
                    int bd = fl_incircle_sos(b, c, d, a, x[1], x[2], x[3], x[0]) < 0 &&
                             fl_incircle_sos(b, d, a, c, x[1], x[3], x[0], x[2]) < 0;
                    quads++;
                    bad += ac + bd != 1;
                }
    CHECK_EQ_INT(quads, 495);
    CHECK_EQ_INT(bad, 0);
}

/* ---- brute-force Delaunay / regular triangulations through the SoS predicates ---- */

typedef struct point_set {
    int n;
    double p[32][4];
    uint32_t idx[32];
} point_set;

static int in_conflict2(const point_set *ps, int weighted, int i, int j, int k, int l)
{
    if (weighted)
        return fl_incircle_weighted_sos(ps->p[i], ps->p[j], ps->p[k], ps->p[l], ps->idx[i],
                                        ps->idx[j], ps->idx[k], ps->idx[l]) > 0;
    return fl_incircle_sos(ps->p[i], ps->p[j], ps->p[k], ps->p[l], ps->idx[i], ps->idx[j],
                           ps->idx[k], ps->idx[l]) > 0;
}

/* Twice the signed area in exact arithmetic (small integer coordinates). */
static double area2(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* Every ccw triangle with no point in conflict is kept. The kept triangles must cover the
 * convex hull exactly once: areas sum to the hull's, and every edge is used once (hull edge)
 * or twice in opposite directions. Returns the number of triangles. */
static int check_triangulation2(const point_set *ps, int weighted, double hull_area2)
{
    int n = ps->n, tris = 0, edge_use[32][32];
    double area = 0;
    memset(edge_use, 0, sizeof edge_use);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            for (int k = 0; k < n; k++) {
                if (i == j || j == k || i == k) continue;
                if (!(i < j && i < k)) continue; /* each triangle once, rotated to start at min */
                if (fl_orient2d(ps->p[i], ps->p[j], ps->p[k]) <= 0) continue;
                int empty = 1;
                for (int l = 0; l < n && empty; l++)
                    if (l != i && l != j && l != k && in_conflict2(ps, weighted, i, j, k, l))
                        empty = 0;
                if (!empty) continue;
                tris++;
                area += area2(ps->p[i], ps->p[j], ps->p[k]);
                edge_use[i][j]++, edge_use[j][k]++, edge_use[k][i]++;
            }
    CHECK_NEAR(area, hull_area2, 0);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            CHECK(edge_use[i][j] <= 1);
    return tris;
}

static void shuffle_indices(point_set *ps, unsigned long long *s, int spread)
{
    for (int i = 0; i < ps->n; i++)
        ps->idx[i] = (uint32_t)i * (uint32_t)spread;
    for (int i = ps->n - 1; i > 0; i--) {
        int j = rand_int(s, 0, i);
        uint32_t t = ps->idx[i];
        ps->idx[i] = ps->idx[j];
        ps->idx[j] = t;
    }
}

static void test_sos_delaunay_of_cocircular_and_grid_points_is_a_triangulation(void)
{
    unsigned long long seed = 77;
    static const int circle[12][2] = {{3, 4},   {4, 3},   {-3, 4}, {-4, 3}, {3, -4}, {4, -3},
                                      {-3, -4}, {-4, -3}, {5, 0},  {-5, 0}, {0, 5},  {0, -5}};
    for (int round = 0; round < 4; round++) {
        point_set grid = {.n = 16}, ring = {.n = 12};
        for (int i = 0; i < 16; i++) {
            grid.p[i][0] = i % 4;
            grid.p[i][1] = i / 4;
            grid.p[i][2] = 0;
        }
        for (int i = 0; i < 12; i++) {
            ring.p[i][0] = circle[i][0];
            ring.p[i][1] = circle[i][1];
            ring.p[i][2] = 0;
        }
        shuffle_indices(&grid, &seed, round % 2 ? 1 : 268435399);
        shuffle_indices(&ring, &seed, 1);
        /* n points of which h on the hull boundary, none hidden: 2n - 2 - h triangles */
        CHECK_EQ_INT(check_triangulation2(&grid, 0, 18), 2 * 16 - 2 - 12);
        CHECK_EQ_INT(check_triangulation2(&ring, 0, 2 * 74), 2 * 12 - 2 - 12);
        /* weights putting every lifted point on one plane: only the perturbation decides,
         * some points may become hidden, the result must still tile the hull */
        for (int i = 0; i < 16; i++) {
            double *q = grid.p[i];
            q[2] = q[0] * q[0] + q[1] * q[1] - (2 * q[0] - q[1] + 3);
        }
        check_triangulation2(&grid, 1, 18);
    }
}

/* Six times the signed volume, exact for small integers. */
static double volume6(const double *a, const double *b, const double *c, const double *d)
{
    double ad[3], bd[3], cd[3];
    for (int j = 0; j < 3; j++)
        ad[j] = a[j] - d[j], bd[j] = b[j] - d[j], cd[j] = c[j] - d[j];
    return ad[0] * (bd[1] * cd[2] - bd[2] * cd[1]) - ad[1] * (bd[0] * cd[2] - bd[2] * cd[0]) +
           ad[2] * (bd[0] * cd[1] - bd[1] * cd[0]);
}

/* 3D analogue: tetrahedra with orient3d > 0 and no point in conflict must tile the hull. */
static void check_tetrahedralization(const point_set *ps, int weighted, double hull_volume6)
{
    int n = ps->n;
    double volume = 0;
    for (int a = 0; a < n; a++)
        for (int b = a + 1; b < n; b++)
            for (int c = a + 1; c < n; c++)
                for (int d = a + 1; d < n; d++) {
                    if (c == b || d == b || d == c) continue;
                    const double *A = ps->p[a], *B = ps->p[b], *C = ps->p[c], *D = ps->p[d];
                    if (fl_orient3d(A, B, C, D) <= 0) continue;
                    int empty = 1;
                    for (int e = 0; e < n && empty; e++) {
                        if (e == a || e == b || e == c || e == d) continue;
                        const uint32_t *x = ps->idx;
                        int s = weighted ? fl_insphere_weighted_sos(A, B, C, D, ps->p[e], x[a],
                                                                    x[b], x[c], x[d], x[e])
                                         : fl_insphere_sos(A, B, C, D, ps->p[e], x[a], x[b], x[c],
                                                           x[d], x[e]);
                        empty = s < 0;
                    }
                    /* (a, b, c, d) and its even permutations fixing a are the same tetrahedron;
                     * count it once: b < c < d up to an even rotation of (b, c, d) */
                    if (empty && b < c && b < d) volume += volume6(A, B, C, D);
                }
    CHECK_NEAR(volume, hull_volume6, 0);
}

static void test_sos_delaunay_of_cospherical_and_grid_points_is_a_tetrahedralization(void)
{
    unsigned long long seed = 99;
    for (int round = 0; round < 2; round++) {
        point_set cube = {.n = 9}, grid = {.n = 12};
        for (int i = 0; i < 8; i++)
            for (int j = 0; j < 3; j++)
                cube.p[i][j] = (i >> j & 1) ? 1 : -1;
        cube.p[8][0] = cube.p[8][1] = cube.p[8][2] = 0;
        for (int i = 0; i < 12; i++) {
            grid.p[i][0] = i % 3;
            grid.p[i][1] = (i / 3) % 2;
            grid.p[i][2] = i / 6;
            grid.p[i][3] = 0;
        }
        shuffle_indices(&cube, &seed, 1);
        shuffle_indices(&grid, &seed, 1000003);
        check_tetrahedralization(&cube, 0, 6 * 8);
        cube.n = 8; /* all eight corners on one sphere */
        check_tetrahedralization(&cube, 0, 6 * 8);
        check_tetrahedralization(&grid, 0, 6 * 2);
        for (int i = 0; i < 12; i++) { /* lifted points on one plane */
            double *q = grid.p[i];
            q[3] = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] - (q[0] + 2 * q[2] - 1);
        }
        check_tetrahedralization(&grid, 1, 6 * 2);
    }
}

FL_TEST_MAIN(FL_TEST_CASE(test_sos_matches_symbolic_expansion_of_perturbed_determinant),
             FL_TEST_CASE(test_sos_is_zero_only_when_documented),
             FL_TEST_CASE(test_sos_flips_sign_when_two_points_swap_with_their_indices),
             FL_TEST_CASE(test_incircle_sos_puts_later_cocircular_point_inside),
             FL_TEST_CASE(test_exactly_one_diagonal_of_cocircular_quadrilateral_is_delaunay),
             FL_TEST_CASE(test_sos_delaunay_of_cocircular_and_grid_points_is_a_triangulation),
             FL_TEST_CASE(test_sos_delaunay_of_cospherical_and_grid_points_is_a_tetrahedralization))
