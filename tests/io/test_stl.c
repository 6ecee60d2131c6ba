/* STL reader and writer: exact welding (cube, grid, -0.0), binary/ASCII detection, float32
 * round trips, computed normals, and malformed files failing at the right offset or line. */
#include <float.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "fl_test.h"

/* Cube corner i is (i&1, i>>1&1, i>>2&1); six quads, two triangles each. */
static const int cube_quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                     {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};

static void cube_corner(int i, float v[3])
{
    v[0] = (float)(i & 1);
    v[1] = (float)(i >> 1 & 1);
    v[2] = (float)(i >> 2 & 1);
}

/* The 12 triangles of the cube as 9 floats each. */
static void cube_triangles(float tri[12][9])
{
    for (int f = 0; f < 6; f++)
        for (int k = 0; k < 2; k++) {
            int c[3] = {cube_quads[f][0], cube_quads[f][k + 1], cube_quads[f][k + 2]};
            for (int j = 0; j < 3; j++)
                cube_corner(c[j], &tri[2 * f + k][3 * j]);
        }
}

static void put_le32(unsigned char *p, uint32_t u)
{
    for (int i = 0; i < 4; i++)
        p[i] = (unsigned char)(u >> (8 * i));
}

static void put_float(unsigned char *p, float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    put_le32(p, u);
}

/* A binary STL of n triangles into buf (84 + 50 n bytes); returns its size. */
static size_t binary_stl(unsigned char *buf, const char *header, const float (*tri)[9], size_t n)
{
    memset(buf, 0, 84 + 50 * n);
    memcpy(buf, header, strlen(header));
    put_le32(buf + 80, (uint32_t)n);
    for (size_t t = 0; t < n; t++) {
        unsigned char *rec = buf + 84 + 50 * t;
        for (int k = 0; k < 9; k++)
            put_float(rec + 12 + 4 * k, tri[t][k]);
    }
    return 84 + 50 * n;
}

static fl_status parse_stl(const void *data, size_t size, fl_mesh *m, fl_error *err)
{
    return fl_parse_mesh("stl", "t.stl", data, size, m, err);
}

/* Every corner of triangle t of m has the coordinates given in tri[t]. */
static int corners_match(const fl_mesh *m, const float (*tri)[9], size_t n)
{
    if (m->triangle_count != n) return 0;
    for (size_t t = 0; t < n; t++)
        for (int j = 0; j < 3; j++)
            for (int c = 0; c < 3; c++)
                if (m->xyz[3 * m->tri[3 * t + (size_t)j] + (size_t)c] != tri[t][3 * j + c])
                    return 0;
    return 1;
}

static void test_stl_binary_cube_welds_12_facets_into_8_vertices(void)
{
    float tri[12][9];
    cube_triangles(tri);
    unsigned char buf[84 + 50 * 12];
    size_t size = binary_stl(buf, "cube", (const float(*)[9])tri, 12);
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(parse_stl(buf, size, &m, &err), FL_OK, &err);
    CHECK_EQ_INT(m.vertex_count, 8);
    CHECK_EQ_INT(m.triangle_count, 12);
    CHECK(corners_match(&m, (const float(*)[9])tri, 12));
    fl_mesh_free(&m);
}

static void test_stl_binary_with_header_starting_solid_is_read_as_binary(void)
{
    float tri[12][9];
    cube_triangles(tri);
    unsigned char buf[84 + 50 * 12];
    size_t size =
        binary_stl(buf, "solid cube exported by a careless tool", (const float(*)[9])tri, 12);
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(parse_stl(buf, size, &m, &err), FL_OK, &err);
    CHECK_EQ_INT(m.vertex_count, 8);
    CHECK(corners_match(&m, (const float(*)[9])tri, 12));
    fl_mesh_free(&m);
}

/* The cube as ASCII, split over two solids, with mixed-case keywords and CRLF. */
static size_t ascii_cube(char *text, size_t cap)
{
    float tri[12][9];
    cube_triangles(tri);
    size_t len = 0;
    for (int t = 0; t < 12; t++) {
        if (t == 0 || t == 6)
            len += (size_t)snprintf(text + len, cap - len, "solid part %d\r\n", t / 6);
        len +=
            (size_t)snprintf(text + len, cap - len, "  FACET normal 0 0 0\r\n    outer loop\r\n");
        for (int j = 0; j < 3; j++)
            len += (size_t)snprintf(text + len, cap - len, "      vertex %g %g %g\r\n",
                                    (double)tri[t][3 * j], (double)tri[t][3 * j + 1],
                                    (double)tri[t][3 * j + 2]);
        len += (size_t)snprintf(text + len, cap - len, "    endloop\r\n  endfacet\r\n");
        if (t == 5 || t == 11) len += (size_t)snprintf(text + len, cap - len, "EndSolid part\r\n");
    }
    return len;
}

