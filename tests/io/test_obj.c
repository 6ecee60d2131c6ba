/* OBJ reader and writer: reference forms, relative indices, ignored statements, fan
 * triangulation, exact round trips, and malformed files that must fail at the right line. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "fl_test.h"

static fl_status parse_obj(const char *text, fl_mesh *m, fl_error *err)
{
    return fl_parse_mesh("obj", "t.obj", text, strlen(text), m, err);
}

static int triangle_is(const fl_mesh *m, size_t t, uint32_t a, uint32_t b, uint32_t c)
{
    return t < m->triangle_count && m->tri[3 * t] == a && m->tri[3 * t + 1] == b &&
           m->tri[3 * t + 2] == c;
}

static void test_obj_all_reference_forms_name_the_same_vertices(void)
{
    const char *text = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                       "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
                       "f 1 2 3\n"
                       "f 1/1 2/2 3/3\n"
                       "f 1//1 2//1 3//1\n"
                       "f 1/1/1 2/2/1 3/3/1\n"
                       "f 1/1/1\t2//1   3\n";
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(parse_obj(text, &m, &err), FL_OK, &err);
    CHECK_EQ_INT(m.vertex_count, 3);
    CHECK_EQ_INT(m.triangle_count, 5);
    for (size_t t = 0; t < 5; t++)
        CHECK(triangle_is(&m, t, 0, 1, 2));
    fl_mesh_free(&m);
}

static void test_obj_negative_indices_count_back_from_the_last_vertex_so_far(void)
{
    const char *text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                       "f -4 -3 -2 -1\n" /* quad 0 1 2 3 */
                       "v 5 5 5\n"
                       "f -1 -2 -5\n"; /* now -1 is vertex 4 */
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(parse_obj(text, &m, &err), FL_OK, &err);
    CHECK_EQ_INT(m.vertex_count, 5);
    CHECK_EQ_INT(m.triangle_count, 3);
    CHECK(triangle_is(&m, 0, 0, 1, 2));
    CHECK(triangle_is(&m, 1, 0, 2, 3));
    CHECK(triangle_is(&m, 2, 4, 3, 0));
    fl_mesh_free(&m);
}

static void test_obj_ngon_fans_into_n_minus_2_triangles(void)
{
    const char *text = "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 2 0\nv -1 1 0\n"
                       "f 1 2 3 4 5 6\n";
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(parse_obj(text, &m, &err), FL_OK, &err);
    CHECK_EQ_INT(m.triangle_count, 4);
    for (uint32_t k = 0; k < 4; k++)
        CHECK(triangle_is(&m, k, 0, k + 1, k + 2));
    fl_mesh_free(&m);
}

static void test_obj_ignores_other_statements_and_extra_vertex_columns(void)
{
    const char *text = "# exported\r\n"
                       "mtllib scene.mtl\r\n"
                       "o thing\r\ng group1\r\ns off\r\nusemtl red\r\n"
                       "v 1 2 3 1.0\r\n"            /* w */
                       "v 4 5 6 0.5 0.25 0.125\r\n" /* colour */
                       "v 7 8 9 # trailing comment\r\n"
                       "vn 0 0 1\r\nvt 0.5 0.5\r\nvp 0.1\r\n"
                       "l 1 2\r\np 3\r\n"
                       "f 1 2 3 # a comment\r\n"
                       "curv 0 1 1 2\r\n";
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(parse_obj(text, &m, &err), FL_OK, &err);
    CHECK_EQ_INT(m.vertex_count, 3);
    CHECK_EQ_INT(m.triangle_count, 1);
    for (int i = 0; i < 9 && m.vertex_count == 3; i++)
        CHECK(m.xyz[i] == i + 1);
    fl_mesh_free(&m);
}

static void test_obj_positive_index_may_refer_to_a_later_vertex(void)
{
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(parse_obj("v 0 0 0\nf 1 2 3\nv 1 0 0\nv 0 1 0\n", &m, &err), FL_OK, &err);
    CHECK(triangle_is(&m, 0, 0, 1, 2));
    fl_mesh_free(&m);
}

