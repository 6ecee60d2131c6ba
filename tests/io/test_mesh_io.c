/* Mesh I/O by extension: dispatch, usage errors, and atomic writes that leave no trace (and an
 * existing target untouched) when they fail. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "fl_test.h"

static double cube_xyz[24] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0,
                              0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
static uint32_t cube_tri[36] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};

static fl_mesh cube(void)
{
    fl_mesh m = {8, cube_xyz, 12, cube_tri};
    return m;
}

/* Triangle t of a and of b have the same corner coordinates (vertex numbering may differ). */
static int same_geometry(const fl_mesh *a, const fl_mesh *b)
{
    if (a->triangle_count != b->triangle_count) return 0;
    for (size_t i = 0; i < 3 * a->triangle_count; i++)
        for (int c = 0; c < 3; c++)
            if (a->xyz[3 * a->tri[i] + (size_t)c] != b->xyz[3 * b->tri[i] + (size_t)c]) return 0;
    return 1;
}

static void test_mesh_round_trips_through_every_format_and_case_of_extension(void)
{
    static const char *paths[] = {"io_mesh_rt.off", "io_mesh_rt.OBJ", "io_mesh_rt.Ply",
                                  "io_mesh_rt.STL", "io_mesh_rt.d/x.ply"};
    fl_mesh m = cube();
    mkdir("io_mesh_rt.d", 0755);
    for (size_t i = 0; i < sizeof paths / sizeof paths[0]; i++) {
        fl_error err;
        fl_mesh back;
        CHECK_STATUS(fl_write_mesh(paths[i], &m, &err), FL_OK, &err);
        CHECK_STATUS(fl_read_mesh(paths[i], &back, &err), FL_OK, &err);
        CHECK_MSG(back.vertex_count == 8 && same_geometry(&m, &back), "%s", paths[i]);
        fl_mesh_free(&back);
        remove(paths[i]);
    }
    rmdir("io_mesh_rt.d");
}

static void test_mesh_empty_mesh_round_trips_in_every_format(void)
{
    static const char *paths[] = {"io_mesh_empty.off", "io_mesh_empty.obj", "io_mesh_empty.ply",
                                  "io_mesh_empty.stl"};
    fl_mesh empty = {0, NULL, 0, NULL};
    for (size_t i = 0; i < sizeof paths / sizeof paths[0]; i++) {
        fl_error err;
        fl_mesh back;
        CHECK_STATUS(fl_write_mesh(paths[i], &empty, &err), FL_OK, &err);
        CHECK_STATUS(fl_read_mesh(paths[i], &back, &err), FL_OK, &err);
        CHECK_MSG(back.vertex_count == 0 && back.triangle_count == 0, "%s", paths[i]);
        fl_mesh_free(&back);
        remove(paths[i]);
    }
}

