/* Constrained constriction (thesis §5.7): edges the user requires on the boundary are never
 * deleted; when they make a polygon through all points impossible the call says so. */
#include "recon2_test_util.h"

static int on_boundary_edge(const fl_reconstruction2 *rec, uint32_t a, uint32_t b)
{
    for (size_t i = 0; i < rec->boundary_count; i++) {
        uint32_t p = rec->boundary[i], q = rec->boundary[(i + 1) % rec->boundary_count];
        if ((p == a && q == b) || (p == b && q == a)) return 1;
    }
    return 0;
}

static void test_kept_chord_cutting_off_a_hull_point_is_reported_impossible(void)
{
    /* Points in convex position: every point is a hull vertex, so a simple polygon through all
     * of them is the hull itself and a chord 0-2 can never be on it. */
    size_t n = 20;
    double *xy = rt_star(n, 0, 0);
    uint32_t keep[] = {0, 2};
    fl_reconstruct2_options opt = {0};
    opt.keep = keep;
    opt.keep_count = 1;
    fl_reconstruction2 rec;
    fl_error err;
    CHECK_STATUS(fl_reconstruct2(xy, n, &opt, &rec, &err), FL_OK, &err);
    rt_check_valid(xy, &rec);
    CHECK(!rec.all_on_boundary);
    CHECK(strstr(rec.reason, "kept edge") != NULL);
    fl_reconstruction2_free(&rec);
    free(xy);
}

/* Random sets: keep an edge the unconstrained result has inside (a chord of its triangulation).
 * Whenever the call reports success, the kept edge is a boundary edge; §5.7 allows the
 * constrained constriction to lock, but on scattered points that must stay rare. */
static void test_kept_edges_end_up_on_the_boundary(void)
{
    int tried = 0, kept = 0;
    for (unsigned long long seed = 1; seed <= 40; seed++) {
        size_t n = 60;
        double *xy = malloc(2 * n * sizeof *xy);
        unsigned long long st = seed;
        for (size_t i = 0; i < 2 * n; i++)
            xy[i] = fl_test_rand01(&st);
        fl_reconstruction2 free_rec, rec;
        fl_error err;
        CHECK_STATUS(fl_reconstruct2(xy, n, NULL, &free_rec, &err), FL_OK, &err);
        uint32_t keep[2] = {0, 0};
        for (size_t t = 0; t < free_rec.triangle_count && keep[0] == keep[1]; t++)
            for (int k = 0; k < 3; k++) {
                uint32_t a = free_rec.tri[3 * t + k], b = free_rec.tri[3 * t + (k + 1) % 3];
                if (!on_boundary_edge(&free_rec, a, b)) keep[0] = a, keep[1] = b;
            }
        fl_reconstruct2_options opt = {0};
        opt.keep = keep;
        opt.keep_count = 1;
        CHECK_STATUS(fl_reconstruct2(xy, n, &opt, &rec, &err), FL_OK, &err);
        rt_check_valid(xy, &rec);
        tried++;
        if (rec.all_on_boundary) {
            kept++;
            CHECK(on_boundary_edge(&rec, keep[0], keep[1]));
        }
        fl_reconstruction2_free(&free_rec);
        fl_reconstruction2_free(&rec);
        free(xy);
    }
    CHECK_MSG(10 * kept >= 9 * tried, "only %d of %d constrained runs succeeded", kept, tried);
}

/* Keeping every edge of the sampled curve (i, i+1) forces its order even under the Voronoi
 * skeleton key, on a star deep enough that not all its edges are Delaunay-obvious. */
