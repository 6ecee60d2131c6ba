/* The reductions of thesis §3.2 and the classical graphs of §2.2, each against a brute-force
 * reading of its definition with exact (GMP) predicates. */
#include "gamma_oracle.h"

static fl_graph gamma_graph(const double *p, size_t n, int dim, int range, double c0, double c1,
                            double c2, double c3)
{
    fl_gamma_params gp = {range, {c0, c1, c2, c3}};
    fl_graph g;
    fl_error err;
    CHECK_STATUS(fl_gamma_graph(p, n, dim, &gp, NULL, &g, &err), FL_OK, &err);
    return g;
}

static fl_graph classic(const double *p, size_t n, int dim, fl_graph_kind kind, double param)
{
    fl_graph g;
    fl_error err;
    CHECK_STATUS(fl_classic_graph(p, n, dim, kind, param, &g, &err), FL_OK, &err);
    return g;
}

/* A graph from a predicate over simplices (edges or dim-simplices). */
typedef int (*simplex_pred)(const double *p, size_t n, int dim, const uint32_t *s);

static size_t count_matches(const fl_graph *g, const double *p, size_t n, int dim, int k,
                            simplex_pred pred, int *mismatch)
{
    uint32_t s[3] = {0, 0, 0};
    size_t count = 0;
    *mismatch = 0;
    for (s[0] = 0; s[0] < n; s[0]++)
        for (s[1] = s[0] + 1; s[1] < n; s[1]++)
            for (s[2] = k == 3 ? s[1] + 1 : 0; k == 2 || s[2] < n; s[2]++) {
                int want = pred(p, n, dim, s);
                count += want;
                if (want != oracle_graph_has(g, s) && (*mismatch)++ < 3)
                    fprintf(stderr, "simplex %u %u %u: definition says %d\n", s[0], s[1],
                            k == 3 ? s[2] : 0, want);
                if (k == 2) break;
            }
    return count;
}

/* Def. 2.10: no point strictly on one side of the hyperplane, none in the closed simplex. */
static int is_hull_simplex(const double *p, size_t n, int dim, const uint32_t *s)
{
    const double *a = p + s[0] * dim, *b = p + s[1] * dim, *c = dim == 3 ? p + s[2] * dim : NULL;
    int pos = 0, neg = 0;
    if (dim == 3 && oracle_side3(a, b, c, a) == 0) {
        /* collinear triple? test via any projection */
        int flat = 1;
        for (int k = 0; k < 3; k++) {
            double u[2] = {a[(k + 1) % 3], a[(k + 2) % 3]}, v[2] = {b[(k + 1) % 3], b[(k + 2) % 3]},
                   w[2] = {c[(k + 1) % 3], c[(k + 2) % 3]};
            if (oracle_orient2(u, v, w)) flat = 0;
        }
        if (flat) return 0;
    }
    for (size_t i = 0; i < n; i++) {
        if (i == s[0] || i == s[1] || (dim == 3 && i == s[2])) continue;
        const double *q = p + i * dim;
        int o = dim == 2 ? oracle_orient2(a, b, q) : oracle_side3(a, b, c, q);
        pos |= o > 0;
        neg |= o < 0;
        if (o == 0) {
            if (dim == 2) {
                if (oracle_diametral(2, a, b, q) < 0) return 0; /* on the open segment */
                continue;
            }
            int drop = 0; /* project along an axis where the triangle does not degenerate */
            for (int k = 0; k < 3; k++) {
                double u[2] = {a[(k + 1) % 3], a[(k + 2) % 3]},
                       v[2] = {b[(k + 1) % 3], b[(k + 2) % 3]},
                       w[2] = {c[(k + 1) % 3], c[(k + 2) % 3]};
                if (oracle_orient2(u, v, w)) drop = k;
            }
            int i0 = (drop + 1) % 3, i1 = (drop + 2) % 3;
            double u[2] = {a[i0], a[i1]}, v[2] = {b[i0], b[i1]}, w[2] = {c[i0], c[i1]},
                   x[2] = {q[i0], q[i1]};
            int t = oracle_orient2(u, v, w);
            if (oracle_orient2(u, v, x) * t >= 0 && oracle_orient2(v, w, x) * t >= 0 &&
                oracle_orient2(w, u, x) * t >= 0)
                return 0;
        }
    }
    return !(pos && neg);
}

