/* Hierarchical point-in-polyhedron and intersection (thesis §7.4) agree exactly with brute
 * force: inclusion against a ray in a different direction (+z) over every triangle, with its
 * own symbolic perturbation, and on-surface tests by exact predicates; intersection against all
 * pairs of triangles tested with the exact triangle-triangle test. */
#include "fl_test.h"
#include "hal/hal3_internal.h"
#include "hal3_meshes.h"
#include "hal3_oracle.h"
#include "mesh/intersect.h"

static const double *V(const fl_mesh *m, uint32_t v)
{
    return m->xyz + 3 * (size_t)v;
}

static uint8_t brute_inside(const fl_mesh *m, const double *x)
{
    return hal3_oracle_inside(m, x);
}

static fl_mesh query_mesh(int i)
{
    switch (i) {
    case 0:
        return hal3_blob(3, 1.0, 1.0, 1.0, 0.15);
    case 1:
        return hal3_cube(3);
    case 2:
        return hal3_peanut();
    default:
        return hal3_blob(2, 2.0, 1.0, 0.6, 0.0);
    }
}

static void test_hal3_inclusion_equals_brute_force_on_random_and_surface_points(void)
{
    for (int i = 0; i < 4; i++) {
        fl_mesh m = query_mesh(i);
        fl_hal3 hal;
        fl_error err;
        CHECK_STATUS(fl_hal3_build(&m, NULL, &hal, &err), FL_OK, &err);
        if (hal.node_count == 0) {
            fl_mesh_free(&m);
            continue;
        }
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (size_t t = 0; t < 3 * m.triangle_count; t++)
            for (int k = 0; k < 3; k++) {
                lo[k] = fmin(lo[k], V(&m, m.tri[t])[k]);
                hi[k] = fmax(hi[k], V(&m, m.tri[t])[k]);
            }
        size_t n = 1500;
        double *q = malloc(3 * n * sizeof(double));
        for (size_t k = 0; k < n; k++) {
            if (k % 5 == 0) { /* a vertex: on the surface */
                memcpy(q + 3 * k, V(&m, m.tri[(k * 7) % (3 * m.triangle_count)]),
                       3 * sizeof(double));
            } else if (k % 5 == 1) { /* a vertex's coordinates mixed: on ray-degenerate lines */
                const double *a = V(&m, m.tri[(k * 11) % (3 * m.triangle_count)]);
                const double *b = V(&m, m.tri[(k * 13) % (3 * m.triangle_count)]);
                q[3 * k] = hal3_rand() * (hi[0] - lo[0]) + lo[0];
                q[3 * k + 1] = a[1];
                q[3 * k + 2] = b[2];
            } else {
                for (int c = 0; c < 3; c++)
                    q[3 * k + c] = lo[c] + (hi[c] - lo[c]) * (1.2 * hal3_rand() - 0.1);
            }
        }
        if (i == 1) /* the cube's faces are axis planes: grid points lie on them exactly */
            for (size_t k = 2; k < n; k += 5)
                for (int c = 0; c < 3; c++)
                    q[3 * k + c] = floor(q[3 * k + c] * 2 + 0.5) / 2;
        uint8_t *w = malloc(n);
        CHECK_STATUS(fl_hal3_contains(&hal, q, n, w, &err), FL_OK, &err);
        size_t diff = 0, count[3] = {0, 0, 0};
        for (size_t k = 0; k < n; k++) {
            uint8_t b = brute_inside(&m, q + 3 * k);
            diff += b != w[k];
            count[b]++;
        }
        CHECK_MSG(diff == 0, "mesh %d: %zu of %zu answers differ from brute force", i, diff, n);
        CHECK(count[0] > 0 && count[1] > 0 && count[2] > 0);
        free(q);
        free(w);
        fl_hal3_free(&hal);
        fl_mesh_free(&m);
    }
}

static int cmp_pair(const void *x, const void *y)
{
    const uint32_t *a = x, *b = y;
    if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
    return a[1] < b[1] ? -1 : a[1] > b[1];
}

static void check_intersection(const fl_mesh *a, const fl_mesh *b, int expect_some)
{
    fl_hal3 ha, hb;
    fl_error err;
    CHECK_STATUS(fl_hal3_build(a, NULL, &ha, &err), FL_OK, &err);
    CHECK_STATUS(fl_hal3_build(b, NULL, &hb, &err), FL_OK, &err);
    if (!ha.node_count || !hb.node_count) return;
    size_t cap = 1024, n = 0;
    uint32_t *bf = malloc(2 * cap * sizeof(uint32_t));
    for (uint32_t s = 0; s < a->triangle_count; s++)
        for (uint32_t t = 0; t < b->triangle_count; t++) {
            const uint32_t *x = a->tri + 3 * (size_t)s, *y = b->tri + 3 * (size_t)t;
            if (!fl_triangles_intersect(V(a, x[0]), V(a, x[1]), V(a, x[2]), V(b, y[0]), V(b, y[1]),
                                        V(b, y[2])))
                continue;
            if (n == cap) bf = realloc(bf, 2 * (cap *= 2) * sizeof(uint32_t));
            bf[2 * n] = s, bf[2 * n + 1] = t, n++;
        }
    qsort(bf, n, 2 * sizeof(uint32_t), cmp_pair);
    fl_hal3_pairs p, first;
    CHECK_STATUS(fl_hal3_intersect(&ha, &hb, 0, &p, &err), FL_OK, &err);
    CHECK_EQ_INT(p.count, n);
    CHECK(p.count != n || n == 0 || memcmp(p.pairs, bf, 2 * n * sizeof(uint32_t)) == 0);
    CHECK(expect_some ? n > 0 : n == 0);
    CHECK_STATUS(fl_hal3_intersect(&ha, &hb, 1, &first, &err), FL_OK, &err);
    CHECK_EQ_INT(first.count, n > 0);
    fl_hal3_pairs_free(&p);
    fl_hal3_pairs_free(&first);
    free(bf);
    fl_hal3_free(&ha);
    fl_hal3_free(&hb);
}

