/* The mesh build of build_mesh.c (issue #9): centroid splits first, then every node's bounding
 * triangle fitted bottom-up, its radius ε measured exactly on the vertices of small nodes and
 * found by branch and bound over the finished subtree for large ones. Checked against brute
 * force in long double (tests/sweep/sweep_oracle.h) over EVERY node:
 *  - containment (§4.1, what the queries rest on): every vertex below a node lies within ε of
 *    its triangle. Shrinking every stored ε by a part in 10^4 fails five of the seven cases
 *    below, dropping the child's ε from the branch and bound's subtree bound fails three;
 *  - tightness: ε is the largest such distance up to rounding, so the branch and bound leaves
 *    nothing on the table (a looser ε costs queries); pruning subtrees whose bound is up to
 *    1.5x the largest distance found fails four cases;
 *  - structure: every triangle is exactly one leaf, children come after their parents (the
 *    bottom-up passes of boxes.c and deform.c need it).
 * Meshes: a noisy sphere, a soup of random triangles (nodes whose bounds prune badly), a flat
 * grid (every distance a tie at 0), one triangle repeated, needles along a line, a small mesh
 * far from the origin, coordinates near the 1e150 limit, a two-sided sphere (twins whose normals
 * cancel), and meshes of one and two triangles. */
#include <stdint.h>

#include "fl_test.h"
#include "sweep/sweep_internal.h"
#include "sweep_oracle.h"

static unsigned long long rng = 0xb01dfaceULL;

static double uniform(double lo, double hi)
{
    return lo + (hi - lo) * fl_test_rand01(&rng);
}

static fl_mesh new_mesh(size_t nv, size_t nt)
{
    fl_mesh m = {nv, malloc(3 * nv * sizeof(double)), nt, malloc(3 * nt * sizeof(uint32_t))};
    return m;
}

static void free_mesh(fl_mesh *m)
{
    free(m->xyz);
    free(m->tri);
}

/* A latitude-longitude sphere of radius r about c, every vertex moved radially by up to
 * `noise` (relative): rows x cols quads, two triangles each. */
static fl_mesh noisy_sphere(int rows, int cols, double r, const double *c, double noise)
{
    fl_mesh m = new_mesh((size_t)(rows + 1) * cols, 2 * (size_t)rows * cols);
    for (int i = 0; i <= rows; i++)
        for (int j = 0; j < cols; j++) {
            double th = 3.14159265358979 * (i + 0.5) / (rows + 1.0), ph = 6.2831853 * j / cols;
            double rr = r * (1 + uniform(-noise, noise));
            double *p = m.xyz + 3 * ((size_t)i * cols + j);
            p[0] = c[0] + rr * sin(th) * cos(ph);
            p[1] = c[1] + rr * sin(th) * sin(ph);
            p[2] = c[2] + rr * cos(th);
        }
    size_t t = 0;
    for (int i = 0; i < rows; i++)
        for (int j = 0; j < cols; j++, t += 2) {
            uint32_t a = (uint32_t)(i * cols + j), b = (uint32_t)(i * cols + (j + 1) % cols);
            uint32_t q[6] = {a, b, b + (uint32_t)cols, a, b + (uint32_t)cols, a + (uint32_t)cols};
            memcpy(m.tri + 3 * t, q, sizeof q);
        }
    return m;
}

/* nt triangles with corners uniform in the cube [0, side)^3, each its own three vertices. */
static fl_mesh soup(size_t nt, double side)
{
    fl_mesh m = new_mesh(3 * nt, nt);
    for (size_t i = 0; i < 9 * nt; i++)
        m.xyz[i] = uniform(0, side);
    for (size_t i = 0; i < 3 * nt; i++)
        m.tri[i] = (uint32_t)i;
    return m;
}

/* An n x n grid in the plane z = 0.5 x + 0.25 y (tilted, so the plane is not a frame axis). */
static fl_mesh flat_grid(int n)
{
    fl_mesh m = new_mesh((size_t)n * n, 2 * (size_t)(n - 1) * (n - 1));
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            double *p = m.xyz + 3 * ((size_t)i * n + j);
            p[0] = i, p[1] = j, p[2] = 0.5 * i + 0.25 * j;
        }
    size_t t = 0;
    for (int i = 0; i + 1 < n; i++)
        for (int j = 0; j + 1 < n; j++, t += 2) {
            uint32_t a = (uint32_t)(i * n + j), b = a + (uint32_t)n;
            uint32_t q[6] = {a, a + 1, b + 1, a, b + 1, b};
            memcpy(m.tri + 3 * t, q, sizeof q);
        }
    return m;
}

