/* Regressions for what the round-3 fuzz targets (fuzz_hausdorff, fuzz_smooth, fuzz_hal3,
 * fuzz_skin, fuzz_render) found. Each case is the minimized finding; the answer is checked
 * against an independent method (long-double brute-force distances, tests/sweep/sweep_oracle.h). */
#include <stdio.h>
#include <unistd.h>

#include "degen.h"
#include "sweep/sweep_oracle.h"

static ld brute_mesh_distance(const fl_mesh *m, const double *p)
{
    ld best = INFINITY;
    for (size_t t = 0; t < m->triangle_count; t++) {
        ld d = oracle_mesh_element(m->xyz, m->tri, t, p);
        if (d < best) best = d;
    }
    return best;
}

/* fuzz_hausdorff: with keep_field, a vertex that no triangle uses stayed a placeholder sample at
 * (0, 0, 0) with distance 0 in the field, although the field promises every vertex's distance. */
static void test_hausdorff_field_measures_unused_vertices(void)
{
    double av[] = {10, 20, 30, 0, 0, 0, 1, 0, 0, 0, 1, 0};
    uint32_t at[] = {1, 2, 3};
    double bv[] = {0, 0, 1, 1, 0, 1, 0, 1, 1};
    uint32_t bt[] = {0, 1, 2};
    fl_mesh a = {4, av, 1, at}, b = {3, bv, 1, bt};
    fl_hausdorff_options o = {0};
    o.keep_field = 1;
    fl_hausdorff_result r;
    fl_error err;
    CHECK_STATUS(fl_hausdorff_meshes(&a, &b, &o, &r, &err), FL_OK, &err);
    /* the unused vertex takes no part in the distance: h(A,B) = 1 (the triangles are 1 apart) */
    CHECK_NEAR(r.h_ab[0], 1.0, 1e-9);
    CHECK(r.field_ab.mesh.vertex_count >= 4);
    for (size_t i = 0; i < r.field_ab.mesh.vertex_count; i++) {
        const double *p = r.field_ab.mesh.xyz + 3 * i;
        ld d = brute_mesh_distance(&b, p);
        CHECK_MSG(fabsl((ld)r.field_ab.distance[i] - d) <= 1e-12L * (1 + d),
                  "field vertex %zu (%g %g %g): %.17g, brute force %.17Lg", i, p[0], p[1], p[2],
                  r.field_ab.distance[i], d);
    }
    CHECK(r.field_ab.mesh.xyz[0] == 10 && r.field_ab.mesh.xyz[1] == 20);
    fl_hausdorff_result_free(&r);
}

/* fuzz_hausdorff: the sweep's point-triangle distance overflowed (4th powers of the
 * coordinates) for triangles with edges beyond ~1e77 and underflowed below ~1e-77, so every
 * such triangle fell back to its edges: from (0, 1, 0) s to the triangle 0, (0, 1, 1) s,
 * (1, 1, 0) s it answered s / sqrt(2) instead of s / sqrt(3). */
static void test_sweep_face_distance_at_extreme_scales(void)
{
    static const double scales[] = {1e150, 1e100, 1e80, 1.0, 1e-80, 1e-100};
    for (size_t k = 0; k < sizeof scales / sizeof *scales; k++) {
        double s = scales[k];
        double v[] = {0, 0, 0, 0, s, s, s, s, 0};
        uint32_t t[] = {0, 1, 2};
        fl_mesh m = {3, v, 1, t};
        fl_sweep *sw = NULL;
        fl_error err;
        CHECK_STATUS(fl_sweep_build(&m, NULL, &sw, &err), FL_OK, &err);
        if (!sw) continue;
        double q[] = {0, s, 0, s / 4, s / 2, -s, 0.3 * s, 0.9 * s, 0.1 * s};
        for (int i = 0; i < 3; i++) {
            fl_closest r;
            CHECK_STATUS(fl_sweep_closest(sw, q + 3 * i, 1, 0, &r, &err), FL_OK, &err);
            ld d = brute_mesh_distance(&m, q + 3 * i);
            CHECK_MSG(fabsl((ld)r.distance - d) <= 1e-12L * d,
                      "scale %g, query %d: %.17g, brute force %.17Lg", s, i, r.distance, d);
        }
        CHECK_NEAR(brute_mesh_distance(&m, q) / s, 1 / sqrt(3.0), 1e-12);
        fl_sweep_free(sw);
        /* the same through the Hausdorff distance of the triangle and a point-like triangle */
        double pv[] = {0, s, 0, 0, s, 0, 0, s, 0};
        fl_mesh pm = {3, pv, 1, t};
        fl_hausdorff_result hr;
        CHECK_STATUS(fl_hausdorff_meshes(&pm, &m, NULL, &hr, &err), FL_OK, &err);
        double truth = s / sqrt(3.0);
        CHECK_MSG(hr.h_ab[0] <= truth * (1 + 1e-9) && hr.h_ab[1] >= truth * (1 - 1e-9),
                  "scale %g: h(point, triangle) in [%.17g, %.17g], true %.17g", s, hr.h_ab[0],
                  hr.h_ab[1], s / sqrt(3.0));
        fl_hausdorff_result_free(&hr);
    }
}

