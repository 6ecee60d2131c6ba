/* Degenerate inputs for the 2D flintstone queries (issue #7, "Done when"): touching polygons
 * (a shared vertex, a shared edge or part of one, a vertex on another's edge, each the only
 * contact, and the same one ulp apart), repeated vertices and collinear runs. Every answer is
 * compared with brute force over all edges with exact predicates (hal2_oracle.h); for
 * intersection both the full pair list (thesis §7.4: hierarchical = all pairs) and the early
 * exit, in both argument orders. */
#include "hal2_oracle.h"

/* Both orders; returns the pair count (the same both ways). */
static size_t check_pairs(const fl_polygon *a, const fl_polygon *b)
{
    size_t k = check_hal2_intersection(a, b);
    CHECK_EQ_INT(check_hal2_intersection(b, a), k);
    return k;
}

/* Coordinates are multiplied by this power of two (exact, so contacts stay contacts) to run the
 * same configurations where squared distances overflow or underflow. */
static double ring_scale = 1;

static fl_polygon one_ring(test_poly *t, const double *xy, size_t n)
{
    tp_init(t);
    tp_add_ring(t, xy, n, 0);
    for (size_t k = 0; k < 2 * n; k++)
        t->pg.xy[k] *= ring_scale;
    return t->pg;
}

/* A closed square with `per` vertices on each side (collinear runs), counter-clockwise from
 * (x0, y0): axis-parallel [x0, x0 + s] x [y0, y0 + s], or with `diamond` set the diamond with
 * corners (x0, y0), (x0 + s, y0 - s), (x0 + 2s, y0), (x0 + s, y0 + s). Coordinates are dyadic,
 * hence exact, for dyadic x0, y0, s and per a power of two. */
static size_t subdivided_square(double *xy, double x0, double y0, double s, size_t per, int diamond)
{
    static const double dir[2][4][2] = {{{1, 0}, {0, 1}, {-1, 0}, {0, -1}},
                                        {{1, -1}, {1, 1}, {-1, 1}, {-1, -1}}};
    size_t n = 0;
    for (int side = 0; side < 4; side++)
        for (size_t k = 0; k < per; k++) {
            xy[2 * n] = x0, xy[2 * n + 1] = y0, n++;
            x0 += dir[diamond][side][0] * s / (double)per;
            y0 += dir[diamond][side][1] * s / (double)per;
        }
    return n;
}

/* Each configuration touches in exactly the way its name says and nowhere else; the expected
 * pair count follows from the picture and is also what brute force says. */
static void touching_polygons(void)
{
    test_poly ta, tb;
    fl_polygon a, b;
    /* corner to corner: the unit squares [0,1]^2 and [1,2]^2 share only (1, 1); two edges of
     * each end there, so 2 x 2 pairs */
    double sq1[] = {0, 0, 1, 0, 1, 1, 0, 1}, sq2[] = {1, 1, 2, 1, 2, 2, 1, 2};
    a = one_ring(&ta, sq1, 4), b = one_ring(&tb, sq2, 4);
    CHECK_EQ_INT(check_pairs(&a, &b), 4);
    fl_polygon_free(&b);
    /* one ulp apart diagonally: no contact */
    double sq3[] = {1, 1, 2, 1, 2, 2, 1, 2};
    sq3[0] = sq3[6] = nextafter(1, 2);
    sq3[1] = sq3[3] = nextafter(1, 2);
    b = one_ring(&tb, sq3, 4);
    CHECK_EQ_INT(check_pairs(&a, &b), 0);
    fl_polygon_free(&b);
    /* a whole shared edge x = 1, 0 <= y <= 1: the shared edge meets the shared edge and its
     * two neighbours on the other side, the two neighbours meet at the end points */
    double sq4[] = {1, 0, 2, 0, 2, 1, 1, 1};
    b = one_ring(&tb, sq4, 4);
    CHECK_EQ_INT(check_pairs(&a, &b), 7);
    fl_polygon_free(&b);
    /* part of an edge: [1, 2] x [0.5, 1.5] overlaps x = 1 on 0.5 <= y <= 1 */
    double sq5[] = {1, 0.5, 2, 0.5, 2, 1.5, 1, 1.5};
    b = one_ring(&tb, sq5, 4); /* the overlap, and each square's edge ending on the other's */
    CHECK_EQ_INT(check_pairs(&a, &b), 3);
    fl_polygon_free(&b);
    /* a vertex in the interior of an edge: the triangle's apex (0.5, 1) on the top edge of the
     * square; the apex's two edges meet that one edge */
    double tri[] = {0.5, 1, 1, 2, 0, 2};
    b = one_ring(&tb, tri, 3);
    CHECK_EQ_INT(check_pairs(&a, &b), 2);
    fl_polygon_free(&b);
    tri[1] = nextafter(1, 2); /* and one ulp above it: apart */
    b = one_ring(&tb, tri, 3);
    CHECK_EQ_INT(check_pairs(&a, &b), 0);
    fl_polygon_free(&b);
    tri[1] = nextafter(1, 0); /* one ulp below: the apex crosses into the square */
    b = one_ring(&tb, tri, 3);
    CHECK_EQ_INT(check_pairs(&a, &b), 2);
    fl_polygon_free(&b);
    fl_polygon_free(&a);
}