static void test_gamma_minus1_1_is_the_convex_hull(void)
{
    struct {
        int dim, lattice;
        size_t n;
    } sets[] = {{2, 0, 40}, {2, 1, 30}, {3, 0, 14}, {3, 1, 16}};
    for (size_t i = 0; i < 4; i++) {
        int dim = sets[i].dim;
        size_t n = sets[i].n;
        double *p = sets[i].lattice ? oracle_grid_points(n, dim, dim == 2 ? 6 : 3, 600 + i)
                                    : oracle_random_points(n, dim, 600 + i);
        fl_graph g = gamma_graph(p, n, dim, 0, -1, 1, 0, 0),
                 h = gamma_graph(p, n, dim, 0, 1, -1, 0, 0);
        int bad;
        size_t count = count_matches(&g, p, n, dim, dim, is_hull_simplex, &bad);
        CHECK(count > 0);
        CHECK_EQ_INT(bad, 0);
        CHECK(oracle_graph_equal(&g, &h)); /* γ(1,-1) = γ(-1,1) too */
        fl_graph_free(&g);
        fl_graph_free(&h);
        free(p);
    }
}

/* Def. 2.11 for non-degenerate sets: the simplex is a facet of a cell with an empty ball. */
static int is_delaunay_simplex(const double *p, size_t n, int dim, const uint32_t *s)
{
    const double *pts[4];
    for (int k = 0; k < dim; k++)
        pts[k] = p + s[k] * dim;
    for (size_t apex = 0; apex < n; apex++) {
        if (apex == s[0] || apex == s[1] || (dim == 3 && apex == s[2])) continue;
        pts[dim] = p + apex * dim;
        int empty = 1;
        for (size_t q = 0; q < n && empty; q++) {
            if (q == apex || q == s[0] || q == s[1] || (dim == 3 && q == s[2])) continue;
            if (oracle_in_ball(dim, pts, p + q * dim) > 0) empty = 0;
        }
        if (empty) return 1;
    }
    return 0;
}

static void test_gamma_range_minus1_1_0_1_is_delaunay(void)
{
    for (int dim = 2; dim <= 3; dim++) {
        size_t n = dim == 2 ? 16 : 9;
        double *p = oracle_random_points(n, dim, 700 + dim);
        fl_graph g = gamma_graph(p, n, dim, 1, -1, 1, 0, 1);
        fl_graph d = classic(p, n, dim, FL_GRAPH_DELAUNAY, 0);
        int bad;
        count_matches(&g, p, n, dim, dim, is_delaunay_simplex, &bad);
        CHECK_EQ_INT(bad, 0);
        CHECK(oracle_graph_equal(&g, &d));
        fl_graph_free(&g);
        fl_graph_free(&d);
        free(p);
    }
}

static int is_gabriel_edge(const double *p, size_t n, int dim, const uint32_t *s)
{
    for (size_t q = 0; q < n; q++)
        if (q != s[0] && q != s[1] &&
            oracle_diametral(dim, p + s[0] * dim, p + s[1] * dim, p + q * dim) < 0)
            return 0;
    return 1;
}

static void test_gamma_0_0_is_the_gabriel_graph_in_2d(void)
{
    for (int lattice = 0; lattice <= 1; lattice++) {
        size_t n = 40;
        double *p = lattice ? oracle_grid_points(n, 2, 8, 800) : oracle_random_points(n, 2, 801);
        fl_graph g = gamma_graph(p, n, 2, 0, 0, 0, 0, 0),
                 gg = classic(p, n, 2, FL_GRAPH_GABRIEL, 0);
        int bad;
        count_matches(&g, p, n, 2, 2, is_gabriel_edge, &bad);
        CHECK_EQ_INT(bad, 0);
        CHECK(oracle_graph_equal(&g, &gg));
        fl_graph_free(&g);
        fl_graph_free(&gg);
        free(p);
    }
}

static void test_gabriel_graph_3d_matches_definition_2_9(void)
{
    for (int lattice = 0; lattice <= 1; lattice++) {
        size_t n = 20;
        double *p = lattice ? oracle_grid_points(n, 3, 4, 810) : oracle_random_points(n, 3, 811);
        fl_graph gg = classic(p, n, 3, FL_GRAPH_GABRIEL, 0);
        int bad;
        count_matches(&gg, p, n, 3, 2, is_gabriel_edge, &bad);
        CHECK_EQ_INT(bad, 0);
        fl_graph_free(&gg);
        free(p);
    }
}

