/* Axis-aligned boxes alongside the swept-sphere bounding elements ("tighter or cheaper bounding
 * volumes near the leaves", issue #9). A region's points lie in both its swept element (§3.1,
 * §4.1) and the box of its leaves' corners, so max(box distance, d - ε) is a lower bound as
 * valid as either, and the box distance costs a handful of operations where the swept element
 * costs a point-triangle solve. query.c first measures the box and only solves against the
 * element when the box does not already put the region behind the best upper bound.
 *
 * The boxes are exact (minima and maxima of input coordinates, no rounding), computed bottom-up
 * in one pass over the node array: builders number children after their parents. */
#if defined(__linux__) && !defined(_DEFAULT_SOURCE)
#define _DEFAULT_SOURCE /* madvise */
#endif
#include <stdint.h>
#include <stdlib.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "core/core.h"
#include "sweep/sweep_internal.h"

void fl_sweep_advise_huge(void *p, size_t bytes)
{
#ifdef MADV_HUGEPAGE
    /* Whole pages inside the block only; the advice is a hint, so its result is ignored. */
    uintptr_t first = ((uintptr_t)p + 4095) & ~(uintptr_t)4095;
    uintptr_t last = ((uintptr_t)p + bytes) & ~(uintptr_t)4095;
    if (p && bytes >= ((size_t)4 << 20) && last > first)
        (void)madvise((void *)first, last - first, MADV_HUGEPAGE);
#else
    (void)p, (void)bytes;
#endif
}

/* The box of a leaf: its segment's or triangle's corners. */
static void leaf_box(const fl_sweep *s, const fl_sweep_node *node, double *box)
{
    int corners = s->triangles ? 3 : 2;
    for (int c = 0; c < 3; c++) {
        double lo = node->v[c], hi = node->v[c];
        for (int k = 1; k < corners; k++) {
            double x = node->v[3 * k + c];
            lo = x < lo ? x : lo;
            hi = x > hi ? x : hi;
        }
        box[c] = lo;
        box[3 + c] = hi;
    }
}

static void union_box(const double *a, const double *b, double *out)
{
    for (int c = 0; c < 3; c++) {
        out[c] = a[c] < b[c] ? a[c] : b[c];
        out[3 + c] = a[3 + c] > b[3 + c] ? a[3 + c] : b[3 + c];
    }
}

fl_sweep_box *fl_sweep_box_alloc(size_t n)
{
    if (n == 0 || n > SIZE_MAX / sizeof(fl_sweep_box)) return NULL;
    return aligned_alloc(64, n * sizeof(fl_sweep_box)); /* a multiple of 64 bytes */
}

/* Fills s->box from the leaves up. Returns 0 (and leaves the boxes out) if a child does not
 * come after its parent, which the reverse pass needs. */
static int fill_boxes(fl_sweep *s)
{
    for (size_t i = s->node_count; i-- > 0;) {
        const fl_sweep_node *node = s->nodes + i;
        fl_sweep_box *box = s->box + i;
        box->child[0] = node->child[0];
        box->child[1] = node->child[1];
        box->pad[0] = box->pad[1] = 0;
        if (fl_sweep_is_leaf(node)) {
            leaf_box(s, node, box->b);
            continue;
        }
        uint32_t a = node->child[0], b = node->child[1];
        if (a <= i || b <= i || a >= s->node_count || b >= s->node_count) return 0;
        union_box(s->box[a].b, s->box[b].b, box->b);
    }
    return 1;
}

void fl_sweep_compute_boxes(fl_sweep *s)
{
    if (!s->box) {
        s->box = fl_sweep_box_alloc(s->node_count);
        fl_sweep_advise_huge(s->box, s->node_count * sizeof *s->box);
    }
    if (s->box && !fill_boxes(s)) {
        free(s->box);
        s->box = NULL;
    }
}
