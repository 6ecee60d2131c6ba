/* SVG pictures of polygons: a standalone document, one subpath per ring, finite coordinates
 * inside the viewBox, y flipped so that up is up. */
#include "io/io_internal.h"
#include "io_test_util.h"

static size_t count_of(const char *text, const char *needle)
{
    size_t n = 0;
    for (const char *p = strstr(text, needle); p; p = strstr(p + 1, needle))
        n++;
    return n;
}

static char *draw(const fl_polygon *poly)
{
    char *text;
    size_t size;
    fl_status st = FL_ERR_IO;
    IO_TEST_CAPTURE(fl_svg_polygon_write(fp, poly), text, size, st);
    CHECK_EQ_INT(st, FL_OK);
    CHECK(size == strlen(text));
    return text;
}

/* Reads every coordinate pair of every path; checks they are finite and inside the viewBox
 * and returns the smallest and largest picture y. */
static void check_path_coordinates(const char *text, size_t want_pairs, double *min_y,
                                   double *max_y)
{
    double w = 0, h = 0;
    const char *vb = strstr(text, "viewBox=\"");
    CHECK(vb && sscanf(vb + 9, "0 0 %lf %lf", &w, &h) == 2);
    CHECK(isfinite(w) && isfinite(h) && w > 0 && h > 0);
    size_t pairs = 0;
    *min_y = INFINITY;
    *max_y = -INFINITY;
    for (const char *d = strstr(text, " d=\""); d; d = strstr(d, " d=\"")) {
        const char *p = d + 4;
        while (*p != '"') {
            if (*p == 'M' || *p == 'L' || *p == 'Z' || *p == ' ') {
                p++;
                continue;
            }
            char *stop;
            double x = strtod(p, &stop);
            double y = strtod(stop, &stop);
            CHECK(stop > p && isfinite(x) && isfinite(y));
            CHECK(x >= 0 && x <= w && y >= 0 && y <= h);
            *min_y = fmin(*min_y, y);
            *max_y = fmax(*max_y, y);
            pairs++;
            p = stop;
        }
        d = p;
    }
    CHECK_EQ_INT(pairs, want_pairs);
}

static void test_svg_standalone_with_subpath_per_ring(void)
{
    /* A square with a triangular hole, and a separate triangle above it. */
    double xy[] = {0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 2, 1, 1, 2, 5, 6, 7, 6, 6, 9};
    size_t ring_start[] = {0, 4, 7, 10};
    size_t polygon_start[] = {0, 2, 3};
    fl_polygon poly = {10, xy, 3, ring_start, 2, polygon_start};
    char *text = draw(&poly);
    CHECK(strncmp(text, "<svg xmlns=\"http://www.w3.org/2000/svg\"", 39) == 0);
    size_t n = strlen(text);
    CHECK(n > 7 && strcmp(text + n - 7, "</svg>\n") == 0);
    CHECK_EQ_INT(count_of(text, "<g"), count_of(text, "</g>"));
    /* One filled path a polygon and one stroked path a ring; each ring is one subpath in
     * each layer. */
    CHECK_EQ_INT(count_of(text, "<path"), 2 + 3);
    CHECK_EQ_INT(count_of(text, "M"), 2 * 3);
    CHECK_EQ_INT(count_of(text, "Z\""), 2 + 3);
    CHECK_EQ_INT(count_of(text, "fill-rule=\"evenodd\""), 1);
    double min_y, max_y;
    check_path_coordinates(text, 2 * 10, &min_y, &max_y);
    /* y is flipped: the top vertex (6, 9) is drawn nearest the top of the picture, y=0 at the
     * bottom margin; the longer extent (9 units) spans the 1000-unit picture. */
    CHECK_NEAR(min_y, 50, 1e-6);
    CHECK_NEAR(max_y, 1050, 1e-6);
    free(text);
}

static void test_svg_extreme_and_degenerate_coordinates_stay_finite(void)
{
    double huge[] = {-1.7e308, -1.7e308, 1.7e308, -1.7e308, 0, 1.7e308};
    size_t ring_start[] = {0, 3};
    size_t polygon_start[] = {0, 1};
    fl_polygon poly = {3, huge, 1, ring_start, 1, polygon_start};
    double min_y, max_y;
    char *text = draw(&poly);
    check_path_coordinates(text, 2 * 3, &min_y, &max_y);
    free(text);
    double point[] = {3, 3, 3, 3, 3, 3};
    poly.xy = point;
    text = draw(&poly);
    check_path_coordinates(text, 2 * 3, &min_y, &max_y);
    CHECK_EQ_INT(min_y, max_y);
    free(text);
}

static void test_svg_empty_polygon_is_a_valid_picture(void)
{
    size_t zero[] = {0};
    fl_polygon poly = {0, NULL, 0, zero, 0, zero};
    char *text = draw(&poly);
    CHECK(strncmp(text, "<svg", 4) == 0 && strstr(text, "</svg>") != NULL);
    CHECK_EQ_INT(count_of(text, "<path"), 0);
    free(text);
}

FL_TEST_MAIN(FL_TEST_CASE(test_svg_standalone_with_subpath_per_ring),
             FL_TEST_CASE(test_svg_extreme_and_degenerate_coordinates_stay_finite),
             FL_TEST_CASE(test_svg_empty_polygon_is_a_valid_picture))
