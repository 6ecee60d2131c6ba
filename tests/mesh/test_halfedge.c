/* The half-edge view (src/mesh/halfedge.h) against direct O(n^2) definitions. */
#include "fl_test.h"
#include "mesh/halfedge.h"
#include "mesh_fixtures.h"

/* The half-edge view against a direct definition: twins are the unique other half-edge with the
 * same vertex pair, vertex corners are exactly the half-edges leaving the vertex. */
static void test_halfedge_view_matches_brute_force(void)
{
    fl_mesh m = fx_torus(3, 1, 9, 7);
    fl_mesh extra = fx_from_arrays((const double[]){0, 0, 0, 1, 0, 0, 0, 1, 0}, 3,
                                   (const uint32_t[]){0, 1, 2, 0, 1, 2, 1, 0, 2}, 3);
    m = fx_concat(m, extra);
    fl_halfedges he;
    fl_error err;
    CHECK_STATUS(fl_halfedges_build(&m, &he, &err), FL_OK, &err);
    uint32_t nh = (uint32_t)(3 * m.triangle_count);
    int ok = 1;
    for (uint32_t h = 0; h < nh; h++) {
        uint32_t a = m.tri[h], b = m.tri[fl_he_next(h)], same = 0, other = FL_HE_NONE;
        for (uint32_t g = 0; g < nh; g++) {
            uint32_t c = m.tri[g], d = m.tri[fl_he_next(g)];
            if ((c == a && d == b) || (c == b && d == a)) {
                same++;
                if (g != h) other = g;
                ok &= he.halfedge_edge[g] == he.halfedge_edge[h];
            }
        }
        ok &= fl_he_edge_valence(&he, h) == same;
        ok &= he.twin[h] == (same == 2 ? other : FL_HE_NONE);
        uint32_t e = he.halfedge_edge[h];
        ok &= he.edge_vertices[2 * e] == (a < b ? a : b) &&
              he.edge_vertices[2 * e + 1] == (a < b ? b : a);
    }
    CHECK(ok);
    CHECK_EQ_INT(he.edge_count, 3 * 9 * 7 + 3);
    for (uint32_t v = 0; v < m.vertex_count; v++) {
        uint32_t n = 0;
        for (uint32_t h = 0; h < nh; h++)
            n += m.tri[h] == v;
        CHECK_EQ_INT(he.vertex_start[v + 1] - he.vertex_start[v], n);
        for (uint32_t i = he.vertex_start[v]; i < he.vertex_start[v + 1]; i++)
            CHECK_EQ_INT(m.tri[he.vertex_corners[i]], v);
    }
    CHECK_EQ_INT(fl_he_neighbor(&he, 0, 0), he.twin[0] / 3);
    fl_halfedges_free(&he);
    fl_mesh_free(&m);
}

static void test_halfedge_rejects_out_of_range_index(void)
{
    fl_mesh m = fx_tetrahedron();
    m.tri[7] = 9;
    fl_halfedges he;
    fl_error err;
    CHECK_STATUS(fl_halfedges_build(&m, &he, &err), FL_ERR_INPUT, &err);
    CHECK(he.twin == NULL);
    fl_halfedges_free(&he);
    fl_mesh_free(&m);
}

static void test_halfedge_of_empty_mesh_is_empty(void)
{
    fl_mesh m = {3, (double[]){0, 0, 0, 1, 1, 1, 2, 2, 2}, 0, NULL};
    fl_halfedges he;
    fl_error err;
    CHECK_STATUS(fl_halfedges_build(&m, &he, &err), FL_OK, &err);
    CHECK_EQ_INT(he.edge_count, 0);
    CHECK_EQ_INT(he.vertex_start[3], 0);
    fl_halfedges_free(&he);
}

FL_TEST_MAIN(FL_TEST_CASE(test_halfedge_view_matches_brute_force),
             FL_TEST_CASE(test_halfedge_rejects_out_of_range_index),
             FL_TEST_CASE(test_halfedge_of_empty_mesh_is_empty))
