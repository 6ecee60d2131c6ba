/* fl_balls_union_euler: the Euler characteristic of a union of open balls, against the
 * alpha-complex oracle of skin_oracle.h (independent of src/skin: a global scan of every ball
 * per simplex instead of local link tests, long double instead of exact signs) on random sets,
 * and against values from elementary geometry on exactly degenerate sets (cube corners whose
 * balls meet at one point, tangent balls, nested balls) and on the inputs that have no 3D
 * triangulation (fewer than 4 centres, coplanar, collinear, duplicates). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "fl_test.h"
#include "skin_rng.h"
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function" /* the oracle's skin-function half */
#include "skin_oracle.h"
#pragma GCC diagnostic pop

static uint64_t rng_state = 0x9e3779b97f4a7c15ULL;

static double rnd(void)
{
    return skin_rng_next(&rng_state);
}

static long long union_euler(const double *b, size_t n)
{
    long long chi = -12345;
    fl_error err;
    CHECK_STATUS(fl_balls_union_euler(b, n, &chi, &err), FL_OK, &err);
    return chi;
}

/* n random balls, centres in [0, side]^3, radii in [rlo, rhi]; with probability `neg` a ball
 * gets a negative weight -r^2 instead (an empty ball that still shapes the power diagram). */
static void random_balls(double *b, int n, double side, double rlo, double rhi, double neg)
{
    for (int i = 0; i < n; i++) {
        for (int c = 0; c < 3; c++)
            b[4 * i + c] = side * rnd();
        double r = rlo + (rhi - rlo) * rnd();
        b[4 * i + 3] = rnd() < neg ? -r * r : r * r;
    }
}

static void test_union_euler_matches_alpha_oracle_on_random_sets(void)
{
    static const int sizes[] = {5, 6, 8, 12, 20, 30, 50, 80, 120, 200};
    double *b = malloc(4 * 200 * sizeof *b);
    CHECK(b != NULL);
    int sets = 0, nonzero = 0, above_one = 0, below_one = 0;
    for (int s = 0; s < 10; s++)
        for (int rep = 0; rep < 6; rep++) {
            int n = sizes[s];
            /* the cube grows like n^(1/3), so every size sees overlaps, gaps, tunnels */
            double side = 2 * cbrt((double)n);
            random_balls(b, n, side, 0.4 + 0.1 * rep, 0.9 + 0.1 * rep, rep % 2 ? 0.3 : 0);
            int ok;
            long long want = euler_union_oracle(b, (size_t)n, &ok);
            CHECK(ok);
            long long got = union_euler(b, (size_t)n);
            CHECK_MSG(got == want, "n %d rep %d: chi %lld, oracle %lld", n, rep, got, want);
            sets++;
            nonzero += want != 0;
            above_one += want > 1;
            below_one += want < 1;
        }
    /* the sets are not trivial: several components and, somewhere, tunnels (chi < 1) */
    CHECK_MSG(above_one > 10 && below_one > 0, "sets %d: chi > 1 on %d, chi < 1 on %d", sets,
              above_one, below_one);
    (void)nonzero;
    free(b);
}

/* Balls of weight w at the 8 corners of the cube [-1, 1]^3. */
static void cube_corner_balls(double *b, double w)
{
    for (int i = 0; i < 8; i++) {
        b[4 * i + 0] = i & 1 ? 1 : -1;
        b[4 * i + 1] = i & 2 ? 1 : -1;
        b[4 * i + 2] = i & 4 ? 1 : -1;
        b[4 * i + 3] = w;
    }
}

