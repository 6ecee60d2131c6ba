/* Hierarchical point-in-polyhedron on the flintstone tree (thesis §7.4, HAL paper §5.1).
 *
 * Point inclusion is the parity of the crossings of an axis-parallel ray from X with the
 * triangles: along axis k, towards the nearest face of the mesh's bounding box (a short ray
 * enters few subtrees; the answer does not depend on the choice). The ray is symbolically
 * perturbed: X is moved by (e, e^2) in the coordinates (k+1, k+2) for an infinitesimal e, so
 * it meets no edge or vertex in that projection and the parity is the winding number's for
 * every X off the surface; a triangle is crossed when the perturbed X lies inside its
 * projection (fl_orient2d, ties broken by the perturbation's first non-zero term) and its
 * plane is ahead of X (fl_orient3d). X on a triangle is decided exactly.
 *
 * Pruning. The tree's parts (the nodes' pieces of surface) are compact patches, a good
 * hierarchy; but a ball is a poor bound for a ray: a part of diameter d whose flintstone has
 * radius r ~ d is entered by every ray through a disc of area ~ pi d^2, however flat the part,
 * and a ray through a long object meets many such balls (the first version, a +x ray against
 * the flintstones, was 4-15x slower than CGAL's AABB tree). So each call first lays the tree
 * out for rays (`ray_tree`): the non-empty nodes in depth-first order with a skip index (the
 * end of the subtree: a stackless walk over one array), chains of single-child nodes collapsed,
 * and for each node the bounds of its triangles' coordinates, rounded outwards to float (32
 * bytes an entry). A subtree is skipped only when a float comparison proves X outside its
 * range in the two other axes or its range behind X, so the ray (and its infinitesimal
 * perturbation, the tests being closed) misses every triangle of it. Leaves carry their
 * triangle's coordinates. The answers are the brute-force test's; the tree's role here is the
 * hierarchy, the flintstones' balls are not used. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "hal/hal3_internal.h"

typedef struct ray_entry {
    float b[6]; /* lo[3] and -hi[3] of the subtree's vertices, rounded outwards: a subtree is
                   missed when some b[c] > w[c] (point_parity), one test form for all six */
    uint32_t skip;      /* first entry after this subtree */
    uint32_t leaf;      /* index of the triangle in ray_tree.tri, or FL_HAL3_NONE */
} ray_entry;

typedef struct ray_tree {
    ray_entry *e;
    size_t n;
    double *tri; /* 9 doubles a leaf: a, b, c */
    size_t nleaf;
    double lo[3], hi[3]; /* bounding box of the mesh */
} ray_tree;

/* float bounds that hold the double v: comparisons of a double with a float are exact. */
static float down(double v)
{
    float f = (float)v;
    return (double)f > v ? nextafterf(f, -INFINITY) : f;
}

static float up(double v)
{
    float f = (float)v;
    return (double)f < v ? nextafterf(f, INFINITY) : f;
}

static void ray_tree_free(ray_tree *t)
{
    free(t->e);
    free(t->tri);
}

/* The one non-empty child of nd when it has exactly one, else FL_HAL3_NONE. */
static uint32_t only_child(const fl_hal3 *hal, const fl_hal3_node *nd)
{
    uint32_t only = FL_HAL3_NONE;
    for (uint32_t c = 0; c < nd->child_count; c++) {
        if (hal->nodes[nd->child_first + c].face_count == 0) continue;
        if (only != FL_HAL3_NONE) return FL_HAL3_NONE;
        only = nd->child_first + c;
    }
    return only;
}

static void leaf_entry(const fl_hal3 *hal, const fl_hal3_node *nd, ray_tree *t)
{
    ray_entry *e = &t->e[t->n];
    double *p = t->tri + 9 * t->nleaf;
    const uint32_t *v = hal->mesh.tri + 3 * (size_t)nd->face;
    for (int k = 0; k < 3; k++) memcpy(p + 3 * k, hal->mesh.xyz + 3 * (size_t)v[k], 24);
    for (int k = 0; k < 3; k++) {
        e->b[k] = down(fmin(p[k], fmin(p[k + 3], p[k + 6])));
        e->b[k + 3] = -up(fmax(p[k], fmax(p[k + 3], p[k + 6])));
    }
    e->leaf = (uint32_t)t->nleaf++;
    e->skip = (uint32_t)++t->n;
}

