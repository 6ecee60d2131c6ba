/* Hierarchical point inclusion (thesis Lemma 6.1 and §7.4; HAL paper §5.1).
 *
 * The answer is the parity of the crossings of the rightward horizontal ray from X with all
 * edges, counted with the half-open rule (an edge counts when exactly one end point is strictly
 * above X and X is strictly on the ray's side of it, by fl_orient2d); for X on no edge that
 * parity is the winding number's, and the brute-force test computes exactly this over every
 * edge. The hierarchy replaces a polyline B by its chord A whenever X is provably outside B's
 * flintstone F: F is convex and holds A and B, so the closed path B A^-1 has winding number 0
 * around X, and the signed (hence the parity of the) crossing count of B equals A's. X on an
 * edge of B is inside F, so such edges are always reached and tested exactly; "provably outside"
 * uses the enlarged floating discs (FL_HAL2_REL) and the exact fl_orient2d for half-planes. */
#include <math.h>
#include <stdlib.h>

#include "core/core.h"
#include "hal/hal2_internal.h"

static int on_segment_collinear(const double *a, const double *b, const double *x)
{
    return fmin(a[0], b[0]) <= x[0] && x[0] <= fmax(a[0], b[0]) && fmin(a[1], b[1]) <= x[1] &&
           x[1] <= fmax(a[1], b[1]);
}

/* Crossing of the rightward ray from x with a b (half-open rule), x known not on a b. */
static int ray_crosses(const double *a, const double *b, const double *x)
{
    if ((a[1] > x[1]) == (b[1] > x[1])) return 0;
    int o = fl_orient2d(a, b, x);
    return b[1] > a[1] ? o > 0 : o < 0;
}

/* An original edge: 2 when x is on it, else its crossing (0 or 1). */
static int edge_test(const double *a, const double *b, const double *x)
{
    if (fl_orient2d(a, b, x) == 0 && on_segment_collinear(a, b, x)) return 2;
    return ray_crosses(a, b, x);
}

static int outside_flintstone(const double *xy, const fl_hal2_node *nd, const double *x)
{
    if (fl_hal2_outside_disc(nd->disc[0], x[0], x[1])) return 1;
    const double *a = xy + 2 * (size_t)nd->p, *b = xy + 2 * (size_t)nd->s;
    switch (nd->kind) {
    case FL_HAL2_TWO_DISCS:
        return fl_hal2_outside_disc(nd->disc[1], x[0], x[1]);
    case FL_HAL2_DISC_HALFPLANE:
        return fl_orient2d(a, b, x) * nd->side < 0;
    case FL_HAL2_SEGMENT:
        return fl_orient2d(a, b, x) != 0 || !on_segment_collinear(a, b, x);
    default:
        return 0;
    }
}

/* Polyline v_p..v_s given by `node` (or a single edge p->s when node < 0): pushes the node, or
 * tests the edge; returns 2 on the boundary, else the crossing count mod 2. */
static int visit(const double *xy, int32_t node, uint32_t p, uint32_t s, const double *x,
                 int32_t *stack, size_t *top)
{
    if (node >= 0) {
        stack[(*top)++] = node;
        return 0;
    }
    return edge_test(xy + 2 * (size_t)p, xy + 2 * (size_t)s, x);
}

/* Crossing parity of ring r (or 2 when x is on it). */
static int ring_parity(const fl_hal2 *hal, const fl_hal2_ring *rg, const double *x, int32_t *stack)
{
    if (fl_hal2_outside_disc(rg->disc, x[0], x[1])) return 0;
    const double *xy = hal->polygon.xy;
    size_t top = 0;
    int parity = visit(xy, rg->child[0], rg->root[0], rg->root[1], x, stack, &top);
    if (parity == 2) return 2;
    int t = visit(xy, rg->child[1], rg->root[1], rg->root[0], x, stack, &top);
    if (t == 2) return 2;
    parity ^= t;
    while (top > 0) {
        const fl_hal2_node *nd = &hal->nodes[stack[--top]];
        if (outside_flintstone(xy, nd, x)) {
            parity ^= ray_crosses(xy + 2 * (size_t)nd->p, xy + 2 * (size_t)nd->s, x);
            continue;
        }
        t = visit(xy, nd->child[0], nd->p, nd->q, x, stack, &top);
        if (t == 2) return 2;
        parity ^= t;
        t = visit(xy, nd->child[1], nd->q, nd->s, x, stack, &top);
        if (t == 2) return 2;
        parity ^= t;
    }
    return parity;
}

fl_status fl_hal2_contains(const fl_hal2 *hal, const double *xy, size_t n, uint8_t *where,
                           fl_error *err)
{
    if (!hal || (n > 0 && (!xy || !where)))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal2_contains: NULL argument");
    /* A traversal keeps at most one pending node per tree level plus one. */
    int32_t *stack = fl_alloc_array(hal->node_count + 4, sizeof(int32_t));
    if (!stack) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal2_contains: out of memory");
    fl_status st = FL_OK;
    for (size_t k = 0; k < n; k++) {
        const double *x = xy + 2 * k;
        if (!isfinite(x[0]) || !isfinite(x[1])) {
            st = fl_fail(err, FL_ERR_INPUT, NULL, -1, "hal2_contains: query %zu is not finite", k);
            break;
        }
        int parity = 0;
        for (size_t r = 0; r < hal->polygon.ring_count && parity != 2; r++) {
            int t = ring_parity(hal, &hal->rings[r], x, stack);
            parity = t == 2 ? 2 : parity ^ t;
        }
        where[k] = parity == 2 ? FL_HAL2_BOUNDARY : parity ? FL_HAL2_INSIDE : FL_HAL2_OUTSIDE;
    }
    free(stack);
    return st;
}