/* Balls of weight w at the 8 corners of the cube [-1, 1]^3: side 2, face diagonal 2 sqrt 2,
 * centre at squared distance 3 from every corner. Open balls:
 *   w = 1   sides tangent, 8 separate balls:                      chi 8
 *   w = 1.5 sides overlap, face diagonals do not: the 12-edge frame, chi 8 - 12 = -4
 *   w = 2   face diagonals tangent, face centres (power 0) not covered: still the frame, -4
 *   w = 2.5 faces covered (face centre power -0.5), the cube's centre (power 0.5) not: a
 *           hollow shell, chi 2
 *   w = 3   the centre has power exactly 0: only that point is missed, still chi 2
 *   w = 3.5 solid: chi 1
 * Every 4 or 5 corner balls are cospherical (co-orthogonal), the most degenerate regular
 * triangulation, and w = 1, 2, 3 put the decisive powers exactly at 0; w = 2 +- 2^-40 and
 * 3 +- 2^-40 put them 2^-40 from 0, on the side that the values above w say. */
static void test_cospherical_cube_corners_have_the_elementary_euler(void)
{
    const double d = ldexp(1, -40); /* decided by the exact stage: the filter cannot */
    const double w[] = {1, 1.5, 2, 2.5, 3, 3.5, 2 - d, 2 + d, 3 - d, 3 + d};
    static const long long chi[] = {8, -4, -4, 2, 2, 1, -4, 2, 2, 1};
    for (int k = 0; k < 10; k++) {
        double b[32];
        cube_corner_balls(b, w[k]);
        long long got = union_euler(b, 8);
        CHECK_MSG(got == chi[k], "w %g: chi %lld, expected %lld", w[k], got, chi[k]);
        int ok;
        long long oracle = euler_union_oracle(b, 8, &ok);
        CHECK(ok);
        CHECK_MSG(oracle == chi[k], "w %g: oracle %lld, expected %lld", w[k], oracle, chi[k]);
    }
}

/* A chain of 6 unit balls at spacing 2 (tangent, so open balls are disjoint: chi 6), with a
 * fifth ball off the line so the triangulation is 3D; at spacing 2 - 2^-40 they overlap:
 * chi 2 (the chain and the extra ball). */
static void test_tangent_balls_are_separate_and_overlapping_ones_connect(void)
{
    for (int overlap = 0; overlap < 2; overlap++) {
        double step = overlap ? 2 - ldexp(1, -40) : 2;
        double b[28];
        for (int i = 0; i < 6; i++) {
            b[4 * i + 0] = step * i;
            b[4 * i + 1] = 0;
            b[4 * i + 2] = 0;
            b[4 * i + 3] = 1;
        }
        b[24] = 5;
        b[25] = 7;
        b[26] = 3;
        b[27] = 1;
        long long want = overlap ? 2 : 7;
        CHECK_MSG(union_euler(b, 7) == want, "overlap %d: chi %lld, expected %lld", overlap,
                  union_euler(b, 7), want);
    }
}

/* Small balls inside a big one (some hidden: centred at the big one's centre) and one small
 * ball sticking out: one component, no hole, chi 1; and a hollow: 14 balls of radius 1.2 on a
 * sphere of radius 2 (cube corners and face centres) cover a shell around an empty core,
 * chi 2 (and with a ball in the core, below). */
