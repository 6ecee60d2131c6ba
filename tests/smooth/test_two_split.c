/* Properties of the two-split surfaces (thesis §9.7 as printed: thin triangle pairs split in
 * two inside a three-split surface) on meshes with thin triangles: icospheres stretched 1:1:8
 * and flattened 8:8:1 and the demo torus. What holds: interpolation, the three-split parts stay
 * G1, eq. 9.6 makes every spoke tangent-plane continuous up to the split point S. What does not
 * (docs/smooth.md derives it): at S the constant multipliers of eq. 9.5 force the four points Y_i
 * onto one line through Z, so the micro patches have no common tangent plane there; the test
 * asserts that degeneracy, the reason the scheme is not exposed as G1. The G1 oracle
 * (g1_oracle.h) pairs patch edges by sorting, independently of the library. */
#include "cli/cli_run.h"
#include "g1_oracle.h"

enum { MESHES = 5 };

static fl_mesh scaled(fl_mesh m, double sx, double sy, double sz)
{
    for (size_t v = 0; v < m.vertex_count; v++) {
        m.xyz[3 * v] *= sx;
        m.xyz[3 * v + 1] *= sy;
        m.xyz[3 * v + 2] *= sz;
    }
    return m;
}

static fl_mesh test_mesh(int i)
{
    fl_mesh m = {0};
    fl_error err;
    switch (i) {
    case 0:
        return scaled(g1_icosphere(1, 0, 1), 1, 1, 8);
    case 1:
        return scaled(g1_icosphere(2, 0, 1), 1, 1, 8);
    case 2:
        return scaled(g1_icosphere(2, 0, 1), 8, 8, 1);
    case 3:
        return scaled(g1_icosphere(1, 0, 1), 8, 8, 1);
    default:
        CHECK_STATUS(fl_read_mesh(FL_SOURCE_DIR "/data/demo/torus.off", &m, &err), FL_OK, &err);
        return m;
    }
}

static fl_g1_surface build(const fl_mesh *m, int scheme)
{
    fl_g1_surface s;
    fl_error err;
    fl_g1_surface_options o = {.scheme = scheme};
    CHECK_STATUS(fl_g1_surface_build(m, &o, &s, &err), FL_OK, &err);
    return s;
}

/* Largest normal jump over patch edges of one kind: 0 inside a pair (spokes), 1 between a pair
 * patch and a three-split patch, 2 elsewhere. Pair patches come first (4 a pair). */
static double jump_of_kind(const fl_g1_surface *s, int kind, int samples)
{
    size_t ne = 3 * s->patch_count, np = 4 * s->two_split_pairs;
    g1_pe *pe = g1_sorted_patch_edges(s);
    double worst = 0;
    for (size_t i = 0; i + 1 < ne; i++) {
        if (pe[i].key != pe[i + 1].key) continue;
        uint32_t a = pe[i].pe, b = pe[i + 1].pe;
        int in_a = a / 3 < np, in_b = b / 3 < np;
        int k = in_a && in_b ? 0 : in_a != in_b ? 1 : 2;
        if (k == kind)
            for (int j = 0; j <= samples; j++) {
                double t = (double)j / samples, pa[3], na[3], pb[3], nb[3];
                g1_edge_point(s, a, t, 0, pa, na);
                g1_edge_point(s, b, 1 - t, 0, pb, nb);
                worst = fmax(worst, g1_angle_deg(na, nb));
            }
        i++;
    }
    free(pe);
    return worst;
}

