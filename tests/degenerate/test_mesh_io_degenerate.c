/* Degenerate meshes for fl_mesh_check and degenerate / hostile files for every reader.
 * Expected outcomes: the report counts of hand-made meshes whose topology is known by
 * construction (closed tetrahedron, open, non-manifold edge and vertex, inconsistently
 * oriented, self-intersecting, degenerate faces, duplicate vertices); readers reject empty,
 * truncated and NaN/Inf files and absurd element counts (1e18 in a PLY/OFF header, 2^32-1 STL
 * triangles) with FL_ERR_INPUT or FL_ERR_NOMEM and a message, quickly and without a huge
 * allocation attempt succeeding by accident. */
#include "degen.h"

static const double TET_V[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 5, 5, 5, 6, 5, 5, 5, 6, 5};
static const uint32_t TET_T[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};

static fl_mesh_report check(const double *v, size_t nv, const uint32_t *t, size_t nt)
{
    fl_mesh m = {nv, (double *)v, nt, (uint32_t *)t};
    fl_mesh_report rep;
    fl_error err;
    memset(&rep, 0, sizeof rep);
    CHECK_STATUS(fl_mesh_check(&m, NULL, &rep, &err), FL_OK, &err);
    return rep;
}

static void test_mesh_check_topologies(void)
{
    fl_mesh_report r = check(TET_V, 4, TET_T, 4);
    CHECK(r.closed && r.manifold && r.oriented && r.genus == 0 && r.edges == 6);
    CHECK(r.self_intersections == 0 && r.volume > 0);
    fl_mesh_report_free(&r);
    r = check(TET_V, 4, TET_T, 3); /* open: one face missing */
    CHECK(!r.closed && r.boundary_edges == 3 && r.manifold && r.oriented);
    CHECK(isnan(r.volume));
    fl_mesh_report_free(&r);
    uint32_t flipped[12];
    memcpy(flipped, TET_T, sizeof flipped);
    flipped[9] = 2, flipped[10] = 1; /* face 3 reversed */
    r = check(TET_V, 4, flipped, 4);
    CHECK(r.closed && !r.oriented && r.misoriented_edges == 3 && r.genus == -1);
    fl_mesh_report_free(&r);
    uint32_t fin[] = {0, 1, 2, 0, 1, 3, 0, 1, 4}; /* three triangles on edge 0-1 */
    r = check(TET_V, 5, fin, 3);
    CHECK(!r.manifold && r.nonmanifold_edges == 1);
    fl_mesh_report_free(&r);
    uint32_t bow[] = {0, 1, 2, 0, 4, 5}; /* two triangles sharing only vertex 0 */
    r = check(TET_V, 6, bow, 2);
    CHECK_MSG(!r.manifold && r.nonmanifold_vertices == 1, "manifold %d vertices %zu components %zu",
              r.manifold, r.nonmanifold_vertices, r.components);
    fl_mesh_report_free(&r);
    /* Two triangles crossing each other. */
    double xv[] = {0, 0, 0, 2, 0, 0, 0, 2, 0, 0.5, 0.5, -1, 0.5, 0.5, 1, 3, 3, 0};
    uint32_t xt[] = {0, 1, 2, 3, 4, 5};
    r = check(xv, 6, xt, 2);
    CHECK_EQ_INT(r.self_intersections, 1);
    fl_mesh_report_free(&r);
    /* Degenerate faces (repeated index, collinear) and duplicate vertices. */
    double dv[] = {0, 0, 0, 1, 1, 1, 2, 2, 2, 0, 0, 0, -0.0, 0, 0};
    uint32_t dt[] = {0, 0, 1, 0, 1, 2, 3, 4, 1};
    r = check(dv, 5, dt, 3);
    CHECK_EQ_INT(r.degenerate_faces, 3);
    CHECK_EQ_INT(r.duplicate_vertices, 2);
    fl_mesh_report_free(&r);
    /* Empty mesh: not closed, no components. */
    r = check(NULL, 0, NULL, 0);
    CHECK(!r.closed && r.components == 0 && r.faces == 0);
    fl_mesh_report_free(&r);
    /* Errors. */
    fl_mesh m = {3, (double *)TET_V, 1, (uint32_t *)TET_T + 9}; /* uses vertex 3 */
    fl_mesh_report rep;
    fl_error err;
    CHECK_FAILS(fl_mesh_check(&m, NULL, &rep, &err), &err, FL_ERR_INPUT, "but the mesh has 3");
    double nv[] = {0, 0, 0, 1, 0, 0, 0, NAN, 0};
    uint32_t nt[] = {0, 1, 2};
    fl_mesh nm = {3, nv, 1, nt};
    CHECK_FAILS(fl_mesh_check(&nm, NULL, &rep, &err), &err, FL_ERR_INPUT, "non-finite");
}

typedef struct file_case {
    const char *format;
    const char *name;
    const char *data;
    size_t size; /* 0: strlen(data) */
    fl_status status;
} file_case;

static void run_mesh_cases(const file_case *c, size_t count)
{
    for (size_t i = 0; i < count; i++) {
        fl_mesh m;
        fl_error err;
        size_t size = c[i].size ? c[i].size : strlen(c[i].data);
        fl_status st = fl_parse_mesh(c[i].format, c[i].name, c[i].data, size, &m, &err);
        fprintf(stderr, "  %s %s: %s\n", c[i].format, c[i].name, err.message);
        CHECK_MSG(st == c[i].status, "%s %s: status %d (%s)", c[i].format, c[i].name, (int)st,
                  err.message);
        if (st != FL_OK) CHECK_MSG(err.message[0] != '\0', "%s: empty message", c[i].name);
        if (st == FL_OK) fl_mesh_free(&m);
        else CHECK(m.xyz == NULL && m.tri == NULL && m.vertex_count == 0);
    }
}

