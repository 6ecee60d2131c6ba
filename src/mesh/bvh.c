/* Median-split AABB tree and its self-overlap traversal. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "mesh/bvh.h"

/* During the build the primitives' centres (inexact, but only used to choose splits)
 * are permuted together with their ids in contiguous arrays, so each level of the top-down
 * split streams through memory instead of chasing ids into the input boxes. */
typedef struct build_ctx {
    double *cent;    /* 3 per entry, permuted with order */
    uint32_t *order; /* input positions in leaf order */
    int leaf_size;
    fl_bvh *bvh;
} build_ctx;

static void swap_entries(build_ctx *c, size_t i, size_t j)
{
    uint32_t t = c->order[i];
    c->order[i] = c->order[j], c->order[j] = t;
    for (int k = 0; k < 3; k++) {
        double x = c->cent[3 * i + k];
        c->cent[3 * i + k] = c->cent[3 * j + k], c->cent[3 * j + k] = x;
    }
}

/* Rearranges entries [lo, hi) so that entry k has the k-th smallest centre on `axis`.
 * Quickselect with a pseudo-random pivot: median-of-three pivots go quadratic on ordered
 * inputs met in practice (a comb polygon's edges do it), a hashed pivot position does not and
 * keeps the build deterministic. Expected linear. */
static void select_kth(build_ctx *c, size_t lo, size_t hi, size_t k, int axis)
{
    const double *x = c->cent + axis;
    uint64_t state = (uint64_t)lo * 0x9E3779B97F4A7C15ULL ^ (uint64_t)hi;
    while (hi - lo > 2) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        double pivot = x[3 * (lo + (size_t)((state >> 33) % (hi - lo)))];
        size_t i = lo, j = hi - 1;
        for (;;) { /* Hoare partition: equal keys split evenly, so duplicates stay linear */
            while (x[3 * i] < pivot)
                i++;
            while (x[3 * j] > pivot)
                j--;
            if (i >= j) break;
            swap_entries(c, i, j);
            i++, j--;
        }
        if (k <= j)
            hi = j + 1;
        else
            lo = j + 1;
    }
    if (hi - lo == 2 && x[3 * lo] > x[3 * (lo + 1)]) swap_entries(c, lo, lo + 1);
}

static int widest_centre_axis(const build_ctx *c, size_t lo, size_t hi)
{
    double mn[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, mx[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (size_t i = lo; i < hi; i++)
        for (int k = 0; k < 3; k++) {
            double v = c->cent[3 * i + k];
            mn[k] = v < mn[k] ? v : mn[k];
            mx[k] = v > mx[k] ? v : mx[k];
        }
    int axis = 0;
    for (int k = 1; k < 3; k++)
        if (mx[k] - mn[k] > mx[axis] - mn[axis]) axis = k;
    return axis;
}

/* Splits top-down with an explicit stack (depth bounded by the balanced tree's height);
 * boxes are filled afterwards, bottom-up. */
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
        if (hi - lo <= (size_t)c->leaf_size) {
            nodes[n].left = 0, nodes[n].start = (uint32_t)lo, nodes[n].count = (uint32_t)(hi - lo);
            continue;
        }
        size_t mid = lo + (hi - lo) / 2;
        select_kth(c, lo, hi, mid, widest_centre_axis(c, lo, hi));
        nodes[n].left = (uint32_t)used, nodes[n].start = 0, nodes[n].count = 0;
        used += 2;
        stack[top].node = nodes[n].left, stack[top].lo = lo, stack[top].hi = mid, top++;
        stack[top].node = nodes[n].left + 1, stack[top].lo = mid, stack[top].hi = hi, top++;
    }
    c->bvh->node_count = used;
}

/* Float bounds that contain the double interval [lo, hi]. */
static void round_out(const double *box, float *out)
{
    for (int k = 0; k < 3; k++) {
        float lo = (float)box[k], hi = (float)box[3 + k];
        if ((double)lo > box[k]) lo = nextafterf(lo, -HUGE_VALF);
        if ((double)hi < box[3 + k]) hi = nextafterf(hi, HUGE_VALF);
        out[k] = lo, out[3 + k] = hi;
    }
}

static void merge_box(float *into, const float *b)
{
    for (int k = 0; k < 3; k++) {
        into[k] = b[k] < into[k] ? b[k] : into[k];
        into[3 + k] = b[3 + k] > into[3 + k] ? b[3 + k] : into[3 + k];
    }
}

/* Children follow their parent in the array, so one reverse sweep sees them first. */
static void fill_node_boxes(fl_bvh *bvh)
{
    for (size_t n = bvh->node_count; n-- > 0;) {
        fl_bvh_node *node = &bvh->nodes[n];
        const float *first =
            node->count ? bvh->prim_box + 6 * (size_t)node->start : bvh->nodes[node->left].box;
        memcpy(node->box, first, sizeof node->box);
        if (node->count) {
            for (uint32_t i = 1; i < node->count; i++)
                merge_box(node->box, bvh->prim_box + 6 * ((size_t)node->start + i));
        } else {
            merge_box(node->box, bvh->nodes[node->left + 1].box);
        }
    }
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
    build_ctx c = {fl_alloc_array(n, 3 * sizeof(double)), fl_alloc_array(n, sizeof(uint32_t)),
                   leaf_size, bvh};
    bvh->nodes = fl_alloc_array(2 * n, sizeof *bvh->nodes); /* n leaves at most */
    bvh->prim = fl_alloc_array(n, sizeof *bvh->prim);
    bvh->prim_box = fl_alloc_array(n, 6 * sizeof(float));
    if (!c.cent || !c.order || !bvh->nodes || !bvh->prim || !bvh->prim_box) {
        free(c.cent);
        free(c.order);
        fl_bvh_free(bvh);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory building the box tree");
    }
    for (size_t i = 0; i < n; i++) {
        c.order[i] = (uint32_t)i;
        for (int k = 0; k < 3; k++) /* halves first: no overflow near DBL_MAX */
            c.cent[3 * i + k] = 0.5 * boxes[6 * i + k] + 0.5 * boxes[6 * i + 3 + k];
    }
    build_tree(&c, n);
    for (size_t i = 0; i < n; i++) {
        bvh->prim[i] = ids ? ids[c.order[i]] : c.order[i];
        round_out(boxes + 6 * (size_t)c.order[i], bvh->prim_box + 6 * i);
    }
    bvh->prim_count = n;
    fill_node_boxes(bvh);
    fl_bvh_node *shrunk = realloc(bvh->nodes, bvh->node_count * sizeof *shrunk);
    if (shrunk) bvh->nodes = shrunk;
    free(c.cent);
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

static int boxes_overlap(const float *a, const float *b)
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

static float box_extent(const float *b)
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
