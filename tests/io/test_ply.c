/* PLY reader and writer. Files are generated here byte by byte in all three encodings (ascii,
 * binary little and big endian), so the expected values and byte offsets come from the layout
 * the test itself wrote, not from the reader. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "fl_test.h"

enum { ASCII, LE, BE };
static const char *format_name[] = {"ascii", "binary_little_endian", "binary_big_endian"};

typedef struct plybuf {
    unsigned char d[16384];
    size_t n;
    int fmt;
    size_t body; /* offset of the first byte after the header */
} plybuf;

static void put_text(plybuf *b, const char *s)
{
    size_t len = strlen(s);
    if (b->n + len <= sizeof b->d) memcpy(b->d + b->n, s, len);
    b->n += len;
}

static void put_header(plybuf *b, int fmt, const char *declarations)
{
    char line[64];
    b->n = 0;
    b->fmt = fmt;
    put_text(b, "ply\n");
    snprintf(line, sizeof line, "format %s 1.0\n", format_name[fmt]);
    put_text(b, line);
    put_text(b, declarations);
    put_text(b, "end_header\n");
    b->body = b->n;
}

static void put_bytes(plybuf *b, uint64_t u, size_t size)
{
    for (size_t i = 0; i < size; i++) {
        size_t shift = 8 * (b->fmt == BE ? size - 1 - i : i);
        b->d[b->n++] = (unsigned char)(u >> shift);
    }
}

/* One value of the named PLY type, in the buffer's encoding. */
static void put(plybuf *b, const char *type, double v)
{
    if (b->fmt == ASCII) {
        char s[40];
        snprintf(s, sizeof s, "%.17g ", v);
        put_text(b, s);
        return;
    }
    if (!strcmp(type, "char") || !strcmp(type, "int8")) put_bytes(b, (uint8_t)(int8_t)v, 1);
    if (!strcmp(type, "uchar") || !strcmp(type, "uint8")) put_bytes(b, (uint8_t)v, 1);
    if (!strcmp(type, "short") || !strcmp(type, "int16")) put_bytes(b, (uint16_t)(int16_t)v, 2);
    if (!strcmp(type, "ushort") || !strcmp(type, "uint16")) put_bytes(b, (uint16_t)v, 2);
    if (!strcmp(type, "int") || !strcmp(type, "int32")) put_bytes(b, (uint32_t)(int32_t)v, 4);
    if (!strcmp(type, "uint") || !strcmp(type, "uint32")) put_bytes(b, (uint32_t)v, 4);
    if (!strcmp(type, "float") || !strcmp(type, "float32")) {
        float f = (float)v;
        uint32_t u;
        memcpy(&u, &f, sizeof u);
        put_bytes(b, u, 4);
    }
    if (!strcmp(type, "double") || !strcmp(type, "float64")) {
        uint64_t u;
        memcpy(&u, &v, sizeof u);
        put_bytes(b, u, 8);
    }
}

static void end_item(plybuf *b)
{
    if (b->fmt == ASCII) put_text(b, "\n");
}

static fl_status parse_ply(const plybuf *b, size_t size, fl_mesh *m, fl_error *err)
{
    return fl_parse_mesh("ply", "t.ply", b->d, size, m, err);
}

static int triangle_is(const fl_mesh *m, size_t t, uint32_t a, uint32_t b, uint32_t c)
{
    return t < m->triangle_count && m->tri[3 * t] == a && m->tri[3 * t + 1] == b &&
           m->tri[3 * t + 2] == c;
}

/* ---- a file with shuffled properties, lists everywhere and extra elements ---- */

