#include <stdio.h>

#include "fl_test.h"

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    if (!f) return;
    fputs(text, f);
    fclose(f);
}

static void test_balls_round_trip_exactly(void)
{
    double xyzw[] = {0.1, -2.5e-300, 3e300, 0.25, 1.0 / 3.0, 2, 3, -4};
    fl_balls b = {2, xyzw}, back = {0};
    fl_error err;
    CHECK_STATUS(fl_write_balls("balls_rt.xyzw", &b, &err), FL_OK, &err);
    CHECK_STATUS(fl_read_balls("balls_rt.xyzw", &back, &err), FL_OK, &err);
    CHECK_EQ_INT(back.count, 2);
    for (int i = 0; i < 8 && back.count == 2; i++)
        CHECK(back.xyzw[i] == xyzw[i]);
    fl_balls_free(&back);
    remove("balls_rt.xyzw");
}

static void test_balls_need_four_numbers_a_line(void)
{
    fl_balls b;
    fl_error err;
    write_text("balls_bad.xyzw", "# x y z w\n0 0 0 1\n1 1 1\n");
    CHECK_STATUS(fl_read_balls("balls_bad.xyzw", &b, &err), FL_ERR_INPUT, &err);
    CHECK_EQ_INT(err.line, 3);
    CHECK(strstr(err.message, "expected 4 numbers") != NULL);
    write_text("balls_bad.xyzw", "0 0 0 nan\n");
    CHECK_STATUS(fl_read_balls("balls_bad.xyzw", &b, &err), FL_ERR_INPUT, &err);
    CHECK_EQ_INT(err.line, 1);
    write_text("balls_bad.xyzw", "# nothing\n");
    CHECK_STATUS(fl_read_balls("balls_bad.xyzw", &b, &err), FL_ERR_INPUT, &err);
    remove("balls_bad.xyzw");
    CHECK_STATUS(fl_read_balls("no-such-file.xyzw", &b, &err), FL_ERR_IO, &err);
}

FL_TEST_MAIN(FL_TEST_CASE(test_balls_round_trip_exactly),
             FL_TEST_CASE(test_balls_need_four_numbers_a_line))