static void test_nested_balls_and_a_hollow_shell(void)
{
    double b[4 * 16];
    int n = 0;
    double big[4] = {0.5, 0.25, 0.125, 9};
    for (int c = 0; c < 4; c++)
        b[4 * n + c] = big[c];
    n++;
    for (int i = 0; i < 6; i++, n++) { /* inside the big ball */
        b[4 * n + 0] = 0.5 + 0.3 * (i % 3) - 0.3;
        b[4 * n + 1] = 0.25 + 0.2 * (i / 3);
        b[4 * n + 2] = 0.125 + 0.1 * i;
        b[4 * n + 3] = 0.25;
    }
    double same_centre[4] = {0.5, 0.25, 0.125, 1}; /* hidden by the big ball */
    for (int c = 0; c < 4; c++)
        b[4 * n + c] = same_centre[c];
    n++;
    double outside[4] = {3.4, 0.25, 0.125, 0.25};
    for (int c = 0; c < 4; c++)
        b[4 * n + c] = outside[c];
    n++;
    CHECK_EQ_INT(union_euler(b, (size_t)n), 1);
    int ok;
    CHECK_EQ_INT(euler_union_oracle(b, (size_t)n, &ok), 1);

    n = 0;
    for (int i = 0; i < 8; i++, n++) {
        double s = 2 / sqrt(3);
        b[4 * n + 0] = i & 1 ? s : -s;
        b[4 * n + 1] = i & 2 ? s : -s;
        b[4 * n + 2] = i & 4 ? s : -s;
        b[4 * n + 3] = 1.44;
    }
    for (int i = 0; i < 6; i++, n++) {
        b[4 * n + 0] = i / 2 == 0 ? (i % 2 ? 2 : -2) : 0;
        b[4 * n + 1] = i / 2 == 1 ? (i % 2 ? 2 : -2) : 0;
        b[4 * n + 2] = i / 2 == 2 ? (i % 2 ? 2 : -2) : 0;
        b[4 * n + 3] = 1.44;
    }
    CHECK_EQ_INT(union_euler(b, (size_t)n), 2);
    CHECK_EQ_INT(euler_union_oracle(b, (size_t)n, &ok), 2);
    /* a unit ball at the centre touches all 14 (reach 2.2 > 2) but leaves the cavity around
     * it: the shell, the core and 14 bridges, S^2 plus 13 loops, chi 2 - 13; radius 2.5
     * fills the core, chi 1 */
    b[4 * n + 0] = b[4 * n + 1] = b[4 * n + 2] = 0;
    b[4 * n + 3] = 1;
    n++;
    CHECK_EQ_INT(union_euler(b, (size_t)n), -11);
    CHECK_EQ_INT(euler_union_oracle(b, (size_t)n, &ok), -11);
    b[4 * n - 1] = 6.25;
    CHECK_EQ_INT(union_euler(b, (size_t)n), 1);
    CHECK_EQ_INT(euler_union_oracle(b, (size_t)n, &ok), 1);
}

/* Inputs without a 3D regular triangulation (the auxiliary-ball path) and trivial ones. */
static void test_few_coplanar_collinear_and_duplicate_balls(void)
{
    CHECK_EQ_INT(union_euler(NULL, 0), 0);
    double one[4] = {1, 2, 3, 0.5};
    CHECK_EQ_INT(union_euler(one, 1), 1);
    double empty[4] = {1, 2, 3, -0.5};
    CHECK_EQ_INT(union_euler(empty, 1), 0);
    double two[8] = {0, 0, 0, 1, 1.5, 0, 0, 1}; /* overlapping */
    CHECK_EQ_INT(union_euler(two, 2), 1);
    two[4] = 2; /* tangent: open balls disjoint */
    CHECK_EQ_INT(union_euler(two, 2), 2);
    double three[12] = {0, 0, 0, 1, 1.5, 0, 0, 1, 3, 0, 0, 1}; /* collinear chain */
    CHECK_EQ_INT(union_euler(three, 3), 1);
    three[8] = 4.5;
    CHECK_EQ_INT(union_euler(three, 3), 2);
    /* 4 coplanar balls on the corners of a square of side 2: radius 1.1 makes a ring (sides
     * overlap, diagonals 2.83 do not), radius 1.5 a disc (the centre at squared distance 2) */
    double sq[16] = {0, 0, 0, 1.21, 2, 0, 0, 1.21, 2, 2, 0, 1.21, 0, 2, 0, 1.21};
    CHECK_EQ_INT(union_euler(sq, 4), 0);
    for (int i = 0; i < 4; i++)
        sq[4 * i + 3] = 2.25;
    CHECK_EQ_INT(union_euler(sq, 4), 1);
    /* a coplanar ring of 12 balls (a hexagon's corners and edge midpoints, radius just over
     * half the spacing): chi 0; duplicates of every ball change nothing */
    double ring[4 * 24];
    for (int i = 0; i < 12; i++) {
        double a = 2 * 3.14159265358979323846 * i / 12;
        ring[4 * i + 0] = 4 * cos(a);
        ring[4 * i + 1] = 4 * sin(a);
        ring[4 * i + 2] = 1;
        ring[4 * i + 3] = 1.2 * 1.2;
    }
    CHECK_EQ_INT(union_euler(ring, 12), 0);
    for (int i = 0; i < 48; i++)
        ring[48 + i] = ring[i];
    CHECK_EQ_INT(union_euler(ring, 24), 0);
    /* a collinear chain far from the origin: x = 1e20 for all (ulp 16384), y = 0, 1, 2, radius
     * 0.6: one component; the auxiliary balls must not round onto the plane x = 1e20 (found by
     * fuzz_skin: an auxiliary tetrahedron sized by the extent alone was flat there) */
    double far[12] = {1e20, 0, 0, 0.36, 1e20, 1, 0, 0.36, 1e20, 2, 0, 0.36};
    CHECK_EQ_INT(union_euler(far, 3), 1);
    far[3] = far[7] = far[11] = 0.2; /* radius 0.447 < 0.5: three separate balls */
    CHECK_EQ_INT(union_euler(far, 3), 3);
    /* duplicate centres with other weights on a 3D set */
    double dup[4 * 6] = {0, 0, 0, 1, 3, 0, 0, 1,   0, 3, 0, 1,
                         0, 0, 3, 1, 0, 0, 0, 0.5, 3, 0, 0, 4.41};
    CHECK_EQ_INT(union_euler(dup, 6), 3); /* ball 5 (radius 2.1 at (3,0,0)) joins 0 and 1 */
    int ok;
    CHECK_EQ_INT(euler_union_oracle(dup, 6, &ok), 3);
}

