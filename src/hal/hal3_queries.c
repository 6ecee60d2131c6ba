/* Hierarchical point-in-polyhedron and polyhedron-polyhedron intersection (thesis §7.4, HAL
 * paper §5).
 *
 * Point inclusion is the parity of the crossings of the ray from X in +x direction with the
 * triangles. The ray is symbolically perturbed: X is moved by (0, e, e^2) in (y, z) for an
 * infinitesimal e, so it meets no edge or vertex in the yz-projection and the parity is the
 * winding number's for every X off the surface; a triangle is crossed when the perturbed X lies
 * inside its yz-projection (fl_orient2d, ties broken by the perturbation's first non-zero
 * term) and in front of its plane (fl_orient3d). X on a triangle is decided exactly first. The
 * flintstones only prune: a subtree is skipped when the ray provably misses its flintstone
 * (floating test with the enlarged radii; the perturbation is infinitesimal), which contains
 * all its triangles, so the answer equals the brute-force test's. (The §5.1 replacement of a
 * part by its triangle would need the crack between a side path and its segment filled; the
 * ray pruning needs nothing but containment.)
 *
 * Intersection descends both trees at once, pruning pairs of flintstones that are provably
 * disjoint by the three ∩/∪ cases of §7.4, and tests pairs of original triangles exactly. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "hal/hal3_internal.h"
#include "mesh/intersect.h"

/* ---- point inclusion ---- */

static const double *vx(const fl_mesh *m, uint32_t v)
{
    return m->xyz + 3 * (size_t)v;
}

/* Squared distance from c to the ray x + t e_x, t >= 0. */
static double ray_d2(const double *ball, const double *x)
{
    double dy = ball[1] - x[1], dz = ball[2] - x[2], dx = ball[0] - x[0];
    return dx >= 0 ? dy * dy + dz * dz : dx * dx + dy * dy + dz * dz;
}

static int ray_misses_ball(const double *ball, const double *x)
{
    return ray_d2(ball, x) > ball[3] * (1 + FL_HAL3_REL) + FL_HAL3_ABS;
}