/* Closes inner entry i: its subtree ends here; its bounds are its direct children's union. */
static void close_entry(ray_tree *t, uint32_t i)
{
    ray_entry *e = &t->e[i];
    e->skip = (uint32_t)t->n;
    for (int c = 0; c < 6; c++) e->b[c] = INFINITY;
    for (uint32_t j = i + 1; j < e->skip; j = t->e[j].skip)
        for (int c = 0; c < 6; c++) e->b[c] = fminf(e->b[c], t->e[j].b[c]);
}

/* Lays out the non-empty part of the tree depth-first (explicit stack: the depth is not
 * bounded by a small constant). Stack items: a node to enter, or (with the top bit) an entry
 * to close after its children. Each entered node pushes at most 1 + 4 items. */
static fl_status ray_tree_build(const fl_hal3 *hal, ray_tree *t)
{
    memset(t, 0, sizeof *t);
    size_t leaves = 0;
    for (size_t i = 0; i < hal->node_count; i++) leaves += hal->nodes[i].kind == FL_HAL3_LEAF;
    t->e = fl_alloc_array(2 * leaves + 1, sizeof *t->e);
    t->tri = fl_alloc_array(9 * leaves + 1, sizeof(double));
    fl_vec stack;
    fl_vec_init(&stack, sizeof(uint32_t));
    int bad = !t->e || !t->tri;
    const uint32_t CLOSE = 0x80000000u;
    for (uint32_t r = (uint32_t)(hal->node_count > 1 ? 2 : 1); r-- > 0 && !bad;)
        if (hal->nodes[r].face_count) bad |= fl_vec_push(&stack, &r, 1);
    while (!bad && stack.count > 0) {
        uint32_t item = ((uint32_t *)stack.data)[--stack.count];
        if (item & CLOSE) {
            close_entry(t, item & ~CLOSE);
            continue;
        }
        const fl_hal3_node *nd = &hal->nodes[item];
        for (uint32_t c; nd->kind != FL_HAL3_LEAF && (c = only_child(hal, nd)) != FL_HAL3_NONE;)
            nd = &hal->nodes[c];
        if (nd->kind == FL_HAL3_LEAF) {
            leaf_entry(hal, nd, t);
            continue;
        }
        t->e[t->n].leaf = FL_HAL3_NONE;
        uint32_t mark = (uint32_t)t->n++ | CLOSE;
        bad |= fl_vec_push(&stack, &mark, 1);
        for (uint32_t c = nd->child_count; c-- > 0 && !bad;) {
            uint32_t ch = nd->child_first + c;
            if (hal->nodes[ch].face_count) bad |= fl_vec_push(&stack, &ch, 1);
        }
    }
    fl_vec_free(&stack);
    for (int k = 0; k < 3; k++) t->lo[k] = INFINITY, t->hi[k] = -INFINITY;
    for (size_t v = 0; v < 9 * t->nleaf && !bad; v++) {
        t->lo[v % 3] = fmin(t->lo[v % 3], t->tri[v]);
        t->hi[v % 3] = fmax(t->hi[v % 3], t->tri[v]);
    }
    if (bad || t->n >= CLOSE) {
        ray_tree_free(t);
        return FL_ERR_NOMEM;
    }
    return FL_OK;
}

/* 1 iff x lies on the closed, non-degenerate triangle abc. */
static int on_triangle(const double *a, const double *b, const double *c, const double *x)
{
    if (fl_orient3d(a, b, c, x) != 0) return 0;
    for (int ax = 0; ax < 3; ax++) {
        int i = (ax + 1) % 3, j = (ax + 2) % 3;
        double A[2] = {a[i], a[j]}, B[2] = {b[i], b[j]}, C[2] = {c[i], c[j]}, X[2] = {x[i], x[j]};
        int s = fl_orient2d(A, B, C);
        if (s == 0) continue;
        return fl_orient2d(A, B, X) * s >= 0 && fl_orient2d(B, C, X) * s >= 0 &&
               fl_orient2d(C, A, X) * s >= 0;
    }
    return 0;
}

/* The sign o = orient2d(a, b, x) of 2D points made non-zero by the perturbation
 * x + (e, e^2): the first non-zero coefficient of e (a1 - b1), then of e^2 (b0 - a0). */
static int perturbed(int o, const double *a, const double *b)
{
    if (o) return o;
    if (a[1] != b[1]) return a[1] > b[1] ? 1 : -1;
    return b[0] > a[0] ? 1 : b[0] < a[0] ? -1 : 0;
}

