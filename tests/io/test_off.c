/* OFF reader and writer: layout variants, fan triangulation, exact round trips, and a battery
 * of malformed files that must each fail with FL_ERR_INPUT at the right line. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "fl_test.h"

static fl_status parse_off(const char *text, fl_mesh *m, fl_error *err)
{
    return fl_parse_mesh("off", "t.off", text, strlen(text), m, err);
}

static const char *cube_off = "OFF\n"
                              "8 6 12\n"
                              "0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
                              "0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                              "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n"
                              "4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

static void test_off_quads_fan_triangulate_from_their_first_vertex(void)
{
    static const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                    {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(parse_off(cube_off, &m, &err), FL_OK, &err);
    CHECK_EQ_INT(m.vertex_count, 8);
    CHECK_EQ_INT(m.triangle_count, 12);
    for (int f = 0; f < 6 && m.triangle_count == 12; f++)
        for (int k = 0; k < 2; k++) {
            const uint32_t *t = m.tri + 3 * (2 * f + k);
            CHECK(t[0] == (uint32_t)quads[f][0] && t[1] == (uint32_t)quads[f][k + 1] &&
                  t[2] == (uint32_t)quads[f][k + 2]);
        }
    /* Vertex i of the cube has coordinates given by its position in the list above. */
    CHECK(m.xyz[3 * 6] == 1 && m.xyz[3 * 6 + 1] == 1 && m.xyz[3 * 6 + 2] == 1);
    CHECK(m.xyz[3 * 3] == 0 && m.xyz[3 * 3 + 1] == 1 && m.xyz[3 * 3 + 2] == 0);
    fl_mesh_free(&m);
}

static void test_off_polygon_with_n_vertices_gives_n_minus_2_triangles(void)
{
    char text[2048];
    for (int n = 3; n <= 9; n++) {
        int len = snprintf(text, sizeof text, "OFF\n%d 1 0\n", n);
        for (int i = 0; i < n; i++)
            len += snprintf(text + len, sizeof text - (size_t)len, "%d %d 0\n", i, i * i);
        len += snprintf(text + len, sizeof text - (size_t)len, "%d", n);
        for (int i = 0; i < n; i++)
            len += snprintf(text + len, sizeof text - (size_t)len, " %d", i);
        snprintf(text + len, sizeof text - (size_t)len, "\n");
        fl_mesh m;
        fl_error err;
        CHECK_STATUS(parse_off(text, &m, &err), FL_OK, &err);
        CHECK_EQ_INT(m.triangle_count, n - 2);
        fl_mesh_free(&m);
    }
}

static void test_off_accepts_comments_crlf_colours_and_counts_on_keyword_line(void)
{
    const char *text = "# a coloured tetrahedron\r\n"
                       "COFF 4 4 6 # counts on the keyword line\r\n"
                       "\r\n"
                       "0 0 0 255 0 0 255\r\n"
                       "1 0 0 0 255 0 255  # colour columns are ignored\r\n"
                       "0 1 0 0 0 255 255\r\n"
                       "# a comment between records\r\n"
                       "0 0 1 9 9 9 9\r\n"
                       "3 0 2 1 1.0 0.0 0.0\r\n"
                       "3 0 1 3\r\n"
                       "3 1 2 3 0 0 1 1\r\n"
                       "3 2 0 3"; /* no final newline */
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(parse_off(text, &m, &err), FL_OK, &err);
    CHECK_EQ_INT(m.vertex_count, 4);
    CHECK_EQ_INT(m.triangle_count, 4);
    if (m.triangle_count == 4) {
        CHECK(m.tri[0] == 0 && m.tri[1] == 2 && m.tri[2] == 1);
        CHECK(m.tri[9] == 2 && m.tri[10] == 0 && m.tri[11] == 3);
        CHECK(m.xyz[11] == 1.0);
    }
    fl_mesh_free(&m);
}

static void test_off_vertices_only_is_a_valid_point_set(void)
{
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(parse_off("OFF\n2 0 0\n1.5 -2 3e2\n-0.25 0 1\n", &m, &err), FL_OK, &err);
    CHECK_EQ_INT(m.vertex_count, 2);
    CHECK_EQ_INT(m.triangle_count, 0);
    CHECK(m.xyz[0] == 1.5 && m.xyz[1] == -2 && m.xyz[2] == 300 && m.xyz[3] == -0.25);
    fl_mesh_free(&m);
}

/* Doubles across the whole range: subnormals, huge, negative zero, many digits. */
static double awkward_double(unsigned long long *rng)
{
    static const double special[] = {
        0.0, -0.0,      4.9406564584124654e-324, 2.2250738585072009e-308, 1.7976931348623157e308,
        0.1, 1.0 / 3.0, -123456789.123456789};
    unsigned long long r = fl_test_rand_u64(rng);
    if (r % 4 == 0) return special[(r >> 8) % 8];
    double mant = fl_test_rand01(rng) - 0.5;
    int exp = (int)((r >> 16) % 600) - 300;
    return ldexp(mant, exp);
}