static void test_hal2_touching_polygons_intersect_exactly_like_brute_force(void)
{
    touching_polygons();
}

/* ... also at 2^600 (squared distances overflow to Inf) and 2^-1000 (they underflow; the ulp
 * steps become subnormal but stay exact): pruning weakens, answers must not change. */
static void test_hal2_touching_polygons_at_extreme_scales(void)
{
    const double scales[] = {0x1p600, 0x1p-1000};
    for (size_t k = 0; k < 2; k++) {
        ring_scale = scales[k];
        touching_polygons();
    }
    ring_scale = 1;
}

/* The root pair is two distinct points and the tree has n - 2 nodes (Thm. 7.2) also where
 * squared distances underflow (2^-1000) or overflow (2^600): the farthest-pair sweep on the
 * smallest enclosing circle compared underflowed squared distances, all 0, and picked one vertex
 * twice (then the tiny triangle's tree had 2 nodes and one edge was reported twice). */
static void test_hal2_root_pair_is_a_chord_at_extreme_scales(void)
{
    const double scales[] = {1, 0x1p600, 0x1p-1000, 0x1p-1060};
    for (size_t k = 0; k < 4; k++)
        for (unsigned long long seed = 0; seed < 6; seed++) {
            unsigned long long rng = seed + 11;
            double xy[2 * 40];
            size_t n = seed == 0 ? 3 : 5 * seed + 3;
            if (seed == 0) { /* the triangle of the touching test */
                const double tri[] = {0.5, 1, 1, 2, 0, 2};
                memcpy(xy, tri, sizeof tri);
            } else {
                star_ring(xy, n, 0, 0, 64, &rng);
                for (size_t i = 0; i < 2 * n; i++)
                    xy[i] = round(xy[i]); /* integers: exact after scaling */
            }
            ring_scale = scales[k];
            test_poly t;
            fl_polygon p = one_ring(&t, xy, n);
            ring_scale = 1;
            fl_hal2 h;
            fl_error err;
            CHECK_STATUS(fl_hal2_build(&p, NULL, &h, &err), FL_OK, &err);
            const double *a = p.xy + 2 * h.rings[0].root[0], *b = p.xy + 2 * h.rings[0].root[1];
            CHECK(a[0] != b[0] || a[1] != b[1]);
            CHECK_EQ_INT(h.node_count, n - 2);
            fl_hal2_free(&h);
            fl_polygon_free(&p);
        }
}

/* The same contacts deep in the trees: the touching edges are single edges of long collinear
 * runs (segment flintstones, §7.2.1) and of other polylines, so the descent has to reach them
 * through flintstones that only touch. */
