/* Hierarchical polyhedron-polyhedron intersection (thesis §7.4, HAL paper §5.2); point
 * inclusion is in hal3_contains.c.
 *
 * Intersection descends both trees at once, pruning pairs of flintstones that are provably
 * disjoint by the three ∩/∪ cases of §7.4, and tests pairs of original triangles exactly. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "hal/hal3_internal.h"
#include "mesh/intersect.h"

static const double *vx(const fl_mesh *m, uint32_t v)
{
    return m->xyz + 3 * (size_t)v;
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
    /* Early exit: disjoint bounding boxes (exact comparisons of the stored extremes; every
     * triangle lies in its mesh's box) share no point, and this answers far-apart meshes in
     * O(1) instead of descending until the root flintstones separate. */
    for (int k = 0; k < 3; k++)
        if (a->box[3 + k] < b->box[k] || b->box[3 + k] < a->box[k]) return FL_OK;
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
