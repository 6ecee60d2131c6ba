/* .xy polygon rings: blocks separated by blank lines, closing repeats, errors with lines,
 * exact round trips. */
#include "io/io_internal.h"
#include "io_test_util.h"

static fl_status parse(const char *text, fl_polygon *poly, fl_error *err)
{
    return fl_xy_polygon_parse("t.xy", text, strlen(text), poly, err);
}

/* Checks that the ring and polygon tables are consistent with the fl_polygon contract. */
static void check_one_polygon_per_ring(const fl_polygon *p)
{
    CHECK_EQ_INT(p->polygon_count, p->ring_count);
    CHECK_EQ_INT(p->ring_start[0], 0);
    CHECK_EQ_INT(p->ring_start[p->ring_count], p->vertex_count);
    for (size_t i = 0; i <= p->polygon_count; i++)
        CHECK_EQ_INT(p->polygon_start[i], i);
}

static void test_xy_blank_lines_separate_rings(void)
{
    fl_polygon p;
    fl_error err;
    const char *text = "# two squares\r\n0 0\r\n1 0\r\n1 1\r\n0 1\r\n\r\n\r\n"
                       "5,5\n6,5 # corner\n# a comment line does not end the ring\n6,6\n";
    CHECK_STATUS(parse(text, &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.ring_count, 2);
    CHECK_EQ_INT(p.vertex_count, 7);
    if (p.ring_count == 2) {
        check_one_polygon_per_ring(&p);
        CHECK_EQ_INT(p.ring_start[1], 4);
        CHECK(p.xy[8] == 5 && p.xy[9] == 5 && p.xy[12] == 6 && p.xy[13] == 6);
    }
    fl_polygon_free(&p);
}

static void test_xy_closing_repeat_is_dropped(void)
{
    fl_polygon p;
    fl_error err;
    CHECK_STATUS(parse("x y\n0 0\n2 0\n2 2\n0 0\n", &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.vertex_count, 3);
    fl_polygon_free(&p);
    /* Only an exact repeat closes: a last vertex 1e-300 away is a vertex of its own. */
    CHECK_STATUS(parse("0 0\n2 0\n2 2\n1e-300 0\n", &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.vertex_count, 4);
    fl_polygon_free(&p);
}

static void test_xy_short_ring_names_its_first_line(void)
{
    fl_polygon p;
    fl_error err;
    fl_status st = parse("0 0\n1 0\n1 1\n\n# next\n5 5\n6 6\n5 5\n\n7 7\n8 7\n8 8\n", &p, &err);
    CHECK_INPUT_ERROR(st, err, 6, "2 distinct vertices");
    CHECK(p.xy == NULL && p.ring_count == 0);
    st = parse("0 0\n1 0\n1 1\n\n3 3\n", &p, &err);
    CHECK_INPUT_ERROR(st, err, 5, "1 distinct vertices");
}

static void test_xy_bad_lines_rejected_with_line(void)
{
    fl_polygon p;
    fl_error err;
    fl_status st = parse("0 0\n1 0 7\n1 1\n", &p, &err);
    CHECK_INPUT_ERROR(st, err, 2, "expected 2 numbers, got 3");
    st = parse("0 0\n1 zero\n1 1\n", &p, &err);
    CHECK_INPUT_ERROR(st, err, 2, "'zero' is not a number");
    st = parse("0 0\n1 0\n1 1\n\n\n1 nan\n", &p, &err);
    CHECK_INPUT_ERROR(st, err, 6, "not a finite number");
    st = parse("# nothing\n\n", &p, &err);
    CHECK_INPUT_ERROR(st, err, -1, "no rings");
}

static void test_xy_unterminated_buffer_not_overread(void)
{
    size_t n;
    char *buf = io_test_unterminated("0 0\n1 0\n1 1.5", &n);
    fl_polygon p;
    fl_error err;
    CHECK_STATUS(fl_xy_polygon_parse("t.xy", buf, n, &p, &err), FL_OK, &err);
    if (p.vertex_count == 3) CHECK(p.xy[5] == 1.5);
    fl_polygon_free(&p);
    free(buf);
}

/* Rings written with %.17g and read back are the same doubles; holes come back as polygons
 * of their own (the documented loss of the .xy format). */
static void test_xy_round_trip_is_exact_and_splits_holes(void)
{
    unsigned long long rng = 3;
    double xy[2 * 11];
    for (int i = 0; i < 22; i++)
        xy[i] = (fl_test_rand01(&rng) - 0.5) * 1e6 / 3.0;
    size_t ring_start[] = {0, 4, 7, 11};
    size_t polygon_start[] = {0, 2, 3};
    fl_polygon in = {11, xy, 3, ring_start, 2, polygon_start};
    char *text;
    size_t size;
    fl_status st = FL_ERR_IO;
    IO_TEST_CAPTURE(fl_xy_polygon_write(fp, &in), text, size, st);
    CHECK_EQ_INT(st, FL_OK);
    fl_polygon out;
    fl_error err;
    CHECK_STATUS(fl_xy_polygon_parse("rt.xy", text, size, &out, &err), FL_OK, &err);
    CHECK_EQ_INT(out.vertex_count, 11);
    CHECK_EQ_INT(out.ring_count, 3);
    if (out.vertex_count == 11 && out.ring_count == 3) {
        CHECK(memcmp(out.xy, xy, sizeof xy) == 0);
        CHECK(memcmp(out.ring_start, ring_start, sizeof ring_start) == 0);
        check_one_polygon_per_ring(&out);
    }
    fl_polygon_free(&out);
    free(text);
}

FL_TEST_MAIN(FL_TEST_CASE(test_xy_blank_lines_separate_rings),
             FL_TEST_CASE(test_xy_closing_repeat_is_dropped),
             FL_TEST_CASE(test_xy_short_ring_names_its_first_line),
             FL_TEST_CASE(test_xy_bad_lines_rejected_with_line),
             FL_TEST_CASE(test_xy_unterminated_buffer_not_overread),
             FL_TEST_CASE(test_xy_round_trip_is_exact_and_splits_holes))
