/* Locked constriction and its augmentation (thesis §4.3.3, §5.4): when no boundary edge of the
 * pruned Delaunay triangulation is removable but points remain inside, edges of
 * γ([-1,1],[c0,1]) for c0 < 0 are added until every point is on the boundary. Checked against
 * independent oracles: the lock condition read off the returned triangles, and membership of
 * every boundary edge in γ([-1,1],[c0,1]) by brute force over all points (Theorem 3.1). */
#include "recon2_test_util.h"

static double *random_points(size_t n, unsigned long long seed)
{
    double *xy = malloc(2 * n * sizeof *xy);
    for (size_t i = 0; i < 2 * n; i++)
        xy[i] = fl_test_rand01(&seed);
    return xy;
}

/* Def. 3.1-3.3 by brute force: the largest c1' for which the symmetric lens N_γ(c1',c1') of
 * u-w is empty: min over points p seeing u-w under an obtuse angle θ of sin θ - 1; 0 when no
 * point does (an empty Gabriel disc); -2 when a point lies on the open segment. */
static double brute_lens_param(const double *xy, size_t n, uint32_t u, uint32_t w)
{
    const double *pu = xy + 2 * (size_t)u, *pw = xy + 2 * (size_t)w;
    double min_sin = 1;
    for (size_t i = 0; i < n; i++) {
        if (i == u || i == w) continue;
        const double *p = xy + 2 * i;
        double ax = pu[0] - p[0], ay = pu[1] - p[1], bx = pw[0] - p[0], by = pw[1] - p[1];
        if (ax * bx + ay * by >= 0) continue;
        if (fl_orient2d(pu, pw, p) == 0) return -2;
        double s = fabs(ax * by - ay * bx) / hypot(ax, ay) / hypot(bx, by);
        if (s < min_sin) min_sin = s;
    }
    return min_sin < 1 ? min_sin - 1 : 0;
}

static int dt_has_edge(const fl_dt2 *dt, uint32_t a, uint32_t b)
{
    for (size_t t = 0; t < dt->triangle_count; t++)
        for (int k = 0; k < 3; k++)
            if (dt->tri[3 * t + k] == a && dt->tri[3 * t + (k + 1) % 3] == b) return 1;
    return 0;
}

/* Every boundary edge is a Delaunay edge or, when c0 is given, an edge of γ([-1,1],[c0,1]). */
static void check_boundary_edges_in_gamma_graph(const double *xy, size_t n,
                                                const fl_reconstruction2 *rec)
{
    fl_dt2 dt;
    fl_error err;
    CHECK_STATUS(fl_dt2_build(xy, n, NULL, &dt, &err), FL_OK, &err);
    for (size_t i = 0; i < rec->boundary_count; i++) {
        uint32_t a = rec->boundary[i], b = rec->boundary[(i + 1) % rec->boundary_count];
        if (dt_has_edge(&dt, a, b) || dt_has_edge(&dt, b, a)) continue;
        CHECK_MSG(!isnan(rec->augmented_c0), "edge %u-%u is not Delaunay", a, b);
        double c1 = brute_lens_param(xy, n, a, b);
        CHECK_MSG(c1 >= rec->augmented_c0 - 1e-12, "edge %u-%u has c1' = %g < c0 = %g", a, b, c1,
                  rec->augmented_c0);
    }
    fl_dt2_free(&dt);
}

/* The stop rule of Algorithm 5.1 with an empty heap: for every boundary edge, the interior
 * triangle on it has its third vertex on the boundary already. */
static int is_locked(const fl_reconstruction2 *rec, size_t n)
{
    char *on = calloc(n, 1);
    for (size_t i = 0; i < rec->boundary_count; i++)
        on[rec->boundary[i]] = 1;
    int locked = 1;
    for (size_t i = 0; i < rec->boundary_count; i++) {
        uint32_t a = rec->boundary[i], b = rec->boundary[(i + 1) % rec->boundary_count];
        for (size_t t = 0; t < rec->triangle_count; t++)
            for (int k = 0; k < 3; k++)
                if (rec->tri[3 * t + k] == a && rec->tri[3 * t + (k + 1) % 3] == b &&
                    !on[rec->tri[3 * t + (k + 2) % 3]])
                    locked = 0;
    }
    free(on);
    return locked;
}

static void test_locked_delaunay_constriction_is_completed_by_augmentation(void)
{
    int locked_count = 0;
    for (unsigned long long seed = 1; seed <= 60; seed++) {
        size_t n = 12 + (size_t)(seed % 30);
        double *xy = random_points(n, seed);
        fl_reconstruct2_options pure = {0};
        pure.extra_levels = -1;
        fl_reconstruction2 a, b;
        fl_error err;
        CHECK_STATUS(fl_reconstruct2(xy, n, &pure, &a, &err), FL_OK, &err);
        CHECK_STATUS(fl_reconstruct2(xy, n, NULL, &b, &err), FL_OK, &err);
        rt_check_valid(xy, &a);
        rt_check_valid(xy, &b);
        CHECK_MSG(b.all_on_boundary, "seed %llu: %s", seed, b.reason);
        check_boundary_edges_in_gamma_graph(xy, n, &a);
        check_boundary_edges_in_gamma_graph(xy, n, &b);
        if (a.all_on_boundary) {
            CHECK(isnan(b.augmented_c0));
            CHECK_EQ_INT(a.boundary_count, b.boundary_count);
            CHECK(memcmp(a.boundary, b.boundary, a.boundary_count * sizeof *a.boundary) == 0);
        } else {
            locked_count++;
            CHECK(is_locked(&a, n));
            CHECK(strstr(a.reason, "locked") != NULL);
            CHECK(b.augmented_c0 >= -1 && b.augmented_c0 < 0);
        }
        fl_reconstruction2_free(&a);
        fl_reconstruction2_free(&b);
        free(xy);
    }
    CHECK_MSG(locked_count >= 5, "only %d of 60 sets locked; the test needs locked cases",
              locked_count);
}

static void test_random_sets_of_every_criterion_give_polygons_through_all_points(void)
{
    for (int c = 0; c < 3; c++)
        for (unsigned long long seed = 100; seed < 110; seed++) {
            size_t n = 300;
            double *xy = random_points(n, seed);
            fl_reconstruct2_options opt = {0};
            opt.criterion = (fl_reconstruct2_criterion)c;
            fl_reconstruction2 rec;
            fl_error err;
            CHECK_STATUS(fl_reconstruct2(xy, n, &opt, &rec, &err), FL_OK, &err);
            rt_check_valid(xy, &rec);
            CHECK_MSG(rec.all_on_boundary, "criterion %d seed %llu: %s", c, seed, rec.reason);
            check_boundary_edges_in_gamma_graph(xy, n, &rec);
            fl_reconstruction2_free(&rec);
            free(xy);
        }
}

FL_TEST_MAIN(FL_TEST_CASE(test_locked_delaunay_constriction_is_completed_by_augmentation),
             FL_TEST_CASE(test_random_sets_of_every_criterion_give_polygons_through_all_points))