static const char *sample_declarations = "comment made by the test\n"
                                         "obj_info generated\n"
                                         "element material 2\n"
                                         "property list uchar float coefficients\n"
                                         "property int id\n"
                                         "element vertex 4\n"
                                         "property float nx\n"
                                         "property double z\n"
                                         "property uchar red\n"
                                         "property list ushort int neighbours\n"
                                         "property int16 x\n"
                                         "property float32 y\n"
                                         "element face 3\n"
                                         "property uchar flags\n"
                                         "property list uint8 int32 vertex_indices\n"
                                         "property float quality\n"
                                         "element edge 2\n"
                                         "property int vertex1\n"
                                         "property int vertex2\n";

static const double sample_xyz[4][3] = {
    {-3, 0.5, 1e-300}, {5, -1.25, 2}, {0, 3, -7.125}, {1000, 0, 1.0 / 3.0}};
static const int sample_faces[3][6] = {{3, 0, 1, 2}, {4, 0, 1, 2, 3}, {5, 3, 2, 1, 0, 1}};

static void put_sample_vertices(plybuf *b)
{
    for (int i = 0; i < 4; i++) {
        put(b, "float", 0.25 * i); /* nx */
        put(b, "double", sample_xyz[i][2]);
        put(b, "uchar", 200 + i);
        put(b, "ushort", i); /* i neighbours */
        for (int k = 0; k < i; k++)
            put(b, "int", k);
        put(b, "int16", sample_xyz[i][0]);
        put(b, "float32", sample_xyz[i][1]);
        end_item(b);
    }
}

static void put_sample(plybuf *b, int fmt)
{
    put_header(b, fmt, sample_declarations);
    put(b, "uchar", 2), put(b, "float", 0.5), put(b, "float", 0.25), put(b, "int", 7);
    end_item(b);
    put(b, "uchar", 0), put(b, "int", 8), end_item(b);
    put_sample_vertices(b);
    for (int f = 0; f < 3; f++) {
        put(b, "uchar", 9);
        put(b, "uint8", sample_faces[f][0]);
        for (int k = 1; k <= sample_faces[f][0]; k++)
            put(b, "int32", sample_faces[f][k]);
        put(b, "float", 0.75);
        end_item(b);
    }
    for (int e = 0; e < 2; e++)
        put(b, "int", e), put(b, "int", e + 1), end_item(b);
}

static void check_sample(const fl_mesh *m)
{
    CHECK_EQ_INT(m->vertex_count, 4);
    /* A face of n vertices gives n - 2 triangles: 1 + 2 + 3. */
    CHECK_EQ_INT(m->triangle_count, 6);
    if (m->vertex_count != 4 || m->triangle_count != 6) return;
    CHECK(memcmp(m->xyz, sample_xyz, sizeof sample_xyz) == 0);
    CHECK(triangle_is(m, 0, 0, 1, 2));
    CHECK(triangle_is(m, 1, 0, 1, 2) && triangle_is(m, 2, 0, 2, 3));
    /* The pentagon repeats vertex 1; it is kept (mesh checks report degenerate faces). */
    CHECK(triangle_is(m, 3, 3, 2, 1) && triangle_is(m, 4, 3, 1, 0) && triangle_is(m, 5, 3, 0, 1));
}

static void test_ply_shuffled_properties_and_extra_elements_in_all_encodings(void)
{
    for (int fmt = ASCII; fmt <= BE; fmt++) {
        plybuf b;
        put_sample(&b, fmt);
        fl_mesh m;
        fl_error err;
        CHECK_STATUS(parse_ply(&b, b.n, &m, &err), FL_OK, &err);
        check_sample(&m);
        fl_mesh_free(&m);
    }
}

static void test_ply_header_with_crlf_line_ends(void)
{
    const char *text = "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty float x\r\n"
                       "property float y\r\nproperty float z\r\nelement face 1\r\n"
                       "property list uchar uint vertex_index\r\nend_header\r\n"
                       "0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n";
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(fl_parse_mesh("ply", "t.ply", text, strlen(text), &m, &err), FL_OK, &err);
    CHECK(m.vertex_count == 3 && triangle_is(&m, 0, 0, 1, 2));
    fl_mesh_free(&m);
}

