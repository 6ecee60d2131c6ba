/* The speed-ups of issue #9, each checked against an independent computation: the boxes kept
 * alongside the swept spheres (boxes.c: exact union of the corners below), the bounding
 * triangles of large nodes shaped on a sample (build_mesh.c: every vertex must still lie within
 * ε, §4.1), and the cursor's back list and first upper bound (query.c: answers equal brute
 * force on streams that walk, jump away and come back, §3.2 / §5.1). Degenerate inputs: a mesh
 * of one triangle repeated 300 times, a mesh whose every triangle is collinear, a polyline. */
#include <stdint.h>

#include "fl_test.h"
#include "sweep/sweep_internal.h"
#include "sweep_oracle.h"

static unsigned long long rng = 0x5eed5eedULL;

static double uniform(double lo, double hi)
{
    return lo + (hi - lo) * fl_test_rand01(&rng);
}

/* A wavy n x n grid in [0, n)^2 with tall spikes: every 97th vertex is lifted by n / 4. A
 * node's sample rarely holds a spike, so its ε has to come from measuring every vertex. */
static fl_mesh spiky_grid(int n)
{
    size_t nt = 2 * (size_t)(n - 1) * (n - 1);
    fl_mesh m = {(size_t)n * n, malloc(3 * (size_t)n * n * sizeof(double)), nt,
                 malloc(3 * nt * sizeof(uint32_t))};
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            size_t v = (size_t)i * n + j;
            m.xyz[3 * v] = i;
            m.xyz[3 * v + 1] = j;
            m.xyz[3 * v + 2] = 0.3 * sin(0.7 * i) * cos(0.4 * j) + (v % 97 == 5 ? n / 4.0 : 0);
        }
    size_t t = 0;
    for (int i = 0; i + 1 < n; i++)
        for (int j = 0; j + 1 < n; j++, t += 2) {
            uint32_t a = (uint32_t)(i * n + j), b = a + (uint32_t)n;
            uint32_t q[6] = {a, b, b + 1, a, b + 1, a + 1};
            memcpy(m.tri + 3 * t, q, sizeof q);
        }
    return m;
}

/* nt triangles over nv vertices from a rule: repeated (all the same triangle) or collinear
 * (every vertex on one line). */
static fl_mesh degenerate_mesh(int collinear)
{
    size_t nv = 40, nt = 300;
    fl_mesh m = {nv, malloc(3 * nv * sizeof(double)), nt, malloc(3 * nt * sizeof(uint32_t))};
    for (size_t v = 0; v < nv; v++) {
        double s = collinear ? (double)v * 0.37 : (double)(v % 3);
        m.xyz[3 * v] = 1 + s, m.xyz[3 * v + 1] = 2 - 0.5 * s, m.xyz[3 * v + 2] = 0.25 * s;
        if (!collinear) m.xyz[3 * v + 1] += v % 3 == 1; /* vertices 0,1,2 a proper triangle */
    }
    for (size_t t = 0; t < nt; t++)
        for (int k = 0; k < 3; k++)
            m.tri[3 * t + k] = collinear ? (uint32_t)((t * 7 + (size_t)k * 13) % nv) : (uint32_t)k;
    return m;
}

/* The corners of element e: a mesh triangle, or segment e of a closed polyline of n points. */
typedef struct shape {
    const double *xyz;
    const uint32_t *tri; /* NULL: polyline */
    size_t n;            /* points of the polyline */
    size_t elements;
} shape;

static int corners(const shape *sh, size_t e, const double *out[3])
{
    if (!sh->tri) {
        out[0] = sh->xyz + 3 * e;
        out[1] = sh->xyz + 3 * ((e + 1) % sh->n);
        return 2;
    }
    for (int k = 0; k < 3; k++)
        out[k] = oracle_vertex(sh->xyz, sh->tri, e, k);
    return 3;
}

static ld element_distance(const shape *sh, size_t e, const double *p)
{
    return sh->tri ? oracle_mesh_element(sh->xyz, sh->tri, e, p)
                   : oracle_polyline_element(sh->xyz, sh->n, e, p);
}

/* Every node's box equals the union of the corners of the elements below it (recomputed here
 * from the input, bottom-up over the tree), its box record keeps its children, and, for
 * meshes, every vertex below a node lies within ε of its triangle (the oracle's distance,
 * long double). */