/* One leaf whose bounds the ray from x along axis k (dir = +1 or -1) enters: 2 when x is on
 * the triangle, else 1 when the perturbed ray crosses it, else 0. The projection is onto the
 * axes (k+1, k+2) (a cyclic permutation, so fl_orient3d's sign is that of the permuted
 * coordinates). The unperturbed signs decide first: x strictly outside the closed projection is
 * neither on the triangle nor crossing; inside the closed projection of a triangle whose plane
 * is not parallel to the ray, orient3d = 0 means on the triangle. */
static int leaf_test(const double *p, const double *x, int k, int dir)
{
    const double *a = p, *b = p + 3, *c = p + 6;
    int i = (k + 1) % 3, j = (k + 2) % 3;
    double A[2] = {a[i], a[j]}, B[2] = {b[i], b[j]}, C[2] = {c[i], c[j]}, X[2] = {x[i], x[j]};
    int s = fl_orient2d(A, B, C);
    if (s == 0) return on_triangle(a, b, c, x) ? 2 : 0;
    int o1 = fl_orient2d(A, B, X);
    if (o1 == -s) return 0;
    int o2 = fl_orient2d(B, C, X);
    if (o2 == -s) return 0;
    int o3 = fl_orient2d(C, A, X);
    if (o3 == -s) return 0;
    int o = fl_orient3d(a, b, c, x);
    if (o == 0) return 2;
    if (perturbed(o1, A, B) != s || perturbed(o2, B, C) != s || perturbed(o3, C, A) != s)
        return 0;
    return o * s * dir > 0;
}

/* 2 on the surface, else the crossing parity of the ray from x along axis k, direction dir.
 * An entry is skipped when x is outside its range in the two other axes or its whole range
 * lies behind x: six float comparisons against u (x rounded up; +inf where no lower bound is
 * tested) and d (x rounded down; -inf where no upper bound is tested), so "lo > u" proves
 * x < lo and "hi < d" proves x > hi. One branch, not six: the outcome is data-dependent and
 * poorly predicted. */
static int point_parity(const ray_tree *t, const double *x, int k, int dir)
{
    float w[6]; /* u, then -d */
    for (int c = 0; c < 3; c++) w[c] = up(x[c]), w[c + 3] = -down(x[c]);
    w[dir > 0 ? k : k + 3] = INFINITY;
    int parity = 0;
    for (size_t n = 0; n < t->n;) {
        const ray_entry *e = &t->e[n];
        int miss = 0;
        for (int c = 0; c < 6; c++) miss |= e->b[c] > w[c];
        if (miss) {
            n = e->skip;
            continue;
        }
        n++;
        if (e->leaf == FL_HAL3_NONE) continue;
        int r = leaf_test(t->tri + 9 * (size_t)e->leaf, x, k, dir);
        if (r == 2) return 2;
        parity ^= r;
    }
    return parity;
}

/* Ray direction: towards the nearest face of the mesh's bounding box (the shortest ray meets
 * the fewest subtrees; CGAL's Side_of_triangle_mesh picks the nearer of +-z the same way). */
static int pick_axis(const ray_tree *t, const double *x, int *dir)
{
    int best = 0;
    double d = INFINITY;
    for (int k = 0; k < 3; k++) {
        if (t->hi[k] - x[k] < d) d = t->hi[k] - x[k], best = k, *dir = 1;
        if (x[k] - t->lo[k] < d) d = x[k] - t->lo[k], best = k, *dir = -1;
    }
    return best;
}

fl_status fl_hal3_contains(const fl_hal3 *hal, const double *xyz, size_t n, uint8_t *where,
                           fl_error *err)
{
    if (!hal || (n > 0 && (!xyz || !where)))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal3_contains: NULL argument");
    if (hal->node_count == 0)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal3_contains: empty tree");
    ray_tree t;
    if (ray_tree_build(hal, &t))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3_contains: out of memory");
    for (size_t k = 0; k < n; k++) {
        const double *x = xyz + 3 * k;
        if (!isfinite(x[0]) || !isfinite(x[1]) || !isfinite(x[2])) {
            ray_tree_free(&t); /* the answers before it stay written */
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "hal3_contains: query %zu is not finite",
                           k);
        }
        int out = 0, dir = 1;
        for (int c = 0; c < 3; c++) out |= x[c] < t.lo[c] || x[c] > t.hi[c];
        int axis = pick_axis(&t, x, &dir); /* sets dir: not in the same call's arguments */
        int p = out ? 0 : point_parity(&t, x, axis, dir);
        where[k] = p == 2 ? FL_HAL3_BOUNDARY : p ? FL_HAL3_INSIDE : FL_HAL3_OUTSIDE;
    }
    ray_tree_free(&t);
    return FL_OK;
}
