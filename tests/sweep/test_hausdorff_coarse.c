/* Certified Hausdorff distance (Guéziec §6) between a coarse mesh and the fine curved surface it
 * approximates — the simplification case of the paper's Fig. 10, where most of the coarse mesh
 * lies within a small distance of the fine one and only a ridge reaches the maximum. This is
 * where the fixed-element bound (3) decides most pieces and most midpoint samples are measured
 * on candidate elements only (no cursor query, docs/hausdorff.md): both must keep the interval
 * certified against dense brute-force sampling, and agree with the all-exact run of keep_field.
 */
#include <stdint.h>

#include "fl_test.h"
#include "hausdorff_oracle.h"

/* z = amp * sin(3 x + 1) * cos(2 y) over [0,1]^2, sampled on an n x n grid (2 n^2 triangles).
 * With a small n it is a coarse approximation whose vertices lie on the fine surface. */
static fl_mesh wavy(int n, double amp)
{
    fl_mesh m = oracle_grid(n, 0, 0, 0);
    for (size_t v = 0; v < m.vertex_count; v++) {
        double *p = m.xyz + 3 * v;
        p[2] = amp * sin(3 * p[0] + 1) * cos(2 * p[1]);
    }
    return m;
}

static void run(const fl_mesh *a, const fl_mesh *b, int keep_field, int both,
                fl_hausdorff_result *r)
{
    fl_hausdorff_options o = {0};
    o.relative = 1e-4;
    o.keep_field = keep_field;
    o.both_directions = both;
    fl_error err;
    CHECK_STATUS(fl_hausdorff_meshes(a, b, &o, r, &err), FL_OK, &err);
}

/* Both intervals (pieces measured on candidates only, and all exact with keep_field) contain
 * the dense value, close to the precision, and overlap each other (both contain the truth). */
static void test_coarse_against_fine_surface_contains_dense_value(void)
{
    const int coarse[] = {2, 3};
    for (int i = 0; i < 2; i++) {
        fl_mesh a = wavy(coarse[i], 0.2), b = wavy(10, 0.2);
        fl_hausdorff_result r, f;
        run(&a, &b, 0, 0, &r);
        run(&a, &b, 1, 0, &f);
        oracle_check_certificate(&a, &b, &r, 20, 1);
        CHECK(f.hausdorff[1] - f.hausdorff[0] <= f.precision);
        CHECK_MSG(fmax(r.hausdorff[0], f.hausdorff[0]) <= fmin(r.hausdorff[1], f.hausdorff[1]),
                  "[%.17g, %.17g] and [%.17g, %.17g] disjoint", r.hausdorff[0], r.hausdorff[1],
                  f.hausdorff[0], f.hausdorff[1]);
        fl_hausdorff_result_free(&r);
        fl_hausdorff_result_free(&f);
        fl_mesh_free(&a);
        fl_mesh_free(&b);
    }
}

/* Each directed interval to precision (both_directions): the direction of small distances is
 * refined too, almost entirely through candidate-only samples, and still contains its dense
 * value. */
static void test_both_directions_on_nearly_coincident_meshes(void)
{
    fl_mesh a = wavy(3, 0.05), b = wavy(10, 0.05);
    fl_hausdorff_result r;
    run(&a, &b, 0, 1, &r);
    oracle_check_certificate(&a, &b, &r, 20, 1);
    CHECK(r.h_ab[1] - r.h_ab[0] <= r.precision && r.h_ba[1] - r.h_ba[0] <= r.precision);
    fl_hausdorff_result_free(&r);
    fl_mesh_free(&a);
    fl_mesh_free(&b);
}

/* A coarse mesh on a flat, finely triangulated plane with one raised vertex: the flat part is
 * at distance 0 but spans many elements of B (no single-element bound holds for a big piece),
 * the maximum of h(a, b) is at the raised vertex. */
static void test_flat_part_over_many_elements(void)
{
    fl_mesh a = oracle_grid(2, 0, 0, 0), b = oracle_grid(12, 0, 0, 0);
    a.xyz[3 * 4 + 2] = 0.1; /* the centre vertex of the 3 x 3 grid of a */
    fl_hausdorff_result r;
    run(&a, &b, 0, 1, &r);
    oracle_check_certificate(&a, &b, &r, 20, 1);
    /* h(a, b) = 0.1 exactly: a's heights over the plane of b, which a covers, peak there. */
    CHECK(r.h_ab[0] <= 0.1 && 0.1 <= r.h_ab[1]);
    fl_hausdorff_result_free(&r);
    fl_mesh_free(&a);
    fl_mesh_free(&b);
}

FL_TEST_MAIN(FL_TEST_CASE(test_coarse_against_fine_surface_contains_dense_value),
             FL_TEST_CASE(test_both_directions_on_nearly_coincident_meshes),
             FL_TEST_CASE(test_flat_part_over_many_elements))
