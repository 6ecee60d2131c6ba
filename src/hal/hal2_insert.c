/* Dynamic insertion of a vertex into a flintstone tree (thesis §7.5): the new vertex is
 * located down the path of polylines that contain its edge; every flintstone on the path that
 * still holds it (decided exactly against the circles through v_p, v_s and the extreme vertices
 * v_q, v_r of Def. 7.3) stays as it is, with its floating discs grown to hold the vertex, and the
 * subtree under the first flintstone that does not hold it is rebuilt. A flintstone that holds
 * the vertex keeps its split vertex (still extreme on its side), widths and certificate. If the
 * ring's smallest enclosing disc gets another farthest pair, the ring's tree is rebuilt. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "hal/hal2_internal.h"

static int in_circle(const double *a, const double *b, const double *c, const double *x)
{
    return fl_incircle(a, b, c, x) * fl_orient2d(a, b, c) >= 0;
}

/* 1 when the flintstone of nd still holds x with its shape and split vertex unchanged. */
static int admits(const double *xy, const fl_hal2_node *nd, const double *x)
{
    const double *a = xy + 2 * (size_t)nd->p, *b = xy + 2 * (size_t)nd->s;
    const double *q = xy + 2 * (size_t)nd->q, *r = xy + 2 * (size_t)nd->r;
    int o = fl_orient2d(a, b, x);
    switch (nd->kind) {
    case FL_HAL2_TWO_DISCS:
        return in_circle(a, b, q, x) && in_circle(a, b, r, x);
    case FL_HAL2_DISC_HALFPLANE:
        return o * nd->side >= 0 && in_circle(a, b, q, x);
    case FL_HAL2_SEGMENT:
        return o == 0 && fmin(a[0], b[0]) <= x[0] && x[0] <= fmax(a[0], b[0]) &&
               fmin(a[1], b[1]) <= x[1] && x[1] <= fmax(a[1], b[1]);
    default:
        return 0;
    }
}

typedef struct located {
    int32_t stop_parent; /* node owning the slot to (re)build, -1 for the ring */
    int stop_child;      /* which child slot */
    int32_t stop_node;   /* node to rebuild, -1 when the slot is a single edge */
    uint32_t path_len;   /* admissible nodes on the path, stored in path[] */
} located;

/* Walks from ring rg's root towards edge after -> after + 1 (old numbering). */
static located locate(const fl_hal2 *hal, const fl_hal2_ring *rg, uint32_t after, const double *x,
                      int32_t *path)
{
    located lc = {-1, 0, -1, 0};
    uint32_t n = rg->count, off = (after - rg->root[0] + n) % n;
    lc.stop_child = off < (rg->root[1] - rg->root[0] + n) % n ? 0 : 1;
    int32_t cur = rg->child[lc.stop_child];
    while (cur >= 0) {
        const fl_hal2_node *nd = &hal->nodes[cur];
        if (!admits(hal->polygon.xy, nd, x)) {
            lc.stop_node = cur;
            return lc;
        }
        path[lc.path_len++] = cur;
        lc.stop_parent = cur;
        lc.stop_child = (after - nd->p + n) % n < (nd->q - nd->p + n) % n ? 0 : 1;
        cur = nd->child[lc.stop_child];
    }
    return lc;
}

static uint32_t shifted(uint32_t v, uint32_t ins)
{
    return v >= ins ? v + 1 : v;
}

/* Makes room for the vertex at index ins of ring `ring` and renumbers every stored index. */
static void insert_vertex(fl_hal2 *hal, uint32_t ring, uint32_t ins, const double *x)
{
    fl_polygon *pg = &hal->polygon;
    memmove(pg->xy + 2 * (size_t)ins + 2, pg->xy + 2 * (size_t)ins,
            2 * (pg->vertex_count - ins) * sizeof(double));
    pg->xy[2 * (size_t)ins] = x[0];
    pg->xy[2 * (size_t)ins + 1] = x[1];
    pg->vertex_count++;
    for (size_t r = ring + 1; r <= pg->ring_count; r++)
        pg->ring_start[r]++;
    for (size_t r = 0; r < pg->ring_count; r++) {
        fl_hal2_ring *rg = &hal->rings[r];
        if (r > ring) rg->first++;
        rg->root[0] = shifted(rg->root[0], ins);
        rg->root[1] = shifted(rg->root[1], ins);
    }
    hal->rings[ring].count++;
    for (size_t k = 0; k < hal->node_count; k++) {
        fl_hal2_node *nd = &hal->nodes[k];
        nd->p = shifted(nd->p, ins);
        nd->q = shifted(nd->q, ins);
        nd->s = shifted(nd->s, ins);
        nd->r = shifted(nd->r, ins);
    }
}