static void test_hal3_intersecting_pairs_equal_brute_force(void)
{
    fl_mesh a = hal3_blob(2, 1.0, 1.0, 1.0, 0.1);
    fl_mesh b = hal3_blob(2, 1.5, 0.8, 0.7, 0.05);
    for (size_t v = 0; v < b.vertex_count; v++)
        b.xyz[3 * v] += 1.1, b.xyz[3 * v + 1] += 0.3;
    check_intersection(&a, &b, 1);
    fl_mesh c = hal3_cube(2), d = hal3_cube(2);
    for (size_t v = 0; v < d.vertex_count; v++)
        d.xyz[3 * v] += 2; /* touching along a face */
    check_intersection(&c, &d, 1);
    for (size_t v = 0; v < d.vertex_count; v++)
        d.xyz[3 * v] += 0.5; /* apart */
    check_intersection(&c, &d, 0);
    fl_mesh_free(&a);
    fl_mesh_free(&b);
    fl_mesh_free(&c);
    fl_mesh_free(&d);
}

/* The early exit of fl_hal3_intersect (disjoint bounding boxes) must be exact: hal->box equals
 * the vertices' extremes, and a copy of the cube moved along each axis, in each direction, by
 * exactly its extent (the faces touch: pairs) or by one ulp more (boxes apart by one ulp: no
 * pair) gives the brute-force pairs in both argument orders. */
static void test_hal3_intersect_box_early_exit_is_exact(void)
{
    fl_mesh c = hal3_cube(2);
    fl_hal3 hc;
    fl_error err;
    CHECK_STATUS(fl_hal3_build(&c, NULL, &hc, &err), FL_OK, &err);
    for (int k = 0; k < 3; k++) {
        double lo = INFINITY, hi = -INFINITY;
        for (size_t v = 0; v < c.vertex_count; v++)
            lo = fmin(lo, c.xyz[3 * v + k]), hi = fmax(hi, c.xyz[3 * v + k]);
        CHECK(hc.box[k] == lo && hc.box[3 + k] == hi);
    }
    fl_hal3_free(&hc);
    for (int k = 0; k < 3; k++)
        for (int sign = -1; sign <= 1; sign += 2)
            for (int ulp = 0; ulp < 2; ulp++) {
                fl_mesh d = hal3_cube(2);
                double shift = ulp ? nextafter(2.0, 3.0) : 2.0;
                for (size_t v = 0; v < d.vertex_count; v++)
                    d.xyz[3 * v + (size_t)k] += sign * shift;
                check_intersection(&c, &d, !ulp);
                check_intersection(&d, &c, !ulp);
                fl_mesh_free(&d);
            }
    fl_mesh_free(&c);
}

static void test_hal3_contains_rejects_non_finite_queries(void)
{
    fl_mesh m = hal3_icosphere(1);
    fl_hal3 hal;
    fl_error err;
    CHECK_STATUS(fl_hal3_build(&m, NULL, &hal, &err), FL_OK, &err);
    double q[6] = {0, 0, 0, NAN, 0, 0};
    uint8_t w[2];
    CHECK_STATUS(fl_hal3_contains(&hal, q, 2, w, &err), FL_ERR_INPUT, &err);
    CHECK(w[0] == FL_HAL3_INSIDE);
    fl_hal3_free(&hal);
    fl_mesh_free(&m);
}

/* The inclusion ray runs along the axis towards the nearest face of the bounding box
 * (hal3_contains.c), so each of the six directions must meet its own degenerate cases: queries
 * near each face whose two other coordinates are a vertex's (the ray runs through a vertex),
 * the mean of an edge's end points (through an edge, on the cube's grid exactly), or the
 * cube's grid values (along a face). Property: answers equal the +z brute force, and all six
 * directions are exercised (the test recomputes the nearest face). */