static void test_ply_faces_before_vertices_are_accepted(void)
{
    for (int fmt = ASCII; fmt <= BE; fmt++) {
        plybuf b;
        put_header(&b, fmt,
                   "element face 1\nproperty list uchar uint vertex_indices\n"
                   "element vertex 3\nproperty double x\nproperty double y\nproperty double z\n");
        put(&b, "uchar", 3), put(&b, "uint", 2), put(&b, "uint", 1), put(&b, "uint", 0);
        end_item(&b);
        for (int i = 0; i < 9; i++)
            put(&b, "double", i);
        fl_mesh m;
        fl_error err;
        CHECK_STATUS(parse_ply(&b, b.n, &m, &err), FL_OK, &err);
        CHECK(m.vertex_count == 3 && triangle_is(&m, 0, 2, 1, 0));
        CHECK(m.vertex_count == 3 && m.xyz[8] == 8);
        fl_mesh_free(&m);
    }
}

static void test_ply_every_scalar_type_and_alias_reads_coordinates(void)
{
    static const char *types[] = {"char",  "uchar",  "short",   "ushort", "int",   "uint",
                                  "float", "double", "int8",    "uint8",  "int16", "uint16",
                                  "int32", "uint32", "float32", "float64"};
    for (int fmt = ASCII; fmt <= BE; fmt++)
        for (size_t t = 0; t < sizeof types / sizeof types[0]; t++) {
            char decl[256];
            snprintf(decl, sizeof decl,
                     "element vertex 2\nproperty %s z\nproperty %s x\nproperty %s y\n", types[t],
                     types[t], types[t]);
            plybuf b;
            put_header(&b, fmt, decl);
            /* Values every type holds exactly; the large one checks the byte order. */
            int is_signed = types[t][0] != 'u';
            int bytes = strstr(types[t], "char") || strstr(types[t], "8") ? 1 : 2;
            double big = bytes == 1 ? 100 : 300;
            double values[6] = {3, 1, 2, big, is_signed ? -7 : 7, 0};
            for (int i = 0; i < 6; i++)
                put(&b, types[t], values[i]);
            fl_mesh m;
            fl_error err;
            CHECK_STATUS(parse_ply(&b, b.n, &m, &err), FL_OK, &err);
            CHECK_MSG(m.vertex_count == 2 && m.xyz[0] == 1 && m.xyz[1] == 2 && m.xyz[2] == 3 &&
                          m.xyz[3] == values[4] && m.xyz[4] == 0 && m.xyz[5] == big,
                      "type %s format %d", types[t], fmt);
            fl_mesh_free(&m);
        }
}

static void test_ply_vertices_only_is_a_valid_point_set(void)
{
    plybuf b;
    put_header(&b, LE,
               "element vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
               "element face 0\nproperty list uchar int vertex_indices\n");
    for (int i = 0; i < 6; i++)
        put(&b, "float", i);
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(parse_ply(&b, b.n, &m, &err), FL_OK, &err);
    CHECK(m.vertex_count == 2 && m.triangle_count == 0 && m.xyz[5] == 5);
    fl_mesh_free(&m);
}

