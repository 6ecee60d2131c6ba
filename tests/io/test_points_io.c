/* The public point and polygon readers/writers: dispatch by extension, usage
 * errors that list the formats, exact file round trips, atomic output that
 * leaves the target untouched on failure, and point sets stored in mesh
 * formats. Files are written in the test's working directory (the build tree)
 * and removed afterwards. */
#include "io_test_util.h"

static void write_file(const char *path, const char *text)
{
    FILE *fp = fopen(path, "wb");
    CHECK(fp != NULL);
    if (!fp) return;
    fputs(text, fp);
    fclose(fp);
}

/* The whole file as a NUL-terminated string (caller frees), or NULL if it does
 * not exist. */
static char *read_file(const char *path)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) return NULL;
    fseek(fp, 0, SEEK_END);
    long n = ftell(fp);
    rewind(fp);
    char *text = malloc((size_t)n + 1);
    size_t got = fread(text, 1, (size_t)n, fp);
    text[got] = '\0';
    fclose(fp);
    return text;
}

static void test_read_points_dispatches_by_extension_case_insensitively(void)
{
    write_file("io_pts_test.CSV", "x,y,z\r\n1,2,3\r\n4,5,6\r\n");
    fl_points p;
    fl_error err;
    CHECK_STATUS(fl_read_points("io_pts_test.CSV", &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.count, 2);
    CHECK_EQ_INT(p.dim, 3);
    if (p.count == 2) CHECK(p.coords[5] == 6);
    fl_points_free(&p);
    remove("io_pts_test.CSV");
    /* Errors name the file being read. */
    write_file("io_pts_bad.xyz", "1 2 3\n4 5\n");
    CHECK_EQ_INT(fl_read_points("io_pts_bad.xyz", &p, &err), FL_ERR_INPUT);
    CHECK(strcmp(err.file, "io_pts_bad.xyz") == 0 && err.line == 2);
    remove("io_pts_bad.xyz");
}

static void test_unknown_extensions_are_usage_errors_listing_formats(void)
{
    fl_points p;
    fl_polygon g;
    fl_error err;
    CHECK_EQ_INT(fl_read_points("cloud.las", &p, &err), FL_ERR_USAGE);
    CHECK(strstr(err.message, ".las") && strstr(err.message, ".xyz") &&
          strstr(err.message, ".ply"));
    CHECK_EQ_INT(fl_read_points("no_extension", &p, &err), FL_ERR_USAGE);
    CHECK(strstr(err.message, "no file extension") != NULL);
    CHECK_EQ_INT(fl_parse_points("las", "mem", "1 2 3", 5, &p, &err), FL_ERR_USAGE);
    CHECK_EQ_INT(fl_read_polygon("shape.shp", &g, &err), FL_ERR_USAGE);
    CHECK(strstr(err.message, ".geojson") != NULL);
    CHECK_EQ_INT(fl_parse_polygon("kml", "mem", "", 0, &g, &err), FL_ERR_USAGE);
    fl_points pts = {1, 3, (double[]){1, 2, 3}};
    CHECK_EQ_INT(fl_write_points("out.pcd", &pts, &err), FL_ERR_USAGE);
    CHECK(strstr(err.message, ".xyz") != NULL);
    CHECK(read_file("out.pcd") == NULL);
    CHECK_EQ_INT(fl_write_polygon("out.dxf", &(fl_polygon){0}, &err), FL_ERR_USAGE);
}

static void test_null_arguments_are_usage_errors(void)
{
    fl_points p;
    fl_polygon g;
    fl_error err;
    CHECK_EQ_INT(fl_read_points(NULL, &p, &err), FL_ERR_USAGE);
    CHECK_EQ_INT(fl_read_points("a.xyz", NULL, &err), FL_ERR_USAGE);
    CHECK_EQ_INT(fl_parse_points("xyz", "m", "1 2", 3, NULL, &err), FL_ERR_USAGE);
    CHECK_EQ_INT(fl_read_polygon(NULL, &g, &err), FL_ERR_USAGE);
    CHECK_EQ_INT(fl_parse_polygon("xy", "m", "", 0, NULL, &err), FL_ERR_USAGE);
    CHECK_EQ_INT(fl_write_points("a.xyz", NULL, &err), FL_ERR_USAGE);
    CHECK_EQ_INT(fl_write_polygon(NULL, &g, &err), FL_ERR_USAGE);
    CHECK_EQ_INT(fl_parse_points(NULL, "m", "1 2", 3, &p, &err), FL_ERR_USAGE);
}

static void test_missing_file_is_io_error(void)
{
    fl_points p;
    fl_polygon g;
    fl_error err;
    CHECK_EQ_INT(fl_read_points("io_no_such_file.xyz", &p, &err), FL_ERR_IO);
    CHECK(strcmp(err.file, "io_no_such_file.xyz") == 0);
    CHECK_EQ_INT(fl_read_polygon("io_no_such_file.geojson", &g, &err), FL_ERR_IO);
}

static void test_parse_accepts_format_with_dot_and_capitals(void)
{
    fl_points p;
    fl_error err;
    CHECK_STATUS(fl_parse_points(".XYZ", NULL, "1 2\n3 4\n", 8, &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.count, 2);
    fl_points_free(&p);
    CHECK_EQ_INT(fl_parse_points("xyz", "x", NULL, 4, &p, &err), FL_ERR_USAGE);
    CHECK_EQ_INT(fl_parse_points("xyz", "x", NULL, 0, &p, &err), FL_ERR_INPUT);
}

static void test_points_files_round_trip_exactly(void)
{
    static const char *paths[] = {"io_rt.xyz", "io_rt.xy", "io_rt.txt"};
    unsigned long long rng = 5;
    double c[3 * 50];
    for (int i = 0; i < 150; i++)
        c[i] = (fl_test_rand01(&rng) - 0.5) * 1e3 / 7.0;
    for (size_t k = 0; k < 3; k++) {
        fl_points in = {50, k == 1 ? 2 : 3, c};
        fl_points out;
        fl_error err;
        CHECK_STATUS(fl_write_points(paths[k], &in, &err), FL_OK, &err);
        CHECK_STATUS(fl_read_points(paths[k], &out, &err), FL_OK, &err);
        CHECK_EQ_INT(out.count, 50);
        CHECK_EQ_INT(out.dim, in.dim);
        if (out.count == 50 && out.dim == in.dim)
            CHECK(memcmp(out.coords, c, 50 * (size_t)in.dim * sizeof(double)) == 0);
        fl_points_free(&out);
        remove(paths[k]);
    }
}

/* A failed write must leave the previous file as it was (atomic output). */
static void test_failed_write_leaves_target_untouched(void)
{
    const char *path = "io_keep.xyz";
    write_file(path, "1 2 3\n");
    fl_error err;
    fl_points nan_points = {2, 3, (double[]){1, 2, 3, 4, NAN, 6}};
    CHECK_EQ_INT(fl_write_points(path, &nan_points, &err), FL_ERR_INPUT);
    CHECK(strstr(err.message, "point 1") != NULL);
    fl_points flat = {1, 3, (double[]){7, 8, 9}};
    CHECK_EQ_INT(fl_write_points("io_keep.xy", &flat, &err), FL_ERR_USAGE);
    fl_points bad_dim = {1, 4, (double[]){1, 2, 3, 4}};
    CHECK_EQ_INT(fl_write_points(path, &bad_dim, &err), FL_ERR_USAGE);
    char *text = read_file(path);
    CHECK(text && strcmp(text, "1 2 3\n") == 0);
    free(text);
    CHECK(read_file("io_keep.xy") == NULL);
    remove(path);
}

static void test_polygon_files_round_trip(void)
{
    double xy[] = {0, 0, 8, 0, 8, 8, 0, 8, 2, 2, 2, 3, 3.25, 3, 10, 10, 12, 10, 11, 12.5};
    size_t ring_start[] = {0, 4, 7, 10};
    size_t polygon_start[] = {0, 2, 3};
    fl_polygon in = {10, xy, 3, ring_start, 2, polygon_start};
    static const char *paths[] = {"io_rt.geojson", "io_rt.json", "io_rt.xy"};
    for (size_t k = 0; k < 3; k++) {
        fl_polygon out;
        fl_error err;
        CHECK_STATUS(fl_write_polygon(paths[k], &in, &err), FL_OK, &err);
        CHECK_STATUS(fl_read_polygon(paths[k], &out, &err), FL_OK, &err);
        CHECK_EQ_INT(out.vertex_count, 10);
        CHECK_EQ_INT(out.ring_count, 3);
        /* .xy has no holes: each ring comes back as its own polygon. */
        CHECK_EQ_INT(out.polygon_count, k == 2 ? 3 : 2);
        if (out.vertex_count == 10 && out.ring_count == 3) {
            CHECK(memcmp(out.xy, xy, sizeof xy) == 0);
            CHECK(memcmp(out.ring_start, ring_start, sizeof ring_start) == 0);
        }
        fl_polygon_free(&out);
        remove(paths[k]);
    }
    fl_error err;
    CHECK_STATUS(fl_write_polygon("io_rt.svg", &in, &err), FL_OK, &err);
    char *svg = read_file("io_rt.svg");
    CHECK(svg && strncmp(svg, "<svg", 4) == 0);
    free(svg);
    remove("io_rt.svg");
}

static void test_write_polygon_rejects_inconsistent_tables(void)
{
    double xy[] = {0, 0, 1, 0, 1, 1, 0, 1};
    size_t short_ring[] = {0, 2, 4};
    size_t two_polygons[] = {0, 1, 2};
    fl_polygon g = {4, xy, 2, short_ring, 2, two_polygons};
    fl_error err;
    CHECK_EQ_INT(fl_write_polygon("io_bad.geojson", &g, &err), FL_ERR_INPUT);
    CHECK(strstr(err.message, "ring 0 has 2 vertices") != NULL);
    size_t wrong_end[] = {0, 3};
    size_t one_polygon[] = {0, 1};
    fl_polygon h = {4, xy, 1, wrong_end, 1, one_polygon};
    CHECK_EQ_INT(fl_write_polygon("io_bad.geojson", &h, &err), FL_ERR_USAGE);
    size_t ring[] = {0, 4};
    size_t empty_polygon[] = {0, 0, 1};
    fl_polygon k = {4, xy, 1, ring, 2, empty_polygon};
    CHECK_EQ_INT(fl_write_polygon("io_bad.svg", &k, &err), FL_ERR_USAGE);
    CHECK(read_file("io_bad.geojson") == NULL && read_file("io_bad.svg") == NULL);
}

/* Point sets in mesh formats: the vertices, with or without faces, as 3D
 * points. */
static void test_points_from_mesh_formats(void)
{
    const char *off = "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1.5\n3 0 1 2\n";
    const char *obj = "# cloud\nv 1 2 3\nv 4 5 6\n";
    fl_points p;
    fl_error err;
    CHECK_STATUS(fl_parse_points("off", "t.off", off, strlen(off), &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.count, 4);
    CHECK_EQ_INT(p.dim, 3);
    if (p.count == 4) CHECK(p.coords[11] == 1.5);
    fl_points_free(&p);
    CHECK_STATUS(fl_parse_points("obj", "t.obj", obj, strlen(obj), &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.count, 2);
    if (p.count == 2) CHECK(p.coords[3] == 4 && p.coords[5] == 6);
    fl_points_free(&p);
    /* .ply written from 2D points gets z = 0 and reads back as the same x, y. */
    fl_points flat = {3, 2, (double[]){0.1, 0.2, -3, 4e10, 5, 6}};
    CHECK_STATUS(fl_write_points("io_rt.ply", &flat, &err), FL_OK, &err);
    CHECK_STATUS(fl_read_points("io_rt.ply", &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.count, 3);
    CHECK_EQ_INT(p.dim, 3);
    for (size_t i = 0; i < 3 && p.count == 3; i++)
        CHECK(p.coords[3 * i] == flat.coords[2 * i] &&
              p.coords[3 * i + 1] == flat.coords[2 * i + 1] && p.coords[3 * i + 2] == 0);
    fl_points_free(&p);
    remove("io_rt.ply");
}

/* The bundled demo inputs: their first lines state how many points they hold. */
static void test_demo_inputs_read_as_points(void)
{
    static const struct {
        const char *file;
        size_t count;
        int dim;
    } demo[] = {{"leaf.xy", 160, 2}, {"peanut.xyz", 1500, 3}, {"torus.off", 512, 3}};
    for (size_t i = 0; i < 3; i++) {
        /* FL_TEST_DATA_DIR is <repo>/tests/data (which need not exist): take <repo> from it. */
        char path[1024];
        size_t root = strlen(FL_TEST_DATA_DIR) - strlen("/tests/data");
        snprintf(path, sizeof path, "%.*s/data/demo/%s", (int)root, FL_TEST_DATA_DIR, demo[i].file);
        fl_points p;
        fl_error err;
        CHECK_STATUS(fl_read_points(path, &p, &err), FL_OK, &err);
        CHECK_EQ_INT(p.count, demo[i].count);
        CHECK_EQ_INT(p.dim, demo[i].dim);
        fl_points_free(&p);
    }
}

FL_TEST_MAIN(FL_TEST_CASE(test_read_points_dispatches_by_extension_case_insensitively),
             FL_TEST_CASE(test_unknown_extensions_are_usage_errors_listing_formats),
             FL_TEST_CASE(test_null_arguments_are_usage_errors),
             FL_TEST_CASE(test_missing_file_is_io_error),
             FL_TEST_CASE(test_parse_accepts_format_with_dot_and_capitals),
             FL_TEST_CASE(test_points_files_round_trip_exactly),
             FL_TEST_CASE(test_failed_write_leaves_target_untouched),
             FL_TEST_CASE(test_polygon_files_round_trip),
             FL_TEST_CASE(test_write_polygon_rejects_inconsistent_tables),
             FL_TEST_CASE(test_points_from_mesh_formats),
             FL_TEST_CASE(test_demo_inputs_read_as_points))