static void test_bad_input_is_rejected(void)
{
    fl_error err;
    long long chi;
    double b[8] = {0, 0, 0, 1, 1, 0, 0, NAN};
    CHECK_STATUS(fl_balls_union_euler(b, 2, &chi, &err), FL_ERR_INPUT, &err);
    b[7] = INFINITY;
    CHECK_STATUS(fl_balls_union_euler(b, 2, &chi, &err), FL_ERR_INPUT, &err);
    b[7] = 1;
    b[1] = 1e300;
    CHECK_STATUS(fl_balls_union_euler(b, 2, &chi, &err), FL_ERR_INPUT, &err);
    CHECK_STATUS(fl_balls_union_euler(b, 2, NULL, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_balls_union_euler(NULL, 2, &chi, &err), FL_ERR_USAGE, &err);
    /* the same 4 balls at scales 2^-500, 1 and 2^150 (exact scalings): a ball at the origin
     * and three at distance 1 along the axes, radius 0.75: the axis pairs overlap (1.5 > 1),
     * the outer pairs too (1.5 > sqrt 2), the outer triple has no common point (circumradius
     * 0.816 > 0.75), each triple with the origin has (0.707 < 0.75): chi 4 - 6 + 3 = 1 */
    static const int scale[3] = {-500, 0, 150};
    for (int s = 0; s < 3; s++) {
        double q[16];
        for (int i = 0; i < 4; i++) {
            q[4 * i + 0] = ldexp(i == 1, scale[s]);
            q[4 * i + 1] = ldexp(i == 2, scale[s]);
            q[4 * i + 2] = ldexp(i == 3, scale[s]);
            q[4 * i + 3] = ldexp(0.5625, 2 * scale[s]);
        }
        CHECK_MSG(union_euler(q, 4) == 1, "scale 2^%d: chi %lld", scale[s], union_euler(q, 4));
    }
}

/* ---- fl_balls_union_betti ---- */

static void union_betti(const double *b, size_t n, long long *be)
{
    fl_error err;
    be[0] = be[1] = be[2] = -12345;
    CHECK_STATUS(fl_balls_union_betti(b, n, be, &err), FL_OK, &err);
    CHECK_MSG(be[0] - be[1] + be[2] == union_euler(b, n), "betti %lld %lld %lld, chi %lld", be[0],
              be[1], be[2], union_euler(b, n));
}

static int find_root(int *parent, int a)
{
    while (parent[a] != a)
        a = parent[a] = parent[parent[a]];
    return a;
}

/* Components of the union by brute force: two open balls meet iff |c_i - c_j| < r_i + r_j. */
static long long overlap_components(const double *b, int n)
{
    int *parent = malloc((size_t)n * sizeof *parent);
    CHECK(parent != NULL);
    for (int i = 0; i < n; i++)
        parent[i] = i;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < i; j++) {
            if (b[4 * i + 3] <= 0 || b[4 * j + 3] <= 0) continue;
            double d2 = 0;
            for (int c = 0; c < 3; c++)
                d2 += (b[4 * i + c] - b[4 * j + c]) * (b[4 * i + c] - b[4 * j + c]);
            double r = sqrt(b[4 * i + 3]) + sqrt(b[4 * j + 3]);
            if (d2 < r * r) parent[find_root(parent, i)] = find_root(parent, j);
        }
    long long count = 0;
    for (int i = 0; i < n; i++)
        count += b[4 * i + 3] > 0 && find_root(parent, i) == i;
    free(parent);
    return count;
}