/* fuzz_hausdorff: the quadratic bound of a piece summed (a_i - mu)^2 / 2K, whose square
 * underflowed for lengths near 1e-117: a segment of B between two points lying on A got the
 * upper bound 0 (printed 1.6e-124) while its midpoint is s/2 from A. */
static void test_hausdorff_bound_at_1e_117(void)
{
    static const double scales[] = {1.1725540106225486e-117, 1e-100, 1.0, 1e100};
    for (size_t k = 0; k < sizeof scales / sizeof *scales; k++) {
        double s = scales[k];
        double a[] = {0, 0, 0, -s, -s, -s}, b[] = {-s, -s, 0, 0};
        fl_hausdorff_result r;
        fl_error err;
        fl_hausdorff_options o = {0};
        o.both_directions = 1;
        CHECK_STATUS(fl_hausdorff_polylines(a, 3, 0, b, 2, 0, 2, &o, &r, &err), FL_OK, &err);
        /* on b, (-ts, -ts) is min(ts, s - ts) from a: h(b, a) = s / 2 at t = 1/2 */
        CHECK_MSG(r.h_ba[0] <= s / 2 * (1 + 1e-9) && r.h_ba[1] >= s / 2 * (1 - 1e-9),
                  "scale %g: h(b, a) in [%.17g, %.17g], true %.17g", s, r.h_ba[0], r.h_ba[1],
                  s / 2);
        fl_hausdorff_result_free(&r);
    }
}

/* fuzz_smooth: at a turn of 180 degrees minus a rounding error (the neighbours of v 1e-208
 * apart) the weighted tangent sum cancelled exactly and the tangent and two control points
 * were NaN. The curve must interpolate with finite control points. */
static void test_g1_curve_near_spike_is_finite(void)
{
    /* second ring: an edge of 2e-323, whose uniform and inverse weights 1/l, 1/l^2 were inf */
    double rings[2][8] = {{0, 0, 6, -3.375, -7.6592162721380899e-208, 0, 0, 6},
                          {0, 4, 6, 2, 5.625, 5.875, 1.9762625833649862e-323, 4}};
    size_t rs[] = {0, 4}, ps[] = {0, 1};
    for (int w = 0; w < 8; w++) {
        double *xy = rings[w / 4];
        fl_polygon p = {4, xy, 1, rs, 1, ps};
        fl_g1_curve_options o = {w % 4, 0};
        fl_g1_curve c;
        fl_error err;
        CHECK_STATUS(fl_g1_curve_build(&p, &o, &c, &err), FL_OK, &err);
        if (!c.ctrl) continue;
        for (size_t i = 0; i < 4; i++) {
            for (int k = 0; k < 8; k++)
                CHECK_MSG(isfinite(c.ctrl[8 * i + k]), "weighting %d: segment %zu", w, i);
            CHECK_NEAR(hypot(c.tangent[2 * i], c.tangent[2 * i + 1]), 1.0, 1e-12);
            CHECK(c.ctrl[8 * i] == xy[2 * i] && c.ctrl[8 * i + 1] == xy[2 * i + 1]);
        }
        fl_g1_curve_free(&c);
    }
}

/* fuzz_smooth: vertex normals of a mesh at 1e150 came out as the zero vector (|n|^2 overflowed
 * and n / inf = 0 passed as normalized); a mesh at 1e306 gave inf control points and is now
 * outside the documented range. */