static void test_off_write_then_read_is_bit_exact(void)
{
    unsigned long long rng = 7;
    fl_mesh m = {0};
    m.vertex_count = 300;
    m.triangle_count = 500;
    m.xyz = malloc(3 * m.vertex_count * sizeof(double));
    m.tri = malloc(3 * m.triangle_count * sizeof(uint32_t));
    for (size_t i = 0; i < 3 * m.vertex_count; i++)
        m.xyz[i] = awkward_double(&rng);
    for (size_t i = 0; i < 3 * m.triangle_count; i++)
        m.tri[i] = (uint32_t)(fl_test_rand_u64(&rng) % m.vertex_count);
    fl_error err;
    const char *path = "io_off_roundtrip.off";
    CHECK_STATUS(fl_write_mesh(path, &m, &err), FL_OK, &err);
    fl_mesh back;
    CHECK_STATUS(fl_read_mesh(path, &back, &err), FL_OK, &err);
    CHECK_EQ_INT(back.vertex_count, m.vertex_count);
    CHECK_EQ_INT(back.triangle_count, m.triangle_count);
    if (back.vertex_count == m.vertex_count && back.triangle_count == m.triangle_count) {
        CHECK(memcmp(back.xyz, m.xyz, 3 * m.vertex_count * sizeof(double)) == 0);
        CHECK(memcmp(back.tri, m.tri, 3 * m.triangle_count * sizeof(uint32_t)) == 0);
    }
    remove(path);
    fl_mesh_free(&back);
    fl_mesh_free(&m);
}

typedef struct bad_case {
    const char *text;
    long line;
    const char *fragment; /* expected in the message */
} bad_case;

#define PAD "0.000000000 0.000000000 0.000000000\n" /* makes a file long enough for its counts */

static const bad_case bad_off[] = {
    {"", 1, "empty file"},
    {"# nothing but a comment\n\n", 3, "no OFF header"},
    {"8 6 0\n0 0 0\n", 1, "missing OFF header"},
    {"PLY\n", 1, "missing OFF header"},
    {"4OFF\n1 0 0\n0 0 0 0\n", 1, "only 3D"},
    {"OFF BINARY\n", 1, "binary OFF"},
    {"OFF\n", 2, "counts line"},
    {"OFF\n3\n", 2, "number of faces"},
    {"OFF\n3 x 0\n", 2, "'x'"},
    {"OFF\n-3 1 0\n", 2, "non-negative"},
    {"OFF\n3 1 0 7\n", 2, "unexpected '7'"},
    {"OFF\n1099511627776 0 0\n0 0 0\n", 2, "limit"},
    {"OFF\n4000000000 1 0\n0 0 0\n", 2, "need at least"},
    {"OFF\n3 0 0\n" PAD PAD, 5, "declares 3 vertices, found 2"},
    {"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n" PAD, 7, "expected the number of vertices"},
    {"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n# end\n" PAD, 8, "number of vertices"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n    ", 6, "at least 3"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", 6, "index 3 is out of range"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", 6, "index -1 is out of range"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", 6, "lists only 3"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 b\n", 6, "expected a vertex index"},
    {"OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", 4, "not a finite"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 -inf 0\n3 0 1 2\n", 5, "not a finite"},
    {"OFF\n3 1 0\n0 0 0\n1 abc 0\n0 1 0\n3 0 1 2\n", 4, "'abc'"},
    {"OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n    ", 4, "has 2"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n", 7, "after the last face"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n" PAD, 6, "expected the number of vertices"},
    {"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"
     "          \n"
     "          \n",
     9, "declares 2 faces, found 1"},
};

static void test_off_malformed_files_fail_at_the_right_line(void)
{
    for (size_t i = 0; i < sizeof bad_off / sizeof bad_off[0]; i++) {
        fl_mesh m;
        fl_error err;
        fl_status st = parse_off(bad_off[i].text, &m, &err);
        CHECK_MSG(st == FL_ERR_INPUT, "case %zu: status %d", i, (int)st);
        if (st != FL_ERR_INPUT) {
            fl_mesh_free(&m);
            continue;
        }
        CHECK_MSG(err.line == bad_off[i].line, "case %zu: line %ld, expected %ld (%s)", i, err.line,
                  bad_off[i].line, err.message);
        CHECK_MSG(strstr(err.message, bad_off[i].fragment) != NULL,
                  "case %zu: message '%s' lacks '%s'", i, err.message, bad_off[i].fragment);
        CHECK(strcmp(err.file, "t.off") == 0);
        CHECK(m.vertex_count == 0 && m.xyz == NULL && m.triangle_count == 0 && m.tri == NULL);
    }
}

/* The reader must not rely on a terminating NUL: parse a prefix of a larger buffer whose next
 * byte would continue the last number. */
static void test_off_reads_only_the_given_bytes(void)
{
    const char *text = "OFF\n1 0 0\n1 2 3999";
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(fl_parse_mesh("off", "t.off", text, strlen(text) - 3, &m, &err), FL_OK, &err);
    CHECK(m.vertex_count == 1 && m.xyz[2] == 3.0);
    fl_mesh_free(&m);
}

FL_TEST_MAIN(FL_TEST_CASE(test_off_quads_fan_triangulate_from_their_first_vertex),
             FL_TEST_CASE(test_off_polygon_with_n_vertices_gives_n_minus_2_triangles),
             FL_TEST_CASE(test_off_accepts_comments_crlf_colours_and_counts_on_keyword_line),
             FL_TEST_CASE(test_off_vertices_only_is_a_valid_point_set),
             FL_TEST_CASE(test_off_write_then_read_is_bit_exact),
             FL_TEST_CASE(test_off_malformed_files_fail_at_the_right_line),
             FL_TEST_CASE(test_off_reads_only_the_given_bytes))
