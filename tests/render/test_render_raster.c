/* The rasterizer on known scenes: silhouettes against independently computed pixel counts,
 * z-buffer order independence, spheres against pi r^2, shading properties, input errors. */
#include "render_scenes.h"

static const uint8_t white[4] = {255, 255, 255, 255};

static fl_status render_mesh(const fl_render_options *opt, const fl_mesh *m,
                             const fl_render_mesh_style *st, fl_image *img, fl_render_stats *s)
{
    fl_render *r = NULL;
    fl_error err;
    fl_status status = fl_render_new(opt, &r, &err);
    if (!status) status = fl_render_add_mesh(r, m, st, &err);
    if (!status) status = fl_render_finish(r, img, s, &err);
    fl_render_free(r);
    return status;
}

/* The cube's silhouette is the convex hull of its 8 projected corners. Every pixel centre
 * inside the hull by more than 1e-6 px must be covered, and none outside by more than that
 * (sample positions and edge functions are the same arithmetic on the same projected
 * corners, so only centres within rounding distance of the silhouette may go either way). */
static void check_cube_silhouette(double az, double el, int ortho)
{
    fl_render_options opt = {
        .width = 320, .height = 240, .azimuth = az, .elevation = el, .orthographic = ortho};
    fl_mesh m = cube_mesh();
    fl_image img = {0};
    fl_render_stats s;
    CHECK_EQ_INT(render_mesh(&opt, &m, NULL, &img, &s), FL_OK);
    double px[8][2];
    for (int i = 0; i < 8; i++) {
        double q[3];
        fl_render_project(&s.camera, cube_xyz + 3 * i, q);
        px[i][0] = q[0];
        px[i][1] = q[1];
    }
    size_t inner = count_inside((const double(*)[2])px, 8, 320, 240, 1e-6);
    size_t outer = count_inside((const double(*)[2])px, 8, 320, 240, -1e-6);
    CHECK_MSG(s.pixels_covered >= inner && s.pixels_covered <= outer,
              "az %g el %g ortho %d: covered %zu, expected %zu..%zu", az, el, ortho,
              s.pixels_covered, inner, outer);
    CHECK_EQ_INT(count_color(&img, white), 320 * 240 - s.pixels_covered);
    fl_image_free(&img);
}

static void test_cube_along_axis_covers_its_projected_square(void)
{
    /* Seen along -x orthographically the cube is a unit square, fitted into the image height
     * minus the 5% margins: side 240 * 0.9 = 216 px, so 216^2 pixels up to one row and one
     * column of pixel centres on the boundary: |covered - 216^2| <= 2 * 216 + 1. */
    fl_render_options opt = {.width = 320, .height = 240, .orthographic = 1};
    fl_mesh m = cube_mesh();
    fl_image img = {0};
    fl_render_stats s;
    CHECK_EQ_INT(render_mesh(&opt, &m, NULL, &img, &s), FL_OK);
    CHECK_NEAR(s.camera.scale, 216, 1e-9);
    CHECK_NEAR((double)s.pixels_covered, 216.0 * 216.0, 2 * 216 + 1);
    fl_image_free(&img);
    check_cube_silhouette(0, 0, 1);
}

static void test_cube_silhouette_matches_hull_of_projected_corners(void)
{
    check_cube_silhouette(30, 20, 1);
    check_cube_silhouette(-65, 35, 1);
    check_cube_silhouette(30, 20, 0);
    check_cube_silhouette(200, -50, 0);
    check_cube_silhouette(10, 90, 0); /* from straight above: the turntable pole */
}

/* Two squares facing the camera at different depths, drawn in both orders. */
static fl_status two_squares(int near_first, int ortho, fl_image *img)
{
    /* Looking along -x (azimuth 0): larger x is nearer. The near square is red and smaller. */
    static const double near_xyz[12] = {1, -0.5, -0.5, 1, 0.5, -0.5, 1, 0.5, 0.5, 1, -0.5, 0.5};
    static const double far_xyz[12] = {0, -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1};
    static const uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    static const uint8_t red[4] = {220, 0, 0, 255}, blue[4] = {0, 0, 220, 255};
    fl_mesh near = {4, (double *)near_xyz, 2, (uint32_t *)tri};
    fl_mesh far = {4, (double *)far_xyz, 2, (uint32_t *)tri};
    fl_render_mesh_style sn = {.color = red}, sf = {.color = blue};
    fl_render_options opt = {.width = 100, .height = 100, .orthographic = ortho};
    fl_render *r = NULL;
    fl_error err;
    fl_status st = fl_render_new(&opt, &r, &err);
    for (int k = 0; k < 2 && st == FL_OK; k++) {
        int draw_near = (k == 0) == (near_first != 0);
        st = fl_render_add_mesh(r, draw_near ? &near : &far, draw_near ? &sn : &sf, &err);
    }
    if (st == FL_OK) st = fl_render_finish(r, img, NULL, &err);
    fl_render_free(r);
    return st;
}