/* b0 against the balls' overlap graph on the random sets of the Euler test (several
 * components each), and b1 = b0 + b2 - chi by construction (union_betti checks the sum). */
static void test_union_betti_components_match_the_overlap_graph(void)
{
    double *b = malloc(4 * 130 * sizeof *b);
    CHECK(b != NULL);
    int several = 0;
    for (int rep = 0; rep < 12; rep++) {
        int n = 20 + 10 * rep;
        random_balls(b, n, 2.5 * cbrt((double)n), 0.3 + 0.05 * rep, 0.8, rep % 3 ? 0.2 : 0);
        long long be[3];
        union_betti(b, (size_t)n, be);
        long long want = overlap_components(b, n);
        CHECK_MSG(be[0] == want, "n %d: b0 %lld, overlap graph %lld", n, be[0], want);
        CHECK(be[1] >= 0 && be[2] >= 0);
        several += want > 1;
    }
    CHECK(several > 6);
    free(b);
}

/* Balls of radius 0.75 on a random subset of the m^3 integer lattice (every lattice point
 * present with probability p): the most degenerate input (every unit cube's corners are
 * cospherical). The gaps are found cube by cube: a unit cube's centre is 0.866 from its
 * corners, so it is never covered, and the uncovered points of a cube all reach its centre; a
 * face is fully covered iff its 4 corners are present (its centre is 0.707 from them, any
 * point of it at most that from the nearest corner); so the complement's components are those
 * of the graph on the unit cubes of [-1, m]^3 joined across faces with a missing corner, and
 * the cubes outside the lattice reach infinity. b2 is the number of the other components;
 * b0 comes from the overlap graph (neighbours at 1 and sqrt 2 overlap, at sqrt 3 not). */