static void test_keeping_the_whole_curve_gives_it_back(void)
{
    size_t n = 120;
    double *xy = rt_star(n, 4, 0.5);
    uint32_t *keep = malloc(2 * n * sizeof *keep);
    for (size_t i = 0; i < n; i++)
        keep[2 * i] = (uint32_t)i, keep[2 * i + 1] = (uint32_t)((i + 1) % n);
    fl_reconstruct2_options opt = {0};
    opt.keep = keep;
    opt.keep_count = n;
    opt.criterion = FL_RECONSTRUCT2_VORONOI_SKELETON;
    fl_reconstruction2 rec;
    fl_error err;
    CHECK_STATUS(fl_reconstruct2(xy, n, &opt, &rec, &err), FL_OK, &err);
    rt_check_valid(xy, &rec);
    CHECK(rec.all_on_boundary);
    CHECK(rt_is_input_order(&rec, n));
    fl_reconstruction2_free(&rec);
    free(keep);
    free(xy);
}

/* Edges that the unconstrained constriction puts on the boundary anyway are Delaunay edges that
 * are never deleted; keeping them constrains nothing, so the result must be the same. */
static void test_keeping_edges_of_the_free_result_changes_nothing(void)
{
    for (unsigned long long seed = 50; seed < 60; seed++) {
        size_t n = 80;
        double *xy = malloc(2 * n * sizeof *xy);
        unsigned long long st = seed;
        for (size_t i = 0; i < 2 * n; i++)
            xy[i] = fl_test_rand01(&st);
        fl_reconstruct2_options pure = {0};
        pure.extra_levels = -1;
        fl_reconstruction2 a, b;
        fl_error err;
        CHECK_STATUS(fl_reconstruct2(xy, n, &pure, &a, &err), FL_OK, &err);
        uint32_t keep[2 * 10];
        size_t count = 0;
        for (size_t i = 0; i < a.boundary_count && count < 10; i += 7, count++)
            keep[2 * count] = a.boundary[i],
                     keep[2 * count + 1] = a.boundary[(i + 1) % a.boundary_count];
        pure.keep = keep;
        pure.keep_count = count;
        CHECK_STATUS(fl_reconstruct2(xy, n, &pure, &b, &err), FL_OK, &err);
        CHECK_EQ_INT(a.boundary_count, b.boundary_count);
        CHECK(a.boundary_count == b.boundary_count &&
              memcmp(a.boundary, b.boundary, a.boundary_count * sizeof *a.boundary) == 0);
        CHECK_EQ_INT(a.all_on_boundary, b.all_on_boundary);
        fl_reconstruction2_free(&a);
        fl_reconstruction2_free(&b);
        free(xy);
    }
}

static void test_impossible_kept_edges_are_rejected(void)
{
    const double xy[] = {0, 0, 2, 0, 2, 2, 0, 2, 1, 1, 3, 3, 1, 0.5};
    fl_reconstruct2_options opt = {0};
    fl_reconstruction2 rec;
    fl_error err;
    uint32_t crossing[] = {0, 2, 1, 3};
    uint32_t three[] = {4, 0, 4, 1, 4, 2};
    uint32_t range[] = {0, 7};
    uint32_t self[] = {3, 3};
    uint32_t through[] = {0, 5}; /* passes through point 4 = (1,1) */
    struct {
        uint32_t *keep;
        size_t count;
    } bad[] = {{crossing, 2}, {three, 3}, {range, 1}, {self, 1}, {through, 1}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        opt.keep = bad[i].keep;
        opt.keep_count = bad[i].count;
        CHECK_STATUS(fl_reconstruct2(xy, 7, &opt, &rec, &err), FL_ERR_INPUT, &err);
        CHECK(rec.boundary == NULL);
    }
    opt.keep = NULL;
    opt.keep_count = 1;
    CHECK_STATUS(fl_reconstruct2(xy, 7, &opt, &rec, &err), FL_ERR_USAGE, &err);
}

FL_TEST_MAIN(FL_TEST_CASE(test_kept_chord_cutting_off_a_hull_point_is_reported_impossible),
             FL_TEST_CASE(test_kept_edges_end_up_on_the_boundary),
             FL_TEST_CASE(test_keeping_the_whole_curve_gives_it_back),
             FL_TEST_CASE(test_keeping_edges_of_the_free_result_changes_nothing),
             FL_TEST_CASE(test_impossible_kept_edges_are_rejected))