static void test_ply_write_then_read_is_bit_exact(void)
{
    unsigned long long rng = 3;
    fl_mesh m = {0};
    m.vertex_count = 500;
    m.triangle_count = 900;
    m.xyz = malloc(3 * m.vertex_count * sizeof(double));
    m.tri = malloc(3 * m.triangle_count * sizeof(uint32_t));
    for (size_t i = 0; i < 3 * m.vertex_count; i++)
        m.xyz[i] = ldexp(fl_test_rand01(&rng) - 0.5, (int)(fl_test_rand_u64(&rng) % 2000) - 1000);
    m.xyz[7] = -0.0;
    for (size_t i = 0; i < 3 * m.triangle_count; i++)
        m.tri[i] = (uint32_t)(fl_test_rand_u64(&rng) % m.vertex_count);
    const char *path = "io_ply_roundtrip.ply";
    fl_error err;
    CHECK_STATUS(fl_write_mesh(path, &m, &err), FL_OK, &err);
    fl_mesh back;
    CHECK_STATUS(fl_read_mesh(path, &back, &err), FL_OK, &err);
    CHECK_EQ_INT(back.vertex_count, m.vertex_count);
    CHECK_EQ_INT(back.triangle_count, m.triangle_count);
    if (back.vertex_count == m.vertex_count && back.triangle_count == m.triangle_count) {
        CHECK(memcmp(back.xyz, m.xyz, 3 * m.vertex_count * sizeof(double)) == 0);
        CHECK(memcmp(back.tri, m.tri, 3 * m.triangle_count * sizeof(uint32_t)) == 0);
    }
    char head[40] = {0};
    FILE *f = fopen(path, "rb");
    CHECK(f && fread(head, 1, 36, f) == 36);
    if (f) fclose(f);
    CHECK(strncmp(head, "ply\nformat binary_little_endian 1.0\n", 36) == 0);
    remove(path);
    fl_mesh_free(&back);
    fl_mesh_free(&m);
}

/* ---- malformed binary files: errors at byte offsets ---- */

/* 3 float vertices (12 bytes each) and one face: count at body+36, index j at body+37+4j. */
static void put_triangle(plybuf *b, int fmt, int count, const int *index, float bad_y)
{
    put_header(b, fmt,
               "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
               "element face 1\nproperty list uchar int vertex_indices\n");
    const float v[3][3] = {{0, 0, 0}, {1, bad_y, 0}, {0, 1, 0}};
    for (int i = 0; i < 3; i++)
        for (int c = 0; c < 3; c++)
            put(b, "float", v[i][c]);
    end_item(b);
    put(b, "uchar", count);
    for (int k = 0; k < count; k++)
        put(b, "int", index[k]);
    end_item(b);
}

static void expect_offset(const plybuf *b, size_t size, long long offset, const char *fragment)
{
    fl_mesh m;
    fl_error err;
    fl_status st = parse_ply(b, size, &m, &err);
    CHECK_MSG(st == FL_ERR_INPUT, "status %d for '%s'", (int)st, fragment);
    if (st != FL_ERR_INPUT) {
        fl_mesh_free(&m);
        return;
    }
    CHECK_MSG(err.offset == offset, "offset %lld, expected %lld (%s)", err.offset, offset,
              err.message);
    CHECK_MSG(strstr(err.message, fragment) != NULL, "message '%s' lacks '%s'", err.message,
              fragment);
    CHECK(m.xyz == NULL && m.tri == NULL && m.vertex_count == 0 && m.triangle_count == 0);
}

static void test_ply_binary_errors_name_the_byte_offset(void)
{
    for (int fmt = LE; fmt <= BE; fmt++) {
        plybuf b;
        const int good[3] = {0, 1, 2}, high[3] = {0, 3, 2}, negative[3] = {0, 1, -1};
        long long body;
        put_triangle(&b, fmt, 3, high, 0);
        body = (long long)b.body;
        expect_offset(&b, b.n, body + 37 + 4, "index 3 is out of range");
        put_triangle(&b, fmt, 3, negative, 0);
        expect_offset(&b, b.n, body + 37 + 8, "index -1 is out of range");
        put_triangle(&b, fmt, 2, good, 0);
        expect_offset(&b, b.n, body + 36, "at least 3");
        put_triangle(&b, fmt, 3, good, NAN);
        expect_offset(&b, b.n, body + 12 + 4, "coordinate y is not finite");
        put_triangle(&b, fmt, 3, good, INFINITY);
        expect_offset(&b, b.n, body + 12 + 4, "not finite");
        put_triangle(&b, fmt, 3, good, 0);
        b.d[b.n++] = 0;
        expect_offset(&b, b.n, body + 49, "1 bytes of unexpected data");
        /* The face claims 200 indices; the file ends after 3. */
        put_triangle(&b, fmt, 3, good, 0);
        b.d[body + 36] = 200;
        expect_offset(&b, b.n, body + 37, "unexpected end of file in element 'face'");
    }
}