static void test_mesh_unknown_extension_is_a_usage_error_listing_the_formats(void)
{
    fl_mesh m = cube(), out;
    fl_error err;
    CHECK_STATUS(fl_read_mesh("scene.dae", &out, &err), FL_ERR_USAGE, &err);
    CHECK(strstr(err.message, "'.dae'") && strstr(err.message, ".off .obj .ply .stl"));
    CHECK(strcmp(err.file, "scene.dae") == 0);
    CHECK_STATUS(fl_read_mesh("dir.v2/mesh", &out, &err), FL_ERR_USAGE, &err);
    CHECK(strstr(err.message, "no file extension") != NULL);
    CHECK_STATUS(fl_write_mesh("out.xyz", &m, &err), FL_ERR_USAGE, &err);
    CHECK(strstr(err.message, ".off .obj .ply .stl") != NULL);
    CHECK_STATUS(fl_parse_mesh("gltf", "buf", "x", 1, &out, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_parse_mesh("OFF", "buf", "OFF\n0 0 0\n", 10, &out, &err), FL_OK, &err);
    CHECK(out.vertex_count == 0 && out.triangle_count == 0);
    fl_mesh_free(&out);
}

static void test_mesh_read_of_a_missing_file_is_an_io_error(void)
{
    fl_mesh out;
    fl_error err;
    CHECK_STATUS(fl_read_mesh("io_mesh_does_not_exist.ply", &out, &err), FL_ERR_IO, &err);
    CHECK(strcmp(err.file, "io_mesh_does_not_exist.ply") == 0);
    CHECK(out.xyz == NULL && out.tri == NULL);
}

static void test_mesh_failed_parse_zeroes_the_output(void)
{
    double junk;
    fl_mesh out = {5, &junk, 5, NULL};
    fl_error err;
    CHECK_STATUS(fl_parse_mesh("obj", "b.obj", "v 1 2\n", 6, &out, &err), FL_ERR_INPUT, &err);
    CHECK(out.vertex_count == 0 && out.xyz == NULL && out.triangle_count == 0);
    CHECK_STATUS(fl_parse_mesh("off", "b.off", NULL, 0, &out, &err), FL_ERR_INPUT, &err);
    CHECK(strstr(err.message, "empty file") != NULL);
    CHECK_STATUS(fl_parse_mesh("off", "b.off", NULL, 3, &out, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_parse_mesh("off", "b.off", "OFF", 3, NULL, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_read_mesh("x.off", NULL, &err), FL_ERR_USAGE, &err);
}

static int file_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

static int read_small(const char *path, char *buf, size_t size)
{
    FILE *f = fopen(path, "rb");
    if (!f) return -1;
    size_t n = fread(buf, 1, size - 1, f);
    buf[n] = '\0';
    fclose(f);
    return (int)n;
}

/* No "<prefix>.tmp.*" file is left in the working directory. */
static int no_temporaries(const char *prefix)
{
    DIR *d = opendir(".");
    if (!d) return 0;
    struct dirent *e;
    int clean = 1;
    size_t n = strlen(prefix);
    while ((e = readdir(d)))
        if (strncmp(e->d_name, prefix, n) == 0 && strstr(e->d_name + n, ".tmp.")) clean = 0;
    closedir(d);
    return clean;
}

static void test_mesh_failed_write_leaves_no_file_and_the_target_untouched(void)
{
    fl_mesh m = cube();
    fl_error err;
    /* The directory does not exist: nothing is created. */
    CHECK_STATUS(fl_write_mesh("io_mesh_no_such_dir/out.off", &m, &err), FL_ERR_IO, &err);
    CHECK(!file_exists("io_mesh_no_such_dir/out.off") && !file_exists("io_mesh_no_such_dir"));

    /* An existing target survives a mesh that cannot be written. */
    const char *path = "io_mesh_existing.ply";
    FILE *f = fopen(path, "w");
    fputs("old content", f);
    fclose(f);
    uint32_t bad_tri[3] = {0, 1, 8};
    fl_mesh bad = {8, cube_xyz, 1, bad_tri};
    CHECK_STATUS(fl_write_mesh(path, &bad, &err), FL_ERR_INPUT, &err);
    CHECK(strstr(err.message, "refers to vertex 8") != NULL);
    double nan_xyz[24];
    memcpy(nan_xyz, cube_xyz, sizeof nan_xyz);
    nan_xyz[13] = NAN;
    fl_mesh with_nan = {8, nan_xyz, 12, cube_tri};
    CHECK_STATUS(fl_write_mesh(path, &with_nan, &err), FL_ERR_INPUT, &err);
    CHECK(strstr(err.message, "vertex 4") != NULL);
    char buf[64];
    CHECK(read_small(path, buf, sizeof buf) == 11 && strcmp(buf, "old content") == 0);
    CHECK(no_temporaries("io_mesh_existing.ply"));
    remove(path);

    /* The target is a directory: the rename fails, the temporary is removed. */
    const char *dir = "io_mesh_dir_target.stl";
    mkdir(dir, 0755);
    CHECK_STATUS(fl_write_mesh(dir, &m, &err), FL_ERR_IO, &err);
    struct stat st;
    CHECK(stat(dir, &st) == 0 && S_ISDIR(st.st_mode));
    CHECK(no_temporaries(dir));
    rmdir(dir);
}

/* A file's bytes in a buffer of exactly its size, so that ASan flags any read past the end. */
static unsigned char *file_bytes(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    unsigned char *buf = malloc(1 << 16);
    *size = fread(buf, 1, 1 << 16, f);
    fclose(f);
    return buf;
}

/* Every reader, fed corrupted files, returns OK with a valid mesh or FL_ERR_INPUT with a
 * location, a message and a zeroed mesh. */
static void check_corruptions(const char *format, const unsigned char *good, size_t size,
                              unsigned long long *rng)
{
    static const unsigned char interesting[] = {'0', '9',  ' ',  '\n', '-', '.', 'e', '/',
                                                '#', 0x00, 0x7f, 0xff, 'n', 'i', '3'};
    for (int iter = 0; iter < 1500; iter++) {
        size_t len = size;
        unsigned char *buf = malloc(size);
        memcpy(buf, good, size);
        int edits = 1 + (int)(fl_test_rand_u64(rng) % 3);
        for (int k = 0; k < edits; k++) {
            size_t at = (size_t)(fl_test_rand_u64(rng) % size);
            unsigned long long r = fl_test_rand_u64(rng);
            buf[at] = r & 1 ? interesting[(r >> 1) % sizeof interesting] : (unsigned char)(r >> 8);
        }
        if (fl_test_rand_u64(rng) % 4 == 0) len = (size_t)(fl_test_rand_u64(rng) % size);
        unsigned char *exact = malloc(len ? len : 1);
        memcpy(exact, buf, len);
        fl_mesh m;
        fl_error err;
        fl_status st = fl_parse_mesh(format, "fuzz", exact, len, &m, &err);
        CHECK_MSG(st == FL_OK || st == FL_ERR_INPUT, "%s: status %d", format, (int)st);
        if (st == FL_OK) {
            int valid = 1;
            for (size_t i = 0; i < 3 * m.triangle_count; i++)
                valid &= m.tri[i] < m.vertex_count;
            for (size_t i = 0; i < 3 * m.vertex_count; i++)
                valid &= isfinite(m.xyz[i]);
            CHECK_MSG(valid, "%s: invalid mesh accepted (iteration %d)", format, iter);
            fl_mesh_free(&m);
        } else {
            CHECK_MSG((err.line >= 1 || err.offset >= 0) && err.message[0],
                      "%s: error without location: %s", format, err.message);
            CHECK(m.xyz == NULL && m.tri == NULL);
        }
        free(exact);
        free(buf);
    }
}

static void test_mesh_readers_survive_random_corruption(void)
{
    static const char *paths[] = {"io_mesh_fuzz.off", "io_mesh_fuzz.obj", "io_mesh_fuzz.ply",
                                  "io_mesh_fuzz.stl"};
    static const char *ascii_ply =
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
        "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
        "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n4 0 1 2 3\n";
    static const char *ascii_stl = "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                                   "vertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid s\n";
    unsigned long long rng = 99;
    fl_mesh m = cube();
    fl_error err;
    for (size_t i = 0; i < sizeof paths / sizeof paths[0]; i++) {
        CHECK_STATUS(fl_write_mesh(paths[i], &m, &err), FL_OK, &err);
        size_t size;
        unsigned char *good = file_bytes(paths[i], &size);
        if (good) check_corruptions(paths[i] + strlen(paths[i]) - 3, good, size, &rng);
        free(good);
        remove(paths[i]);
    }
    check_corruptions("ply", (const unsigned char *)ascii_ply, strlen(ascii_ply), &rng);
    check_corruptions("stl", (const unsigned char *)ascii_stl, strlen(ascii_stl), &rng);
}

FL_TEST_MAIN(FL_TEST_CASE(test_mesh_round_trips_through_every_format_and_case_of_extension),
             FL_TEST_CASE(test_mesh_empty_mesh_round_trips_in_every_format),
             FL_TEST_CASE(test_mesh_unknown_extension_is_a_usage_error_listing_the_formats),
             FL_TEST_CASE(test_mesh_read_of_a_missing_file_is_an_io_error),
             FL_TEST_CASE(test_mesh_failed_parse_zeroes_the_output),
             FL_TEST_CASE(test_mesh_failed_write_leaves_no_file_and_the_target_untouched),
             FL_TEST_CASE(test_mesh_readers_survive_random_corruption))