/* Degenerate meshes: `repeat` copies of one triangle, or needles (three vertices of a line,
 * one of them moved off it by 1e-13) along the line x = 2y = 4z. */
static fl_mesh degenerate(size_t nt, int needles)
{
    fl_mesh m = new_mesh(needles ? 3 * nt : 3, nt);
    for (size_t v = 0; v < m.vertex_count; v++) {
        double s = needles ? (double)((v * 37) % 101) : (double)v;
        m.xyz[3 * v] = s, m.xyz[3 * v + 1] = 0.5 * s, m.xyz[3 * v + 2] = 0.25 * s;
        if (needles && v % 3 == 1) m.xyz[3 * v + 2] += 1e-13;
        if (!needles && v == 1) m.xyz[3 * v + 1] += 1;
    }
    for (size_t t = 0; t < nt; t++)
        for (int k = 0; k < 3; k++)
            m.tri[3 * t + k] = needles ? (uint32_t)(3 * t + (size_t)k) : (uint32_t)k;
    return m;
}

/* Largest |coordinate| of a node's triangle. */
static double node_scale(const fl_sweep_node *node)
{
    double s = 0;
    for (int i = 0; i < 9; i++)
        s = fmax(s, fabs(node->v[i]));
    return s;
}

/* Containment and tightness of every internal node's ε, by brute force over its leaves. */
static void check_radii(const fl_sweep *s, const fl_mesh *m)
{
    uint32_t *stack = malloc(s->node_count * sizeof *stack);
    size_t outside = 0, loose = 0, worst = 0;
    double worst_gap = 0;
    for (size_t i = 0; i < s->node_count; i++) {
        const fl_sweep_node *node = s->nodes + i;
        if (fl_sweep_is_leaf(node)) {
            outside += node->eps != 0;
            continue;
        }
        ld far = 0;
        size_t top = 0;
        stack[top++] = (uint32_t)i;
        while (top > 0) {
            const fl_sweep_node *d = s->nodes + stack[--top];
            if (!fl_sweep_is_leaf(d)) {
                stack[top++] = d->child[0];
                stack[top++] = d->child[1];
                continue;
            }
            for (int k = 0; k < 3; k++) {
                ld x = oracle_triangle(oracle_vertex(m->xyz, m->tri, d->element, k), node->v,
                                       node->v + 3, node->v + 6);
                far = x > far ? x : far;
            }
        }
        outside += (ld)node->eps < far;
        /* Rounding: the build clamps barycentrics within 1e-6 of the triangle (1e-6 of its
         * size) and widens by 64 ulps of the largest coordinate. */
        double size = 0;
        for (int k = 0; k < 3; k++) {
            const double *a = node->v + 3 * k, *b = node->v + 3 * ((k + 1) % 3);
            size = fmax(size, hypot(hypot(a[0] - b[0], a[1] - b[1]), a[2] - b[2]));
        }
        double slack = 1e-5 * size + 1e-12 * fmax(s->scale, node_scale(node));
        double gap = node->eps - (double)far - slack;
        if (gap > 0) {
            loose++;
            if (gap > worst_gap) worst_gap = gap, worst = i;
        }
    }
    CHECK_MSG(outside == 0, "%zu nodes leave a vertex outside their volume", outside);
    CHECK_MSG(loose == 0, "%zu radii looser than the farthest vertex (node %zu by %g)", loose,
              worst, worst_gap);
    free(stack);
}