static void test_ply_every_truncation_of_a_binary_file_fails_cleanly(void)
{
    for (int fmt = LE; fmt <= BE; fmt++) {
        plybuf b;
        put_sample(&b, fmt);
        for (size_t len = 0; len < b.n; len++) {
            fl_mesh m;
            fl_error err;
            fl_status st = parse_ply(&b, len, &m, &err);
            CHECK_MSG(st == FL_ERR_INPUT, "prefix of %zu bytes: status %d", len, (int)st);
            if (st != FL_ERR_INPUT) fl_mesh_free(&m);
            /* Inside the body the error is a byte offset within the prefix. */
            if (len > b.body)
                CHECK_MSG(err.offset >= (long long)b.body && err.offset <= (long long)len,
                          "prefix %zu: offset %lld", len, err.offset);
        }
    }
}

static void test_ply_huge_claimed_counts_fail_before_allocating(void)
{
    plybuf b;
    put_header(&b, LE,
               "element vertex 4000000000\nproperty float x\nproperty float y\nproperty float z\n");
    memset(b.d + b.n, 0, 1024);
    b.n += 1024;
    expect_offset(&b, b.n, (long long)b.body, "claims 4000000000 items");
    /* 2^62 items of 8 bytes overflow 64 bits; still a clean error. */
    put_header(&b, BE,
               "element blob 4611686018427387904\nproperty double a\n"
               "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n");
    memset(b.d + b.n, 0, 12);
    b.n += 12;
    expect_offset(&b, b.n, (long long)b.body, "element 'blob' claims");
    /* A list property counts at its smallest (empty) size: 2^40 faces of 1 byte. */
    put_header(&b, LE,
               "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
               "element junk 1099511627776\nproperty list uchar int stuff\n");
    memset(b.d + b.n, 0, 100);
    b.n += 100;
    expect_offset(&b, b.n, (long long)b.body, "element 'junk' claims");
}

/* ---- malformed headers and ascii bodies: errors at lines ---- */

typedef struct bad_case {
    const char *text;
    long line;
    const char *fragment;
} bad_case;

#define VTX "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
#define FACE "element face 1\nproperty list uchar int vertex_indices\n"
#define ASC "ply\nformat ascii 1.0\n" VTX FACE "end_header\n" /* body starts at line 10 */

