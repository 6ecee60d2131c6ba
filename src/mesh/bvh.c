/* Median-split AABB tree and its self-overlap traversal. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "mesh/bvh.h"

typedef struct build_ctx {
    const double *boxes; /* input boxes, indexed by input position */
    uint32_t *order;     /* input positions, permuted into leaf order */
    int leaf_size;
    fl_bvh *bvh;
} build_ctx;

static double centre(const build_ctx *c, uint32_t i, int axis)
{
    return c->boxes[6 * (size_t)i + axis] + c->boxes[6 * (size_t)i + 3 + axis];
}

/* Rearranges order[lo, hi) so that order[k] has the k-th smallest centre on `axis`
 * (quickselect with a median-of-three pivot; expected linear). */
static void select_kth(const build_ctx *c, uint32_t *order, size_t lo, size_t hi, size_t k,
                       int axis)
{
    while (hi - lo > 2) {
        size_t mid = lo + (hi - lo) / 2;
        double a = centre(c, order[lo], axis), b = centre(c, order[mid], axis),
               d = centre(c, order[hi - 1], axis);
        double pivot = a < b ? (b < d ? b : (a < d ? d : a)) : (a < d ? a : (b < d ? d : b));
        size_t i = lo, j = hi - 1;
        for (;;) { /* Hoare partition: equal keys split evenly, so duplicates stay linear */
            while (centre(c, order[i], axis) < pivot)
                i++;
            while (centre(c, order[j], axis) > pivot)
                j--;
            if (i >= j) break;
            uint32_t t = order[i];
            order[i] = order[j], order[j] = t;
            i++, j--;
        }
        if (k <= j)
            hi = j + 1;
        else
            lo = j + 1;
    }
    if (hi - lo == 2 && centre(c, order[lo], axis) > centre(c, order[lo + 1], axis)) {
        uint32_t t = order[lo];
        order[lo] = order[lo + 1], order[lo + 1] = t;
    }
}

static void node_box(const build_ctx *c, size_t lo, size_t hi, double *box, double *cbox)
{
    for (int k = 0; k < 3; k++)
        box[k] = cbox[k] = HUGE_VAL, box[3 + k] = cbox[3 + k] = -HUGE_VAL;
    for (size_t i = lo; i < hi; i++) {
        const double *b = c->boxes + 6 * (size_t)c->order[i];
        for (int k = 0; k < 3; k++) {
            double m = b[k] + b[3 + k];
            if (b[k] < box[k]) box[k] = b[k];
            if (b[3 + k] > box[3 + k]) box[3 + k] = b[3 + k];
            if (m < cbox[k]) cbox[k] = m;
            if (m > cbox[3 + k]) cbox[3 + k] = m;
        }
    }
}

/* Builds the subtree of node `n` over order[lo, hi); iterative with an explicit stack whose
 * depth is bounded by the balanced tree's height. */
static void build_tree(build_ctx *c, size_t n_prims)
{
    struct {
        uint32_t node;
        size_t lo, hi;
    } stack[128];
    int top = 0;
    fl_bvh_node *nodes = c->bvh->nodes;
    size_t used = 1;
    stack[top].node = 0, stack[top].lo = 0, stack[top].hi = n_prims, top++;
    while (top > 0) {
        top--;
        uint32_t n = stack[top].node;
        size_t lo = stack[top].lo, hi = stack[top].hi;
        double cbox[6];
        node_box(c, lo, hi, nodes[n].box, cbox);
        if (hi - lo <= (size_t)c->leaf_size) {
            nodes[n].left = 0, nodes[n].start = (uint32_t)lo, nodes[n].count = (uint32_t)(hi - lo);
            continue;
        }
        int axis = 0;
        for (int k = 1; k < 3; k++)
            if (cbox[3 + k] - cbox[k] > cbox[3 + axis] - cbox[axis]) axis = k;
        size_t mid = lo + (hi - lo) / 2;
        select_kth(c, c->order, lo, hi, mid, axis);
        nodes[n].left = (uint32_t)used, nodes[n].start = 0, nodes[n].count = 0;
        used += 2;
        stack[top].node = nodes[n].left, stack[top].lo = lo, stack[top].hi = mid, top++;
        stack[top].node = nodes[n].left + 1, stack[top].lo = mid, stack[top].hi = hi, top++;
    }
    c->bvh->node_count = used;
}