/* Every triangle is one leaf, reached once from the root; children come after parents. */
static void check_structure(const fl_sweep *s, const fl_mesh *m)
{
    CHECK(s->node_count == 2 * m->triangle_count - 1);
    unsigned char *seen = calloc(m->triangle_count, 1);
    size_t leaves = 0, misordered = 0, repeated = 0;
    for (size_t i = 0; i < s->node_count; i++) {
        const fl_sweep_node *node = s->nodes + i;
        if (fl_sweep_is_leaf(node)) {
            leaves++;
            if (node->element >= m->triangle_count || seen[node->element]++) repeated++;
            continue;
        }
        for (int k = 0; k < 2; k++)
            misordered += node->child[k] <= i || node->child[k] >= s->node_count;
    }
    CHECK_MSG(leaves == m->triangle_count && repeated == 0, "%zu leaves, %zu repeated", leaves,
              repeated);
    CHECK_MSG(misordered == 0, "%zu children numbered before their parent", misordered);
    free(seen);
}

static void check_build(fl_mesh *m)
{
    fl_sweep *s;
    fl_error err;
    CHECK_STATUS(fl_sweep_build(m, NULL, &s, &err), FL_OK, &err);
    check_structure(s, m);
    check_radii(s, m);
    fl_sweep_free(s);
    free_mesh(m);
}

static void test_sweep_build_noisy_sphere_radii_exact(void)
{
    double c[3] = {0.3, -0.2, 0.1};
    fl_mesh m = noisy_sphere(40, 50, 1.0, c, 0.02);
    check_build(&m);
}

static void test_sweep_build_random_soup_radii_exact(void)
{
    fl_mesh m = soup(1500, 10);
    check_build(&m);
}

static void test_sweep_build_flat_grid_radii_exact(void)
{
    fl_mesh m = flat_grid(33);
    check_build(&m);
}

static void test_sweep_build_repeated_triangle_radii_exact(void)
{
    fl_mesh m = degenerate(400, 0);
    check_build(&m);
}

static void test_sweep_build_needles_radii_exact(void)
{
    fl_mesh m = degenerate(500, 1);
    check_build(&m);
}

/* Every triangle of a noisy sphere twice, the second copy reversed: the median splits pair
 * twins, whose summed normal cancels exactly, so small nodes take the Jacobi fallback of
 * normal_frame beside nodes that take the summed-normal frame. */
static void test_sweep_build_two_sided_radii_exact(void)
{
    double c[3] = {-0.4, 0.2, 0.7};
    fl_mesh a = noisy_sphere(12, 16, 2.0, c, 0.05);
    fl_mesh m = new_mesh(a.vertex_count, 2 * a.triangle_count);
    memcpy(m.xyz, a.xyz, 3 * a.vertex_count * sizeof(double));
    for (size_t t = 0; t < a.triangle_count; t++) {
        const uint32_t *q = a.tri + 3 * t;
        uint32_t twin[6] = {q[0], q[1], q[2], q[0], q[2], q[1]};
        memcpy(m.tri + 6 * t, twin, sizeof twin);
    }
    free_mesh(&a);
    check_build(&m);
}

/* Far from the origin (1e6 away, size 1e-3) and near the 1e150 limit: rounding slack and the
 * corner bounds of the branch and bound at both ends of the range. */
static void test_sweep_build_far_and_huge_coordinates(void)
{
    double far[3] = {1e6, -2e6, 3e6}, huge[3] = {0, 0, 0};
    fl_mesh a = noisy_sphere(20, 30, 1e-3, far, 0.05);
    check_build(&a);
    fl_mesh b = noisy_sphere(20, 30, 1e149, huge, 0.05);
    check_build(&b);
}

static void test_sweep_build_one_and_two_triangles(void)
{
    for (size_t nt = 1; nt <= 2; nt++) {
        fl_mesh m = soup(nt, 1);
        check_build(&m);
    }
}

FL_TEST_MAIN(FL_TEST_CASE(test_sweep_build_noisy_sphere_radii_exact),
             FL_TEST_CASE(test_sweep_build_random_soup_radii_exact),
             FL_TEST_CASE(test_sweep_build_flat_grid_radii_exact),
             FL_TEST_CASE(test_sweep_build_repeated_triangle_radii_exact),
             FL_TEST_CASE(test_sweep_build_needles_radii_exact),
             FL_TEST_CASE(test_sweep_build_two_sided_radii_exact),
             FL_TEST_CASE(test_sweep_build_far_and_huge_coordinates),
             FL_TEST_CASE(test_sweep_build_one_and_two_triangles))