static void test_mesh_readers_hostile(void)
{
    static char stl_huge[84];
    memset(stl_huge, 0, sizeof stl_huge);
    stl_huge[80] = stl_huge[81] = stl_huge[82] = stl_huge[83] = (char)0xff; /* 2^32-1 facets */
    file_case cases[] = {
        {"off", "empty", "", 0, FL_ERR_INPUT},
        {"obj", "empty", "", 0, FL_ERR_INPUT},
        {"ply", "empty", "", 0, FL_ERR_INPUT},
        {"stl", "empty", "", 0, FL_ERR_INPUT},
        {"off", "1e18 vertices", "OFF\n1000000000000000000 1 0\n0 0 0\n", 0, FL_ERR_INPUT},
        {"off", "1e18 faces", "OFF\n3 1000000000000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 0,
         FL_ERR_INPUT},
        {"ply", "1e18 vertices", "ply\nformat ascii 1.0\nelement vertex 1000000000000000000\n"
         "property float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n", 0,
         FL_ERR_INPUT},
        {"ply", "1e18 binary", "ply\nformat binary_little_endian 1.0\nelement vertex "
         "1000000000000000000\nproperty double x\nproperty double y\nproperty double z\n"
         "end_header\n", 0, FL_ERR_INPUT},
        {"ply", "1e18 faces", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
         "property float y\nproperty float z\nelement face 1000000000000000000\nproperty list "
         "uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 0, FL_ERR_INPUT},
        {"stl", "2^32-1 facets, no data", stl_huge, sizeof stl_huge, FL_ERR_INPUT},
        {"off", "NaN vertex", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", 0, FL_ERR_INPUT},
        {"obj", "Inf vertex", "v 0 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n", 0, FL_ERR_INPUT},
        {"obj", "index 0", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", 0, FL_ERR_INPUT},
        {"off", "index out of range", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", 0,
         FL_ERR_INPUT},
        {"off", "truncated", "OFF\n3 1 0\n0 0 0\n1 0", 0, FL_ERR_INPUT},
        {"off", "1e400 coordinate", "OFF\n3 1 0\n0 0 0\n1e400 0 0\n0 1 0\n3 0 1 2\n", 0,
         FL_ERR_INPUT},
    };
    run_mesh_cases(cases, sizeof cases / sizeof *cases);
}

static void test_point_polygon_readers_hostile(void)
{
    struct {
        const char *format, *name, *data;
        fl_status status;
    } pc[] = {
        {"xyz", "empty", "", FL_ERR_INPUT},
        {"xyz", "NaN", "0 0 0\nnan 1 2\n", FL_ERR_INPUT},
        {"xy", "Inf", "0 0\n-inf 1\n", FL_ERR_INPUT},
        {"xyz", "mixed columns", "0 0 0\n1 1\n", FL_ERR_INPUT},
        {"csv", "1e-320 subnormal", "x,y\n1e-320,0\n0,1e-320\n", FL_OK},
        {"ply", "1e18 points", "ply\nformat ascii 1.0\nelement vertex 1000000000000000000\n"
         "property float x\nproperty float y\nproperty float z\nend_header\n", FL_ERR_INPUT},
    };
    for (size_t i = 0; i < sizeof pc / sizeof *pc; i++) {
        fl_points p;
        fl_error err;
        fl_status st = fl_parse_points(pc[i].format, pc[i].name, pc[i].data, strlen(pc[i].data),
                                       &p, &err);
        fprintf(stderr, "  points %s: %s\n", pc[i].name, err.message);
        CHECK_MSG(st == pc[i].status, "points %s: %d (%s)", pc[i].name, (int)st, err.message);
        if (st == FL_OK) fl_points_free(&p);
    }
    struct {
        const char *format, *name, *data;
        fl_status status;
        size_t vertices;
    } gc[] = {
        {"xy", "repeated vertices", "0 0\n0 0\n4 0\n4 0\n4 4\n", FL_OK, 5},
        {"xy", "collinear vertices", "0 0\n1 0\n2 0\n2 2\n", FL_OK, 4},
        {"geojson", "unclosed ring", "{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[1,0],[0,1]]]}",
         FL_ERR_INPUT, 0},
        {"geojson", "NaN-like", "{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[1e999,0],[0,1],"
         "[0,0]]]}", FL_ERR_INPUT, 0},
        {"geojson", "truncated", "{\"type\":\"Polygon\",\"coordinates\":[[[0,0],", FL_ERR_INPUT, 0},
        {"geojson", "deep nesting", "[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[["
         "[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[["
         "[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[",
         FL_ERR_INPUT, 0},
    };
    for (size_t i = 0; i < sizeof gc / sizeof *gc; i++) {
        fl_polygon p;
        fl_error err;
        fl_status st = fl_parse_polygon(gc[i].format, gc[i].name, gc[i].data,
                                        strlen(gc[i].data), &p, &err);
        fprintf(stderr, "  polygon %s: %s\n", gc[i].name, err.message);
        CHECK_MSG(st == gc[i].status, "polygon %s: %d (%s)", gc[i].name, (int)st, err.message);
        if (st == FL_OK) {
            CHECK_EQ_INT(p.vertex_count, gc[i].vertices);
            fl_polygon_free(&p);
        }
    }
}

int main(void)
{
    fl_test_case cases[] = {
        FL_TEST_CASE(test_mesh_check_topologies),
        FL_TEST_CASE(test_mesh_readers_hostile),
        FL_TEST_CASE(test_point_polygon_readers_hostile),
    };
    return fl_test_run(cases, sizeof cases / sizeof *cases);
}