static const bad_case bad_ply[] = {
    {"", 1, "empty file"},
    {"PLY\nformat ascii 1.0\n", 1, "first line must be 'ply'"},
    {"solid x\n", 1, "first line must be 'ply'"},
    {"ply\nformat ascii 2.0\n" VTX "end_header\n", 2, "version 1.0"},
    {"ply\nformat binary 1.0\n" VTX "end_header\n", 2, "got 'binary'"},
    {"ply\n" VTX "end_header\n", 2, "missing 'format'"},
    {"ply\nformat ascii 1.0\n" VTX, 7, "no 'end_header'"},
    {"ply\nformat ascii 1.0\nproperty float x\n", 3, "before any 'element'"},
    {"ply\nformat ascii 1.0\nelement vertex 1\nproperty int128 x\n", 4, "'int128'"},
    {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float\n", 4, "needs a name"},
    {"ply\nformat ascii 1.0\nelement vertex -1\n", 3, "non-negative"},
    {"ply\nformat ascii 1.0\nelement vertex many\n", 3, "'many'"},
    {"ply\nformat ascii 1.0\nelement vertex 4294967296\n", 3, "limit"},
    {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n"
     "0 0\n",
     3, "no scalar property 'z'"},
    {"ply\nformat ascii 1.0\n" VTX VTX "end_header\n", 7, "duplicate element"},
    {"ply\nformat ascii 1.0\n" VTX "property double x\nend_header\n", 7, "duplicate property"},
    {"ply\nformat ascii 1.0\n" VTX "element face 1\nproperty list uchar int indices\nend_header\n",
     7, "no list property 'vertex_indices'"},
    {"ply\nformat ascii 1.0\n" VTX "element face 1\nproperty list float int vertex_indices\n", 8,
     "count type must be an integer"},
    {"ply\nformat ascii 1.0\n" VTX "element face 1\nproperty list uchar float vertex_indices\n", 8,
     "indices must have an integer type"},
    {"ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n",
     5, "no 'element vertex'"},
    {"ply\nformat ascii 1.0\nbogus line\n", 3, "unknown header keyword"},
    {"ply\nformat ascii 1.0\nelement vertex 1000000\nproperty float x\nproperty float y\n"
     "property float z\nend_header\n0 0 0\n",
     3, "claims 1000000 items"},
    {ASC "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n", 11, "got 'zero'"},
    {ASC "0 0 0\n1 0 0\n0 1 nan\n3 0 1 2\n", 12, "not a finite"},
    {ASC "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", 13, "index 3 is out of range"},
    {ASC "0 0 0\n1 0 0\n0 1 0\n3 0 -2 1\n", 13, "index -2 is out of range"},
    {ASC "0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n", 13, "expected an integer"},
    {ASC "0 0 0\n1 0 0\n0 1 0\n2 0 1\n\n", 13, "at least 3"},
    {ASC "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n\n7\n", 15, "unexpected data '7'"},
    {ASC "0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n\n\n", 16, "unexpected end of file in element 'face'"},
};

static void test_ply_malformed_headers_and_ascii_bodies_fail_at_the_right_line(void)
{
    for (size_t i = 0; i < sizeof bad_ply / sizeof bad_ply[0]; i++) {
        fl_mesh m;
        fl_error err;
        fl_status st =
            fl_parse_mesh("ply", "t.ply", bad_ply[i].text, strlen(bad_ply[i].text), &m, &err);
        CHECK_MSG(st == FL_ERR_INPUT, "case %zu: status %d", i, (int)st);
        if (st != FL_ERR_INPUT) {
            fl_mesh_free(&m);
            continue;
        }
        CHECK_MSG(err.line == bad_ply[i].line, "case %zu: line %ld, expected %ld (%s)", i, err.line,
                  bad_ply[i].line, err.message);
        CHECK_MSG(strstr(err.message, bad_ply[i].fragment) != NULL,
                  "case %zu: message '%s' lacks '%s'", i, err.message, bad_ply[i].fragment);
        CHECK(m.xyz == NULL && m.tri == NULL && m.vertex_count == 0 && m.triangle_count == 0);
    }
}

FL_TEST_MAIN(FL_TEST_CASE(test_ply_shuffled_properties_and_extra_elements_in_all_encodings),
             FL_TEST_CASE(test_ply_header_with_crlf_line_ends),
             FL_TEST_CASE(test_ply_faces_before_vertices_are_accepted),
             FL_TEST_CASE(test_ply_every_scalar_type_and_alias_reads_coordinates),
             FL_TEST_CASE(test_ply_vertices_only_is_a_valid_point_set),
             FL_TEST_CASE(test_ply_write_then_read_is_bit_exact),
             FL_TEST_CASE(test_ply_binary_errors_name_the_byte_offset),
             FL_TEST_CASE(test_ply_every_truncation_of_a_binary_file_fails_cleanly),
             FL_TEST_CASE(test_ply_huge_claimed_counts_fail_before_allocating),
             FL_TEST_CASE(test_ply_malformed_headers_and_ascii_bodies_fail_at_the_right_line))