static double beta_param;

/* Def. 2.15 literally: two discs of radius d/(2(1-|b|)) with centres on opposite sides;
 * intersection for b < 0, union for b >= 0. */
static int is_beta_circle_edge(const double *p, size_t n, int dim, const uint32_t *s)
{
    return oracle_gamma_empty(p, n, dim, s, beta_param, beta_param);
}

static void test_gamma_c_c_is_the_circle_beta_skeleton(void)
{
    const double betas[] = {-0.9, -0.5, -0.2, 0, 0.1, 0.2, 0.6};
    double *p = oracle_random_points(30, 2, 900);
    for (size_t i = 0; i < sizeof betas / sizeof betas[0]; i++) {
        beta_param = betas[i];
        fl_graph g = gamma_graph(p, 30, 2, 0, betas[i], betas[i], 0, 0);
        fl_graph b = classic(p, 30, 2, FL_GRAPH_BETA_CIRCLE, betas[i]);
        int bad;
        count_matches(&b, p, 30, 2, 2, is_beta_circle_edge, &bad);
        CHECK_EQ_INT(bad, 0);
        CHECK(oracle_graph_equal(&g, &b));
        fl_graph_free(&g);
        fl_graph_free(&b);
    }
    free(p);
}

static void test_gamma_1_1_is_empty_and_minus1_minus1_complete(void)
{
    for (int dim = 2; dim <= 3; dim++) {
        size_t n = dim == 2 ? 25 : 10;
        double *p = oracle_random_points(n, dim, 1000 + dim);
        fl_graph e = gamma_graph(p, n, dim, 0, 1, 1, 0, 0),
                 c = gamma_graph(p, n, dim, 0, -1, -1, 0, 0);
        size_t all = dim == 2 ? n * (n - 1) / 2 : n * (n - 1) * (n - 2) / 6;
        CHECK_EQ_INT(e.simplex_count, 0);
        CHECK_EQ_INT(c.simplex_count, all);
        fl_graph_free(&e);
        fl_graph_free(&c);
        free(p);
    }
}

/* Def. 2.8: no point strictly closer to both ends than they are to each other. */
static int is_rng_edge(const double *p, size_t n, int dim, const uint32_t *s)
{
    const double *a = p + s[0] * dim, *b = p + s[1] * dim;
    for (size_t q = 0; q < n; q++) {
        if (q == s[0] || q == s[1]) continue;
        long double dab = 0, dqa = 0, dqb = 0;
        for (int k = 0; k < dim; k++) {
            long double x = p[q * dim + k];
            dab += ((long double)a[k] - b[k]) * ((long double)a[k] - b[k]);
            dqa += (x - a[k]) * (x - a[k]);
            dqb += (x - b[k]) * (x - b[k]);
        }
        if (dqa < dab && dqb < dab) return 0;
    }
    return 1;
}

static void test_rng_and_lune_skeleton_match_definitions_2_8_and_2_16(void)
{
    for (int dim = 2; dim <= 3; dim++)
        for (int lattice = 0; lattice <= 1; lattice++) {
            size_t n = dim == 2 ? 40 : 20;
            double *p = lattice ? oracle_grid_points(n, dim, dim == 2 ? 8 : 4, 1100)
                                : oracle_random_points(n, dim, 1101);
            fl_graph r = classic(p, n, dim, FL_GRAPH_RNG, 0);
            int bad;
            count_matches(&r, p, n, dim, 2, is_rng_edge, &bad);
            CHECK_EQ_INT(bad, 0);
            if (dim == 2) { /* §2.2.11: β_l(1/2) = RNG, β_l(0) = GG */
                fl_graph l = classic(p, n, 2, FL_GRAPH_BETA_LUNE, 0.5);
                fl_graph l0 = classic(p, n, 2, FL_GRAPH_BETA_LUNE, 0);
                fl_graph gg = classic(p, n, 2, FL_GRAPH_GABRIEL, 0);
                CHECK(oracle_graph_equal(&l, &r));
                CHECK(oracle_graph_equal(&l0, &gg));
                fl_graph_free(&l);
                fl_graph_free(&l0);
                fl_graph_free(&gg);
            }
            fl_graph_free(&r);
            free(p);
        }
}