/* Every patch corner at a mesh vertex is the vertex, with the surface's vertex normal. */
static void test_two_split_interpolates_vertices_and_normals_to_1e12(void)
{
    for (int i = 0; i < 2 * MESHES; i++) {
        fl_mesh m = test_mesh(i / 2);
        fl_g1_surface s = build(&m, i % 2 ? FL_G1_TWO_SPLIT_AS_PRINTED : FL_G1_TWO_SPLIT);
        CHECK_MSG(s.two_split_pairs > 0, "mesh %d has no thin pair", i);
        CHECK_EQ_INT(s.patch_count, 3 * m.triangle_count - 2 * s.two_split_pairs);
        double verr, nerr;
        g1_corner_errors(&s, &m, NULL, &verr, &nerr, NULL);
        CHECK_MSG(verr <= 1e-12 && nerr <= 1e-12, "mesh %d: vertex %g normal %g", i, verr, nerr);
        fl_g1_surface_free(&s);
        fl_mesh_free(&m);
    }
}

/* §9.7: "the two two-split triangles have four three-split triangles as neighbors": a patch
 * edge shared by two pair patches is a spoke (it ends at a split point, node >= vertex_count),
 * and one triangle of every pair is thin (its three-split at the centroid has an angle < 15°). */
static void test_two_split_pairs_are_thin_and_isolated(void)
{
    for (int i = 0; i < MESHES; i++) {
        fl_mesh m = test_mesh(i);
        fl_g1_surface s = build(&m, FL_G1_TWO_SPLIT);
        size_t np = 4 * s.two_split_pairs;
        for (size_t a = 0; a < 3 * np; a++)
            for (size_t b = a + 1; b < 3 * np; b++) {
                uint32_t a0 = s.corner[a], a1 = s.corner[3 * (a / 3) + (a + 1) % 3];
                uint32_t b0 = s.corner[b], b1 = s.corner[3 * (b / 3) + (b + 1) % 3];
                if (a0 == b1 && a1 == b0)
                    CHECK(a0 >= m.vertex_count || a1 >= m.vertex_count);
            }
        for (size_t pr = 0; pr < s.two_split_pairs; pr++) {
            double worst = 180;
            for (size_t p = 4 * pr; p < 4 * pr + 4; p++) {
                const uint32_t *t = m.tri + 3 * s.macro[p];
                double c[3];
                for (int d = 0; d < 3; d++)
                    c[d] = (m.xyz[3 * t[0] + d] + m.xyz[3 * t[1] + d] + m.xyz[3 * t[2] + d]) / 3;
                for (int k = 0; k < 3; k++) {
                    const double *q[3] = {m.xyz + 3 * t[k], m.xyz + 3 * t[(k + 1) % 3], c};
                    for (int r = 0; r < 3; r++) {
                        double u[3], v[3];
                        for (int d = 0; d < 3; d++) {
                            u[d] = q[(r + 1) % 3][d] - q[r][d];
                            v[d] = q[(r + 2) % 3][d] - q[r][d];
                        }
                        worst = fmin(worst, g1_angle_deg(u, v));
                    }
                }
            }
            CHECK_MSG(worst < 15, "mesh %d pair %zu: three-split angle %g", i, pr, worst);
        }
        fl_g1_surface_free(&s);
        fl_mesh_free(&m);
    }
}

/* The two-split (cross split) is G1 on every micro and macro edge: the normals of the two
 * patches agree to < 1e-7 degrees at 33 points of every patch edge, the patches lie on
 * opposite sides, every edge has its partner; the library's measure agrees. As printed
 * (FL_G1_TWO_SPLIT_AS_PRINTED) the edges away from the pairs stay G1 too. */
static void test_two_split_is_g1_on_every_micro_and_macro_edge(void)
{
    for (int i = 0; i < MESHES; i++) {
        fl_mesh m = test_mesh(i);
        fl_g1_surface s = build(&m, FL_G1_TWO_SPLIT);
        size_t flips, unpaired;
        double jump = g1_max_edge_jump(&s, 32, &flips, &unpaired);
        CHECK_MSG(jump < 1e-7, "mesh %d: normal jump %g degrees", i, jump);
        CHECK_EQ_INT(flips, 0);
        CHECK_EQ_INT(unpaired, 0);
        fl_g1_metrics mt;
        fl_error err;
        CHECK_STATUS(fl_g1_surface_measure(&s, &m, 4, &mt, &err), FL_OK, &err);
        CHECK(mt.max_edge_normal_jump_deg < 1e-7 && mt.orientation_flips == 0);
        fl_g1_surface_free(&s);
        if (i == 4) {
            fl_mesh_free(&m);
            continue; /* time */
        }
        s = build(&m, FL_G1_TWO_SPLIT_AS_PRINTED);
        double j = jump_of_kind(&s, 2, 16);
        CHECK_MSG(j < 1e-7, "mesh %d: %g degrees", i, j);
        fl_g1_surface_free(&s);
        fl_mesh_free(&m);
    }
}

