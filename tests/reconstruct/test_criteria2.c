/* The keys of constriction (thesis Def. 5.1 / eq. 5.1, eq. 4.1, §4.3.4) and writing results. */
#include "recon2_test_util.h"
#include "reconstruct/constrict2_internal.h"

/* Def. 5.1 from the circumcircle itself: centre C by the perpendicular-bisector formula,
 * R = |a - C|, |c0| = 1 - r/R with r = |ab|/2, and the sign of eq. 5.1 (C on c's side of ab). */
static double indicator_from_circle(const double *a, const double *b, const double *c)
{
    double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
    double d = 2 * (bx * cy - by * cx), b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    double centre[2] = {a[0] + (cy * b2 - by * c2) / d, a[1] + (bx * c2 - cx * b2) / d};
    double big_r = hypot(centre[0] - a[0], centre[1] - a[1]), r = hypot(bx, by) / 2;
    int side_c = fl_orient2d(a, b, c), side_centre = fl_orient2d(a, b, centre);
    double mag = 1 - r / big_r;
    return side_centre == 0 ? 0 : side_centre == side_c ? mag : -mag;
}

static void test_gamma_indicator_matches_the_circumradius_definition(void)
{
    const double a[] = {0, 0}, b[] = {2, 0};
    const double apex[][2] = {{1, 3},     {1, 1},   {1, 0.2},
                              {0.3, 0.5}, {5, 0.1}, {1, 1.7320508075688772}};
    for (size_t i = 0; i < sizeof apex / sizeof apex[0]; i++) {
        double g = c2_gamma_indicator(a, b, apex[i]);
        CHECK_NEAR(g, indicator_from_circle(a, b, apex[i]), 1e-12);
        CHECK(g >= -1 && g <= 1);
    }
    /* closed forms: right angle at c gives 0, equilateral 1 - sin 60°, 120° gives sin 120° - 1 */
    const double right[] = {1, 1}, eq[] = {1, 1.7320508075688772}, obt[] = {1, 0.57735026918962573};
    CHECK_NEAR(c2_gamma_indicator(a, b, right), 0, 1e-15);
    CHECK_NEAR(c2_gamma_indicator(a, b, eq), 1 - sqrt(3) / 2, 1e-15);
    CHECK_NEAR(c2_gamma_indicator(a, b, obt), sqrt(3) / 2 - 1, 1e-15);
}

/* The γ-indicator as first written (every rescaling through ldexp): the fast path, which
 * multiplies by 2^-e instead, must give the same double bit for bit, or constriction's order
 * (and result) could change. Triangles at magnitudes from 1e-300 to 1e300, where the rescaled
 * components may be subnormal and the scale itself leaves the fast path. */
static double gamma_by_ldexp(const double *a, const double *b, const double *c)
{
    double ux = a[0] - c[0], uy = a[1] - c[1], vx = b[0] - c[0], vy = b[1] - c[1];
    int e;
    frexp(fmax(fmax(fabs(ux), fabs(uy)), fmax(fabs(vx), fabs(vy))), &e);
    ux = ldexp(ux, -e), uy = ldexp(uy, -e), vx = ldexp(vx, -e), vy = ldexp(vy, -e);
    double lu = hypot(ux, uy), lv = hypot(vx, vy);
    if (!(lu > 0 && lv > 0)) return 1;
    double sin_t = fabs(ux * vy - uy * vx) / lu / lv;
    double cos_t = (ux * vx + uy * vy) / lu / lv;
    if (sin_t > 1) sin_t = 1;
    return cos_t >= 0 ? 1 - sin_t : sin_t - 1;
}

static void test_gamma_indicator_fast_scaling_is_bit_identical(void)
{
    uint64_t x = 0x9e3779b97f4a7c15ull;
    size_t differ = 0, subnormal = 0;
    for (int i = 0; i < 200000; i++) {
        double p[6];
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        double mag = pow(10, (double)(x % 601) - 300); /* 1e-300 .. 1e300 */
        double thin = (x >> 20) % 4 == 0 ? 1e-310 : 1; /* rescaled y: subnormal */
        for (int k = 0; k < 6; k++) {
            x ^= x << 13, x ^= x >> 7, x ^= x << 17;
            p[k] = mag * ((double)(x >> 11) / 9007199254740992.0 - 0.5) * (k % 2 ? thin : 1);
        }
        double fast = c2_gamma_indicator(p, p + 2, p + 4), ref = gamma_by_ldexp(p, p + 2, p + 4);
        differ += memcmp(&fast, &ref, sizeof fast) != 0;
        subnormal += thin < 1 && mag >= 1e-10 && p[1] != p[5];
    }
    CHECK_EQ_INT(differ, 0);
    CHECK(subnormal > 0); /* the subnormal rescaling was exercised */
}

