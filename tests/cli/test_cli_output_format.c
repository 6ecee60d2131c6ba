/* -o's format is checked before the computation: every format a command lists as accepted is
 * one its writer really writes (a file appears, exit 0), and any other extension fails with
 * the usage code, names the accepted formats, and leaves no file. Before this check an
 * unwritable extension failed only after the whole computation (e.g. 11 s of Delaunay). */
#include <sys/stat.h>

#include "cli_run.h"
#include "fl_test.h"

#define DEMO "'" FL_SOURCE_DIR "/data/demo/"

static cli_result r;

typedef struct format_case {
    const char *command; /* without -o */
    const char *formats; /* what the command must write, space separated */
    const char *refused; /* an extension it must refuse at once */
} format_case;

static const format_case formats_of[] = {
    {"delaunay " DEMO "leaf.xy'", "svg off obj ply stl", "tets"},
    {"delaunay " DEMO "peanut.xyz'", "vtk node ele", "off"},
    {"graph " DEMO "leaf.xy' --kind gabriel", "svg obj ply", "off"},
    {"graph " DEMO "peanut.xyz' --kind emst", "obj ply", "svg"},
    {"reconstruct " DEMO "leaf.xy'", "xy geojson json svg off", "ply"},
    {"reconstruct " DEMO "peanut.xyz'", "off obj ply stl", "xy"},
    {"hal " DEMO "leaf-truth.xy' --level 2", "xy geojson json svg", "off"},
    {"hal " DEMO "peanut-truth.off' --level 2", "off obj ply stl", "svg"},
    {"smooth " DEMO "leaf-truth.xy'", "svg xy geojson json", "off"},
    {"smooth " DEMO "peanut-truth.off' --scheme three-split --tess 1", "off obj ply stl bez", "svg"},
    {"skin --balls skinfmt_balls.txt", "off obj ply stl", "xyz"},
};

static long file_size(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? (long)st.st_size : -1;
}

static void test_every_listed_format_is_written(void)
{
    cli_write_file("skinfmt_balls.txt", "0 0 0 1\n1.2 0 0 1\n");
    for (size_t i = 0; i < sizeof formats_of / sizeof formats_of[0]; i++) {
        char formats[64];
        snprintf(formats, sizeof formats, "%s", formats_of[i].formats);
        for (char *f = strtok(formats, " "); f; f = strtok(NULL, " ")) {
            char out[64], args[512];
            snprintf(out, sizeof out, "outfmt_%zu.%s", i, f);
            snprintf(args, sizeof args, "%s -o %s", formats_of[i].command, out);
            CHECK_MSG(cli_run(&r, args) == 0, "%s: exit %d, %s", args, r.code, r.err);
            CHECK_MSG(file_size(out) > 0, "%s wrote no %s", args, out);
            remove(out);
            if (!strcmp(f, "node") || !strcmp(f, "ele")) { /* the pair is written together */
                snprintf(out, sizeof out, "outfmt_%zu.node", i);
                remove(out);
                snprintf(out, sizeof out, "outfmt_%zu.ele", i);
                remove(out);
            }
        }
    }
    remove("skinfmt_balls.txt");
}

static void test_other_formats_fail_before_the_work(void)
{
    cli_write_file("skinfmt_balls.txt", "0 0 0 1\n1.2 0 0 1\n");
    for (size_t i = 0; i < sizeof formats_of / sizeof formats_of[0]; i++) {
        char out[64], args[512];
        snprintf(out, sizeof out, "outfmt_bad_%zu.%s", i, formats_of[i].refused);
        snprintf(args, sizeof args, "%s -o %s --json", formats_of[i].command, out);
        CHECK_MSG(cli_run(&r, args) == 1, "%s: exit %d", args, r.code);
        CHECK_MSG(strstr(r.err, "does not write") && strstr(r.err, formats_of[i].formats),
                  "%s: %s", args, r.err);
        CHECK_MSG(r.out[0] == '\0', "%s printed a result: %s", args, r.out);
        CHECK_MSG(file_size(out) < 0, "%s left %s", args, out);
        /* no extension at all */
        snprintf(args, sizeof args, "%s -o outfmt_noext", formats_of[i].command);
        CHECK_EQ_INT(cli_run(&r, args), 1);
        CHECK_MSG(strstr(r.err, "no file extension") != NULL, "%s: %s", args, r.err);
        CHECK(file_size("outfmt_noext") < 0);
    }
    remove("skinfmt_balls.txt");
}

FL_TEST_MAIN(FL_TEST_CASE(test_every_listed_format_is_written),
             FL_TEST_CASE(test_other_formats_fail_before_the_work))
