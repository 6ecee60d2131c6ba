/* Hierarchical intersection of two flintstone forests (thesis §7.4; HAL paper §5.2). Pairs of
 * bounding areas are refined while they may meet: the larger of the two (in edges) is replaced
 * by its two halves; two original edges are tested exactly. In 2D every flintstone is an
 * intersection of discs (case 1 of §7.4), so two flintstones are disjoint as soon as one disc
 * of each is; the test is done on the enlarged floating discs with a rounding margin, so it only
 * prunes pairs that are provably apart, and the result equals the all-pairs brute force. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "hal/hal2_internal.h"

enum { ITEM_RING, ITEM_NODE, ITEM_EDGE };

/* A piece of one forest: a whole ring, a node's polyline, or one edge p -> s. */
typedef struct item {
    uint8_t kind;
    uint32_t index; /* ring or node */
    uint32_t p, s;
    uint32_t size; /* edges covered */
} item;

typedef struct item_pair {
    item a, b;
} item_pair;

static int on_segment_collinear(const double *a, const double *b, const double *x)
{
    return fmin(a[0], b[0]) <= x[0] && x[0] <= fmax(a[0], b[0]) && fmin(a[1], b[1]) <= x[1] &&
           x[1] <= fmax(a[1], b[1]);
}

/* Closed segments ab and cd share a point, decided exactly. */
static int segments_meet(const double *a, const double *b, const double *c, const double *d)
{
    int o1 = fl_orient2d(a, b, c), o2 = fl_orient2d(a, b, d);
    int o3 = fl_orient2d(c, d, a), o4 = fl_orient2d(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return 1;
    return (o1 == 0 && on_segment_collinear(a, b, c)) ||
           (o2 == 0 && on_segment_collinear(a, b, d)) ||
           (o3 == 0 && on_segment_collinear(c, d, a)) || (o4 == 0 && on_segment_collinear(c, d, b));
}

/* The discs whose intersection bounds the item; returns their number (1 or 2). */
static int item_discs(const fl_hal2 *h, const item *it, double discs[2][3])
{
    if (it->kind == ITEM_RING) {
        memcpy(discs[0], h->rings[it->index].disc, sizeof discs[0]);
        return 1;
    }
    if (it->kind == ITEM_NODE) {
        const fl_hal2_node *nd = &h->nodes[it->index];
        memcpy(discs[0], nd->disc[0], sizeof discs[0]);
        if (nd->kind != FL_HAL2_TWO_DISCS) return 1;
        memcpy(discs[1], nd->disc[1], sizeof discs[1]);
        return 2;
    }
    const double *a = h->polygon.xy + 2 * (size_t)it->p, *b = h->polygon.xy + 2 * (size_t)it->s;
    discs[0][0] = a[0] + (b[0] - a[0]) / 2;
    discs[0][1] = a[1] + (b[1] - a[1]) / 2;
    discs[0][2] = fmax(fl_hal2_d2(discs[0], a[0], a[1]), fl_hal2_d2(discs[0], b[0], b[1]));
    return 1;
}

/* Provably disjoint discs: centre distance above the sum of radii with the rounding margin. */
static int discs_apart(const double *d, const double *e)
{
    double s = sqrt(d[2]) + sqrt(e[2]);
    return fl_hal2_d2(d, e[0], e[1]) > s * s * (1 + FL_HAL2_REL) + FL_HAL2_ABS;
}

static int items_apart(const fl_hal2 *ha, const item *a, const fl_hal2 *hb, const item *b)
{
    double da[2][3], db[2][3];
    int na = item_discs(ha, a, da), nb = item_discs(hb, b, db);
    for (int i = 0; i < na; i++)
        for (int j = 0; j < nb; j++)
            if (discs_apart(da[i], db[j])) return 1;
    return 0;
}

static item polyline_item(const fl_hal2 *h, int32_t node, uint32_t p, uint32_t s)
{
    if (node >= 0) return (item){ITEM_NODE, (uint32_t)node, p, s, h->nodes[node].edges};
    return (item){ITEM_EDGE, 0, p, s, 1};
}

/* The two halves of a ring or a node. */
static void split_item(const fl_hal2 *h, const item *it, item half[2])
{
    if (it->kind == ITEM_RING) {
        const fl_hal2_ring *rg = &h->rings[it->index];
        half[0] = polyline_item(h, rg->child[0], rg->root[0], rg->root[1]);
        half[1] = polyline_item(h, rg->child[1], rg->root[1], rg->root[0]);
        return;
    }
    const fl_hal2_node *nd = &h->nodes[it->index];
    half[0] = polyline_item(h, nd->child[0], nd->p, nd->q);
    half[1] = polyline_item(h, nd->child[1], nd->q, nd->s);
}

static int compare_pairs(const void *x, const void *y)
{
    const uint32_t *a = x, *b = y;
    if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
    return (a[1] > b[1]) - (a[1] < b[1]);
}

/* Processes one pair: records an edge pair, pushes refined pairs; -1 on allocation failure. */
static int step(const fl_hal2 *ha, const fl_hal2 *hb, const item_pair *pr, fl_vec *stack,
                fl_vec *found)
{
    if (items_apart(ha, &pr->a, hb, &pr->b)) return 0;
    if (pr->a.kind == ITEM_EDGE && pr->b.kind == ITEM_EDGE) {
        const double *xa = ha->polygon.xy, *xb = hb->polygon.xy;
        if (!segments_meet(xa + 2 * (size_t)pr->a.p, xa + 2 * (size_t)pr->a.s,
                           xb + 2 * (size_t)pr->b.p, xb + 2 * (size_t)pr->b.s))
            return 0;
        uint32_t e[2] = {pr->a.p, pr->b.p};
        return fl_vec_push(found, e, 1);
    }
    /* "proceed with the next level of the deepest subtree": split the larger piece */
    int split_a = pr->b.kind == ITEM_EDGE || (pr->a.kind != ITEM_EDGE && pr->a.size >= pr->b.size);
    item half[2];
    split_item(split_a ? ha : hb, split_a ? &pr->a : &pr->b, half);
    for (int k = 1; k >= 0; k--) {
        item_pair next = split_a ? (item_pair){half[k], pr->b} : (item_pair){pr->a, half[k]};
        if (fl_vec_push(stack, &next, 1)) return -1;
    }
    return 0;
}

fl_status fl_hal2_intersect(const fl_hal2 *a, const fl_hal2 *b, int first_only, fl_hal2_pairs *out,
                            fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal2_intersect: out is NULL");
    memset(out, 0, sizeof *out);
    if (!a || !b) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal2_intersect: NULL forest");
    fl_vec stack, found;
    fl_vec_init(&stack, sizeof(item_pair));
    fl_vec_init(&found, 2 * sizeof(uint32_t));
    int failed = 0, done = 0;
    for (size_t i = 0; i < a->polygon.ring_count && !failed && !done; i++)
        for (size_t j = 0; j < b->polygon.ring_count && !failed && !done; j++) {
            const fl_hal2_ring *ra = &a->rings[i], *rb = &b->rings[j];
            item_pair root = {{ITEM_RING, (uint32_t)i, 0, 0, ra->count},
                              {ITEM_RING, (uint32_t)j, 0, 0, rb->count}};
            failed = fl_vec_push(&stack, &root, 1);
            while (!failed && !done && stack.count > 0) {
                item_pair pr = ((item_pair *)stack.data)[--stack.count];
                failed = step(a, b, &pr, &stack, &found);
                done = first_only && found.count > 0;
            }
            stack.count = 0;
        }
    fl_vec_free(&stack);
    if (failed) {
        fl_vec_free(&found);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal2_intersect: out of memory");
    }
    out->count = found.count;
    if (found.count > 1) qsort(found.data, found.count, 2 * sizeof(uint32_t), compare_pairs);
    out->pairs = fl_vec_release(&found);
    return FL_OK;
}

void fl_hal2_pairs_free(fl_hal2_pairs *pairs)
{
    if (!pairs) return;
    free(pairs->pairs);
    memset(pairs, 0, sizeof *pairs);
}