fl_status fl_bvh_build(const double *boxes, const uint32_t *ids, size_t n, int leaf_size,
                       fl_bvh *bvh, fl_error *err)
{
    memset(bvh, 0, sizeof *bvh);
    if (n >= (size_t)1 << 31)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "too many primitives (%zu) for the box tree",
                       n);
    if (n == 0) return FL_OK;
    if (leaf_size < 1) leaf_size = 1;
    if (leaf_size > 16) leaf_size = 16;
    build_ctx c = {boxes, fl_alloc_array(n, sizeof(uint32_t)), leaf_size, bvh};
    bvh->nodes =
        fl_alloc_array(2 * n, sizeof *bvh->nodes); /* a binary tree with n leaves at most */
    bvh->prim = fl_alloc_array(n, sizeof *bvh->prim);
    bvh->prim_box = fl_alloc_array(n, 6 * sizeof(double));
    if (!c.order || !bvh->nodes || !bvh->prim || !bvh->prim_box) {
        free(c.order);
        fl_bvh_free(bvh);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory building the box tree");
    }
    for (size_t i = 0; i < n; i++)
        c.order[i] = (uint32_t)i;
    build_tree(&c, n);
    for (size_t i = 0; i < n; i++) {
        bvh->prim[i] = ids ? ids[c.order[i]] : c.order[i];
        memcpy(bvh->prim_box + 6 * i, boxes + 6 * (size_t)c.order[i], 6 * sizeof(double));
    }
    bvh->prim_count = n;
    free(c.order);
    return FL_OK;
}

void fl_bvh_free(fl_bvh *bvh)
{
    free(bvh->nodes);
    free(bvh->prim);
    free(bvh->prim_box);
    memset(bvh, 0, sizeof *bvh);
}

typedef struct pair_ctx {
    const fl_bvh *bvh;
    fl_bvh_pair_fn fn;
    void *user;
    fl_progress_fn progress;
    void *progress_user;
    const char *stage;
    size_t prims_done;
    int stop;
} pair_ctx;

static int boxes_overlap(const double *a, const double *b)
{
    return a[0] <= b[3] && b[0] <= a[3] && a[1] <= b[4] && b[1] <= a[4] && a[2] <= b[5] &&
           b[2] <= a[5];
}

static void leaf_pairs(pair_ctx *c, const fl_bvh_node *a, const fl_bvh_node *b)
{
    const fl_bvh *t = c->bvh;
    for (uint32_t i = a->start; i < a->start + a->count && !c->stop; i++) {
        uint32_t j0 = a == b ? i + 1 : b->start;
        for (uint32_t j = j0; j < b->start + b->count; j++)
            if (boxes_overlap(t->prim_box + 6 * (size_t)i, t->prim_box + 6 * (size_t)j) &&
                c->fn(c->user, t->prim[i], t->prim[j])) {
                c->stop = 1;
                break;
            }
    }
}

static double box_extent(const double *b)
{
    return b[3] - b[0] + b[4] - b[1] + b[5] - b[2];
}

static void cross_pairs(pair_ctx *c, uint32_t a, uint32_t b)
{
    const fl_bvh_node *na = &c->bvh->nodes[a], *nb = &c->bvh->nodes[b];
    if (c->stop || !boxes_overlap(na->box, nb->box)) return;
    if (na->count && nb->count) {
        leaf_pairs(c, na, nb);
    } else if (nb->count || (!na->count && box_extent(na->box) >= box_extent(nb->box))) {
        /* descend the larger node so the two sides shrink together */
        cross_pairs(c, na->left, b);
        cross_pairs(c, na->left + 1, b);
    } else {
        cross_pairs(c, a, nb->left);
        cross_pairs(c, a, nb->left + 1);
    }
}

static void self_pairs(pair_ctx *c, uint32_t n)
{
    const fl_bvh_node *node = &c->bvh->nodes[n];
    if (c->stop) return;
    if (node->count) {
        leaf_pairs(c, node, node);
        size_t before = c->prims_done;
        c->prims_done += node->count;
        if (c->prims_done >> 12 != before >> 12 &&
            fl_progress(c->progress, c->progress_user, c->stage,
                        (double)c->prims_done / (double)c->bvh->prim_count))
            c->stop = 1;
        return;
    }
    self_pairs(c, node->left);
    self_pairs(c, node->left + 1);
    cross_pairs(c, node->left, node->left + 1);
}

int fl_bvh_self_pairs(const fl_bvh *bvh, fl_bvh_pair_fn fn, void *user, fl_progress_fn progress,
                      void *progress_user, const char *stage)
{
    pair_ctx c = {bvh, fn, user, progress, progress_user, stage, 0, 0};
    if (bvh->node_count) self_pairs(&c, 0);
    return c.stop;
}