static void test_hal2_touching_deep_in_the_trees(void)
{
    double xy[2 * 4 * 64 + 8], yz[2 * 4 * 32 + 8];
    test_poly ta, tb;
    fl_polygon a, b;
    size_t n = subdivided_square(xy, 0, 0, 1, 64, 0);
    a = one_ring(&ta, xy, n);
    /* a shared edge stretch: the neighbour [1, 1.5] x [0.25, 0.75] + (0, 1/256), 32 vertices a
     * side, its left side lying on the square's right side (collinear overlap, vertices
     * interleaved with the square's, none shared) */
    size_t m = subdivided_square(yz, 1, 0.25 + 1.0 / 256, 0.5, 32, 0);
    b = one_ring(&tb, yz, m);
    CHECK(check_pairs(&a, &b) > 0);
    fl_polygon_free(&b);
    /* a corner on an edge interior: a diamond whose left corner (1, 0.25 + 1/128) lies on the
     * square's right side between two of its vertices (spaced 1/64); only that corner's two
     * edges meet the one edge */
    m = subdivided_square(yz, 1, 0.25 + 1.0 / 128, 0.25, 32, 1);
    b = one_ring(&tb, yz, m);
    CHECK_EQ_INT(check_pairs(&a, &b), 2);
    fl_polygon_free(&b);
    m = subdivided_square(yz, nextafter(1, 2), 0.25 + 1.0 / 128, 0.25, 32, 1); /* one ulp right */
    b = one_ring(&tb, yz, m);
    CHECK_EQ_INT(check_pairs(&a, &b), 0);
    fl_polygon_free(&b);
    /* a shared corner: the small square moved to [1, 1.5] x [1, 1.5] */
    m = subdivided_square(yz, 1, 1, 0.5, 32, 0);
    b = one_ring(&tb, yz, m);
    CHECK_EQ_INT(check_pairs(&a, &b), 4);
    fl_polygon_free(&b);
    fl_polygon_free(&a);
}

/* Random integer stars (so translations are exact) made to touch: B is moved so that its
 * leftmost vertex lands exactly on A's rightmost vertex, or on the midpoint of one of A's edges
 * (integer when the edge's end points have even coordinate sums). */
static void test_hal2_touching_random_stars(void)
{
    for (unsigned long long seed = 1; seed <= 10; seed++) {
        unsigned long long rng = seed * 77;
        double xa[2 * 90], xb[2 * 70];
        star_ring(xa, 90, 0, 0, 1000, &rng);
        star_ring(xb, 70, 0, 0, 600, &rng);
        for (size_t k = 0; k < 180; k++)
            xa[k] = 2 * round(xa[k] / 2); /* even integers: edge midpoints are integers */
        for (size_t k = 0; k < 140; k++)
            xb[k] = round(xb[k]);
        size_t ra = 0, lb = 0;
        for (size_t k = 1; k < 90; k++)
            if (xa[2 * k] > xa[2 * ra]) ra = k;
        for (size_t k = 1; k < 70; k++)
            if (xb[2 * k] < xb[2 * lb]) lb = k;
        double target[2] = {xa[2 * ra], xa[2 * ra + 1]};
        if (seed % 2 == 0) { /* the midpoint of the edge after A's rightmost vertex */
            size_t nx = (ra + 1) % 90;
            target[0] = (xa[2 * ra] + xa[2 * nx]) / 2;
            target[1] = (xa[2 * ra + 1] + xa[2 * nx + 1]) / 2;
        }
        double dx = target[0] - xb[2 * lb], dy = target[1] - xb[2 * lb + 1];
        for (size_t k = 0; k < 70; k++)
            xb[2 * k] += dx, xb[2 * k + 1] += dy;
        test_poly ta, tb;
        fl_polygon a = one_ring(&ta, xa, 90), b = one_ring(&tb, xb, 70);
        CHECK(check_pairs(&a, &b) > 0); /* they touch at least at the target */
        for (size_t k = 0; k < 70; k++) /* moved one unit further right: brute force decides */
            xb[2 * k] += 1;
        fl_polygon_free(&b);
        b = one_ring(&tb, xb, 70);
        check_pairs(&a, &b);
        fl_polygon_free(&a);
        fl_polygon_free(&b);
    }
}

/* Inclusion on degenerate rings: repeated vertices (consecutive, across the ring's wrap, and a
 * vertex visited twice so the ring pinches), collinear runs with repeats, and two polygons of
 * one fl_polygon sharing an edge. Queries: the half-integer grid (on vertices and edges) plus
 * random points. */