static void test_stl_ascii_cube_in_two_solids_welds_into_8_vertices(void)
{
    char text[8192];
    size_t len = ascii_cube(text, sizeof text);
    float tri[12][9];
    cube_triangles(tri);
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(parse_stl(text, len, &m, &err), FL_OK, &err);
    CHECK_EQ_INT(m.vertex_count, 8);
    CHECK_EQ_INT(m.triangle_count, 12);
    CHECK(corners_match(&m, (const float(*)[9])tri, 12));
    fl_mesh_free(&m);
}

static void test_stl_ascii_loop_of_four_vertices_fans_into_two_triangles(void)
{
    const char *text = "solid q\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                       "vertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid q\n";
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(parse_stl(text, strlen(text), &m, &err), FL_OK, &err);
    CHECK_EQ_INT(m.vertex_count, 4);
    CHECK_EQ_INT(m.triangle_count, 2);
    if (m.triangle_count == 2) CHECK(m.tri[3] == 0 && m.tri[4] == 2 && m.tri[5] == 3);
    fl_mesh_free(&m);
}

static void test_stl_negative_zero_welds_with_positive_zero(void)
{
    const float tri[2][9] = {{0.0f, 0, 0, 1, 0, 0, 0, 1, 0},
                             {-0.0f, -0.0f, -0.0f, 0, 1, 0, 1, 0, 0}};
    unsigned char buf[84 + 100];
    size_t size = binary_stl(buf, "z", tri, 2);
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(parse_stl(buf, size, &m, &err), FL_OK, &err);
    CHECK_EQ_INT(m.vertex_count, 3);
    if (m.vertex_count == 3) CHECK(!signbit(m.xyz[0]) && !signbit(m.xyz[1]));
    fl_mesh_free(&m);
}

/* An n x n grid of unit squares, two triangles each: (n+1)^2 distinct corners. */
static void test_stl_grid_welds_to_n_plus_1_squared_vertices(void)
{
    const size_t n = 120;
    float(*tri)[9] = malloc(2 * n * n * sizeof *tri);
    unsigned char *buf = malloc(84 + 100 * n * n);
    size_t t = 0;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            float x0 = (float)i * 0.1f, x1 = (float)(i + 1) * 0.1f;
            float y0 = (float)j * 0.1f, y1 = (float)(j + 1) * 0.1f;
            const float a[9] = {x0, y0, 0, x1, y0, 0, x1, y1, 0};
            const float b[9] = {x0, y0, 0, x1, y1, 0, x0, y1, 0};
            memcpy(tri[t++], a, sizeof a);
            memcpy(tri[t++], b, sizeof b);
        }
    size_t size = binary_stl(buf, "grid", (const float(*)[9])tri, t);
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(parse_stl(buf, size, &m, &err), FL_OK, &err);
    CHECK_EQ_INT(m.vertex_count, (n + 1) * (n + 1));
    CHECK_EQ_INT(m.triangle_count, 2 * n * n);
    CHECK(corners_match(&m, (const float(*)[9])tri, t));
    fl_mesh_free(&m);
    free(buf);
    free(tri);
}

/* Writing rounds coordinates to float32, and vertices that become equal weld; the expected
 * vertex count is found by brute-force comparison of the rounded positions. */
static void test_stl_round_trip_equals_float32_rounding_and_welding(void)
{
    unsigned long long rng = 5;
    fl_mesh m = {0};
    m.vertex_count = 200;
    m.triangle_count = 300;
    m.xyz = malloc(3 * m.vertex_count * sizeof(double));
    m.tri = malloc(3 * m.triangle_count * sizeof(uint32_t));
    for (size_t i = 0; i < 3 * m.vertex_count; i++)
        m.xyz[i] = (fl_test_rand01(&rng) - 0.5) * 1e3;
    /* Two vertices that differ only below float32 precision. */
    m.xyz[3] = m.xyz[0] * (1 + 1e-12);
    m.xyz[4] = m.xyz[1];
    m.xyz[5] = m.xyz[2];
    for (size_t i = 0; i < 3 * m.triangle_count; i++)
        m.tri[i] = (uint32_t)(i % m.vertex_count);
    fl_error err;
    const char *path = "io_stl_roundtrip.stl";
    CHECK_STATUS(fl_write_mesh(path, &m, &err), FL_OK, &err);
    fl_mesh back;
    CHECK_STATUS(fl_read_mesh(path, &back, &err), FL_OK, &err);
    size_t distinct = 0;
    for (size_t i = 0; i < m.vertex_count; i++) {
        int seen = 0;
        for (size_t j = 0; j < i && !seen; j++) {
            int same = 1;
            for (int c = 0; c < 3; c++)
                same &= (float)m.xyz[3 * i + (size_t)c] == (float)m.xyz[3 * j + (size_t)c];
            seen = same;
        }
        distinct += !seen;
    }
    CHECK_EQ_INT(distinct, m.vertex_count - 1);
    CHECK_EQ_INT(back.vertex_count, distinct);
    CHECK_EQ_INT(back.triangle_count, m.triangle_count);
    int ok = back.triangle_count == m.triangle_count;
    for (size_t t = 0; ok && t < m.triangle_count; t++)
        for (int j = 0; j < 3; j++)
            for (int c = 0; c < 3; c++)
                ok &= back.xyz[3 * back.tri[3 * t + (size_t)j] + (size_t)c] ==
                      (double)(float)m.xyz[3 * m.tri[3 * t + (size_t)j] + (size_t)c];
    CHECK(ok);
    remove(path);
    fl_mesh_free(&back);
    fl_mesh_free(&m);
}