/* §2.2: NNG ⊆ EMST ⊆ RNG ⊆ GG ⊆ DT (edges of the Delaunay simplices in 3D), CH ⊆ DT. */
static void test_inclusion_chain_nng_emst_rng_gg_dt(void)
{
    for (int dim = 2; dim <= 3; dim++)
        for (unsigned long long seed = 1200; seed < 1203; seed++) {
            size_t n = dim == 2 ? 200 : 60;
            double *p = oracle_random_points(n, dim, seed);
            fl_graph nn = classic(p, n, dim, FL_GRAPH_NNG, 0),
                     mst = classic(p, n, dim, FL_GRAPH_EMST, 0);
            fl_graph rng = classic(p, n, dim, FL_GRAPH_RNG, 0),
                     gg = classic(p, n, dim, FL_GRAPH_GABRIEL, 0);
            fl_graph dt = classic(p, n, dim, FL_GRAPH_DELAUNAY, 0),
                     ch = classic(p, n, dim, FL_GRAPH_CONVEX_HULL, 0);
            CHECK(oracle_graph_subset(&nn, &mst));
            CHECK(oracle_graph_subset(&mst, &rng));
            CHECK(oracle_graph_subset(&rng, &gg));
            CHECK(oracle_graph_subset(&ch, &dt));
            CHECK_EQ_INT(mst.simplex_count, n - 1);
            for (size_t e = 0; e < gg.simplex_count; e++) { /* GG ⊆ DT */
                const uint32_t *g = gg.simplices + 2 * e;
                int found = dim == 2 && oracle_graph_has(&dt, g);
                for (size_t t = 0; dim == 3 && t < dt.simplex_count && !found; t++) {
                    const uint32_t *s = dt.simplices + 3 * t;
                    int has0 = s[0] == g[0] || s[1] == g[0] || s[2] == g[0];
                    int has1 = s[0] == g[1] || s[1] == g[1] || s[2] == g[1];
                    found = has0 && has1;
                }
                CHECK(found);
            }
            fl_graph_free(&nn);
            fl_graph_free(&mst);
            fl_graph_free(&rng);
            fl_graph_free(&gg);
            fl_graph_free(&dt);
            fl_graph_free(&ch);
            free(p);
        }
}

static double dist(const double *a, const double *b, int dim)
{
    double s = 0;
    for (int k = 0; k < dim; k++)
        s += (a[k] - b[k]) * (a[k] - b[k]);
    return sqrt(s);
}

/* The EMST's length equals Prim's O(N^2) tree on the complete graph; every point's NNG edge
 * has the length of its nearest neighbour. */
static void test_emst_length_and_nearest_neighbours_match_brute_force(void)
{
    for (int dim = 2; dim <= 3; dim++) {
        size_t n = 150;
        double *p = oracle_random_points(n, dim, 1300 + dim);
        fl_graph mst = classic(p, n, dim, FL_GRAPH_EMST, 0),
                 nn = classic(p, n, dim, FL_GRAPH_NNG, 0);
        double len = 0, prim = 0, *best = malloc(n * sizeof *best);
        char *in = calloc(n, 1);
        for (size_t e = 0; e < mst.simplex_count; e++)
            len += dist(p + mst.simplices[2 * e] * dim, p + mst.simplices[2 * e + 1] * dim, dim);
        for (size_t i = 0; i < n; i++)
            best[i] = INFINITY;
        best[0] = 0;
        for (size_t it = 0; it < n; it++) {
            size_t u = n;
            for (size_t i = 0; i < n; i++)
                if (!in[i] && (u == n || best[i] < best[u])) u = i;
            in[u] = 1;
            prim += best[u];
            for (size_t i = 0; i < n; i++)
                if (!in[i]) best[i] = fmin(best[i], dist(p + u * dim, p + i * dim, dim));
        }
        CHECK_NEAR(len, prim, 1e-9);
        for (size_t i = 0; i < n; i++) {
            double nearest = INFINITY, mine = INFINITY;
            for (size_t j = 0; j < n; j++)
                if (j != i) nearest = fmin(nearest, dist(p + i * dim, p + j * dim, dim));
            for (size_t e = 0; e < nn.simplex_count; e++) {
                const uint32_t *s = nn.simplices + 2 * e;
                if (s[0] == i || s[1] == i)
                    mine = fmin(mine, dist(p + s[0] * dim, p + s[1] * dim, dim));
            }
            CHECK(mine == nearest);
        }
        free(best);
        free(in);
        fl_graph_free(&mst);
        fl_graph_free(&nn);
        free(p);
    }
}