static void test_zbuffer_near_triangle_hides_far_one_in_either_order(void)
{
    for (int ortho = 0; ortho < 2; ortho++) {
        fl_image a = {0}, b = {0};
        CHECK_EQ_INT(two_squares(1, ortho, &a), FL_OK);
        CHECK_EQ_INT(two_squares(0, ortho, &b), FL_OK);
        CHECK(a.rgba && b.rgba && memcmp(a.rgba, b.rgba, 100 * 100 * 4) == 0);
        const uint8_t *c = a.rgba + 4 * (50 * 100 + 50); /* the centre: both squares */
        CHECK_MSG(c[0] > 100 && c[2] < 30, "centre pixel %u %u %u", c[0], c[1], c[2]);
        const uint8_t *e = a.rgba + 4 * (50 * 100 + 12); /* only the far square */
        CHECK_MSG(e[2] > 100 && e[0] < 30, "edge pixel %u %u %u", e[0], e[1], e[2]);
        fl_image_free(&a);
        fl_image_free(&b);
    }
}

/* One ball: its silhouette is a disc. Orthographic radius r*scale; perspective, for a ball on
 * the view axis at distance D from the eye, the cone of rays tangent to it has half-angle
 * asin(r/D), so the image radius is scale * r / sqrt(D^2 - r^2) (scale in pixels per unit of
 * x/w). The number N of pixel centres in a disc of radius R satisfies
 * pi (R - sqrt(2)/2)^2 <= N <= pi (R + sqrt(2)/2)^2: each counted pixel square lies in the
 * disc grown by half a diagonal, and each pixel square inside the shrunk disc is counted. */
static void test_sphere_silhouette_is_pi_r_squared(void)
{
    for (int ortho = 0; ortho < 2; ortho++) {
        double ball[4] = {0.3, -0.2, 0.1, 2.25};
        fl_balls b = {1, ball};
        fl_render_options opt = {
            .width = 300, .height = 300, .orthographic = ortho, .azimuth = 40, .elevation = 25};
        fl_render *r = NULL;
        fl_error err;
        fl_image img = {0};
        fl_render_stats s;
        CHECK_EQ_INT(fl_render_new(&opt, &r, &err), FL_OK);
        CHECK_EQ_INT(fl_render_add_balls(r, &b, NULL, &err), FL_OK);
        CHECK_EQ_INT(fl_render_finish(r, &img, &s, &err), FL_OK);
        double rr = 1.5, R = ortho ? s.camera.scale * rr
                                   : s.camera.scale * rr /
                                         sqrt(s.camera.distance * s.camera.distance - rr * rr);
        double lo = PI * pow(R - SQRT1_2, 2), hi = PI * pow(R + SQRT1_2, 2);
        CHECK_MSG(s.pixels_covered >= lo && s.pixels_covered <= hi,
                  "ortho %d: R %.3f px, covered %zu, expected %.0f..%.0f", ortho, R,
                  s.pixels_covered, lo, hi);
        CHECK(R > 60); /* the box fit leaves the ball a good part of the picture */
        fl_image_free(&img);
        fl_render_free(r);
    }
}

/* Supersampling keeps the silhouette (a pixel counts when any sample is covered, so the count
 * can only grow by boundary pixels) and blends edge pixels. */
static void test_supersampling_blends_only_boundary_pixels(void)
{
    fl_mesh m = cube_mesh();
    fl_render_options opt = {.width = 200, .height = 150, .azimuth = 30, .elevation = 20};
    fl_image a = {0}, b = {0};
    fl_render_stats sa, sb;
    CHECK_EQ_INT(render_mesh(&opt, &m, NULL, &a, &sa), FL_OK);
    opt.supersample = 2;
    CHECK_EQ_INT(render_mesh(&opt, &m, NULL, &b, &sb), FL_OK);
    CHECK(sb.pixels_covered >= sa.pixels_covered);
    CHECK_MSG(sb.pixels_covered - sa.pixels_covered < 2 * (200 + 150), "%zu vs %zu",
              sb.pixels_covered, sa.pixels_covered);
    CHECK_NEAR(sb.camera.scale, sa.camera.scale, 1e-9 * sa.camera.scale);
    fl_image_free(&a);
    fl_image_free(&b);
}

