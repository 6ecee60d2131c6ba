/* Degenerate inputs for 2D and 3D reconstruction by constriction. Expected outcomes: specific
 * errors for too few distinct points, NaN/Inf and collinear (2D) / coplanar (3D) sets; on
 * grids, cocircular/cospherical sets and extreme scales a result whose contract is checked
 * independently: the 2D boundary is a simple counterclockwise polygon (fl_polygon_check) and
 * the 3D boundary a closed, manifold, oriented genus-0 surface without self-intersections
 * (fl_mesh_check). Points on a circle / sphere are all extreme, so all must be on the
 * boundary. */
#include "degen.h"

static void test_reconstruct2_failures(void)
{
    struct {
        const char *name;
        size_t n;
        double xy[10];
        fl_status status;
        const char *message;
    } cases[] = {
        {"empty", 0, {0}, FL_ERR_INPUT, "3"},
        {"one", 1, {1, 1}, FL_ERR_INPUT, "3"},
        {"two", 2, {1, 1, 2, 2}, FL_ERR_INPUT, "3"},
        {"duplicates", 5, {1, 1, 1, 1, 2, 2, 1, 1, 2, 2}, FL_ERR_INPUT, "3"},
        {"collinear", 4, {0, 0, 1, 1, 2, 2, 3, 3}, FL_ERR_ALGORITHM, "collinear"},
        {"NaN", 3, {0, 0, 1, NAN, 2, 2}, FL_ERR_INPUT, "non-finite"},
        {"Inf", 3, {0, 0, 1, 1, INFINITY, 2}, FL_ERR_INPUT, "non-finite"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        fl_reconstruction2 rec;
        fl_error err;
        fl_status st = fl_reconstruct2(cases[i].xy, cases[i].n, NULL, &rec, &err);
        fprintf(stderr, "  reconstruct2 %s: %s\n", cases[i].name, err.message);
        CHECK_FAILS(st, &err, cases[i].status, cases[i].message);
        CHECK(rec.boundary == NULL && rec.boundary_count == 0);
    }
}

static void expect_rec2(const char *name, const double *xy, size_t n, int all_on_boundary)
{
    fl_reconstruction2 rec;
    fl_error err;
    fl_status st = fl_reconstruct2(xy, n, NULL, &rec, &err);
    CHECK_MSG(st == FL_OK, "%s: %s", name, err.message);
    if (st != FL_OK) return;
    double ring[2 * 400];
    for (size_t i = 0; i < rec.boundary_count; i++) {
        ring[2 * i] = xy[2 * rec.boundary[i]];
        ring[2 * i + 1] = xy[2 * rec.boundary[i] + 1];
    }
    size_t rs[2] = {0, rec.boundary_count}, ps[2] = {0, 1};
    fl_polygon poly = {rec.boundary_count, ring, 1, rs, 1, ps};
    fl_polygon_report rep;
    CHECK_STATUS(fl_polygon_check(&poly, &rep, &err), FL_OK, &err);
    CHECK_MSG(rep.simple == 1 && rep.ring_orientation[0] == 1, "%s: boundary simple %d "
              "orientation %d", name, rep.simple, rep.ring_orientation[0]);
    fl_polygon_report_free(&rep);
    if (all_on_boundary)
        CHECK_MSG(rec.all_on_boundary && rec.boundary_count == rec.unique_count,
                  "%s: %zu of %zu on the boundary (%s)", name, rec.boundary_count,
                  rec.unique_count, rec.reason);
    fl_reconstruction2_free(&rec);
}

static void test_reconstruct2_degenerate_sets(void)
{
    double xy[2 * 400];
    static const double scales[] = {1, 1e-300, 1e300 / 16};
    for (size_t s = 0; s < 3; s++) {
        size_t n = grid2(xy, 6, scales[s]);
        expect_rec2("6x6 grid", xy, n, 0);
        n = circle12(xy, scales[s]);
        expect_rec2("12 cocircular", xy, n, 1);
    }
    size_t n = circle12(xy, 1);
    memcpy(xy + 2 * n, xy, 2 * n * sizeof(double)); /* every point twice */
    expect_rec2("12 cocircular twice", xy, 2 * n, 1);
    double near_line[] = {0, 0, 1, 0, 2, 0, 3, 0, 1.5, 1e-300};
    expect_rec2("collinear + one 1e-300 off", near_line, 5, 1);
}

static void test_reconstruct3_failures(void)
{
    struct {
        const char *name;
        size_t n;
        double xyz[15];
        fl_status status;
        const char *message;
    } cases[] = {
        {"empty", 0, {0}, FL_ERR_INPUT, "4"},
        {"three", 3, {0, 0, 0, 1, 0, 0, 0, 1, 0}, FL_ERR_INPUT, "4"},
        {"duplicates", 5, {1, 1, 1, 1, 1, 1, 2, 2, 2, 1, 1, 1, 2, 2, 2}, FL_ERR_INPUT, "4"},
        {"collinear", 4, {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3}, FL_ERR_ALGORITHM, "collinear"},
        {"coplanar", 5, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 3, 2, 0}, FL_ERR_ALGORITHM,
         "coplanar"},
        {"NaN", 4, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, NAN}, FL_ERR_INPUT, "NaN"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        fl_reconstruction3 rec;
        fl_error err;
        fl_status st = fl_reconstruct3(cases[i].xyz, cases[i].n, NULL, &rec, &err);
        fprintf(stderr, "  reconstruct3 %s: %s\n", cases[i].name, err.message);
        CHECK_FAILS(st, &err, cases[i].status, cases[i].message);
        CHECK(rec.tri == NULL && rec.triangle_count == 0);
    }
}