static void test_g1_surface_extreme_scales(void)
{
    static const uint32_t tri[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    static const double scales[] = {1e150, 1e-150, 1.0};
    for (size_t k = 0; k < 3; k++) {
        double s = scales[k], v[] = {0, 0, 0, s, 0, 0, 0, s, 0, 0, 0, s};
        fl_mesh m = {4, v, 4, (uint32_t *)tri};
        fl_g1_surface g;
        fl_error err;
        CHECK_STATUS(fl_g1_surface_build(&m, NULL, &g, &err), FL_OK, &err);
        if (!g.normal) continue;
        for (size_t i = 0; i < 4; i++) {
            const double *n = g.normal + 3 * i;
            CHECK_MSG(fabs(sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1) <= 1e-12,
                      "scale %g: normal %zu = (%g, %g, %g)", s, i, n[0], n[1], n[2]);
        }
        for (size_t i = 0; i < 30 * g.patch_count; i++) CHECK(isfinite(g.ctrl[i]));
        fl_g1_surface_free(&g);
    }
    double big[] = {0, 0, 0, 6.25e306, 0, 0, 0, 1, 0, 0, 0, 1};
    fl_mesh bm = {4, big, 4, (uint32_t *)tri};
    fl_g1_surface g;
    fl_error err;
    CHECK_FAILS(fl_g1_surface_build(&bm, NULL, &g, &err), &err, FL_ERR_INPUT, "1e150");
}

/* fuzz_hal3: a tetrahedron with one vertex at 6.25e298: the squared ball radii overflowed and
 * node 1's flintstone excluded the centroid of its own triangle. Now outside the documented
 * range; at 1e150 the flintstones still contain their triangles. */
static void test_hal3_extreme_scale(void)
{
    static const uint32_t tri[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    double big[] = {-0.5, -0.5, -0.5, -0.5, -0.5, -0.5, 6.25e298, -0.5, -0.5, -0.5, -0.5, -0.5};
    big[3] = 4, big[7] = 4, big[11] = 4;
    fl_mesh bm = {4, big, 4, (uint32_t *)tri};
    fl_hal3 h;
    fl_error err;
    CHECK_FAILS(fl_hal3_build(&bm, NULL, &h, &err), &err, FL_ERR_INPUT, "1e150");
    double s = 1e150, v[] = {0, 0, 0, s, 0, 0, 0, s, 0, 0, 0, s};
    fl_mesh m = {4, v, 4, (uint32_t *)tri};
    CHECK_STATUS(fl_hal3_build(&m, NULL, &h, &err), FL_OK, &err);
    for (size_t n = 0; n < h.node_count; n++) {
        if (h.nodes[n].kind != FL_HAL3_LEAF) continue;
        const uint32_t *t = tri + 3 * h.nodes[n].face;
        double g[3];
        for (int x = 0; x < 3; x++)
            g[x] = v[3 * t[0] + x] / 3 + v[3 * t[1] + x] / 3 + v[3 * t[2] + x] / 3;
        for (int32_t a = (int32_t)n; a >= 0; a = h.nodes[a].parent)
            CHECK_MSG(fl_hal3_flintstone_may_contain(&h, (uint32_t)a, g),
                      "node %d excludes the centroid of face %u", (int)a, h.nodes[n].face);
    }
    fl_hal3_free(&h);
}

/* fuzz_hal3 (while checking a report): with a vertex 1e20 away the circumcentre's denominator
 * rounded to 0 and the root's ball was NaN with squared radius 0, a flintstone that pruned
 * nothing. Every ball must be finite and hold the corners of every triangle below it. */
static void test_hal3_far_vertex_balls_finite(void)
{
    static const uint32_t tri[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    double v[] = {-0.5, -0.5, -0.5, 3.5078125, -0.5, -0.4609375, -0.5, 3.5, 1e20, -0.5, -0.5, 3.5};
    fl_mesh m = {4, v, 4, (uint32_t *)tri};
    fl_hal3 h;
    fl_error err;
    CHECK_STATUS(fl_hal3_build(&m, NULL, &h, &err), FL_OK, &err);
    for (size_t n = 0; n < h.node_count; n++) {
        const fl_hal3_node *nd = h.nodes + n;
        int balls = nd->kind == FL_HAL3_TWO_BALLS || nd->kind == FL_HAL3_BALL_UNION ? 2 : 1;
        for (int j = 0; j < balls; j++)
            for (int k = 0; k < 4; k++)
                CHECK_MSG(isfinite(nd->ball[j][k]), "node %zu ball %d not finite", n, j);
        if (nd->kind != FL_HAL3_LEAF) continue;
        for (int32_t a = (int32_t)n; a >= 0; a = h.nodes[a].parent)
            for (int k = 0; k < 3; k++)
                CHECK(fl_hal3_flintstone_may_contain(&h, (uint32_t)a,
                                                     v + 3 * tri[3 * nd->face + k]));
    }
    fl_hal3_free(&h);
}

/* A stellated octahedron (every face raised to an apex at twice its centroid) times s. */
static void stellated(double s, double *xyz, uint32_t *tri, size_t *nv, size_t *nt)
{
    for (int i = 0; i < 18; i++) xyz[i] = 0;
    for (int i = 0; i < 6; i++) xyz[3 * i + i / 2] = (i & 1) ? -4 : 4;
    *nv = 6, *nt = 0;
    for (uint32_t f = 0; f < 8; f++) {
        uint32_t a = f & 1, b = 2 + ((f >> 1) & 1), c = 4 + ((f >> 2) & 1), q = (uint32_t)*nv;
        if ((a + b + c) & 1) { /* keep the triangles outward */
            uint32_t x = b;
            b = c, c = x;
        }
        for (int k = 0; k < 3; k++)
            xyz[3 * q + k] = 2.0 * (xyz[3 * a + k] + xyz[3 * b + k] + xyz[3 * c + k]) / 3.0;
        ++*nv;
        uint32_t e[9] = {a, b, q, b, c, q, c, a, q};
        memcpy(tri + 3 * *nt, e, sizeof e);
        *nt += 3;
    }
    for (size_t i = 0; i < 3 * *nv; i++) xyz[i] *= s;
}

/* fuzz_hal3: the node error (largest vertex distance to the node's triangle) multiplied dot
 * products, 4th powers of the coordinates; at 1e100 they overflowed to NaN, which fmax
 * dropped: a node certified error 0 with a vertex 1.75e100 away. The certified error of every
 * level must bound the brute-force distance of every vertex to its approximation. */
static void test_hal3_errors_at_1e100(void)
{
    double xs[3 * 14];
    uint32_t tri[3 * 24];
    size_t nv, nt;
    stellated(1e100, xs, tri, &nv, &nt);
    fl_mesh ms = {nv, xs, nt, tri};
    fl_hal3 hs;
    fl_error err;
    CHECK_STATUS(fl_hal3_build(&ms, NULL, &hs, &err), FL_OK, &err);
    if (!hs.nodes) return;
    for (uint32_t level = 0; level <= hs.depth; level++) {
        fl_mesh ap;
        double e = -1;
        CHECK_STATUS(fl_hal3_approximate_level(&hs, level, &ap, &e, &err), FL_OK, &err);
        for (size_t i = 0; i < nv; i++) {
            ld d = brute_mesh_distance(&ap, xs + 3 * i);
            CHECK_MSG(d <= (ld)e * (1 + 1e-9), "level %u: vertex %zu at %.17Lg, certified %.17g",
                      level, i, d, e);
        }
        fl_mesh_free(&ap);
    }
    fl_hal3_free(&hs);
}

/* fuzz_skin: one ball of weight 1e-150 (reach 7e-76) next to an ordinary one: the lookup grid
 * was sized from a box of volume 9e-74 to 1e27 cells along an axis, a double -> size_t
 * conversion out of range (UBSan aborts in the sanitizer build of this test). */
static void test_skin_flat_box_grid(void)
{
    double b[] = {-8, -8, -8, 1e-150, 0, 0, 0, 0.25};
    fl_skin_function *g = NULL;
    fl_error err;
    CHECK_STATUS(fl_skin_function_new(b, 2, 0.5, &g, &err), FL_OK, &err);
    if (!g) return;
    double c[3] = {0, 0, 0}, far[3] = {40, 40, 40};
    CHECK(fl_skin_function_value(g, c) < 0);
    CHECK(fl_skin_function_value(g, far) > 0);
    fl_skin_function_free(g);
}

/* fuzz_render: the half-plane part of a disc of radius 1e300 cut by a line through points near
 * the origin: the chord's construction overflowed and "-inf" was written into the SVG. */
static void test_svg_halfplane_huge_disc(void)
{
    fl_svg *svg = NULL;
    fl_error err;
    CHECK_STATUS(fl_svg_new(100, &svg, &err), FL_OK, &err);
    if (!svg) return;
    double disc[3] = {1.0198041672000625e-309, -7.75, 1e300};
    double a[2] = {-7.75, 1.0198041672000625e-309};
    double b[2] = {1, -7.75}, huge[3] = {-1e308, 0, 1e308};
    CHECK_STATUS(fl_svg_add_disc_halfplane(svg, disc, a, b, -1, NULL, &err), FL_OK, &err);
    CHECK_FAILS(fl_svg_add_disc(svg, huge[0], huge[1], huge[2], NULL, &err), &err, FL_ERR_INPUT,
                "double range");
    char path[64];
    snprintf(path, sizeof path, "fuzz_round3_%ld.svg", (long)getpid());
    CHECK_STATUS(fl_svg_write(svg, path, &err), FL_OK, &err);
    FILE *f = fopen(path, "rb");
    CHECK(f != NULL);
    if (f) {
        char text[4096];
        size_t n = fread(text, 1, sizeof text - 1, f);
        text[n] = 0;
        fclose(f);
        CHECK_MSG(!strstr(text, "inf") && !strstr(text, "nan"), "non-finite in:\n%s", text);
    }
    remove(path);
    fl_svg_free(svg);
}

/* fuzz_skin: a ball of radius 1e-75 at x = -8 asked for a grid spacing far below the
 * coordinates' resolution; grid points coincided after rounding and the mesh had 16 boundary
 * edges. Such a grid is refused now. */
static void test_skin_spacing_below_resolution(void)
{
    double b[] = {-4.25, 0, -8, 1e-150, -8, 0, 0, -0.75};
    fl_skin_options o = {0};
    o.t = 0.5;
    o.cell = 7.0710678118654757e-76;
    fl_mesh m;
    fl_error err;
    CHECK_FAILS(fl_skin_mesh(b, 2, &o, &m, NULL, &err), &err, FL_ERR_INPUT, "resolution");
    CHECK(m.xyz == NULL);
}

/* Round 4: a ball of subnormal weight. sqrt(t w) underflowed to 0, the index dropped the ball's
 * simplices, and G at its centre came from the other ball: 40.8 instead of about -t w (which
 * itself rounds to -0 here). The centre must not be reported outside. */
static void test_skin_subnormal_weight_keeps_its_ball(void)
{
    double balls[] = {-8, -8, -2.75, 0.5, -4, -7.875, -7.75, 4.9406564584124654e-324};
    fl_skin_function *g = NULL;
    fl_error err;
    CHECK_STATUS(fl_skin_function_new(balls, 2, 0.5, &g, &err), FL_OK, &err);
    if (!g) return;
    double v0 = fl_skin_function_value(g, balls), v1 = fl_skin_function_value(g, balls + 4);
    CHECK_MSG(v0 < 0, "G(centre 0) = %g", v0);
    CHECK_MSG(v1 <= 0, "G(centre of the subnormal ball) = %g", v1);
    fl_skin_function_free(g);
}

/* Round 7 (CI's fuzz_skin): two balls of weight 1e-40 at coordinates 1e10. Their reach is below
 * the ulp of their coordinates, so their index boxes are points; with most boxes points the
 * median side was 0, the index fell back to one cell of size 1, and the second centre lay
 * outside it: G = inf ("outside") at a ball's centre. Every centre must read G < 0. */
static void test_skin_point_boxes_keep_every_ball(void)
{
    double balls[] = {1e10, 1e10, 1e10, 1e-40, 2e10, 1e10, 1e10, 1e-40,
                      1e10, 3e10, -1e10, 1e-40};
    for (size_t n = 2; n <= 3; n++) {
        fl_skin_function *g = NULL;
        fl_error err;
        CHECK_STATUS(fl_skin_function_new(balls, n, 0.5, &g, &err), FL_OK, &err);
        if (!g) return;
        for (size_t i = 0; i < n; i++) {
            double v = fl_skin_function_value(g, balls + 4 * i);
            CHECK_MSG(v < 0, "%zu balls: G(centre %zu) = %g", n, i, v);
        }
        fl_skin_function_free(g);
    }
}

int main(void)
{
    fl_test_case cases[] = {
        FL_TEST_CASE(test_hausdorff_field_measures_unused_vertices),
        FL_TEST_CASE(test_sweep_face_distance_at_extreme_scales),
        FL_TEST_CASE(test_hausdorff_bound_at_1e_117),
        FL_TEST_CASE(test_g1_curve_near_spike_is_finite),
        FL_TEST_CASE(test_g1_surface_extreme_scales),
        FL_TEST_CASE(test_hal3_extreme_scale),
        FL_TEST_CASE(test_hal3_far_vertex_balls_finite),
        FL_TEST_CASE(test_hal3_errors_at_1e100),
        FL_TEST_CASE(test_skin_flat_box_grid),
        FL_TEST_CASE(test_svg_halfplane_huge_disc),
        FL_TEST_CASE(test_skin_spacing_below_resolution),
        FL_TEST_CASE(test_skin_subnormal_weight_keeps_its_ball),
        FL_TEST_CASE(test_skin_point_boxes_keep_every_ball),
    };
    return fl_test_run(cases, sizeof cases / sizeof *cases);
}