static double mean_luma(const fl_image *img)
{
    double sum = 0;
    for (size_t i = 0; i < (size_t)img->width * img->height; i++)
        sum += img->rgba[4 * i] + img->rgba[4 * i + 1] + img->rgba[4 * i + 2];
    return sum / (3.0 * img->width * img->height);
}

static void test_wireframe_darkens_without_changing_coverage(void)
{
    fl_mesh m = cube_mesh();
    fl_render_options opt = {.width = 200, .height = 150, .azimuth = 30, .elevation = 20};
    fl_render_mesh_style wire = {.wireframe = 1};
    fl_image a = {0}, b = {0};
    fl_render_stats sa, sb;
    CHECK_EQ_INT(render_mesh(&opt, &m, NULL, &a, &sa), FL_OK);
    CHECK_EQ_INT(render_mesh(&opt, &m, &wire, &b, &sb), FL_OK);
    CHECK_EQ_INT(sa.pixels_covered, sb.pixels_covered);
    CHECK(mean_luma(&b) < mean_luma(&a) - 1);
    fl_image_free(&a);
    fl_image_free(&b);
}

/* Reflection lines: under a parallel projection a plane reflects one direction everywhere, so
 * it shows a single stripe; a sphere's normals sweep every direction, so it shows both. */
static void test_zebra_plane_is_one_stripe_sphere_is_many(void)
{
    static const double quad[12] = {1, -1, -0.3, 1, 1, -0.3, 0.8, 1, 0.7, 0.8, -1, 0.7};
    static const uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    fl_mesh plane = {4, (double *)quad, 2, (uint32_t *)tri};
    fl_render_options opt = {.width = 120, .height = 120, .orthographic = 1};
    fl_render_mesh_style z = {.zebra = 1};
    fl_image img = {0};
    fl_render_stats s;
    CHECK_EQ_INT(render_mesh(&opt, &plane, &z, &img, &s), FL_OK);
    const uint8_t *first = NULL;
    int uniform = 1;
    for (size_t i = 0; i < 120 * 120; i++) {
        const uint8_t *p = img.rgba + 4 * i;
        if (!memcmp(p, white, 4)) continue;
        if (!first) first = p;
        uniform &= memcmp(p, first, 4) == 0;
    }
    CHECK(first && uniform);
    fl_image_free(&img);
    /* A tessellated sphere with exact vertex normals. */
    enum { NU = 48, NV = 24 };
    double xyz[(NU * (NV + 1)) * 3];
    uint32_t t[NU * NV * 6];
    size_t nt = 0;
    for (int j = 0; j <= NV; j++)
        for (int i = 0; i < NU; i++) {
            double th = PI * j / NV, ph = 2 * PI * i / NU, *p = xyz + 3 * (j * NU + i);
            p[0] = sin(th) * cos(ph);
            p[1] = sin(th) * sin(ph);
            p[2] = cos(th);
        }
    for (int j = 0; j < NV; j++)
        for (int i = 0; i < NU; i++) {
            uint32_t a = j * NU + i, b = j * NU + (i + 1) % NU, c = a + NU, d = b + NU;
            uint32_t q[6] = {a, c, d, a, d, b};
            memcpy(t + 3 * nt, q, sizeof q);
            nt += 2;
        }
    fl_mesh sphere = {NU * (NV + 1), xyz, nt, t};
    z.normals = xyz; /* on the unit sphere the position is the normal */
    CHECK_EQ_INT(render_mesh(&opt, &sphere, &z, &img, &s), FL_OK);
    size_t dark = 0, light = 0;
    for (size_t i = 0; i < 120 * 120; i++) {
        const uint8_t *p = img.rgba + 4 * i;
        dark += p[0] < 60;
        light += p[0] > 100 && memcmp(p, white, 4);
    }
    CHECK_MSG(dark > 500 && light > 500, "dark %zu light %zu", dark, light);
    fl_image_free(&img);
}

