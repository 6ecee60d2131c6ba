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

/* Non-degenerate point sets whose Delaunay triangulations have no Hamilton cycle, of the kind
 * Dillencourt (1987) gave (thesis Fig. 5.7: two-connected, with ears on the hull). Found by hill
 * climbing on the number of Hamilton cycles of the triangulation (moving one point at a time,
 * counting cycles by the subset dynamic programme below) until it reached zero; the test
 * re-establishes every property from scratch. */
static const double nonhamiltonian14[] = {
    0.87344180652821568, 0.75856344681734933,  0.42842007050772019, 0.56951737494597265,
    0.33178206694350287, 0.12079442933831025,  0.66162753618051995, 0.4977587944365382,
    0.24931437765604672, 0.3733486789191362,   1.061380461282702,   0.57142263460382703,
    1.0819712406910245,  0.61515547399880977,  0.41377690945551904, 0.94684851530823433,
    0.57503861134779222, 0.50406134087555188,  0.56799698533159326, 0.026450934615847022,
    0.42877776357501485, 0.98596504046728051,  0.40125592015090722, 0.086491636777327255,
    0.69623950916967547, 0.097119702240372849, 0.71260487395776595, 0.41460633247259954};

static const double nonhamiltonian13[] = {
    0.036781046409392733, -0.070515552665459225, -0.31171858618637505, -0.31004655372555334,
    0.15243146863975288,  0.030459720470631044,  0.22805732788918942,  0.03217854611062735,
    -0.47597884691188097, -0.38030421815555787,  0.57236812647075597,  0.47229287035284651,
    0.78278716989161679,  0.23052821573958554,   0.81364665287029347,  0.92231825176826054,
    0.74441575964962325,  0.91365670955339351,   1.0088963967012814,   0.34305966757201328,
    0.45240863680887933,  0.63358004731375739,   0.58094201814991198,  0.40811400315046947,
    0.90665228196368419,  0.65917932221027287};

/* Number of Hamilton cycles of the graph with adjacency bitmasks adj[0..n-1] (n <= 16), by
 * dynamic programming over (visited set, last vertex) from vertex 0. */
static double hamilton_cycles(int n, const uint32_t *adj)
{
    size_t full = (size_t)1 << n;
    double *dp = calloc(full * (size_t)n, sizeof *dp), total = 0;
    dp[1 * (size_t)n + 0] = 1;
    for (size_t m = 1; m < full; m += 2)
        for (int v = 0; v < n; v++) {
            double c = dp[m * (size_t)n + (size_t)v];
            for (int w = 0; w < n && c > 0; w++)
                if ((adj[v] >> w & 1) && !(m >> w & 1))
                    dp[(m | (1u << w)) * (size_t)n + (size_t)w] += c;
        }
    for (int v = 1; v < n; v++)
        if (adj[v] & 1) total += dp[(full - 1) * (size_t)n + (size_t)v];
    free(dp);
    return total / 2;
}

static void check_non_hamiltonian_set(const double *xy, int n)
{
    /* non-degenerate: no four points cocircular, no three collinear */
    int degenerate = 0;
    for (int a = 0; a < n; a++)
        for (int b = a + 1; b < n; b++)
            for (int c = b + 1; c < n; c++) {
                degenerate += fl_orient2d(xy + 2 * a, xy + 2 * b, xy + 2 * c) == 0;
                for (int d = c + 1; d < n; d++)
                    degenerate += fl_incircle(xy + 2 * a, xy + 2 * b, xy + 2 * c, xy + 2 * d) == 0;
            }
    CHECK_EQ_INT(degenerate, 0);
    fl_dt2 dt;
    fl_error err;
    CHECK_STATUS(fl_dt2_build(xy, (size_t)n, NULL, &dt, &err), FL_OK, &err);
    uint32_t adj[16] = {0};
    for (size_t t = 0; t < dt.triangle_count; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t a = dt.tri[3 * t + k], b = dt.tri[3 * t + (k + 1) % 3];
            adj[a] |= 1u << b, adj[b] |= 1u << a;
            for (int p = 0; p < n;
                 p++) /* brute-force empty circles: it is the Delaunay triangulation */
                CHECK(fl_incircle(xy + 2 * dt.tri[3 * t], xy + 2 * dt.tri[3 * t + 1],
                                  xy + 2 * dt.tri[3 * t + 2], xy + 2 * p) <= 0);
        }
    CHECK(hamilton_cycles(n, adj) == 0);
    fl_dt2_free(&dt);

    fl_reconstruct2_options pure = {0};
    pure.extra_levels = -1;
    fl_reconstruction2 a, b;
    CHECK_STATUS(fl_reconstruct2(xy, (size_t)n, &pure, &a, &err), FL_OK, &err);
    rt_check_valid(xy, &a);
    CHECK(!a.all_on_boundary); /* no Hamilton polygon exists in the Delaunay triangulation */
    CHECK(is_locked(&a, (size_t)n));
    CHECK_STATUS(fl_reconstruct2(xy, (size_t)n, NULL, &b, &err), FL_OK, &err);
    rt_check_valid(xy, &b);
    CHECK_MSG(b.all_on_boundary, "%s", b.reason);
    CHECK(b.augmented_c0 >= -1 && b.augmented_c0 < 0);
    check_boundary_edges_in_gamma_graph(xy, (size_t)n, &b);
    fl_reconstruction2_free(&a);
    fl_reconstruction2_free(&b);
}

