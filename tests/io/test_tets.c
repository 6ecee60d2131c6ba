#include <stdio.h>
#include <string.h>

#include "fl_test.h"

static const double cube_xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
static const uint32_t two_tets[] = {0, 1, 2, 3, 1, 2, 3, 4};

static long count_lines(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f) return -1;
    long n = 0;
    int c;
    while ((c = fgetc(f)) != EOF)
        n += c == '\n';
    fclose(f);
    return n;
}

static void test_vtk_lists_every_point_and_cell(void)
{
    fl_error err;
    CHECK_STATUS(fl_write_tets("tets_test.vtk", cube_xyz, 5, two_tets, 2, &err), FL_OK, &err);
    /* 4 header lines + POINTS + 5 + CELLS + 2 + CELL_TYPES + 2 */
    CHECK_EQ_INT(count_lines("tets_test.vtk"), 4 + 1 + 5 + 1 + 2 + 1 + 2);
    FILE *f = fopen("tets_test.vtk", "r");
    char buf[4096];
    size_t n = f ? fread(buf, 1, sizeof buf - 1, f) : 0;
    buf[n] = '\0';
    if (f) fclose(f);
    CHECK(strstr(buf, "CELLS 2 10\n4 0 1 2 3\n4 1 2 3 4\n") != NULL);
    CHECK(strstr(buf, "CELL_TYPES 2\n10\n10\n") != NULL);
    remove("tets_test.vtk");
}

static void test_tetgen_pair_is_written_together(void)
{
    fl_error err;
    CHECK_STATUS(fl_write_tets("tets_test.ele", cube_xyz, 5, two_tets, 2, &err), FL_OK, &err);
    CHECK_EQ_INT(count_lines("tets_test.node"), 2 + 5);
    CHECK_EQ_INT(count_lines("tets_test.ele"), 2 + 2);
    remove("tets_test.node");
    remove("tets_test.ele");
}

static void test_bad_index_or_format_writes_nothing(void)
{
    fl_error err;
    const uint32_t bad[] = {0, 1, 2, 7};
    CHECK_STATUS(fl_write_tets("tets_bad.vtk", cube_xyz, 5, bad, 1, &err), FL_ERR_USAGE, &err);
    CHECK(fopen("tets_bad.vtk", "r") == NULL);
    CHECK_STATUS(fl_write_tets("tets_bad.xyz", cube_xyz, 5, two_tets, 2, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_write_tets("/nonexistent-dir/t.vtk", cube_xyz, 5, two_tets, 2, &err), FL_ERR_IO,
                 &err);
}

FL_TEST_MAIN(FL_TEST_CASE(test_vtk_lists_every_point_and_cell),
             FL_TEST_CASE(test_tetgen_pair_is_written_together),
             FL_TEST_CASE(test_bad_index_or_format_writes_nothing))