static void test_scalars_follow_the_colormap(void)
{
    /* A square facing the camera, scalar 0 on the left edge and 1 on the right: the left
     * side must be blue-dominant and the right side red-dominant under coolwarm. */
    static const double sq[12] = {0, -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1};
    static const double val[4] = {0, 1, 1, 0};
    static const uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    fl_mesh m = {4, (double *)sq, 2, (uint32_t *)tri};
    fl_render_mesh_style st = {.scalars = val};
    fl_render_options opt = {.width = 100, .height = 100, .orthographic = 1};
    fl_image img = {0};
    CHECK_EQ_INT(render_mesh(&opt, &m, &st, &img, NULL), FL_OK);
    const uint8_t *l = img.rgba + 4 * (50 * 100 + 10), *r = img.rgba + 4 * (50 * 100 + 89);
    CHECK_MSG(l[2] > l[0] + 50 && r[0] > r[2] + 50, "left %u,%u,%u right %u,%u,%u", l[0], l[1],
              l[2], r[0], r[1], r[2]);
    fl_image_free(&img);
    uint8_t c0[4], c1[4];
    fl_render_colormap_rgba(FL_RENDER_GRAY, -3, c0);
    fl_render_colormap_rgba(FL_RENDER_GRAY, 7, c1);
    CHECK(c0[0] == 0 && c1[0] == 255 && c0[3] == 255);
}

static void test_vertex_normals_of_cube_point_outward(void)
{
    fl_mesh m = cube_mesh();
    double n[24];
    fl_error err;
    CHECK_EQ_INT(fl_render_vertex_normals(&m, n, &err), FL_OK);
    for (int i = 0; i < 8; i++) {
        double d = 0, len = 0;
        for (int k = 0; k < 3; k++) {
            d += n[3 * i + k] * (cube_xyz[3 * i + k] - 0.5);
            len += n[3 * i + k] * n[3 * i + k];
        }
        CHECK(d > 0);
        CHECK_NEAR(len, 1, 1e-12);
    }
}

static void test_bad_input_is_reported_not_drawn(void)
{
    fl_render *r = NULL;
    fl_error err;
    fl_image img = {0};
    fl_render_options bad = {.width = 0, .height = 10};
    CHECK_EQ_INT(fl_render_new(&bad, &r, &err), FL_ERR_USAGE);
    CHECK(r == NULL);
    bad.width = 20000;
    CHECK_EQ_INT(fl_render_new(&bad, &r, &err), FL_ERR_USAGE);
    bad.width = bad.height = 8192;
    bad.supersample = 2; /* 2^28 samples */
    CHECK_EQ_INT(fl_render_new(&bad, &r, &err), FL_ERR_USAGE);
    CHECK_EQ_INT(fl_render_new(NULL, &r, &err), FL_OK);
    CHECK_EQ_INT(fl_render_finish(r, &img, NULL, &err), FL_ERR_INPUT); /* empty scene */
    CHECK(img.rgba == NULL);
    double xyz[9] = {0, 0, 0, 1, 0, 0, 0, NAN, 0};
    uint32_t tri[3] = {0, 1, 2}, far[3] = {0, 1, 3};
    fl_mesh m = {3, xyz, 1, tri};
    CHECK_EQ_INT(fl_render_add_mesh(r, &m, NULL, &err), FL_ERR_INPUT);
    xyz[7] = 1;
    m.tri = far;
    CHECK_EQ_INT(fl_render_add_mesh(r, &m, NULL, &err), FL_ERR_INPUT);
    double ball[4] = {0, 0, 0, INFINITY};
    fl_balls b = {1, ball};
    CHECK_EQ_INT(fl_render_add_balls(r, &b, NULL, &err), FL_ERR_INPUT);
    ball[3] = -1; /* no extent: skipped, and the scene is still empty */
    CHECK_EQ_INT(fl_render_add_balls(r, &b, NULL, &err), FL_OK);
    CHECK_EQ_INT(fl_render_finish(r, &img, NULL, &err), FL_ERR_INPUT);
    m.tri = tri;
    CHECK_EQ_INT(fl_render_add_mesh(r, &m, NULL, &err), FL_OK);
    CHECK_EQ_INT(fl_render_finish(r, &img, NULL, &err), FL_OK);
    CHECK(img.width == 800 && img.height == 600);
    fl_image_free(&img);
    fl_render_free(r);
}

FL_TEST_MAIN(FL_TEST_CASE(test_cube_along_axis_covers_its_projected_square),
             FL_TEST_CASE(test_cube_silhouette_matches_hull_of_projected_corners),
             FL_TEST_CASE(test_zbuffer_near_triangle_hides_far_one_in_either_order),
             FL_TEST_CASE(test_sphere_silhouette_is_pi_r_squared),
             FL_TEST_CASE(test_supersampling_blends_only_boundary_pixels),
             FL_TEST_CASE(test_wireframe_darkens_without_changing_coverage),
             FL_TEST_CASE(test_zebra_plane_is_one_stripe_sphere_is_many),
             FL_TEST_CASE(test_scalars_follow_the_colormap),
             FL_TEST_CASE(test_vertex_normals_of_cube_point_outward),
             FL_TEST_CASE(test_bad_input_is_reported_not_drawn))