static float get_float(const unsigned char *p)
{
    uint32_t u = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

static void test_stl_writer_stores_right_handed_unit_normals(void)
{
    double xyz[] = {0, 0, 0, 2, 0, 0, 0, 3, 0, 0, 0, 5};
    uint32_t tri[] = {0, 1, 2, 0, 2, 3, 0, 1, 1};
    fl_mesh m = {4, xyz, 3, tri};
    const char *path = "io_stl_normals.stl";
    fl_error err;
    CHECK_STATUS(fl_write_mesh(path, &m, &err), FL_OK, &err);
    unsigned char buf[84 + 150];
    FILE *f = fopen(path, "rb");
    CHECK(f && fread(buf, 1, sizeof buf, f) == sizeof buf && fgetc(f) == EOF);
    if (f) fclose(f);
    CHECK(memcmp(buf, "solid", 5) != 0); /* or readers would take it for ASCII */
    /* (2,0,0) x (0,3,0) is +z; (0,3,0) x (0,0,5) is +x; the third is degenerate. */
    const float expect[3][3] = {{0, 0, 1}, {1, 0, 0}, {0, 0, 0}};
    for (int t = 0; t < 3; t++)
        for (int c = 0; c < 3; c++)
            CHECK(get_float(buf + 84 + 50 * t + 4 * c) == expect[t][c]);
    remove(path);
}

static void test_stl_writer_refuses_coordinates_beyond_float32(void)
{
    double xyz[] = {0, 0, 0, 1e300, 0, 0, 0, 1, 0};
    uint32_t tri[] = {0, 1, 2};
    fl_mesh m = {3, xyz, 1, tri};
    const char *path = "io_stl_huge.stl";
    remove(path);
    fl_error err;
    CHECK_STATUS(fl_write_mesh(path, &m, &err), FL_ERR_INPUT, &err);
    CHECK(strstr(err.message, "float32") != NULL);
    FILE *f = fopen(path, "rb");
    CHECK(f == NULL);
    if (f) fclose(f);
}

typedef struct bad_binary {
    size_t triangle, corner, coord; /* which coordinate to spoil */
    float value;
} bad_binary;

static void test_stl_binary_non_finite_coordinate_fails_at_its_offset(void)
{
    const bad_binary cases[] = {{5, 1, 1, NAN}, {0, 0, 0, INFINITY}, {11, 2, 2, -INFINITY}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        float tri[12][9];
        cube_triangles(tri);
        tri[cases[i].triangle][3 * cases[i].corner + cases[i].coord] = cases[i].value;
        unsigned char buf[84 + 50 * 12];
        size_t size = binary_stl(buf, "bad", (const float(*)[9])tri, 12);
        fl_mesh m;
        fl_error err;
        CHECK_STATUS(parse_stl(buf, size, &m, &err), FL_ERR_INPUT, &err);
        long long offset = 84 + 50 * (long long)cases[i].triangle + 12 +
                           12 * (long long)cases[i].corner + 4 * (long long)cases[i].coord;
        CHECK_EQ_INT(err.offset, offset);
        CHECK(strstr(err.message, "non-finite") != NULL);
        CHECK(m.xyz == NULL && m.tri == NULL && m.vertex_count == 0);
    }
}

static void test_stl_binary_size_mismatch_fails_at_the_count(void)
{
    float tri[12][9];
    cube_triangles(tri);
    unsigned char buf[84 + 50 * 12 + 1];
    size_t size = binary_stl(buf, "cube", (const float(*)[9])tri, 12);
    fl_mesh m;
    fl_error err;
    /* One byte short, one byte long, and a count of 2^32-1 in a small file. */
    CHECK_STATUS(parse_stl(buf, size - 1, &m, &err), FL_ERR_INPUT, &err);
    CHECK(err.offset == 80 && strstr(err.message, "size mismatch"));
    buf[size] = 0;
    CHECK_STATUS(parse_stl(buf, size + 1, &m, &err), FL_ERR_INPUT, &err);
    CHECK(err.offset == 80 && strstr(err.message, "12 triangles"));
    put_le32(buf + 80, UINT32_MAX);
    CHECK_STATUS(parse_stl(buf, size, &m, &err), FL_ERR_INPUT, &err);
    CHECK(err.offset == 80 && strstr(err.message, "4294967295 triangles"));
    CHECK_STATUS(parse_stl("hello", 5, &m, &err), FL_ERR_INPUT, &err);
    CHECK(err.offset == 0 && strstr(err.message, "too short"));
    CHECK_STATUS(parse_stl("", 0, &m, &err), FL_ERR_INPUT, &err);
    CHECK(strstr(err.message, "empty file") != NULL);
}

typedef struct bad_case {
    const char *text;
    long line;
    const char *fragment;
} bad_case;

#define HEAD "solid s\nfacet normal 0 0 1\nouter loop\n"

static const bad_case bad_ascii[] = {
    {HEAD "vertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid\n", 6, "has 2"},
    {HEAD "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendfacet\n", 7, "got 'endfacet'"},
    {HEAD "vertex 0 0 0\nvertex 1 nan 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n", 5,
     "not a finite"},
    {HEAD "vertex 0 0 0\nvertex 1 zero 0\n", 5, "expected a number, got 'zero'"},
    {HEAD "vertex 0 0 0\nvertex 1 0\nendloop\n", 6, "got 'endloop'"},
    {HEAD "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n", 9, "'endsolid'"},
    {HEAD "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid s\njunk\n", 10,
     "got 'junk'"},
    {"solid s\nfacet normal 0 0\nouter loop\n", 3, "got 'outer'"},
    {"solid s\nfacet normal 0 0 1\ninner loop\n", 3, "got 'inner'"},
    {"solid s\nfoo\nendsolid\n", 2, "expected 'facet' or 'endsolid', got 'foo'"},
    {"   solid", 1, "'facet'"},
};

static void test_stl_ascii_malformed_files_fail_at_the_right_line(void)
{
    for (size_t i = 0; i < sizeof bad_ascii / sizeof bad_ascii[0]; i++) {
        fl_mesh m;
        fl_error err;
        fl_status st = parse_stl(bad_ascii[i].text, strlen(bad_ascii[i].text), &m, &err);
        CHECK_MSG(st == FL_ERR_INPUT, "case %zu: status %d", i, (int)st);
        if (st != FL_ERR_INPUT) {
            fl_mesh_free(&m);
            continue;
        }
        CHECK_MSG(err.line == bad_ascii[i].line, "case %zu: line %ld, expected %ld (%s)", i,
                  err.line, bad_ascii[i].line, err.message);
        CHECK_MSG(strstr(err.message, bad_ascii[i].fragment) != NULL,
                  "case %zu: message '%s' lacks '%s'", i, err.message, bad_ascii[i].fragment);
        CHECK(m.vertex_count == 0 && m.xyz == NULL && m.triangle_count == 0 && m.tri == NULL);
    }
}

static void test_stl_binary_looking_solid_file_gets_a_hint(void)
{
    unsigned char buf[200] = "solid but binary";
    put_le32(buf + 80, 7); /* 7 triangles would need 434 bytes */
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(parse_stl(buf, sizeof buf, &m, &err), FL_ERR_INPUT, &err);
    CHECK(strstr(err.message, "binary STL whose size does not match") != NULL);
}

FL_TEST_MAIN(FL_TEST_CASE(test_stl_binary_cube_welds_12_facets_into_8_vertices),
             FL_TEST_CASE(test_stl_binary_with_header_starting_solid_is_read_as_binary),
             FL_TEST_CASE(test_stl_ascii_cube_in_two_solids_welds_into_8_vertices),
             FL_TEST_CASE(test_stl_ascii_loop_of_four_vertices_fans_into_two_triangles),
             FL_TEST_CASE(test_stl_negative_zero_welds_with_positive_zero),
             FL_TEST_CASE(test_stl_grid_welds_to_n_plus_1_squared_vertices),
             FL_TEST_CASE(test_stl_round_trip_equals_float32_rounding_and_welding),
             FL_TEST_CASE(test_stl_writer_stores_right_handed_unit_normals),
             FL_TEST_CASE(test_stl_writer_refuses_coordinates_beyond_float32),
             FL_TEST_CASE(test_stl_binary_non_finite_coordinate_fails_at_its_offset),
             FL_TEST_CASE(test_stl_binary_size_mismatch_fails_at_the_count),
             FL_TEST_CASE(test_stl_ascii_malformed_files_fail_at_the_right_line),
             FL_TEST_CASE(test_stl_binary_looking_solid_file_gets_a_hint))