static void test_every_criterion_reconstructs_a_dense_star_in_order(void)
{
    const char *names[] = {"gamma", "area-change", "voronoi-skeleton"};
    size_t n = 300;
    double *xy = rt_star(n, 5, 0.3);
    for (int c = 0; c < 3; c++) {
        fl_reconstruct2_options opt = {0};
        fl_error err;
        CHECK_STATUS(fl_reconstruct2_criterion_parse(names[c], &opt.criterion, &err), FL_OK, &err);
        CHECK_EQ_INT(opt.criterion, c);
        fl_reconstruction2 rec;
        CHECK_STATUS(fl_reconstruct2(xy, n, &opt, &rec, &err), FL_OK, &err);
        rt_check_valid(xy, &rec);
        CHECK_MSG(rt_is_input_order(&rec, n), "criterion %s", names[c]);
        fl_reconstruction2_free(&rec);
    }
    fl_reconstruct2_criterion crit;
    fl_error err;
    CHECK_STATUS(fl_reconstruct2_criterion_parse("alpha", &crit, &err), FL_ERR_USAGE, &err);
    free(xy);
}

/* §5.2: the selection rule "is orientation and scale independent". Scaling by a power of two and
 * turning by a quarter are exact, so every criterion must give the same polygon, also on scattered
 * points that need augmentation. */
static void test_result_is_independent_of_scale_and_quarter_turns(void)
{
    size_t n = 150;
    double *xy = malloc(2 * n * sizeof *xy), *moved = malloc(2 * n * sizeof *moved);
    unsigned long long st = 5;
    for (size_t i = 0; i < 2 * n; i++)
        xy[i] = fl_test_rand01(&st) - 0.5;
    const double scales[] = {0x1p-500, 0x1p900};
    for (int c = 0; c < 3; c++) {
        fl_reconstruct2_options opt = {0};
        opt.criterion = (fl_reconstruct2_criterion)c;
        fl_reconstruction2 ref, rec;
        fl_error err;
        CHECK_STATUS(fl_reconstruct2(xy, n, &opt, &ref, &err), FL_OK, &err);
        for (int v = 0; v < 3; v++) {
            for (size_t i = 0; i < n; i++) {
                double x = xy[2 * i], y = xy[2 * i + 1];
                if (v < 2)
                    moved[2 * i] = x * scales[v], moved[2 * i + 1] = y * scales[v];
                else
                    moved[2 * i] = -y, moved[2 * i + 1] = x;
            }
            CHECK_STATUS(fl_reconstruct2(moved, n, &opt, &rec, &err), FL_OK, &err);
            CHECK_MSG(rec.boundary_count == ref.boundary_count &&
                          rt_same_cycle(ref.boundary, rec.boundary, ref.boundary_count),
                      "criterion %d, variant %d", c, v);
            CHECK(isnan(rec.augmented_c0) ? isnan(ref.augmented_c0)
                                          : rec.augmented_c0 == ref.augmented_c0);
            fl_reconstruction2_free(&rec);
        }
        fl_reconstruction2_free(&ref);
    }
    free(xy);
    free(moved);
}