static void check_inclusion(const fl_polygon *p, double lo, double hi, unsigned long long seed)
{
    size_t side = (size_t)(2 * (hi - lo)) + 1, n = side * side + 2000, m = 0;
    double *q = malloc(2 * n * sizeof(double));
    for (size_t i = 0; i < side; i++)
        for (size_t j = 0; j < side; j++)
            q[2 * m] = lo + (double)i / 2, q[2 * m + 1] = lo + (double)j / 2, m++;
    unsigned long long rng = seed;
    for (; m < n; m++) {
        q[2 * m] = lo + (hi - lo) * fl_test_rand01(&rng);
        q[2 * m + 1] = lo + (hi - lo) * fl_test_rand01(&rng);
    }
    check_hal2_contains(p, q, n);
    free(q);
}

static void test_hal2_inclusion_with_repeated_vertices_and_shared_edges(void)
{
    /* repeated vertices: (4,0) three times, (0,0) at both ends of the list (the wrap) and a
     * collinear run along y = 0 with a repeat in it */
    double r1[] = {0, 0, 1, 0, 2, 0, 2, 0, 3, 0, 4, 0, 4, 0, 4, 0, 4, 4, 2, 5, 0, 4, 0, 0};
    test_poly t;
    fl_polygon p = one_ring(&t, r1, 12);
    check_inclusion(&p, -1, 6, 1);
    fl_polygon_free(&p);
    /* a pinched ring: (2, 2) visited twice, two lobes touching at that vertex */
    double r2[] = {0, 0, 2, 2, 4, 0, 4, 4, 2, 2, 0, 4};
    p = one_ring(&t, r2, 6);
    check_inclusion(&p, -1, 5, 2);
    fl_polygon_free(&p);
    /* two polygons sharing the edge x = 2 (even-odd: the shared edge is boundary, the rest
     * of both squares inside) and a third touching their common corner (4, 2) */
    double s1[] = {0, 0, 2, 0, 2, 2, 0, 2}, s2[] = {2, 0, 4, 0, 4, 2, 2, 2};
    double s3[] = {4, 2, 6, 2, 6, 4, 4, 4};
    tp_init(&t);
    tp_add_ring(&t, s1, 4, 0);
    tp_add_ring(&t, s2, 4, 0);
    tp_add_ring(&t, s3, 4, 0);
    check_inclusion(&t.pg, -1, 7, 3);
    fl_polygon_free(&t.pg);
}

/* Repeated vertices in intersection: zero-length edges are points and meet whatever passes
 * through them. */
static void test_hal2_intersection_with_repeated_vertices(void)
{
    double r1[] = {0, 0, 1, 0, 2, 0, 2, 0, 3, 0, 4, 0, 4, 0, 4, 4, 2, 5, 0, 4, 0, 0};
    double r2[] = {2, 0, 2, 0, 3, -2, 1, -2}; /* hangs from the repeated (2, 0) */
    double r3[] = {4, 0, 6, 0, 6, 0, 6, 2};   /* shares the repeated corner (4, 0) */
    test_poly ta, tb;
    fl_polygon a = one_ring(&ta, r1, 11), b = one_ring(&tb, r2, 4);
    CHECK(check_pairs(&a, &b) > 0);
    fl_polygon_free(&b);
    b = one_ring(&tb, r3, 4);
    CHECK(check_pairs(&a, &b) > 0);
    fl_polygon_free(&b);
    fl_polygon_free(&a);
}

FL_TEST_MAIN(FL_TEST_CASE(test_hal2_touching_polygons_intersect_exactly_like_brute_force),
             FL_TEST_CASE(test_hal2_touching_polygons_at_extreme_scales),
             FL_TEST_CASE(test_hal2_root_pair_is_a_chord_at_extreme_scales),
             FL_TEST_CASE(test_hal2_touching_deep_in_the_trees),
             FL_TEST_CASE(test_hal2_touching_random_stars),
             FL_TEST_CASE(test_hal2_inclusion_with_repeated_vertices_and_shared_edges),
             FL_TEST_CASE(test_hal2_intersection_with_repeated_vertices))