static long long lattice_cavities(const unsigned char *present, int m)
{
    int side = m + 1; /* cubes with lower corner in [-1, m - 1]^3 */
    int cubes = side * side * side;
    int *parent = malloc((size_t)cubes * sizeof *parent);
    CHECK(parent != NULL);
    for (int i = 0; i < cubes; i++)
        parent[i] = i;
#define LATTICE_AT(x, y, z)                                                                        \
    ((x) >= 0 && (y) >= 0 && (z) >= 0 && (x) < m && (y) < m && (z) < m &&                          \
     present[((x)*m + (y)) * m + (z)])
    for (int x = -1; x < m; x++)
        for (int y = -1; y < m; y++)
            for (int z = -1; z < m; z++) {
                int id = ((x + 1) * side + (y + 1)) * side + (z + 1);
                int on_border = x < 0 || y < 0 || z < 0 || x == m - 1 || y == m - 1 || z == m - 1;
                if (on_border) parent[find_root(parent, id)] = find_root(parent, 0);
                for (int axis = 0; axis < 3; axis++) {
                    int nx = x + (axis == 0), ny = y + (axis == 1), nz = z + (axis == 2);
                    if (nx >= m || ny >= m || nz >= m) continue;
                    /* the face shared with the next cube along axis: corners at coordinate
                     * x+1 (resp. y+1, z+1) on that axis */
                    int full = 1;
                    for (int k = 0; k < 4; k++) {
                        int c[3] = {x, y, z}, o = 0;
                        for (int a = 0; a < 3; a++) {
                            if (a == axis)
                                c[a] += 1;
                            else
                                c[a] += (k >> o++) & 1;
                        }
                        full &= LATTICE_AT(c[0], c[1], c[2]);
                    }
                    int nid = ((nx + 1) * side + (ny + 1)) * side + (nz + 1);
                    if (!full) parent[find_root(parent, id)] = find_root(parent, nid);
                }
            }
#undef LATTICE_AT
    long long count = 0;
    int outside = find_root(parent, 0);
    for (int i = 0; i < cubes; i++)
        count += find_root(parent, i) == i && i != outside;
    free(parent);
    return count;
}

static void test_union_betti_of_lattice_subsets_matches_the_cube_graph(void)
{
    enum { M = 5 };
    double b[4 * M * M * M];
    unsigned char present[M * M * M];
    static const double keep[] = {1, 0.97, 0.93, 0.9, 0.85, 0.8, 0.7, 0.6};
    int cavities = 0, tunnels = 0;
    for (int rep = 0; rep < 16; rep++) {
        int n = 0;
        for (int i = 0; i < M * M * M; i++) {
            present[i] = rnd() < keep[rep % 8];
            if (!present[i]) continue;
            b[4 * n + 0] = i / (M * M);
            b[4 * n + 1] = i / M % M;
            b[4 * n + 2] = i % M;
            b[4 * n + 3] = 0.5625;
            n++;
        }
        long long be[3];
        union_betti(b, (size_t)n, be);
        long long want2 = lattice_cavities(present, M), want0 = overlap_components(b, n);
        CHECK_MSG(be[0] == want0 && be[2] == want2,
                  "rep %d (%d balls): b0 %lld b2 %lld, "
                  "expected %lld and %lld",
                  rep, n, be[0], be[2], want0, want2);
        CHECK(be[1] >= 0);
        cavities += be[2] > 0;
        tunnels += be[1] > 0;
    }
    CHECK(cavities > 4 && tunnels > 4);
}