/* Inside a pair the cross split's rows are the C1 conditions over the square domain:
 * W_i = (E_i-1,1 + E_i,0)/2, Y_i = (X_i-1 + X_i)/2, Z = (Y_i-1 + Y_i+1)/2 for every i, so the
 * corner at S is regular: Y_k - Z and Y_k+1 - Z are not parallel. */
static void test_two_split_pairs_are_c1_cross_splits(void)
{
    for (int i = 0; i < MESHES; i++) {
        fl_mesh m = test_mesh(i);
        fl_g1_surface s = build(&m, FL_G1_TWO_SPLIT);
        double worst = 0, span = 1e300;
        for (size_t pr = 0; pr < s.two_split_pairs; pr++) {
            const double *c[4];
            for (int k = 0; k < 4; k++)
                c[k] = s.ctrl + 30 * (4 * pr + (size_t)k);
            for (int k = 0; k < 4; k++) {
                const double *L = c[(k + 3) % 4], *R = c[k], *N = c[(k + 1) % 4];
                double y0[3], y1[3];
                for (int d = 0; d < 3; d++) {
                    /* W_k (b201 of R) and b021 of L; E_k-1,1 = b120 of L, E_k,0 = b210 of R */
                    worst = fmax(worst, fabs(R[6 + d] - L[21 + d]));
                    worst = fmax(worst, fabs(R[6 + d] - (L[9 + d] + R[3 + d]) / 2));
                    worst = fmax(worst, fabs(R[15 + d] - (L[12 + d] + R[12 + d]) / 2));
                    worst = fmax(worst, fabs(R[27 + d] - (L[15 + d] + N[15 + d]) / 2));
                    y0[d] = R[15 + d] - R[27 + d];
                    y1[d] = R[24 + d] - R[27 + d];
                }
                double a = g1_angle_deg(y0, y1);
                span = fmin(span, fmin(a, 180 - a));
            }
        }
        CHECK_MSG(worst < 1e-12, "mesh %d: C1 relation off by %g", i, worst);
        /* measured minimum 0.63 degrees, on the flattened icosphere's rim */
        CHECK_MSG(span > 0.1, "mesh %d: Y_k - Z, Y_k+1 - Z at %g degrees", i, span);
        fl_g1_surface_free(&s);
        fl_mesh_free(&m);
    }
}

/* AS PRINTED. Eq. 9.6 holds: along every spoke the two micro patches share the tangent plane (normals
 * agree to 1e-7° at 20 points up to 95% of the way to S). At S itself the four Y_i lie on one
 * line through Z or onto Z ((Y_i - Z) x (Y_i+1 - Z) < 1e-9 |V_i - Z|^2): every micro
 * patch is degenerate there, so the normals at S are not defined by the first derivatives and
 * differ (by up to 172° on the stretched icosphere): NOT G1, as derived in docs/smooth.md. */
