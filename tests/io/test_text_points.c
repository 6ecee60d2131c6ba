/* Text point lists (.xyz .xy .txt .csv): accepted layouts, exact values, errors with lines,
 * exact round trips and a linear-time parse. */
#include <stdint.h>
#include <time.h>

#include "io/io_internal.h"
#include "io/text_scan.h"
#include "io_test_util.h"

static fl_status parse(const char *text, fl_points *pts, fl_error *err)
{
    return fl_text_points_parse("t.xyz", text, strlen(text), pts, err);
}

/* The values are compared with the compiler's own conversion of the same literals. */
static void test_points_whitespace_tabs_and_comments(void)
{
    fl_points p;
    fl_error err;
    const char *text = "# a scan\n"
                       "  1.5\t-2   3e2   # first\n"
                       "\n"
                       "# between\n"
                       "0.1 0.2 0.3\n";
    CHECK_STATUS(parse(text, &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.count, 2);
    CHECK_EQ_INT(p.dim, 3);
    if (p.count == 2) {
        CHECK(p.coords[0] == 1.5 && p.coords[1] == -2.0 && p.coords[2] == 3e2);
        CHECK(p.coords[3] == 0.1 && p.coords[4] == 0.2 && p.coords[5] == 0.3);
    }
    fl_points_free(&p);
}

static void test_points_crlf_blank_lines_and_trailing_spaces(void)
{
    fl_points p;
    fl_error err;
    const char *text = "1 2 3   \r\n\r\n4 5 6\t\r\n   \r\n7 8 9";
    CHECK_STATUS(parse(text, &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.count, 3);
    if (p.count == 3) CHECK(p.coords[2] == 3 && p.coords[6] == 7 && p.coords[8] == 9);
    fl_points_free(&p);
}

static void test_points_csv_header_commas_and_semicolons(void)
{
    fl_points p;
    fl_error err;
    const char *text = "# exported\nx,y,z\n1,2,3\n4, 5 ,6\n7;8;9\n10 ,11\t;12 # mixed\n";
    CHECK_STATUS(parse(text, &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.count, 4);
    if (p.count == 4) {
        for (int i = 0; i < 12; i++)
            CHECK(p.coords[i] == i + 1);
    }
    fl_points_free(&p);
}

static void test_points_two_numbers_give_2d(void)
{
    fl_points p;
    fl_error err;
    CHECK_STATUS(parse("0 0\n1 0\n0.5 1\n", &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.dim, 2);
    CHECK_EQ_INT(p.count, 3);
    if (p.count == 3) CHECK(p.coords[4] == 0.5 && p.coords[5] == 1);
    fl_points_free(&p);
}

static void test_points_utf8_bom_is_skipped(void)
{
    fl_points p;
    fl_error err;
    CHECK_STATUS(parse("\xEF\xBB\xBF"
                       "1 2 3\n",
                       &p, &err),
                 FL_OK, &err);
    CHECK_EQ_INT(p.count, 1);
    fl_points_free(&p);
}

static void test_points_count_mismatch_names_line(void)
{
    fl_points p;
    fl_error err;
    fl_status st = parse("# c\n1 2 3\n4 5 6\n\n7 8\n", &p, &err);
    CHECK_INPUT_ERROR(st, err, 5, "expected 3 numbers, got 2");
    CHECK(strcmp(err.file, "t.xyz") == 0);
    CHECK(p.coords == NULL && p.count == 0);
    st = parse("1 2 3 4\n", &p, &err);
    CHECK_INPUT_ERROR(st, err, 1, "expected 2 or 3 numbers");
    st = parse("1\n", &p, &err);
    CHECK_INPUT_ERROR(st, err, 1, "got 1");
}

static void test_points_nonfinite_values_rejected_with_line(void)
{
    static const char *bad[] = {"nan", "NaN", "inf", "-inf", "Infinity", "1e999", "-1e400"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char text[128];
        snprintf(text, sizeof text, "1 2 3\n# x\n4 %s 6\n", bad[i]);
        fl_points p;
        fl_error err;
        fl_status st = parse(text, &p, &err);
        CHECK_INPUT_ERROR(st, err, 3, "not a finite number");
        CHECK(p.coords == NULL);
    }
}

static void test_points_tiny_values_underflow_to_finite(void)
{
    fl_points p;
    fl_error err;
    CHECK_STATUS(parse("4.9406564584124654e-324 1e-400 0\n", &p, &err), FL_OK, &err);
    if (p.count == 1) CHECK(p.coords[0] > 0 && p.coords[1] == 0);
    fl_points_free(&p);
}

static void test_points_text_after_data_rejected(void)
{
    fl_points p;
    fl_error err;
    fl_status st = parse("1 2 3\n4 abc 6\n", &p, &err);
    CHECK_INPUT_ERROR(st, err, 2, "'abc' is not a number");
    st = parse("x y z\nx y z\n1 2 3\n", &p, &err);
    CHECK_INPUT_ERROR(st, err, 2, "only one header line");
    /* A first line with some numbers is a broken data line, not a header. */
    st = parse("1 2 3x\n4 5 6\n", &p, &err);
    CHECK_INPUT_ERROR(st, err, 1, "'3x' is not a number");
}

static void test_points_empty_inputs_rejected(void)
{
    static const char *empty[] = {"", "\n\n", "# only a comment\n", "x,y,z\n"};
    for (size_t i = 0; i < sizeof empty / sizeof empty[0]; i++) {
        fl_points p;
        fl_error err;
        CHECK_EQ_INT(parse(empty[i], &p, &err), FL_ERR_INPUT);
        CHECK(strstr(err.message, "no points") != NULL);
    }
}

/* The buffer has no NUL after the last digit; ASan reports any read beyond it. */
static void test_points_unterminated_buffer_not_overread(void)
{
    size_t n;
    char *buf = io_test_unterminated("1 2 3\n4 5 6.25", &n);
    fl_points p;
    fl_error err;
    CHECK_STATUS(fl_text_points_parse("t.xyz", buf, n, &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.count, 2);
    if (p.count == 2) CHECK(p.coords[5] == 6.25);
    fl_points_free(&p);
    free(buf);
    buf = io_test_unterminated("1 2 3\n4 5 nan", &n);
    CHECK_EQ_INT(fl_text_points_parse("t.xyz", buf, n, &p, &err), FL_ERR_INPUT);
    free(buf);
}

static double random_finite_double(unsigned long long *state)
{
    for (;;) {
        uint64_t bits = fl_test_rand_u64(state);
        double v;
        memcpy(&v, &bits, sizeof v);
        if (isfinite(v)) return v;
    }
}

/* Any finite double, including subnormals and -0, must survive write then read bit for bit. */
static void test_points_round_trip_is_bit_exact(void)
{
    unsigned long long rng = 42;
    for (int dim = 2; dim <= 3; dim++) {
        fl_points in = {500, dim, malloc(500 * (size_t)dim * sizeof(double))};
        for (size_t i = 0; i < in.count * (size_t)dim; i++)
            in.coords[i] = (i % 7 == 0) ? -0.0 : random_finite_double(&rng);
        char *text;
        size_t size;
        fl_status st = FL_ERR_IO;
        IO_TEST_CAPTURE(fl_text_points_write(fp, &in), text, size, st);
        CHECK_EQ_INT(st, FL_OK);
        fl_points out;
        fl_error err;
        CHECK_STATUS(fl_text_points_parse("rt.xyz", text, size, &out, &err), FL_OK, &err);
        CHECK_EQ_INT(out.count, in.count);
        CHECK_EQ_INT(out.dim, dim);
        if (out.count == in.count)
            CHECK(memcmp(out.coords, in.coords, in.count * (size_t)dim * sizeof(double)) == 0);
        fl_points_free(&out);
        fl_points_free(&in);
        free(text);
    }
}

static char *make_points_text(size_t n, size_t *size)
{
    char *text = malloc(n * 40 + 1);
    size_t len = 0;
    unsigned long long rng = 7;
    for (size_t i = 0; i < n; i++)
        len += (size_t)sprintf(text + len, "%.6f %.6f %.6f\n", fl_test_rand01(&rng),
                               fl_test_rand01(&rng), fl_test_rand01(&rng));
    *size = len;
    return text;
}

static double parse_seconds(size_t n)
{
    size_t size;
    char *text = make_points_text(n, &size);
    fl_points p;
    fl_error err;
    clock_t t0 = clock();
    CHECK_STATUS(fl_text_points_parse("big.xyz", text, size, &p, &err), FL_OK, &err);
    double s = (double)(clock() - t0) / CLOCKS_PER_SEC;
    CHECK_EQ_INT(p.count, n);
    fl_points_free(&p);
    free(text);
    return s;
}

/* Four times the points must cost about four times the time; a quadratic scan (e.g. strlen
 * of the rest of the buffer per number) would cost sixteen times. */
static void test_points_parse_time_is_linear(void)
{
    double small = parse_seconds(100000), large = parse_seconds(400000);
    CHECK_MSG(large < 8 * small + 0.05, "100k points: %.3f s, 400k points: %.3f s", small, large);
}

/* Random byte edits never crash or over-read (ASan watches); each result is a point set whose
 * count and dimension agree, or FL_ERR_INPUT with a zeroed output and a line inside the file. */
static void test_points_mutated_inputs_fail_cleanly(void)
{
    const char *seed = "x,y,z\r\n1.5 2 3 # c\n\n-4e2;5,6\n7 8 9\n0x1p3 1e-5 .5\n";
    static const char alphabet[] = "0123456789.-+eE ,;#\n\rxnaif\x00\xff";
    size_t n = strlen(seed);
    unsigned long long rng = 17;
    for (int trial = 0; trial < 3000; trial++) {
        char *buf = malloc(n);
        memcpy(buf, seed, n);
        size_t len = n;
        for (int e = 0; e < 2; e++) {
            size_t at = (size_t)(fl_test_rand_u64(&rng) % len);
            if (fl_test_rand_u64(&rng) % 4 == 0)
                len = at + 1;
            else
                buf[at] = alphabet[fl_test_rand_u64(&rng) % (sizeof alphabet - 1)];
        }
        long lines = 1;
        for (size_t i = 0; i < len; i++)
            lines += buf[i] == '\n';
        fl_points p;
        fl_error err;
        fl_status st = fl_text_points_parse("m.xyz", buf, len, &p, &err);
        if (st == FL_OK) {
            CHECK(p.count > 0 && (p.dim == 2 || p.dim == 3) && p.coords != NULL);
            for (size_t i = 0; i < p.count * (size_t)p.dim; i++)
                CHECK(isfinite(p.coords[i]));
        } else {
            CHECK_EQ_INT(st, FL_ERR_INPUT);
            CHECK(p.coords == NULL && p.count == 0);
            CHECK(err.line >= -1 && err.line <= lines && err.line != 0);
        }
        fl_points_free(&p);
        free(buf);
    }
}

/* fl_scan_double takes a fast path for short decimals; strtod (correctly rounded in glibc) is
 * the oracle: both must give the same bits for decimals of every shape near the fast path's
 * limits (up to 19 digits, exponents around +-22, leading zeros, signs, no integer part). */
static void test_scan_double_matches_strtod_bit_for_bit(void)
{
    unsigned long long rng = 123;
    char s[64];
    for (int trial = 0; trial < 200000; trial++) {
        size_t n = 0;
        unsigned long long r = fl_test_rand_u64(&rng);
        if (r & 1) s[n++] = (r & 2) ? '-' : '+';
        int digits = 1 + (int)((r >> 2) % 19), point = (int)((r >> 8) % (unsigned)(digits + 2));
        int zeros = (int)((r >> 16) % 4);
        for (int i = 0; i < zeros; i++)
            s[n++] = '0';
        for (int i = 0; i < digits; i++) {
            if (i == point) s[n++] = '.';
            s[n++] = (char)('0' + fl_test_rand_u64(&rng) % 10);
        }
        if ((r >> 24) & 1) n += (size_t)sprintf(s + n, "e%d", (int)((r >> 32) % 61) - 30);
        s[n] = '\0';
        char *stop;
        double want = strtod(s, &stop), got = 0;
        fl_number_scan st = fl_scan_double(s, n, &got);
        if (stop != s + n) {
            CHECK_MSG(st == FL_NUMBER_INVALID, "'%s'", s);
        } else {
            CHECK_MSG(st == FL_NUMBER_OK && memcmp(&got, &want, sizeof got) == 0,
                      "'%s': %.17g vs strtod %.17g", s, got, want);
        }
    }
    static const char *edge[] = {"9007199254740993",
                                 "9007199254740992e22",
                                 "1e23",
                                 "-0",
                                 "0.000",
                                 "1.",
                                 ".5",
                                 "123456789012345678901",
                                 "4.35e-3",
                                 "1e-22",
                                 "9999999999999999999e-22",
                                 "0e999"};
    for (size_t i = 0; i < sizeof edge / sizeof edge[0]; i++) {
        double got = 0, want = strtod(edge[i], NULL);
        CHECK_MSG(fl_scan_double(edge[i], strlen(edge[i]), &got) == FL_NUMBER_OK &&
                      memcmp(&got, &want, sizeof got) == 0,
                  "'%s'", edge[i]);
    }
}

FL_TEST_MAIN(FL_TEST_CASE(test_points_whitespace_tabs_and_comments),
             FL_TEST_CASE(test_points_crlf_blank_lines_and_trailing_spaces),
             FL_TEST_CASE(test_points_csv_header_commas_and_semicolons),
             FL_TEST_CASE(test_points_two_numbers_give_2d),
             FL_TEST_CASE(test_points_utf8_bom_is_skipped),
             FL_TEST_CASE(test_points_count_mismatch_names_line),
             FL_TEST_CASE(test_points_nonfinite_values_rejected_with_line),
             FL_TEST_CASE(test_points_tiny_values_underflow_to_finite),
             FL_TEST_CASE(test_points_text_after_data_rejected),
             FL_TEST_CASE(test_points_empty_inputs_rejected),
             FL_TEST_CASE(test_points_unterminated_buffer_not_overread),
             FL_TEST_CASE(test_points_round_trip_is_bit_exact),
             FL_TEST_CASE(test_points_mutated_inputs_fail_cleanly),
             FL_TEST_CASE(test_scan_double_matches_strtod_bit_for_bit),
             FL_TEST_CASE(test_points_parse_time_is_linear))