/* Shapes whose Betti numbers are elementary. */
static void test_union_betti_of_elementary_shapes(void)
{
    long long be[3];
    /* the cube corners of the Euler test: 8 balls; the 12-edge frame (b1 = 12 - 8 + 1); the
     * hollow shell (also when only the centre point is missed); the solid cube */
    const double w[] = {1, 1.5, 2, 2.5, 3, 3.5};
    static const long long want[6][3] = {{8, 0, 0}, {1, 5, 0}, {1, 5, 0},
                                         {1, 0, 1}, {1, 0, 1}, {1, 0, 0}};
    for (int k = 0; k < 6; k++) {
        double b[32];
        cube_corner_balls(b, w[k]);
        union_betti(b, 8, be);
        CHECK_MSG(be[0] == want[k][0] && be[1] == want[k][1] && be[2] == want[k][2],
                  "w %g: betti %lld %lld %lld", w[k], be[0], be[1], be[2]);
    }
    /* a ring of 16 balls of radius 0.5 on a circle of radius 2 (spacing 0.78, tilted out of
     * every coordinate plane): a solid torus; two such rings far apart: 2 components, 2
     * tunnels */
    double ring[4 * 32];
    for (int i = 0; i < 32; i++) {
        double a = 2 * 3.14159265358979323846 * (i % 16) / 16, off = i < 16 ? 0 : 10;
        ring[4 * i + 0] = 2 * cos(a) + off;
        ring[4 * i + 1] = 2 * sin(a) * 0.8;
        ring[4 * i + 2] = 2 * sin(a) * 0.6 + 0.1 * cos(a);
        ring[4 * i + 3] = 0.25;
    }
    union_betti(ring, 16, be);
    CHECK(be[0] == 1 && be[1] == 1 && be[2] == 0);
    union_betti(ring, 32, be);
    CHECK(be[0] == 2 && be[1] == 2 && be[2] == 0);
    /* the full 3^3 lattice with radius 0.6 (edges overlap, face diagonals 1.41 > 1.2 do not):
     * the jungle gym of 54 edges on 27 nodes, b1 = 54 - 27 + 1; radius 0.75 closes its faces
     * and leaves the 8 unit cubes' centres as cavities */
    double lat[4 * 27];
    for (int i = 0; i < 27; i++) {
        lat[4 * i + 0] = i / 9;
        lat[4 * i + 1] = i / 3 % 3;
        lat[4 * i + 2] = i % 3;
        lat[4 * i + 3] = 0.36;
    }
    union_betti(lat, 27, be);
    CHECK_MSG(be[0] == 1 && be[1] == 28 && be[2] == 0, "betti %lld %lld %lld", be[0], be[1], be[2]);
    for (int i = 0; i < 27; i++)
        lat[4 * i + 3] = 0.5625;
    union_betti(lat, 27, be);
    CHECK_MSG(be[0] == 1 && be[1] == 0 && be[2] == 8, "betti %lld %lld %lld", be[0], be[1], be[2]);
    /* nothing, one ball, two apart, coplanar ring (the auxiliary-ball path) */
    union_betti(NULL, 0, be);
    CHECK(be[0] == 0 && be[1] == 0 && be[2] == 0);
    double two[8] = {0, 0, 0, 1, 2, 0, 0, 1};
    union_betti(two, 2, be);
    CHECK(be[0] == 2 && be[1] == 0 && be[2] == 0);
    double sq[16] = {0, 0, 0, 1.21, 2, 0, 0, 1.21, 2, 2, 0, 1.21, 0, 2, 0, 1.21};
    union_betti(sq, 4, be);
    CHECK(be[0] == 1 && be[1] == 1 && be[2] == 0);
    /* bad input: as fl_balls_union_euler, and the numbers are zeroed */
    fl_error err;
    double bad[8] = {0, 0, 0, 1, 1, 0, 0, NAN};
    CHECK_STATUS(fl_balls_union_betti(bad, 2, be, &err), FL_ERR_INPUT, &err);
    CHECK(be[0] == 0 && be[1] == 0 && be[2] == 0);
    CHECK_STATUS(fl_balls_union_betti(bad, 2, NULL, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_balls_union_betti(NULL, 2, be, &err), FL_ERR_USAGE, &err);
}

int main(void)
{
    static const fl_test_case cases[] = {
        FL_TEST_CASE(test_union_euler_matches_alpha_oracle_on_random_sets),
        FL_TEST_CASE(test_cospherical_cube_corners_have_the_elementary_euler),
        FL_TEST_CASE(test_tangent_balls_are_separate_and_overlapping_ones_connect),
        FL_TEST_CASE(test_nested_balls_and_a_hollow_shell),
        FL_TEST_CASE(test_few_coplanar_collinear_and_duplicate_balls),
        FL_TEST_CASE(test_bad_input_is_rejected),
        FL_TEST_CASE(test_union_betti_components_match_the_overlap_graph),
        FL_TEST_CASE(test_union_betti_of_lattice_subsets_matches_the_cube_graph),
        FL_TEST_CASE(test_union_betti_of_elementary_shapes),
    };
    return fl_test_run(cases, sizeof cases / sizeof cases[0]);
}