static void check_nodes(const fl_sweep *s, const shape *sh)
{
    CHECK(s->box != NULL);
    if (!s->box) return;
    double *box = malloc(6 * s->node_count * sizeof *box);
    uint32_t *order = malloc(s->node_count * sizeof *order), *stack = malloc(
                                                                   s->node_count * sizeof *stack);
    size_t n = 0, top = 0, bad_box = 0, bad_eps = 0;
    stack[top++] = 0;
    while (top > 0) { /* preorder; reversed it is a valid bottom-up order */
        uint32_t id = stack[--top];
        order[n++] = id;
        if (!fl_sweep_is_leaf(s->nodes + id)) {
            stack[top++] = s->nodes[id].child[0];
            stack[top++] = s->nodes[id].child[1];
        }
    }
    CHECK(n == s->node_count);
    for (size_t i = n; i-- > 0;) {
        const fl_sweep_node *node = s->nodes + order[i];
        double *b = box + 6 * (size_t)order[i];
        for (int c = 0; c < 3; c++)
            b[c] = INFINITY, b[3 + c] = -INFINITY;
        if (fl_sweep_is_leaf(node)) {
            const double *p[3];
            int k = corners(sh, node->element, p);
            for (int j = 0; j < k; j++)
                for (int c = 0; c < 3; c++)
                    b[c] = fmin(b[c], p[j][c]), b[3 + c] = fmax(b[3 + c], p[j][c]);
        } else {
            for (int j = 0; j < 2; j++)
                for (int c = 0; c < 3; c++) {
                    const double *cb = box + 6 * (size_t)node->child[j];
                    b[c] = fmin(b[c], cb[c]), b[3 + c] = fmax(b[3 + c], cb[3 + c]);
                }
        }
        const fl_sweep_box *kept = s->box + order[i];
        bad_box += memcmp(b, kept->b, 6 * sizeof *b) != 0;
        /* The record's children are the node's (the depth-first search reads them there). */
        bad_box += kept->child[0] != node->child[0] ||
                   (!fl_sweep_is_leaf(node) && kept->child[1] != node->child[1]);
    }
    for (size_t i = 0; sh->tri && i < n; i++) { /* ε contains every vertex below (§4.1) */
        const fl_sweep_node *node = s->nodes + i;
        top = 0;
        stack[top++] = (uint32_t)i;
        while (top > 0) {
            const fl_sweep_node *d = s->nodes + stack[--top];
            if (!fl_sweep_is_leaf(d)) {
                stack[top++] = d->child[0];
                stack[top++] = d->child[1];
                continue;
            }
            const double *p[3];
            corners(sh, d->element, p);
            for (int k = 0; k < 3; k++)
                bad_eps += oracle_triangle(p[k], node->v, node->v + 3, node->v + 6) > node->eps;
        }
    }
    CHECK_MSG(bad_box == 0, "%zu node boxes differ from their corners' union or children",
              bad_box);
    CHECK_MSG(bad_eps == 0, "%zu vertices outside their node's volume", bad_eps);
    free(box);
    free(order);
    free(stack);
}

/* One cursor answers a stream that walks in small steps, jumps far away, walks back and
 * repeats points, so the back list fills and drains and the first upper bound is sometimes
 * far off. Exact answers must equal brute force; tolerance answers must bracket it. */
static void check_stream(const fl_sweep *s, const shape *sh, double scale, int steps)
{
    fl_sweep_cursor *cur;
    fl_error err;
    CHECK_STATUS(fl_sweep_cursor_new(s, &cur, &err), FL_OK, &err);
    double q[3] = {uniform(0, scale), uniform(0, scale), uniform(0, scale)};
    int wrong = 0, loose = 0;
    for (int i = 0; i < steps; i++) {
        double step = i % 60 == 59 ? 3 * scale : i % 60 > 40 ? 0.05 * scale : 0.002 * scale;
        if (i % 60 == 59) /* jump far away; the next steps walk back in bigger strides */
            for (int c = 0; c < 3; c++)
                q[c] += uniform(-step, step);
        else if (i % 60 > 40)
            for (int c = 0; c < 3; c++)
                q[c] += 0.3 * (0.5 * scale - q[c]) + uniform(-step, step);
        else if (i % 11 != 3) /* every 11th query repeats the last point */
            for (int c = 0; c < 3; c++)
                q[c] += uniform(-step, step);
        double tol = i % 7 == 6 ? 0.01 * scale : 0;
        fl_closest r;
        CHECK_STATUS(fl_sweep_cursor_closest(cur, q, tol, &r, &err), FL_OK, &err);
        ld bf = INFINITY;
        for (size_t e = 0; e < sh->elements; e++) {
            ld d = element_distance(sh, e, q);
            if (d < bf) bf = d;
        }
        double slack = 1e-12 * (scale + fabs(q[0]) + fabs(q[1]) + fabs(q[2]));
        if (tol == 0) {
            wrong += !r.exact || fabs(r.distance - (double)bf) > slack ||
                     r.element >= sh->elements ||
                     fabs((double)element_distance(sh, r.element, q) - (double)bf) > slack;
        } else {
            loose += r.lower > (double)bf + slack || r.upper < (double)bf - slack ||
                     (!r.exact && r.upper - r.lower > tol + slack);
        }
    }
    CHECK_MSG(wrong == 0, "%d exact answers differ from brute force", wrong);
    CHECK_MSG(loose == 0, "%d tolerance intervals miss brute force or are too wide", loose);
    fl_sweep_cursor_free(cur);
}

