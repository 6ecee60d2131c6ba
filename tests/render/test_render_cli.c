/* `flintstone render` end to end: the PNG it writes decodes (libpng) to exactly the pixels the
 * library renders in-process with the same options; --json reports them; dispatch by input type;
 * usage errors. */
#include <png.h>

#include "cli/cli_run.h"
#include "render_scenes.h"

/* Decodes an 8-bit RGBA PNG with libpng's simplified API; returns 0 on success. */
static int decode_png(const char *path, fl_image *img)
{
    png_image pi;
    memset(&pi, 0, sizeof pi);
    pi.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&pi, path)) return -1;
    pi.format = PNG_FORMAT_RGBA;
    img->width = pi.width;
    img->height = pi.height;
    img->rgba = malloc(PNG_IMAGE_SIZE(pi));
    if (!img->rgba || !png_image_finish_read(&pi, NULL, img->rgba, 0, NULL)) {
        png_image_free(&pi);
        fl_image_free(img);
        return -1;
    }
    return 0;
}

static void write_cube_off(const char *path)
{
    FILE *f = fopen(path, "w");
    if (!f) return;
    fprintf(f, "OFF\n8 12 0\n");
    for (int i = 0; i < 8; i++)
        fprintf(f, "%g %g %g\n", cube_xyz[3 * i], cube_xyz[3 * i + 1], cube_xyz[3 * i + 2]);
    for (int t = 0; t < 12; t++)
        fprintf(f, "3 %u %u %u\n", cube_tri[3 * t], cube_tri[3 * t + 1], cube_tri[3 * t + 2]);
    fclose(f);
}

static unsigned long long json_uint(const char *json, const char *key)
{
    char k[64];
    snprintf(k, sizeof k, "\"%s\":", key);
    const char *p = strstr(json, k);
    return p ? strtoull(p + strlen(k), NULL, 10) : 0;
}

static void test_png_roundtrips_the_library_pixels(void)
{
    write_cube_off("render_cube.off");
    cli_result r;
    cli_run(&r, "render render_cube.off -o render_cube.png --view 30,20 --size 160x120 --flat "
                "--wireframe --aa --background '#20304080' --json");
    CHECK_MSG(r.code == 0, "%s", r.err);
    fl_image png = {0};
    CHECK(decode_png("render_cube.png", &png) == 0);
    /* The same scene in-process. */
    static const uint8_t bg[4] = {0x20, 0x30, 0x40, 0x80};
    fl_render_options opt = {.width = 160,
                             .height = 120,
                             .azimuth = 30,
                             .elevation = 20,
                             .supersample = 2,
                             .background = bg};
    fl_render_mesh_style st = {.wireframe = 1};
    fl_mesh m = cube_mesh();
    fl_render *rd = NULL;
    fl_error err;
    fl_image img = {0};
    fl_render_stats s = {0};
    CHECK_EQ_INT(fl_render_new(&opt, &rd, &err), FL_OK);
    CHECK_EQ_INT(fl_render_add_mesh(rd, &m, &st, &err), FL_OK);
    CHECK_EQ_INT(fl_render_finish(rd, &img, &s, &err), FL_OK);
    CHECK(png.width == 160 && png.height == 120);
    CHECK(png.rgba && img.rgba && memcmp(png.rgba, img.rgba, 160 * 120 * 4) == 0);
    CHECK_EQ_INT(json_uint(r.out, "width"), 160);
    CHECK_EQ_INT(json_uint(r.out, "height"), 120);
    CHECK_EQ_INT(json_uint(r.out, "pixels_covered"), s.pixels_covered);
    CHECK(strstr(r.out, "\"kind\":\"mesh\"") && strstr(r.out, "\"seconds\":"));
    /* Transparent background pixels keep their alpha through the PNG. */
    CHECK_EQ_INT(png.rgba ? png.rgba[3] : 0, 0x80);
    fl_image_free(&png);
    fl_image_free(&img);
    fl_render_free(rd);
    remove("render_cube.png");
    remove("render_cube.off");
}

static void test_dispatch_by_input_type(void)
{
    cli_write_file("render_balls.xyzw", "0 0 0 1\n1.5 0 0 0.25\n");
    cli_write_file("render_pts.xyz", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n");
    cli_write_file("render_pts.xy", "0 0\n1 0\n1 1\n0 1\n0.4 0.6\n");
    cli_write_file("render_poly.geojson",
                   "{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[2,0],[2,2],[0,0]]]}");
    cli_result r;
    cli_run(&r, "render render_balls.xyzw -o render_balls.png --size 90x60 --json");
    CHECK_MSG(r.code == 0 && strstr(r.out, "\"kind\":\"balls\""), "%s", r.err);
    fl_image img = {0};
    CHECK(decode_png("render_balls.png", &img) == 0 && img.width == 90 && img.height == 60);
    fl_image_free(&img);
    cli_run(&r, "render render_pts.xyz -o render_pts.png --json");
    CHECK_MSG(r.code == 0 && strstr(r.out, "\"kind\":\"points\"") &&
                  json_uint(r.out, "pixels_covered") > 0,
              "%s", r.err);
    /* 2D points: 5 dots, the closed polyline and the 4 edges of the EMST. */
    cli_run(&r, "render render_pts.xy -o render_pts.svg --closed --graph emst --json");
    CHECK_MSG(r.code == 0 && json_uint(r.out, "elements") == 7 &&
                  strstr(r.out, "\"pixels_covered\":null"),
              "%s %s", r.out, r.err);
    cli_run(&r, "render render_poly.geojson --json -o render_poly.svg");
    CHECK_MSG(r.code == 0 && json_uint(r.out, "elements") == 1, "%s %s", r.out, r.err);
    remove("render_balls.png");
    remove("render_pts.png");
    remove("render_pts.svg");
    remove("render_poly.svg");
    remove("render_balls.xyzw");
    remove("render_pts.xyz");
    remove("render_poly.geojson");
    remove("render_pts.xy");
}

static void test_usage_errors_exit_1_and_write_nothing(void)
{
    write_cube_off("render_err.off");
    cli_result r;
    CHECK_EQ_INT(cli_run(&r, "render render_err.off -o render_err.svg"), 1);
    CHECK(strstr(r.err, "PNG") != NULL);
    FILE *f = fopen("render_err.svg", "r");
    CHECK(f == NULL);
    if (f) fclose(f);
    CHECK_EQ_INT(cli_run(&r, "render render_err.off --size 0x10"), 1);
    CHECK_EQ_INT(cli_run(&r, "render render_err.off --view 30"), 1);
    CHECK_EQ_INT(cli_run(&r, "render render_err.off --bogus"), 1);
    CHECK_EQ_INT(cli_run(&r, "render"), 1);
    CHECK_EQ_INT(cli_run(&r, "render missing.off -o x.png"), 4);
    cli_write_file("render_field.txt", "1 2 3\n");
    CHECK_EQ_INT(cli_run(&r, "render render_err.off --field render_field.txt -o x.png"), 2);
    CHECK(strstr(r.err, "8 vertices") != NULL);
    CHECK_EQ_INT(cli_run(&r, "render --help"), 0);
    CHECK(strstr(r.out, "example") != NULL);
    remove("render_err.off");
    remove("render_field.txt");
}

FL_TEST_MAIN(FL_TEST_CASE(test_png_roundtrips_the_library_pixels),
             FL_TEST_CASE(test_dispatch_by_input_type),
             FL_TEST_CASE(test_usage_errors_exit_1_and_write_nothing))
