/* k nearest triangles and all triangles within d on the edge-collapse hierarchy (Guéziec §4.4)
 * against brute force over every triangle (long double oracle, no library code): the k
 * distances equal the k smallest brute-force distances to 1e-12 relative, each reported
 * triangle is at its reported distance, the lists are sorted and without repeats; "within d"
 * returns exactly the triangles at distance <= d (up to the rounding band around d). Random
 * queries through fresh cursors, and a coherent walk through one cursor that mixes closest,
 * k-nearest and within queries (the popped leaves must be queued again for §5.1). Meshes:
 * closed, open, non-manifold/degenerate, a soup. */
#include "test_collapse_meshes.h"

typedef struct ranked {
    ld d;
    uint32_t t;
} ranked;

static int by_distance(const void *a, const void *b)
{
    ld x = ((const ranked *)a)->d, y = ((const ranked *)b)->d;
    return (x > y) - (x < y);
}

/* All triangles sorted by their brute-force distance to q. */
static ranked *brute_sorted(const fl_mesh *m, const double *q)
{
    ranked *all = malloc(m->triangle_count * sizeof *all);
    for (size_t t = 0; t < m->triangle_count; t++)
        all[t] = (ranked){oracle_mesh_element(m->xyz, m->tri, t, q), (uint32_t)t};
    qsort(all, m->triangle_count, sizeof *all, by_distance);
    return all;
}

static double tolerance(const fl_mesh *m, const double *q)
{
    return 1e-12 * (mesh_scale(m) + fabs(q[0]) + fabs(q[1]) + fabs(q[2]));
}

/* A reported list: sorted, no repeats, each triangle at its distance. */
static void check_list(const fl_mesh *m, const double *q, const uint32_t *el, const double *d,
                       size_t n)
{
    double tol = tolerance(m, q);
    uint8_t *seen = calloc(m->triangle_count, 1);
    for (size_t i = 0; i < n; i++) {
        CHECK(el[i] < m->triangle_count);
        if (el[i] >= m->triangle_count) break;
        CHECK_MSG(!seen[el[i]], "triangle %u reported twice", el[i]);
        seen[el[i]] = 1;
        CHECK_NEAR(d[i], (double)oracle_mesh_element(m->xyz, m->tri, el[i], q), tol);
        if (i > 0) /* equidistant triangles (a shared closest vertex) may swap by rounding */
            CHECK_MSG(d[i] >= d[i - 1] - tol, "not sorted: %.17g after %.17g", d[i], d[i - 1]);
    }
    free(seen);
}

static void check_knearest(const fl_mesh *m, const double *q, size_t k, const uint32_t *el,
                           const double *d, size_t found)
{
    size_t expect = k < m->triangle_count ? k : m->triangle_count;
    CHECK_EQ_INT((long long)found, (long long)expect);
    check_list(m, q, el, d, found);
    ranked *all = brute_sorted(m, q);
    for (size_t i = 0; i < found; i++)
        CHECK_NEAR(d[i], (double)all[i].d, tolerance(m, q));
    free(all);
}

static void check_within(const fl_mesh *m, const double *q, double radius, const fl_sweep_hits *h)
{
    check_list(m, q, h->element, h->distance, h->count);
    double tol = tolerance(m, q);
    size_t surely = 0, maybe = 0; /* brute-force counts at radius - tol and radius + tol */
    for (size_t t = 0; t < m->triangle_count; t++) {
        ld d = oracle_mesh_element(m->xyz, m->tri, t, q);
        surely += d <= radius - tol;
        maybe += d <= radius + tol;
    }
    CHECK_MSG(h->count >= surely && h->count <= maybe, "%zu hits, brute force %zu..%zu",
              h->count, surely, maybe);
    for (size_t i = 0; i < h->count; i++)
        CHECK(h->distance[i] <= radius);
}

/* A query near the surface, in the box or far away; a radius reaching a few triangles. */
static void random_query(const fl_mesh *m, int i, double *p)
{
    double s = mesh_scale(m);
    if (i % 3 == 0) {
        size_t t = (size_t)(fl_test_rand01(&cm_rng) * (double)m->triangle_count);
        for (int c = 0; c < 3; c++)
            p[c] = oracle_vertex(m->xyz, m->tri, t, i % 2)[c] + cm_rand(-0.03, 0.03) * s;
    } else {
        double r = i % 3 == 1 ? 1.3 * s : 100 * s;
        for (int c = 0; c < 3; c++)
            p[c] = cm_rand(-r, r);
    }
}