static int ray_misses(const fl_hal3_node *nd, const double *x)
{
    if (nd->face_count == 0) return 1;
    int m0 = ray_misses_ball(nd->ball[0], x);
    if (nd->kind == FL_HAL3_TWO_BALLS) return m0 || ray_misses_ball(nd->ball[1], x);
    if (nd->kind == FL_HAL3_BALL_UNION) return m0 && ray_misses_ball(nd->ball[1], x);
    return m0;
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

/* Sign of orient2d(a, b, x + (e, e^2)) in the yz-plane. */
static int perturbed_orient(const double *a, const double *b, const double *x)
{
    int o = fl_orient2d(a, b, x);
    if (o) return o;
    if (a[1] != b[1]) return a[1] > b[1] ? 1 : -1;
    return b[0] > a[0] ? 1 : b[0] < a[0] ? -1 : 0;
}

/* 1 when the perturbed ray from x (x not on the triangle) crosses triangle abc. */
static int ray_crosses(const double *a, const double *b, const double *c, const double *x)
{
    double A[2] = {a[1], a[2]}, B[2] = {b[1], b[2]}, C[2] = {c[1], c[2]}, X[2] = {x[1], x[2]};
    int s = fl_orient2d(A, B, C);
    if (s == 0) return 0;
    if (perturbed_orient(A, B, X) != s || perturbed_orient(B, C, X) != s ||
        perturbed_orient(C, A, X) != s)
        return 0;
    return fl_orient3d(a, b, c, x) * s > 0;
}

/* 2 on the surface, else the crossing parity. */
static int point_parity(const fl_hal3 *hal, const double *x, uint32_t *stack)
{
    const fl_mesh *m = &hal->mesh;
    size_t top = 0;
    int parity = 0;
    stack[top++] = 0;
    if (hal->node_count > 1) stack[top++] = 1;
    while (top > 0) {
        const fl_hal3_node *nd = &hal->nodes[stack[--top]];
        if (ray_misses(nd, x)) continue;
        if (nd->kind == FL_HAL3_LEAF) {
            const uint32_t *t = m->tri + 3 * (size_t)nd->face;
            const double *a = vx(m, t[0]), *b = vx(m, t[1]), *c = vx(m, t[2]);
            if (on_triangle(a, b, c, x)) return 2;
            parity ^= ray_crosses(a, b, c, x);
            continue;
        }
        for (uint32_t i = 0; i < nd->child_count; i++)
            stack[top++] = nd->child_first + i;
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
    /* Depth-first: at most (children - 1) pending nodes a level, children <= 4. */
    uint32_t *stack = fl_alloc_array(4 * (size_t)hal->depth + 16, sizeof(uint32_t));
    if (!stack) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3_contains: out of memory");
    fl_status st = FL_OK;
    for (size_t k = 0; k < n; k++) {
        const double *x = xyz + 3 * k;
        if (!isfinite(x[0]) || !isfinite(x[1]) || !isfinite(x[2])) {
            st = fl_fail(err, FL_ERR_INPUT, NULL, -1, "hal3_contains: query %zu is not finite", k);
            break;
        }
        int p = point_parity(hal, x, stack);
        where[k] = p == 2 ? FL_HAL3_BOUNDARY : p ? FL_HAL3_INSIDE : FL_HAL3_OUTSIDE;
    }
    free(stack);
    return st;
}

/* ---- intersection ---- */

static int balls_disjoint(const double *a, const double *b)
{
    double d = sqrt(fl_hal3_d2(a, b));
    return d > (sqrt(a[3]) + sqrt(b[3])) * (1 + 1e-9) + 1e-300;
}

static int n_balls(const fl_hal3_node *nd)
{
    return nd->kind == FL_HAL3_TWO_BALLS || nd->kind == FL_HAL3_BALL_UNION ? 2 : 1;
}

/* The three cases of §7.4: F ∩ G = ∅ is proven when (∩,∩) some pair of balls is disjoint;
 * (∩,∪) for every ball of the union some ball of the intersection misses it; (∪,∪) every pair
 * is disjoint. A half-space is dropped (a superset). */
static int flintstones_disjoint(const fl_hal3_node *f, const fl_hal3_node *g)
{
    if (f->face_count == 0 || g->face_count == 0) return 1;
    int uf = f->kind == FL_HAL3_BALL_UNION, ug = g->kind == FL_HAL3_BALL_UNION;
    if (uf && !ug) {
        const fl_hal3_node *t = f;
        f = g, g = t, uf = 0, ug = 1;
    }
    int nf = n_balls(f), ng = n_balls(g);
    if (!uf && !ug) {
        for (int i = 0; i < nf; i++)
            for (int j = 0; j < ng; j++)
                if (balls_disjoint(f->ball[i], g->ball[j])) return 1;
        return 0;
    }
    for (int j = 0; j < ng; j++) {
        int miss = 0;
        for (int i = 0; i < nf; i++)
            miss |= balls_disjoint(f->ball[i], g->ball[j]);
        if (!miss) return 0;
    }
    return 1;
}

static int cmp_pair(const void *x, const void *y)
{
    const uint32_t *a = x, *b = y;
    if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
    return a[1] < b[1] ? -1 : a[1] > b[1];
}

void fl_hal3_pairs_free(fl_hal3_pairs *pairs)
{
    if (!pairs) return;
    free(pairs->pairs);
    memset(pairs, 0, sizeof *pairs);
}

static int leaf_pair(const fl_hal3 *a, const fl_hal3 *b, const fl_hal3_node *x,
                     const fl_hal3_node *y)
{
    const uint32_t *s = a->mesh.tri + 3 * (size_t)x->face, *t = b->mesh.tri + 3 * (size_t)y->face;
    return fl_triangles_intersect(vx(&a->mesh, s[0]), vx(&a->mesh, s[1]), vx(&a->mesh, s[2]),
                                  vx(&b->mesh, t[0]), vx(&b->mesh, t[1]), vx(&b->mesh, t[2]));
}

static double max_r2(const fl_hal3_node *nd)
{
    return n_balls(nd) == 2 ? fmax(nd->ball[0][3], nd->ball[1][3]) : nd->ball[0][3];
}

fl_status fl_hal3_intersect(const fl_hal3 *a, const fl_hal3 *b, int first_only, fl_hal3_pairs *out,
                            fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal3_intersect: NULL argument");
    memset(out, 0, sizeof *out);
    if (!a || !b || !a->node_count || !b->node_count)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal3_intersect: NULL or empty tree");
    fl_vec stack, res;
    fl_vec_init(&stack, 2 * sizeof(uint32_t));
    fl_vec_init(&res, 2 * sizeof(uint32_t));
    fl_status st = FL_OK;
    for (uint32_t i = 0; i < 2 && i < a->node_count; i++)
        for (uint32_t j = 0; j < 2 && j < b->node_count; j++) {
            uint32_t p[2] = {i, j};
            if (fl_vec_push(&stack, p, 1)) st = FL_ERR_NOMEM;
        }
    while (st == FL_OK && stack.count > 0) {
        uint32_t *p = (uint32_t *)stack.data + 2 * --stack.count;
        uint32_t ia = p[0], ib = p[1];
        const fl_hal3_node *x = &a->nodes[ia], *y = &b->nodes[ib];
        if (flintstones_disjoint(x, y)) continue;
        int lx = x->kind == FL_HAL3_LEAF, ly = y->kind == FL_HAL3_LEAF;
        if (lx && ly) {
            if (!leaf_pair(a, b, x, y)) continue;
            uint32_t q[2] = {x->face, y->face};
            if (fl_vec_push(&res, q, 1)) st = FL_ERR_NOMEM;
            if (first_only) break;
            continue;
        }
        int down_a = !lx && (ly || max_r2(x) >= max_r2(y));
        const fl_hal3_node *d = down_a ? x : y;
        for (uint32_t c = 0; c < d->child_count && st == FL_OK; c++) {
            uint32_t q[2] = {down_a ? d->child_first + c : ia, down_a ? ib : d->child_first + c};
            if (fl_vec_push(&stack, q, 1)) st = FL_ERR_NOMEM;
        }
    }
    fl_vec_free(&stack);
    if (st != FL_OK) {
        fl_vec_free(&res);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3_intersect: out of memory");
    }
    if (res.count > 1) qsort(res.data, res.count, 2 * sizeof(uint32_t), cmp_pair);
    out->count = res.count;
    out->pairs = res.data;
    return FL_OK;
}
