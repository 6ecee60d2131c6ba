/* Approximations from a flintstone forest (thesis §7.2.2-7.2.3; HAL paper §3.2-3.3): a set of
 * tree nodes closed under "parent refined", whose split vertices together with the roots'
 * vertices, in ring order (the infix order of the tree), form the approximating polygon. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "hal/hal2_internal.h"

typedef struct cut_rule {
    uint32_t level;   /* refine nodes of level <= level (level mode) */
    double max_error; /* refine nodes whose error exceeds max_error (error mode) */
    int by_error;
} cut_rule;

static int refine(const cut_rule *rule, const fl_hal2_node *nd)
{
    return rule->by_error ? nd->error > rule->max_error : nd->level <= rule->level;
}

/* Marks the kept vertices; returns the certified error (eq. e5 over the unrefined nodes). */
static double select_vertices(const fl_hal2 *hal, const cut_rule *rule, uint8_t *keep,
                              int32_t *stack, uint32_t *deepest)
{
    double error = 0;
    *deepest = 0;
    for (size_t r = 0; r < hal->polygon.ring_count; r++) {
        const fl_hal2_ring *rg = &hal->rings[r];
        size_t top = 0;
        keep[rg->root[0]] = keep[rg->root[1]] = 1;
        for (int c = 0; c < 2; c++)
            if (rg->child[c] >= 0) stack[top++] = rg->child[c];
        while (top > 0) {
            const fl_hal2_node *nd = &hal->nodes[stack[--top]];
            if (!refine(rule, nd)) {
                error = fmax(error, nd->error);
                continue;
            }
            keep[nd->q] = 1;
            if (nd->level > *deepest) *deepest = nd->level;
            for (int c = 0; c < 2; c++)
                if (nd->child[c] >= 0) stack[top++] = nd->child[c];
        }
    }
    return error;
}

static fl_status emit_polygon(const fl_hal2 *hal, const uint8_t *keep, fl_polygon *out)
{
    const fl_polygon *pg = &hal->polygon;
    size_t kept = 0;
    for (size_t v = 0; v < pg->vertex_count; v++)
        kept += keep[v];
    out->vertex_count = kept;
    out->ring_count = pg->ring_count;
    out->polygon_count = pg->polygon_count;
    out->xy = fl_alloc_array(2 * kept + 1, sizeof(double));
    out->ring_start = fl_alloc_array(pg->ring_count + 1, sizeof(size_t));
    out->polygon_start = fl_alloc_array(pg->polygon_count + 1, sizeof(size_t));
    if (!out->xy || !out->ring_start || !out->polygon_start) return FL_ERR_NOMEM;
    memcpy(out->polygon_start, pg->polygon_start, (pg->polygon_count + 1) * sizeof(size_t));
    size_t w = 0;
    out->ring_start[0] = 0;
    for (size_t r = 0; r < pg->ring_count; r++) {
        for (size_t v = pg->ring_start[r]; v < pg->ring_start[r + 1]; v++)
            if (keep[v]) {
                out->xy[2 * w] = pg->xy[2 * v];
                out->xy[2 * w + 1] = pg->xy[2 * v + 1];
                w++;
            }
        out->ring_start[r + 1] = w;
    }
    return FL_OK;
}

static fl_status approximate(const fl_hal2 *hal, const cut_rule *rule, fl_polygon *out,
                             double *error, uint32_t *level, fl_error *err)
{
    uint8_t *keep = fl_calloc_array(hal->polygon.vertex_count + 1, 1);
    int32_t *stack = fl_alloc_array(hal->node_count + 2, sizeof(int32_t));
    fl_status st = FL_OK;
    if (!keep || !stack) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal2 approximation: out of memory");
    } else {
        uint32_t deepest;
        double e = select_vertices(hal, rule, keep, stack, &deepest);
        if (emit_polygon(hal, keep, out) != FL_OK) {
            fl_polygon_free(out);
            st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal2 approximation: out of memory");
        } else {
            if (error) *error = e;
            if (level) *level = deepest;
        }
    }
    free(keep);
    free(stack);
    return st;
}

fl_status fl_hal2_approximate_level(const fl_hal2 *hal, uint32_t level, fl_polygon *out,
                                    double *error, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal2 approximation: out is NULL");
    memset(out, 0, sizeof *out);
    if (!hal) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal2 approximation: hal is NULL");
    cut_rule rule = {level, 0, 0};
    return approximate(hal, &rule, out, error, NULL, err);
}

fl_status fl_hal2_approximate_error(const fl_hal2 *hal, double max_error, fl_polygon *out,
                                    double *error, uint32_t *level, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal2 approximation: out is NULL");
    memset(out, 0, sizeof *out);
    if (!hal) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal2 approximation: hal is NULL");
    if (!(max_error >= 0))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "hal2 approximation: the error bound must be >= 0, got %g", max_error);
    cut_rule rule = {0, max_error, 1};
    return approximate(hal, &rule, out, error, level, err);
}