static void test_hal3_inclusion_rays_along_every_axis_through_vertices_and_edges(void)
{
    for (int i = 0; i < 3; i++) {
        fl_mesh m = query_mesh(i);
        fl_hal3 hal;
        fl_error err;
        CHECK_STATUS(fl_hal3_build(&m, NULL, &hal, &err), FL_OK, &err);
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (size_t v = 0; v < m.vertex_count; v++)
            for (int k = 0; k < 3; k++) {
                lo[k] = fmin(lo[k], m.xyz[3 * v + k]);
                hi[k] = fmax(hi[k], m.xyz[3 * v + k]);
            }
        size_t n = 1200, used[6] = {0, 0, 0, 0, 0, 0}, diff = 0;
        double *q = malloc(3 * n * sizeof(double));
        uint8_t *w = malloc(n);
        for (size_t j = 0; j < n; j++) {
            int k = (int)(j % 3), side = (int)(j / 3 % 2), kind = (int)(j / 6 % 3);
            uint32_t t = (uint32_t)(hal3_rand() * (double)m.triangle_count);
            const double *a = V(&m, m.tri[3 * t]), *b = V(&m, m.tri[3 * t + 1]);
            double *x = q + 3 * j;
            for (int c = 0; c < 3; c++) {
                x[c] = kind == 0 ? a[c] : kind == 1 ? 0.5 * (a[c] + b[c])
                                                   : floor(a[c] * 2 + 0.5) / 2;
            }
            double f = 0.15 * hal3_rand();
            x[k] = side ? hi[k] - f * (hi[k] - lo[k]) : lo[k] + f * (hi[k] - lo[k]);
        }
        CHECK_STATUS(fl_hal3_contains(&hal, q, n, w, &err), FL_OK, &err);
        for (size_t j = 0; j < n; j++) {
            const double *x = q + 3 * j;
            int best = 0;
            double d = INFINITY;
            for (int k = 0; k < 3; k++) {
                if (hi[k] - x[k] < d) d = hi[k] - x[k], best = 2 * k;
                if (x[k] - lo[k] < d) d = x[k] - lo[k], best = 2 * k + 1;
            }
            used[best]++;
            diff += brute_inside(&m, x) != w[j];
        }
        CHECK_MSG(diff == 0, "mesh %d: %zu of %zu answers differ from brute force", i, diff, n);
        for (int k = 0; k < 6; k++) CHECK_MSG(used[k] > 0, "mesh %d: direction %d unused", i, k);
        free(q);
        free(w);
        fl_hal3_free(&hal);
        fl_mesh_free(&m);
    }
}

/* The ray walk stores node bounds as floats rounded outwards (hal3_contains.c). Far from the
 * origin a float's spacing (1 at 1e7) is far larger than the mesh's detail (1e-3): every bound
 * and query coordinate is rounded, and a skip must still be proven (a bound moved inwards past
 * the query's rounding would cut off triangles the ray crosses). Property: on a noisy blob of
 * size 1e-3 at (1e7, -3e6, 5e5) the answers for points near the surface (vertices moved by up to
 * 1e-5, and vertices themselves) equal the brute force's. */
static void test_hal3_inclusion_far_from_the_origin_equals_brute_force(void)
{
    fl_mesh m = hal3_blob(2, 1.0, 1.0, 1.0, 0.15);
    const double off[3] = {1e7, -3e6, 5e5};
    for (size_t v = 0; v < m.vertex_count; v++)
        for (int k = 0; k < 3; k++) m.xyz[3 * v + k] = m.xyz[3 * v + k] * 1e-3 + off[k];
    fl_hal3 hal;
    fl_error err;
    CHECK_STATUS(fl_hal3_build(&m, NULL, &hal, &err), FL_OK, &err);
    size_t n = 1000, diff = 0, count[3] = {0, 0, 0};
    double *q = malloc(3 * n * sizeof(double));
    uint8_t *w = malloc(n);
    for (size_t j = 0; j < n; j++) {
        const double *a = V(&m, (uint32_t)(hal3_rand() * (double)m.vertex_count));
        for (int k = 0; k < 3; k++)
            q[3 * j + k] = a[k] + (j % 4 ? (hal3_rand() - 0.5) * 2e-5 : 0.0);
    }
    CHECK_STATUS(fl_hal3_contains(&hal, q, n, w, &err), FL_OK, &err);
    for (size_t j = 0; j < n; j++) {
        uint8_t b = brute_inside(&m, q + 3 * j);
        diff += b != w[j];
        count[b]++;
    }
    CHECK_MSG(diff == 0, "%zu of %zu answers differ from brute force", diff, n);
    CHECK(count[0] > 0 && count[1] > 0 && count[2] > 0);
    free(q);
    free(w);
    fl_hal3_free(&hal);
    fl_mesh_free(&m);
}

int main(void)
{
    static const fl_test_case cases[] = {
        FL_TEST_CASE(test_hal3_inclusion_equals_brute_force_on_random_and_surface_points),
        FL_TEST_CASE(test_hal3_intersecting_pairs_equal_brute_force),
        FL_TEST_CASE(test_hal3_intersect_box_early_exit_is_exact),
        FL_TEST_CASE(test_hal3_contains_rejects_non_finite_queries),
        FL_TEST_CASE(test_hal3_inclusion_rays_along_every_axis_through_vertices_and_edges),
        FL_TEST_CASE(test_hal3_inclusion_far_from_the_origin_equals_brute_force),
    };
    return fl_test_run(cases, sizeof cases / sizeof cases[0]);
}