static void test_written_polygon_and_mesh_read_back(void)
{
    size_t n = 64;
    double *xy = rt_star(n, 3, 0.3);
    fl_reconstruction2 rec;
    fl_error err;
    CHECK_STATUS(fl_reconstruct2(xy, n, NULL, &rec, &err), FL_OK, &err);
    const char *gj = "recon2_test.geojson", *off = "recon2_test.off", *svg = "recon2_test.svg";
    CHECK_STATUS(fl_write_reconstruction2(gj, xy, n, &rec, &err), FL_OK, &err);
    CHECK_STATUS(fl_write_reconstruction2(off, xy, n, &rec, &err), FL_OK, &err);
    CHECK_STATUS(fl_write_reconstruction2(svg, xy, n, &rec, &err), FL_OK, &err);
    CHECK_STATUS(fl_write_reconstruction2("x.ply", xy, n, &rec, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_write_reconstruction2(gj, xy, n - 1, &rec, &err), FL_ERR_USAGE, &err);
    fl_polygon pg;
    CHECK_STATUS(fl_read_polygon(gj, &pg, &err), FL_OK, &err);
    CHECK_EQ_INT(pg.vertex_count, rec.boundary_count);
    for (size_t i = 0; i < pg.vertex_count && i < rec.boundary_count; i++) {
        CHECK(pg.xy[2 * i] == xy[2 * (size_t)rec.boundary[i]]);
        CHECK(pg.xy[2 * i + 1] == xy[2 * (size_t)rec.boundary[i] + 1]);
    }
    fl_mesh mesh;
    CHECK_STATUS(fl_read_mesh(off, &mesh, &err), FL_OK, &err);
    CHECK_EQ_INT(mesh.vertex_count, n);
    CHECK_EQ_INT(mesh.triangle_count, rec.triangle_count);
    FILE *fp = fopen(svg, "r");
    char head[256] = {0};
    CHECK(fp && fread(head, 1, sizeof head - 1, fp) > 0);
    CHECK(strstr(head, "<svg") != NULL);
    if (fp) fclose(fp);
    remove(gj), remove(off), remove(svg);
    fl_polygon_free(&pg);
    fl_mesh_free(&mesh);
    fl_reconstruction2_free(&rec);
    free(xy);
}

/* c2_gamma_at_least (the test that lets constriction park a key without computing it) against
 * c2_gamma_indicator itself: whenever it says yes, the indicator must be at least the bar —
 * for triangles at magnitudes from 1e-300 to 1e300, thin and fat, and with NaN or infinite
 * coordinates (then it must say no). It must also say yes for the thin triangles across a
 * sampled curve (else it would save nothing). */
static void test_gamma_at_least_never_claims_a_smaller_indicator(void)
{
    unsigned long long st = 2024;
    size_t wrong = 0, yes = 0;
    const double bars[] = {0.5, 0.875, 0.25};
    for (int i = 0; i < 200000; i++) {
        double u = fl_test_rand01(&st), p[6];
        double scale = i % 2 ? pow(10, -300 + 600 * u) : pow(10, -100 + 200 * u);
        for (int k = 0; k < 6; k++)
            p[k] = (fl_test_rand01(&st) - 0.5) * scale;
        if (i % 3 == 0) { /* thin: c far from a and b along their line's normal */
            p[4] = (p[0] + p[2]) / 2 + (p[3] - p[1]) * 40;
            p[5] = (p[1] + p[3]) / 2 - (p[2] - p[0]) * 40;
        }
        if (i % 1000 == 1) p[i % 6] = i % 2000 == 1 ? NAN : HUGE_VAL;
        double bar = bars[i % 3];
        if (!c2_gamma_at_least(p, p + 2, p + 4, bar)) continue;
        yes++;
        int finite = 1;
        for (int k = 0; k < 6; k++)
            finite &= isfinite(p[k]) != 0;
        wrong += !(c2_gamma_indicator(p, p + 2, p + 4) >= bar) || !finite;
    }
    CHECK_EQ_INT(wrong, 0);
    CHECK(yes > 15000);
    const double a[] = {0, 0}, b[] = {1e-3, 0}, c[] = {5e-4, 1}; /* across a curve */
    CHECK(c2_gamma_at_least(a, b, c, 0.5));
    const double right[] = {5e-4, 5e-4}; /* γ = 0 */
    CHECK(!c2_gamma_at_least(a, b, right, 0.5));
}

FL_TEST_MAIN(FL_TEST_CASE(test_gamma_indicator_matches_the_circumradius_definition),
             FL_TEST_CASE(test_gamma_indicator_fast_scaling_is_bit_identical),
             FL_TEST_CASE(test_every_criterion_reconstructs_a_dense_star_in_order),
             FL_TEST_CASE(test_result_is_independent_of_scale_and_quarter_turns),
             FL_TEST_CASE(test_written_polygon_and_mesh_read_back),
             FL_TEST_CASE(test_gamma_at_least_never_claims_a_smaller_indicator))