static double alpha_param;

/* Def. 2.14 with a < 0: an empty ball of radius 1/|a| touches the vertices (edges, 2D). */
static int is_alpha_edge(const double *p, size_t n, int dim, const uint32_t *s)
{
    (void)dim;
    const double *a = p + 2 * s[0], *b = p + 2 * s[1];
    long double rho = 1 / fabsl(alpha_param), r = dist(a, b, 2) / 2;
    if (rho < r) return 0;
    long double t = sqrtl(rho * rho - r * r),
                m[2] = {(a[0] + (long double)b[0]) / 2, (a[1] + (long double)b[1]) / 2};
    long double nx = -(b[1] - (long double)a[1]) / (2 * r),
                ny = (b[0] - (long double)a[0]) / (2 * r);
    for (int side = -1; side <= 1; side += 2) {
        long double cx = m[0] + side * t * nx, cy = m[1] + side * t * ny;
        int empty = 1;
        for (size_t q = 0; q < n && empty; q++) {
            if (q == s[0] || q == s[1]) continue;
            long double dx = p[2 * q] - cx, dy = p[2 * q + 1] - cy;
            if (dx * dx + dy * dy < rho * rho) empty = 0;
        }
        if (empty) return 1;
    }
    return 0;
}

static void test_alpha_shape_matches_definition_2_14(void)
{
    double *p = oracle_random_points(40, 2, 1400);
    const double alphas[] = {-1, -3, -6, -12};
    for (size_t i = 0; i < sizeof alphas / sizeof alphas[0]; i++) {
        alpha_param = alphas[i];
        fl_graph g = classic(p, 40, 2, FL_GRAPH_ALPHA_SHAPE, alphas[i]);
        int bad;
        count_matches(&g, p, 40, 2, 2, is_alpha_edge, &bad);
        CHECK_EQ_INT(bad, 0);
        fl_graph_free(&g);
    }
    fl_graph a0 = classic(p, 40, 2, FL_GRAPH_ALPHA_SHAPE, 0),
             ch = classic(p, 40, 2, FL_GRAPH_CONVEX_HULL, 0);
    fl_graph big = classic(p, 40, 2, FL_GRAPH_ALPHA_SHAPE, 1e-3); /* huge enclosing discs */
    CHECK(oracle_graph_equal(&a0, &ch));
    CHECK(oracle_graph_subset(&big, &ch) && big.simplex_count > 0);
    fl_graph_free(&a0);
    fl_graph_free(&ch);
    fl_graph_free(&big);
    free(p);
}

/* The oracle's own in-ball sign on the unit triangle / tetrahedron, both orientations. */
static void test_oracle_in_ball_signs(void)
{
    double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {0, 1}, in[2] = {0.4, 0.4}, out[2] = {2, 2};
    const double *ccw[3] = {a, b, c}, *cw[3] = {a, c, b};
    CHECK(oracle_in_ball(2, ccw, in) > 0 && oracle_in_ball(2, ccw, out) < 0);
    CHECK(oracle_in_ball(2, cw, in) > 0 && oracle_in_ball(2, cw, out) < 0);
    double A[3] = {0, 0, 0}, B[3] = {1, 0, 0}, C[3] = {0, 1, 0}, D[3] = {0, 0, 1};
    double I[3] = {.2, .2, .2}, O[3] = {3, 3, 3};
    const double *t1[4] = {A, B, C, D}, *t2[4] = {A, C, B, D};
    CHECK(oracle_in_ball(3, t1, I) > 0 && oracle_in_ball(3, t1, O) < 0);
    CHECK(oracle_in_ball(3, t2, I) > 0 && oracle_in_ball(3, t2, O) < 0);
}