static void test_obj_vertices_only_is_a_valid_point_set(void)
{
    fl_mesh m;
    fl_error err;
    CHECK_STATUS(parse_obj("v 1 2 3\nv 4 5 6", &m, &err), FL_OK, &err);
    CHECK_EQ_INT(m.vertex_count, 2);
    CHECK_EQ_INT(m.triangle_count, 0);
    fl_mesh_free(&m);
}

static void test_obj_write_then_read_is_bit_exact(void)
{
    unsigned long long rng = 11;
    fl_mesh m = {0};
    m.vertex_count = 257;
    m.triangle_count = 400;
    m.xyz = malloc(3 * m.vertex_count * sizeof(double));
    m.tri = malloc(3 * m.triangle_count * sizeof(uint32_t));
    for (size_t i = 0; i < 3 * m.vertex_count; i++) {
        double mant = fl_test_rand01(&rng) - 0.5;
        m.xyz[i] = ldexp(mant, (int)(fl_test_rand_u64(&rng) % 2000) - 1000);
    }
    m.xyz[0] = -0.0;
    m.xyz[1] = 4.9406564584124654e-324;
    m.xyz[2] = 1.7976931348623157e308;
    for (size_t i = 0; i < 3 * m.triangle_count; i++)
        m.tri[i] = (uint32_t)(fl_test_rand_u64(&rng) % m.vertex_count);
    fl_error err;
    const char *path = "io_obj_roundtrip.OBJ"; /* the extension is case-insensitive */
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
    const char *fragment;
} bad_case;

static const bad_case bad_obj[] = {
    {"", 1, "empty file"},
    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", 4, "start at 1"},
    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\nf 1 2 3\n", 4, "reference 4 is out of range"},
    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\nf 1 9 3\nf 1 2 3\n", 5, "reference 9"},
    {"v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n", 3, "before the first vertex"},
    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", 4, "has 2"},
    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf\n", 4, "has 0"},
    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 a 3\n", 4, "'a'"},
    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 /2 3\n", 4, "'/2'"},
    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 99999999999 3\n", 4, "out of range"},
    {"v 0 0 0\nv 1 x 0\n", 2, "'x'"},
    {"v 0 0 0\nv 1 0\n", 2, "has 2"},
    {"# c\nv 0 NaN 0\n", 2, "not a finite"},
    {"v 0 0 0\n\n\nv inf 0 0\n", 4, "not a finite"},
    {"v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3 4\r\n", 4, "out of range"},
};

static void test_obj_malformed_files_fail_at_the_right_line(void)
{
    for (size_t i = 0; i < sizeof bad_obj / sizeof bad_obj[0]; i++) {
        fl_mesh m;
        fl_error err;
        fl_status st = parse_obj(bad_obj[i].text, &m, &err);
        CHECK_MSG(st == FL_ERR_INPUT, "case %zu: status %d", i, (int)st);
        if (st != FL_ERR_INPUT) {
            fl_mesh_free(&m);
            continue;
        }
        CHECK_MSG(err.line == bad_obj[i].line, "case %zu: line %ld, expected %ld (%s)", i, err.line,
                  bad_obj[i].line, err.message);
        CHECK_MSG(strstr(err.message, bad_obj[i].fragment) != NULL,
                  "case %zu: message '%s' lacks '%s'", i, err.message, bad_obj[i].fragment);
        CHECK(m.vertex_count == 0 && m.xyz == NULL && m.triangle_count == 0 && m.tri == NULL);
    }
}

FL_TEST_MAIN(FL_TEST_CASE(test_obj_all_reference_forms_name_the_same_vertices),
             FL_TEST_CASE(test_obj_negative_indices_count_back_from_the_last_vertex_so_far),
             FL_TEST_CASE(test_obj_ngon_fans_into_n_minus_2_triangles),
             FL_TEST_CASE(test_obj_ignores_other_statements_and_extra_vertex_columns),
             FL_TEST_CASE(test_obj_positive_index_may_refer_to_a_later_vertex),
             FL_TEST_CASE(test_obj_vertices_only_is_a_valid_point_set),
             FL_TEST_CASE(test_obj_write_then_read_is_bit_exact),
             FL_TEST_CASE(test_obj_malformed_files_fail_at_the_right_line))