static void check_random(const fl_mesh *m, int n)
{
    fl_sweep_collapse *h = NULL;
    fl_error err = {0};
    CHECK_STATUS(fl_sweep_collapse_build(m, NULL, &h, &err), FL_OK, &err);
    if (!h) return;
    uint32_t el[40];
    double d[40];
    for (int i = 0; i < n; i++) {
        double q[3];
        random_query(m, i, q);
        size_t k = 1 + (size_t)(i % 5) * 9, found = 0;
        CHECK_STATUS(fl_sweep_collapse_knearest(h, q, k, el, d, &found, &err), FL_OK, &err);
        check_knearest(m, q, k, el, d, found);
        /* the radius of the k-th nearest (or a bit more): hits are exactly those within it */
        double radius = found ? d[found - 1] * (i % 2 ? 1.0 : 1.01) : 0;
        fl_sweep_hits hits = {0};
        CHECK_STATUS(fl_sweep_collapse_within(h, q, radius, &hits, &err), FL_OK, &err);
        check_within(m, q, radius, &hits);
        fl_sweep_hits_free(&hits);
    }
    fl_sweep_collapse_free(h);
}

static void test_near_random(void)
{
    fl_mesh torus = cm_noisy_torus(24, 10, 0.1);
    check_random(&torus, 120);
    cm_free(&torus);
    fl_mesh grid = cm_open_grid(16, 0.05);
    check_random(&grid, 120);
    cm_free(&grid);
    fl_mesh messy = cm_messy(10);
    check_random(&messy, 120);
    cm_free(&messy);
    fl_mesh soup = cm_soup(150, 0.05);
    check_random(&soup, 90);
    cm_free(&soup);
    fl_mesh one = cm_soup(1, 0.3); /* k beyond the triangle count; within of one triangle */
    check_random(&one, 20);
    cm_free(&one);
}

/* One cursor along a slow walk (§5.1, the refined mesh kept between queries): every kind of
 * query stays exact when they alternate. */
static void test_near_walk(void)
{
    fl_mesh m = cm_noisy_torus(40, 16, 0.05);
    fl_sweep_collapse *h = NULL;
    fl_sweep_collapse_cursor *c = NULL;
    fl_error err = {0};
    CHECK_STATUS(fl_sweep_collapse_build(&m, NULL, &h, &err), FL_OK, &err);
    CHECK_STATUS(fl_sweep_collapse_cursor_new(h, &c, &err), FL_OK, &err);
    if (!c) return;
    double p[3] = {1.2, 0.1, 0.05}, dir[3] = {0, 0, 0};
    uint32_t el[12];
    double d[12];
    for (int i = 0; i < 300; i++) {
        for (int k = 0; k < 3; k++) {
            dir[k] = 0.9 * dir[k] + cm_rand(-0.003, 0.003);
            p[k] += dir[k];
        }
        size_t found = 0;
        if (i % 3 == 0) {
            fl_closest r;
            CHECK_STATUS(fl_sweep_collapse_cursor_closest(c, p, 0.0, &r, &err), FL_OK, &err);
            check_exact(&m, p, &r);
        } else if (i % 3 == 1) {
            CHECK_STATUS(fl_sweep_collapse_cursor_knearest(c, p, 12, el, d, &found, &err), FL_OK,
                         &err);
            check_knearest(&m, p, 12, el, d, found);
        } else {
            fl_sweep_hits hits = {0};
            double radius = (double)brute_distance(&m, p) + 0.05;
            CHECK_STATUS(fl_sweep_collapse_cursor_within(c, p, radius, &hits, &err), FL_OK, &err);
            check_within(&m, p, radius, &hits);
            fl_sweep_hits_free(&hits);
        }
    }
    fl_sweep_collapse_cursor_free(c);
    fl_sweep_collapse_free(h);
    cm_free(&m);
}

static void test_near_usage(void)
{
    fl_mesh m = cm_soup(3, 0.2);
    fl_sweep_collapse *h = NULL;
    fl_error err = {0};
    CHECK_STATUS(fl_sweep_collapse_build(&m, NULL, &h, &err), FL_OK, &err);
    double q[3] = {0, 0, 0}, bad[3] = {NAN, 0, 0}, d[2];
    uint32_t el[2];
    size_t found = 7;
    fl_sweep_hits hits = {0};
    CHECK_STATUS(fl_sweep_collapse_knearest(h, bad, 2, el, d, &found, &err), FL_ERR_USAGE, &err);
    CHECK(found == 0);
    CHECK_STATUS(fl_sweep_collapse_knearest(h, q, 2, NULL, d, &found, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_sweep_collapse_knearest(h, q, 0, NULL, NULL, &found, &err), FL_OK, &err);
    CHECK(found == 0);
    CHECK_STATUS(fl_sweep_collapse_within(h, q, -1, &hits, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_sweep_collapse_within(h, q, NAN, &hits, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_sweep_collapse_within(h, bad, 1, &hits, &err), FL_ERR_USAGE, &err);
    CHECK(hits.count == 0 && hits.element == NULL);
    CHECK_STATUS(fl_sweep_collapse_within(NULL, q, 1, &hits, &err), FL_ERR_USAGE, &err);
    CHECK_STATUS(fl_sweep_collapse_within(h, q, 0, &hits, &err), FL_OK, &err);
    fl_sweep_hits_free(&hits);
    fl_sweep_collapse_free(h);
    cm_free(&m);
}

FL_TEST_MAIN(FL_TEST_CASE(test_near_random), FL_TEST_CASE(test_near_walk),
             FL_TEST_CASE(test_near_usage))
