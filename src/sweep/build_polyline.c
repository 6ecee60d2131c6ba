/* The polyline hierarchy of §3.1: iterative end-point fit. The root is the segment joining the
 * curve's ends; a node over the chain p_i..p_j is split at its most distant vertex p_k, whose
 * distance is the node's ε. The capsule of radius ε around p_i p_j is convex and contains
 * every vertex of the chain, so it contains the whole sub-curve (§3.1, Fig. 1). */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "core/core.h"
#include "sweep/sweep_internal.h"

typedef struct chain {
    size_t i, j;   /* vertex positions along the curve, i < j; position m is point m mod n */
    uint32_t node; /* where this chain's node goes */
} chain;

static const double *chain_point(const double *xyz, size_t n, size_t m)
{
    return xyz + 3 * (m % n);
}

/* The vertex of i < k < j farthest from segment p_i p_j (ties go to the middle, which keeps
 * collinear runs balanced); *eps receives its distance. */
static size_t farthest_vertex(const double *xyz, size_t n, size_t i, size_t j, double *eps)
{
    const double *a = chain_point(xyz, n, i), *b = chain_point(xyz, n, j);
    size_t mid = i + (j - i) / 2, best_k = mid;
    double best = -1;
    for (size_t k = i + 1; k < j; k++) {
        double t, c[3];
        double d = fl_sweep_segment_closest(chain_point(xyz, n, k), a, b, &t, c);
        size_t off = k > mid ? k - mid : mid - k,
               best_off = best_k > mid ? best_k - mid : mid - best_k;
        if (d > best || (d == best && off < best_off)) {
            best = d;
            best_k = k;
        }
    }
    *eps = sqrt(best);
    return best_k;
}

static void set_segment(fl_sweep_node *node, const double *a, const double *b)
{
    for (int c = 0; c < 3; c++) {
        node->v[c] = a[c];
        node->v[3 + c] = b[c];
        node->v[6 + c] = b[c];
    }
}

static fl_status check_polyline(const double *points, size_t n, int dim, fl_error *err)
{
    if (!points) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "polyline points are NULL");
    if (dim != 2 && dim != 3)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "polyline dimension must be 2 or 3, got %d",
                       dim);
    if (n < 2)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "a polyline needs at least 2 points, got %zu",
                       n);
    if (n >= (size_t)1 << 31)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "too many polyline points (%zu)", n);
    for (size_t k = 0; k < n * (size_t)dim; k++)
        if (!fl_sweep_coord_ok(points[k]))
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "polyline point %zu is not finite or beyond 1e150", k / (size_t)dim);
    return FL_OK;
}

/* Splits chains top-down with an explicit stack (the end-point fit may be n deep). */
static fl_status fit_chains(fl_sweep *s, const double *xyz, size_t n, const fl_sweep_options *opt,
                            fl_error *err)
{
    chain *stack = fl_alloc_array(s->node_count, sizeof *stack);
    if (!stack) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for the polyline fit");
    size_t top = 0, next = 1, done = 0;
    stack[top++] = (chain){0, s->elements, 0};
    while (top > 0) {
        chain c = stack[--top];
        fl_sweep_node *node = s->nodes + c.node;
        set_segment(node, chain_point(xyz, n, c.i), chain_point(xyz, n, c.j));
        if (c.j == c.i + 1) {
            node->eps = 0;
            node->child[0] = node->child[1] = FL_SWEEP_LEAF;
            node->element = (uint32_t)c.i;
            if ((++done & 0xffff) == 0 && opt &&
                fl_progress(opt->progress, opt->progress_user, "sweep hierarchy",
                            (double)done / (double)s->elements)) {
                free(stack);
                return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
            }
            continue;
        }
        double eps;
        size_t k = farthest_vertex(xyz, n, c.i, c.j, &eps);
        node->eps = fl_sweep_widen(eps, s->scale);
        node->element = FL_SWEEP_LEAF;
        node->child[0] = (uint32_t)next;
        node->child[1] = (uint32_t)(next + 1);
        stack[top++] = (chain){c.i, k, (uint32_t)next};
        stack[top++] = (chain){k, c.j, (uint32_t)(next + 1)};
        next += 2;
    }
    free(stack);
    return FL_OK;
}

fl_status fl_sweep_polyline_build(const double *points, size_t n, int dim, int closed,
                                  const fl_sweep_options *opt, fl_sweep **out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "output pointer is NULL");
    *out = NULL;
    fl_status st = check_polyline(points, n, dim, err);
    if (st != FL_OK) return st;
    double *xyz = fl_alloc_array(n, 3 * sizeof *xyz);
    if (!xyz) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for %zu points", n);
    double scale = 0;
    for (size_t k = 0; k < n; k++)
        for (int c = 0; c < 3; c++) {
            xyz[3 * k + c] = c < dim ? points[(size_t)dim * k + c] : 0;
            scale = fmax(scale, fabs(xyz[3 * k + c]));
        }
    fl_sweep *s = NULL;
    st = fl_sweep_alloc(dim, 0, closed ? n : n - 1, &s, err);
    if (st == FL_OK) {
        s->scale = scale;
        s->vertex_count = n; /* for fl_sweep_polyline_update (polyline_motion.c) */
        st = fit_chains(s, xyz, n, opt, err);
    }
    free(xyz);
    if (st != FL_OK) {
        fl_sweep_free(s);
        return st;
    }
    fl_sweep_compute_boxes(s);
    *out = s;
    return FL_OK;
}