static void test_non_hamiltonian_delaunay_triangulation_is_solved_by_augmentation(void)
{
    int n = (int)(sizeof nonhamiltonian14 / sizeof nonhamiltonian14[0] / 2);
    double xy[2 * 16];
    check_non_hamiltonian_set(nonhamiltonian14, n);
    for (int i = 0; i < n; i++) /* mirrored and scaled by 2^10: exact, same combinatorics */
        xy[2 * i] = -1024 * nonhamiltonian14[2 * i],
               xy[2 * i + 1] = 1024 * nonhamiltonian14[2 * i + 1];
    check_non_hamiltonian_set(xy, n);
    check_non_hamiltonian_set(nonhamiltonian13, 13);
}

/* extra_levels = L tries c0 = -1/L, -2/L, ..., -1 in turn and reports the first that finished. */
static void test_augmented_c0_is_one_of_the_requested_levels(void)
{
    int seen = 0;
    for (unsigned long long seed = 1; seed <= 30; seed++) {
        size_t n = 40;
        double *xy = random_points(n, seed);
        fl_reconstruct2_options one = {0}, ten = {0};
        one.extra_levels = 1;
        fl_reconstruction2 a, b;
        fl_error err;
        CHECK_STATUS(fl_reconstruct2(xy, n, &one, &a, &err), FL_OK, &err);
        CHECK_STATUS(fl_reconstruct2(xy, n, &ten, &b, &err), FL_OK, &err);
        CHECK(a.all_on_boundary && b.all_on_boundary);
        CHECK(isnan(a.augmented_c0) == isnan(b.augmented_c0));
        if (!isnan(a.augmented_c0)) {
            seen++;
            CHECK(a.augmented_c0 == -1);
            double k = -10 * b.augmented_c0;
            CHECK(k >= 1 && k <= 10 && fabs(k - round(k)) < 1e-9);
        }
        fl_reconstruction2_free(&a);
        fl_reconstruction2_free(&b);
        free(xy);
    }
    CHECK(seen > 0);
}

static int cancel_constriction(void *user, const char *stage, double fraction)
{
    (void)fraction;
    ++*(int *)user;
    return strcmp(stage, "constriction") == 0;
}

static void test_progress_callback_can_cancel_constriction(void)
{
    size_t n = 20000;
    double *xy = rt_star(n, 5, 0.4);
    int calls = 0;
    fl_reconstruct2_options opt = {0};
    opt.progress = cancel_constriction;
    opt.progress_user = &calls;
    fl_reconstruction2 rec;
    fl_error err;
    CHECK_STATUS(fl_reconstruct2(xy, n, &opt, &rec, &err), FL_ERR_ALGORITHM, &err);
    CHECK(strstr(err.message, "cancelled") != NULL);
    CHECK(rec.boundary == NULL);
    CHECK(calls > 0);
    free(xy);
}

FL_TEST_MAIN(FL_TEST_CASE(test_locked_delaunay_constriction_is_completed_by_augmentation),
             FL_TEST_CASE(test_random_sets_of_every_criterion_give_polygons_through_all_points),
             FL_TEST_CASE(test_non_hamiltonian_delaunay_triangulation_is_solved_by_augmentation),
             FL_TEST_CASE(test_augmented_c0_is_one_of_the_requested_levels),
             FL_TEST_CASE(test_progress_callback_can_cancel_constriction))