static void test_two_split_spokes_continuous_but_degenerate_at_split_point(void)
{
    for (int i = 0; i < MESHES; i++) {
        fl_mesh m = test_mesh(i);
        fl_g1_surface s = build(&m, FL_G1_TWO_SPLIT_AS_PRINTED);
        double along = 0, sine = 0, at_s = 0;
        for (size_t pr = 0; pr < s.two_split_pairs; pr++) {
            const double *c[4];
            for (int k = 0; k < 4; k++)
                c[k] = s.ctrl + 30 * (4 * pr + (size_t)k);
            for (int k = 0; k < 4; k++) {
                const double *L = c[(k + 3) % 4], *R = c[k];
                for (int q = 0; q <= 20; q++) {
                    double t = 0.95 * q / 20, pl[3], nl[3], pr3[3], nr[3];
                    fl_g1_patch_eval(L, 0, 1 - t, t, pl, nl);
                    fl_g1_patch_eval(R, 1 - t, 0, t, pr3, nr);
                    along = fmax(along, g1_angle_deg(nl, nr));
                }
                double nl[3], nr[3];
                fl_g1_patch_eval(L, 0, 0, 1, NULL, nl);
                fl_g1_patch_eval(R, 0, 0, 1, NULL, nr);
                at_s = fmax(at_s, g1_angle_deg(nl, nr));
                /* b102 = Y_k, b012 = Y_k+1, b003 = Z, b300 = V_k in patch k (order b300 ...
                 * b003); the area they span at Z against the spoke's length squared */
                double y0[3], y1[3], sp[3], x[3];
                for (int d = 0; d < 3; d++) {
                    y0[d] = R[15 + d] - R[27 + d];
                    y1[d] = R[24 + d] - R[27 + d];
                    sp[d] = R[d] - R[27 + d];
                }
                x[0] = y0[1] * y1[2] - y0[2] * y1[1];
                x[1] = y0[2] * y1[0] - y0[0] * y1[2];
                x[2] = y0[0] * y1[1] - y0[1] * y1[0];
                sine = fmax(sine, sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) /
                                      (sp[0] * sp[0] + sp[1] * sp[1] + sp[2] * sp[2]));
            }
        }
        CHECK_MSG(along < 1e-7, "mesh %d: spoke jump %g", i, along);
        CHECK_MSG(sine < 1e-9, "mesh %d: Y_i span %g at Z", i, sine);
        fprintf(stderr, "mesh %d: spokes %.2g deg, Y span %.2g, jump at S %.3g deg\n", i,
                along, sine, at_s);
        fl_g1_surface_free(&s);
        fl_mesh_free(&m);
    }
}

/* Patches share their boundary curves exactly (the split point is one node for both triangles
 * of a pair), so the tessellation is a closed, oriented manifold of the input's genus. */
static void test_two_split_tessellation_is_watertight(void)
{
    for (int i = 0; i < MESHES; i++) {
        fl_mesh m = test_mesh(i), tm;
        fl_g1_surface s = build(&m, FL_G1_TWO_SPLIT);
        fl_error err;
        double *n = NULL;
        unsigned density = i == 4 ? 2 : 3;
        CHECK_STATUS(fl_g1_surface_tessellate(&s, density, &tm, &n, &err), FL_OK, &err);
        fl_mesh_report r, r0;
        fl_mesh_check_options skip = {.skip_self_intersections = 1};
        CHECK_STATUS(fl_mesh_check(&tm, &skip, &r, &err), FL_OK, &err);
        CHECK_STATUS(fl_mesh_check(&m, &skip, &r0, &err), FL_OK, &err);
        CHECK(r.closed && r.manifold && r.oriented);
        CHECK_EQ_INT(r.genus, r0.genus);
        CHECK_EQ_INT(r.duplicate_vertices, 0);
        CHECK_EQ_INT(tm.triangle_count, s.patch_count * density * density);
        CHECK_EQ_INT((long long)tm.vertex_count,
                     (long long)tm.triangle_count / 2 + 2 - 2 * r0.genus);
        fl_mesh_report_free(&r);
        fl_mesh_report_free(&r0);
        free(n);
        fl_mesh_free(&tm);
        fl_g1_surface_free(&s);
        fl_mesh_free(&m);
    }
}