/* Drops unreachable nodes, renumbering the rest in preorder; recomputes depths. */
static void compact(fl_hal2 *hal, fl_hal2_node *spare, int32_t *stack)
{
    size_t m = 0;
    hal->depth = 0;
    for (size_t r = 0; r < hal->polygon.ring_count; r++) {
        fl_hal2_ring *rg = &hal->rings[r];
        size_t top = 0;
        rg->depth = 0;
        for (int c = 1; c >= 0; c--)
            if (rg->child[c] >= 0) {
                spare[m] = hal->nodes[rg->child[c]];
                rg->child[c] = (int32_t)m;
                stack[top++] = (int32_t)m++;
            }
        while (top > 0) {
            fl_hal2_node *nd = &spare[stack[--top]];
            if (nd->level > rg->depth) rg->depth = nd->level;
            for (int c = 1; c >= 0; c--)
                if (nd->child[c] >= 0) {
                    spare[m] = hal->nodes[nd->child[c]];
                    nd->child[c] = (int32_t)m;
                    stack[top++] = (int32_t)m++;
                }
        }
        if (rg->depth > hal->depth) hal->depth = rg->depth;
    }
    memcpy(hal->nodes, spare, m * sizeof *spare);
    hal->node_count = m;
}

static fl_status check_insert(const fl_hal2 *hal, uint32_t after, const double *x, fl_error *err)
{
    if (!hal || !x) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal2_insert: NULL argument");
    if (after >= hal->polygon.vertex_count)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal2_insert: vertex %u does not exist", after);
    if (!isfinite(x[0]) || !isfinite(x[1]))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "hal2_insert: the vertex is not finite");
    if (hal->polygon.vertex_count >= 0x7FFFFFFF)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "hal2_insert: more than 2^31 vertices");
    return FL_OK;
}

/* Rebuilds what the insertion invalidated: the whole ring when its root pair changed, else the
 * subtree at the located slot (a single edge there becomes a two-edge polyline). */
static void repair(fl_hal2 *hal, uint32_t ring, const located *lc, uint32_t *order,
                   hal2_pending *stack)
{
    fl_hal2_ring *rg = &hal->rings[ring];
    uint32_t old_root[2] = {rg->root[0], rg->root[1]};
    for (uint32_t k = 0; k < rg->count; k++)
        order[k] = rg->first + k;
    uint32_t i, j;
    fl_hal2_sbd(hal->polygon.xy, order, rg->count, &i, &j, rg->disc);
    if (!((i == old_root[0] && j == old_root[1]) || (i == old_root[1] && j == old_root[0]))) {
        fl_hal2_build_ring(hal, ring, order, stack);
        return;
    }
    uint32_t level = 1, p, s;
    int32_t *slot;
    if (lc->stop_parent < 0) {
        slot = &rg->child[lc->stop_child];
        p = lc->stop_child ? rg->root[1] : rg->root[0];
        s = lc->stop_child ? rg->root[0] : rg->root[1];
    } else {
        fl_hal2_node *nd = &hal->nodes[lc->stop_parent];
        slot = &nd->child[lc->stop_child];
        p = lc->stop_child ? nd->q : nd->p;
        s = lc->stop_child ? nd->s : nd->q;
        level = nd->level + 1;
    }
    uint32_t lp = p - rg->first, ls = s - rg->first;
    if (ls <= lp) ls += rg->count;
    fl_hal2_rebuild_node(hal, ring, slot, lp, ls, level, stack);
}

fl_status fl_hal2_insert(fl_hal2 *hal, uint32_t after, const double *xy, fl_error *err)
{
    fl_status st = check_insert(hal, after, xy, err);
    if (st != FL_OK) return st;
    fl_polygon *pg = &hal->polygon;
    uint32_t ring = 0;
    while (pg->ring_start[ring + 1] <= after)
        ring++;
    size_t n = hal->rings[ring].count + 1, cap = hal->node_count + n + 1;
    double *nxy = fl_realloc_array(pg->xy, 2 * pg->vertex_count + 2, sizeof(double));
    if (nxy) pg->xy = nxy;
    fl_hal2_node *nodes = fl_realloc_array(hal->nodes, cap, sizeof(fl_hal2_node));
    if (nodes) hal->nodes = nodes;
    fl_hal2_node *spare = fl_alloc_array(cap, sizeof(fl_hal2_node));
    int32_t *path = fl_alloc_array(cap, sizeof(int32_t));
    uint32_t *order = fl_alloc_array(n, sizeof(uint32_t));
    hal2_pending *stack = fl_alloc_array(n, sizeof(hal2_pending));
    if (!nxy || !nodes || !spare || !path || !order || !stack) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal2_insert: out of memory");
    } else {
        located lc = locate(hal, &hal->rings[ring], after, xy, path);
        for (uint32_t k = 0; k < lc.path_len; k++) { /* these flintstones keep the vertex */
            fl_hal2_node *nd = &hal->nodes[path[k]];
            nd->edges++;
            for (int d = 0; d < (nd->kind == FL_HAL2_TWO_DISCS ? 2 : 1); d++)
                nd->disc[d][2] = fmax(nd->disc[d][2], fl_hal2_d2(nd->disc[d], xy[0], xy[1]));
        }
        insert_vertex(hal, ring, after + 1, xy);
        repair(hal, ring, &lc, order, stack);
        compact(hal, spare, path);
    }
    free(spare);
    free(path);
    free(order);
    free(stack);
    return st;
}