static void test_bad_input_is_reported_not_crashed(void)
{
    double p[8] = {0, 0, 1, 0, 0, 1, 1, 0}; /* points 1 and 3 coincide */
    fl_gamma_params gp = {0, {0, 0}};
    fl_graph g;
    fl_error err;
    CHECK_STATUS(fl_gamma_graph(p, 4, 2, &gp, NULL, &g, &err), FL_ERR_INPUT, &err);
    CHECK(strstr(err.message, "1 and 3") != NULL);
    p[6] = NAN;
    CHECK_STATUS(fl_gamma_graph(p, 4, 2, &gp, NULL, &g, &err), FL_ERR_INPUT, &err);
    p[6] = 5;
    gp.c[0] = 0.5; /* |c0| > |c1| */
    CHECK_STATUS(fl_gamma_graph(p, 4, 2, &gp, NULL, &g, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_gamma_graph(p, 4, 4, &gp, NULL, &g, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_classic_graph(p, 1, 3, FL_GRAPH_BETA_LUNE, 0.5, &g, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_gamma_params_parse("0.1,2", &gp, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_gamma_params_parse("0.1,x", &gp, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_gamma_params_parse("-1,1,-0.5,1", &gp, &err), FL_OK, &err);
    CHECK(gp.range == 1 && gp.c[2] == -0.5);
    fl_graph_kind kind;
    double param;
    CHECK_STATUS(fl_graph_kind_parse("beta-lune:0.25", &kind, &param, &err), FL_OK, &err);
    CHECK(kind == FL_GRAPH_BETA_LUNE && param == 0.25);
    CHECK_STATUS(fl_graph_kind_parse("alpha", &kind, &param, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_graph_kind_parse("voronoi", &kind, &param, &err), FL_ERR_USAGE, &err);
    fl_graph_free(&g);                /* zeroed on failure: freeing is a no-op */
    for (size_t n = 0; n <= 2; n++) { /* too few points for a simplex or a triangulation */
        fl_gamma_params dt = {1, {-1, 1, 0, 1}};
        CHECK_STATUS(fl_gamma_graph(p, n, 2, &dt, NULL, &g, &err), FL_OK, &err);
        CHECK_EQ_INT(g.simplex_count, n == 2 ? 1 : 0);
        fl_graph_free(&g);
        CHECK_STATUS(fl_classic_graph(p, n, 2, FL_GRAPH_EMST, 0, &g, &err), FL_OK, &err);
        CHECK_EQ_INT(g.simplex_count, n == 2 ? 1 : 0);
        fl_graph_free(&g);
    }
}

static void test_graph_writers_produce_the_simplices(void)
{
    double *p = oracle_random_points(20, 2, 1500);
    fl_graph g = classic(p, 20, 2, FL_GRAPH_DELAUNAY, 0);
    fl_error err;
    char path[64];
    const char *exts[] = {"svg", "obj", "ply"};
    for (int i = 0; i < 3; i++) {
        snprintf(path, sizeof path, "graph_writer_test.%s", exts[i]);
        CHECK_STATUS(fl_write_graph(path, p, 20, &g, &err), FL_OK, &err);
        FILE *fp = fopen(path, "r");
        CHECK(fp != NULL);
        size_t lines = 0, edges = 0;
        char buf[256];
        while (fp && fgets(buf, sizeof buf, fp)) {
            lines++;
            edges += strncmp(buf, "<line", 5) == 0 || strncmp(buf, "l ", 2) == 0;
        }
        if (fp) fclose(fp);
        if (i < 2) CHECK_EQ_INT(edges, g.simplex_count);
        if (i == 2) CHECK_EQ_INT(lines, 11 + 20 + g.simplex_count); /* 11 header lines */
        remove(path);
    }
    CHECK_STATUS(fl_write_graph("x.txt", p, 20, &g, &err), FL_ERR_USAGE, &err);
    fl_graph_free(&g);
    free(p);
}

FL_TEST_MAIN(FL_TEST_CASE(test_oracle_in_ball_signs),
             FL_TEST_CASE(test_gamma_minus1_1_is_the_convex_hull),
             FL_TEST_CASE(test_gamma_range_minus1_1_0_1_is_delaunay),
             FL_TEST_CASE(test_gamma_0_0_is_the_gabriel_graph_in_2d),
             FL_TEST_CASE(test_gabriel_graph_3d_matches_definition_2_9),
             FL_TEST_CASE(test_gamma_c_c_is_the_circle_beta_skeleton),
             FL_TEST_CASE(test_gamma_1_1_is_empty_and_minus1_minus1_complete),
             FL_TEST_CASE(test_rng_and_lune_skeleton_match_definitions_2_8_and_2_16),
             FL_TEST_CASE(test_inclusion_chain_nng_emst_rng_gg_dt),
             FL_TEST_CASE(test_emst_length_and_nearest_neighbours_match_brute_force),
             FL_TEST_CASE(test_alpha_shape_matches_definition_2_14),
             FL_TEST_CASE(test_bad_input_is_reported_not_crashed),
             FL_TEST_CASE(test_graph_writers_produce_the_simplices))