/* Smallest angle of the triangles spanned by the patch corners (the micro triangles §9.7 wants
 * less thin). */
static double min_corner_angle(const fl_g1_surface *s)
{
    double worst = 180;
    for (size_t p = 0; p < s->patch_count; p++) {
        const double *c = s->ctrl + 30 * p, *q[3] = {c, c + 18, c + 27};
        for (int r = 0; r < 3; r++) {
            double u[3], v[3];
            for (int d = 0; d < 3; d++) {
                u[d] = q[(r + 1) % 3][d] - q[r][d];
                v[d] = q[(r + 2) % 3][d] - q[r][d];
            }
            worst = fmin(worst, g1_angle_deg(u, v));
        }
    }
    return worst;
}

/* The numbers of docs/smooth.md: jumps by edge kind and deviation, two- vs three-split. */
static void test_two_split_report(void)
{
    for (int i = 0; i < MESHES; i++) {
        fl_mesh m = test_mesh(i);
        fl_g1_surface s = build(&m, FL_G1_TWO_SPLIT_AS_PRINTED), t = build(&m, FL_G1_THREE_SPLIT);
        fl_g1_surface c = build(&m, FL_G1_TWO_SPLIT);
        fl_g1_metrics ms, mt, mc;
        fl_error err;
        CHECK_STATUS(fl_g1_surface_measure(&s, &m, 8, &ms, &err), FL_OK, &err);
        CHECK_STATUS(fl_g1_surface_measure(&t, &m, 8, &mt, &err), FL_OK, &err);
        CHECK_STATUS(fl_g1_surface_measure(&c, &m, 8, &mc, &err), FL_OK, &err);
        fprintf(stderr,
                "mesh %d: %zu triangles, %zu pairs\n"
                "  two-split:  jump %.2g flips %zu dev %.3g corner angle %.3g\n"
                "  three-split: jump %.2g flips %zu dev %.3g corner angle %.3g\n"
                "  as printed: jump %.3g (inner %.3g outer %.3g) flips %zu dev %.3g corner "
                "angle %.3g\n",
                i, m.triangle_count, c.two_split_pairs, mc.max_edge_normal_jump_deg,
                mc.orientation_flips, mc.max_deviation, min_corner_angle(&c),
                mt.max_edge_normal_jump_deg, mt.orientation_flips, mt.max_deviation,
                min_corner_angle(&t), ms.max_edge_normal_jump_deg, jump_of_kind(&s, 0, 16),
                jump_of_kind(&s, 1, 16), ms.orientation_flips, ms.max_deviation,
                min_corner_angle(&s));
        fl_g1_surface_free(&c);
        fl_g1_surface_free(&s);
        fl_g1_surface_free(&t);
        fl_mesh_free(&m);
    }
}

static void test_two_split_cli(void)
{
    cli_result r;
    CHECK_EQ_INT(cli_run(&r, "smooth " FL_SOURCE_DIR "/data/demo/torus.off --scheme two-split "
                             "--samples 2 --json"),
                 0);
    const char *p = strstr(r.out, "\"patches\":");
    CHECK(p && strtod(p + 10, NULL) < 3 * 1024 && strtod(p + 10, NULL) > 2 * 1024);
    CHECK(strstr(r.out, "\"two_split_pairs\":") != NULL);
}

FL_TEST_MAIN(FL_TEST_CASE(test_two_split_interpolates_vertices_and_normals_to_1e12),
             FL_TEST_CASE(test_two_split_pairs_are_thin_and_isolated),
             FL_TEST_CASE(test_two_split_is_g1_on_every_micro_and_macro_edge),
             FL_TEST_CASE(test_two_split_pairs_are_c1_cross_splits),
             FL_TEST_CASE(test_two_split_spokes_continuous_but_degenerate_at_split_point),
             FL_TEST_CASE(test_two_split_tessellation_is_watertight),
             FL_TEST_CASE(test_two_split_report), FL_TEST_CASE(test_two_split_cli))
