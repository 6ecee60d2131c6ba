/* Hierarchical point-in-polyhedron on the flintstone tree (thesis §7.4, HAL paper §5.1).
 *
 * Point inclusion is the parity of the crossings of the ray from X in +x direction with the
 * triangles. The ray is symbolically perturbed: X is moved by (0, e, e^2) in (y, z) for an
 * infinitesimal e, so it meets no edge or vertex in the yz-projection and the parity is the
 * winding number's for every X off the surface; a triangle is crossed when the perturbed X lies
 * inside its yz-projection (fl_orient2d, ties broken by the perturbation's first non-zero term)
 * and behind its plane (fl_orient3d). X on a triangle is decided exactly.
 *
 * Pruning. The tree's parts (the nodes' pieces of surface) are compact patches, a good
 * hierarchy; but a ball is a poor bound for a ray: a part of diameter d whose flintstone has
 * radius r ~ d is entered by every ray through a disc of area ~ pi d^2, however flat the part,
 * and a ray through a long object meets many such balls (the first version, ray against the
 * flintstones, was 4-15x slower than CGAL's AABB tree). So each call first lays the tree out
 * for the ray (`ray_tree`): the non-empty nodes in depth-first order with a skip index (the end
 * of the subtree: a stackless walk), chains of single-child nodes collapsed, and for each node
 * the exact bounds of its triangles' coordinates that a +x ray can see: the y and z ranges and
 * the largest x. Min/max of doubles are exact, so "X_y outside [ylo, yhi], X_z outside
 * [zlo, zhi] or X_x > xhi" proves that the ray (and its infinitesimal perturbation, the tests
 * being closed) misses every triangle of the subtree. Leaves carry their triangle's
 * coordinates, so the walk reads one contiguous array. The answers are the brute-force test's;
 * the flintstones' role here is the hierarchy, not the bound. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "hal/hal3_internal.h"

typedef struct ray_entry {
    double ylo, yhi, zlo, zhi, xhi;
    uint32_t skip; /* first entry after this subtree */
    uint32_t leaf; /* index of the triangle in ray_tree.tri, or FL_HAL3_NONE */
} ray_entry;

typedef struct ray_tree {
    ray_entry *e;
    size_t n;
    double *tri; /* 9 doubles a leaf: a, b, c */
    size_t nleaf;
} ray_tree;

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
    e->ylo = fmin(p[1], fmin(p[4], p[7]));
    e->yhi = fmax(p[1], fmax(p[4], p[7]));
    e->zlo = fmin(p[2], fmin(p[5], p[8]));
    e->zhi = fmax(p[2], fmax(p[5], p[8]));
    e->xhi = fmax(p[0], fmax(p[3], p[6]));
    e->leaf = (uint32_t)t->nleaf++;
    e->skip = (uint32_t)++t->n;
}

/* Closes inner entry i: its subtree ends here; its bounds are its direct children's union. */
static void close_entry(ray_tree *t, uint32_t i)
{
    ray_entry *e = &t->e[i];
    e->skip = (uint32_t)t->n;
    e->ylo = e->zlo = INFINITY;
    e->yhi = e->zhi = e->xhi = -INFINITY;
    for (uint32_t j = i + 1; j < e->skip; j = t->e[j].skip) {
        const ray_entry *c = &t->e[j];
        e->ylo = fmin(e->ylo, c->ylo), e->yhi = fmax(e->yhi, c->yhi);
        e->zlo = fmin(e->zlo, c->zlo), e->zhi = fmax(e->zhi, c->zhi);
        e->xhi = fmax(e->xhi, c->xhi);
    }
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

/* The sign o = orient2d(a, b, x) in the yz-plane (a, b, x point at (y, z)) made non-zero by the
 * perturbation x + (e, e^2): the first non-zero coefficient of e, e^2. */
static int perturbed(int o, const double *a, const double *b)
{
    if (o) return o;
    if (a[1] != b[1]) return a[1] > b[1] ? 1 : -1;
    return b[0] > a[0] ? 1 : b[0] < a[0] ? -1 : 0;
}

/* One leaf whose bounds the ray enters: 2 when x is on the triangle, else 1 when the perturbed
 * ray crosses it, else 0. The unperturbed signs decide first: x strictly outside the closed
 * yz-projection is neither on the triangle nor crossing; inside the closed projection of a
 * triangle whose plane is not parallel to x, orient3d = 0 means on the triangle. */
static int leaf_test(const double *p, const double *x)
{
    const double *a = p, *b = p + 3, *c = p + 6;
    int s = fl_orient2d(a + 1, b + 1, c + 1);
    if (s == 0) return on_triangle(a, b, c, x) ? 2 : 0;
    int o1 = fl_orient2d(a + 1, b + 1, x + 1);
    if (o1 == -s) return 0;
    int o2 = fl_orient2d(b + 1, c + 1, x + 1);
    if (o2 == -s) return 0;
    int o3 = fl_orient2d(c + 1, a + 1, x + 1);
    if (o3 == -s) return 0;
    int o = fl_orient3d(a, b, c, x);
    if (o == 0) return 2;
    if (perturbed(o1, a + 1, b + 1) != s || perturbed(o2, b + 1, c + 1) != s ||
        perturbed(o3, c + 1, a + 1) != s)
        return 0;
    return o * s > 0;
}

/* 2 on the surface, else the crossing parity. */
static int point_parity(const ray_tree *t, const double *x)
{
    int parity = 0;
    const double px = x[0], py = x[1], pz = x[2];
    for (size_t i = 0; i < t->n;) {
        const ray_entry *e = &t->e[i];
        if (py < e->ylo || py > e->yhi || pz < e->zlo || pz > e->zhi || px > e->xhi) {
            i = e->skip;
            continue;
        }
        i++;
        if (e->leaf == FL_HAL3_NONE) continue;
        int r = leaf_test(t->tri + 9 * (size_t)e->leaf, x);
        if (r == 2) return 2;
        parity ^= r;
    }
    return parity;
}

fl_status fl_hal3_contains(const fl_hal3 *hal, const double *xyz, size_t n, uint8_t *where,
                           fl_error *err)
{
    if (!hal || (n > 0 && (!xyz || !where)))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal3_contains: NULL argument");
    if (hal->node_count == 0)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal3_contains: empty tree");
    for (size_t k = 0; k < 3 * n; k++)
        if (!isfinite(xyz[k]))
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "hal3_contains: query %zu is not finite",
                           k / 3);
    ray_tree t;
    if (ray_tree_build(hal, &t))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3_contains: out of memory");
    for (size_t k = 0; k < n; k++) {
        int p = point_parity(&t, xyz + 3 * k);
        where[k] = p == 2 ? FL_HAL3_BOUNDARY : p ? FL_HAL3_INSIDE : FL_HAL3_OUTSIDE;
    }
    ray_tree_free(&t);
    return FL_OK;
}