static void expect_rec3(const char *name, const double *xyz, size_t n, int all_on_boundary)
{
    fl_reconstruction3 rec;
    fl_error err;
    fl_status st = fl_reconstruct3(xyz, n, NULL, &rec, &err);
    CHECK_MSG(st == FL_OK, "%s: %s", name, err.message);
    if (st != FL_OK) return;
    fl_mesh m = {n, (double *)xyz, rec.triangle_count, rec.tri};
    fl_mesh_report rep;
    CHECK_STATUS(fl_mesh_check(&m, NULL, &rep, &err), FL_OK, &err);
    CHECK_MSG(rep.closed && rep.manifold && rep.oriented && rep.genus == 0 &&
                  rep.components == 1 && rep.self_intersections == 0,
              "%s: closed %d manifold %d oriented %d genus %lld components %zu crossings %zu",
              name, rep.closed, rep.manifold, rep.oriented, rep.genus, rep.components,
              rep.self_intersections);
    fl_mesh_report_free(&rep);
    if (all_on_boundary)
        CHECK_MSG(rec.all_on_boundary && rec.triangle_count == 2 * rec.unique_count - 4,
                  "%s: %zu inside, %zu triangles (%s)", name, rec.points_inside,
                  rec.triangle_count, rec.reason);
    fl_reconstruction3_free(&rec);
}

static void test_reconstruct3_degenerate_sets(void)
{
    double xyz[3 * 200];
    static const double scales[] = {1, 1e-300, 1e300 / 16};
    for (size_t s = 0; s < 3; s++) {
        size_t n = grid3(xyz, 3, scales[s]);
        expect_rec3("3x3x3 grid", xyz, n, 0);
        n = sphere30(xyz, scales[s]);
        expect_rec3("30 cospherical", xyz, n, 1);
    }
    size_t n = sphere30(xyz, 1);
    memcpy(xyz + 3 * n, xyz, 3 * n * sizeof(double));
    expect_rec3("30 cospherical twice", xyz, 2 * n, 1);
}

int main(void)
{
    fl_test_case cases[] = {
        FL_TEST_CASE(test_reconstruct2_failures),
        FL_TEST_CASE(test_reconstruct2_degenerate_sets),
        FL_TEST_CASE(test_reconstruct3_failures),
        FL_TEST_CASE(test_reconstruct3_degenerate_sets),
    };
    return fl_test_run(cases, sizeof cases / sizeof *cases);
}