static void check_mesh(fl_mesh *m, double scale, int steps)
{
    fl_sweep *s;
    fl_error err;
    CHECK_STATUS(fl_sweep_build(m, NULL, &s, &err), FL_OK, &err);
    shape sh = {m->xyz, m->tri, 0, m->triangle_count};
    check_nodes(s, &sh);
    check_stream(s, &sh, scale, steps);
    fl_sweep_free(s);
}

static void test_sweep_spiky_grid_boxes_volumes_and_streams_are_exact(void)
{
    fl_mesh m = spiky_grid(40); /* 3042 triangles: nodes up to 24x the sample */
    check_mesh(&m, 40, 400);
    fl_mesh_free(&m);
}

static void test_sweep_repeated_triangle_mesh_is_exact(void)
{
    fl_mesh m = degenerate_mesh(0);
    check_mesh(&m, 4, 180);
    fl_mesh_free(&m);
}

static void test_sweep_collinear_mesh_is_exact(void)
{
    fl_mesh m = degenerate_mesh(1);
    check_mesh(&m, 16, 180);
    fl_mesh_free(&m);
}

/* After fl_sweep_update_vertices the boxes are those of the moved corners. */
static void test_sweep_boxes_follow_vertex_updates(void)
{
    fl_mesh m = spiky_grid(20);
    fl_sweep *s;
    fl_error err;
    CHECK_STATUS(fl_sweep_build(&m, NULL, &s, &err), FL_OK, &err);
    for (size_t i = 0; i < 3 * m.vertex_count; i++)
        m.xyz[i] += 0.2 * sin(1.3 * (double)i) + (i % 3 == 2 ? 0.05 * m.xyz[i - 2] : 0);
    CHECK_STATUS(fl_sweep_update_vertices(s, m.xyz, &err), FL_OK, &err);
    shape sh = {m.xyz, m.tri, 0, m.triangle_count};
    check_nodes(s, &sh);
    check_stream(s, &sh, 20, 120);
    fl_sweep_free(s);
    fl_mesh_free(&m);
}

static void test_sweep_polyline_boxes_and_streams_are_exact(void)
{
    size_t n = 700;
    double *xyz = malloc(3 * n * sizeof *xyz);
    for (size_t i = 0; i < n; i++) {
        double a = 6.283185307179586 * (double)i / (double)n;
        xyz[3 * i] = 5 + 4 * cos(a) + 0.2 * sin(17 * a);
        xyz[3 * i + 1] = 5 + 3 * sin(a);
        xyz[3 * i + 2] = 5 + sin(3 * a) + (i % 50 == 7 ? 2 : 0);
    }
    fl_sweep *s;
    fl_error err;
    CHECK_STATUS(fl_sweep_polyline_build(xyz, n, 3, 1, NULL, &s, &err), FL_OK, &err);
    shape sh = {xyz, NULL, n, n};
    check_nodes(s, &sh);
    check_stream(s, &sh, 10, 300);
    fl_sweep_free(s);
    free(xyz);
}

FL_TEST_MAIN(FL_TEST_CASE(test_sweep_spiky_grid_boxes_volumes_and_streams_are_exact),
             FL_TEST_CASE(test_sweep_repeated_triangle_mesh_is_exact),
             FL_TEST_CASE(test_sweep_collinear_mesh_is_exact),
             FL_TEST_CASE(test_sweep_boxes_follow_vertex_updates),
             FL_TEST_CASE(test_sweep_polyline_boxes_and_streams_are_exact))
