/* Approximations from the 3D flintstone tree (thesis §7.3.2 levels, §7.3.3 adaptive).
 *
 * An approximation is a cut of the tree: a set of nodes such that every original triangle is
 * below exactly one of them. The level cut is crack-free because Algorithm 7.2 refines a whole
 * level at once and splits both triangles of a split side at the same vertex. The adaptive cut
 * keeps that property by closure: a node is refined when its error exceeds the bound, when one
 * of its children is refined (tree), or when a tie partner is (the neighbour across a side
 * that the refinement splits); the smallest set closed under these rules is found with one
 * work list. Then every side of a cut triangle is either unsplit, and shared with the same
 * neighbour as in the level it came from, or split on both sides. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "hal/hal3_internal.h"

/* Writes the triangles of the nodes with keep[n] != 0 as a compact mesh. */
static fl_status cut_mesh(const fl_hal3 *hal, const uint8_t *keep, fl_mesh *out, fl_error *err)
{
    memset(out, 0, sizeof *out);
    size_t nt = 0;
    for (size_t n = 0; n < hal->node_count; n++)
        nt += keep[n] != 0;
    uint32_t *map = fl_alloc_array(hal->mesh.vertex_count + 1, sizeof(uint32_t));
    out->tri = fl_alloc_array(3 * nt + 1, sizeof(uint32_t));
    out->xyz = fl_alloc_array(3 * hal->mesh.vertex_count + 1, sizeof(double));
    if (!map || !out->tri || !out->xyz) {
        free(map);
        fl_mesh_free(out);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
    }
    memset(map, 0xff, hal->mesh.vertex_count * sizeof(uint32_t));
    for (size_t n = 0; n < hal->node_count; n++) {
        if (!keep[n]) continue;
        for (int k = 0; k < 3; k++) {
            uint32_t v = hal->nodes[n].v[k];
            if (map[v] == UINT32_MAX) {
                map[v] = (uint32_t)out->vertex_count++;
                memcpy(out->xyz + 3 * (size_t)map[v], hal->mesh.xyz + 3 * (size_t)v,
                       3 * sizeof(double));
            }
            out->tri[3 * out->triangle_count + (size_t)k] = map[v];
        }
        out->triangle_count++;
    }
    free(map);
    return FL_OK;
}

fl_status fl_hal3_approximate_level(const fl_hal3 *hal, uint32_t level, fl_mesh *out, double *error,
                                    fl_error *err)
{
    if (!hal || !out)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal3_approximate: NULL argument");
    uint8_t *keep = fl_calloc_array(hal->node_count + 1, 1);
    if (!keep) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
    double e = 0;
    for (size_t n = 0; n < hal->node_count; n++) {
        const fl_hal3_node *nd = &hal->nodes[n];
        keep[n] = nd->level == level || (nd->level < level && nd->kind == FL_HAL3_LEAF);
        if (keep[n]) e = fmax(e, nd->error);
    }
    fl_status st = cut_mesh(hal, keep, out, err);
    free(keep);
    if (st == FL_OK && error) *error = e;
    return st;
}

static void refine(uint8_t *ref, uint32_t *stack, size_t *top, const fl_hal3 *hal, uint32_t n)
{
    if (ref[n] || hal->nodes[n].kind == FL_HAL3_LEAF) return;
    ref[n] = 1;
    stack[(*top)++] = n;
}

fl_status fl_hal3_approximate_error(const fl_hal3 *hal, double max_error, fl_mesh *out,
                                    double *error, uint32_t *level, fl_error *err)
{
    if (!hal || !out)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal3_approximate: NULL argument");
    if (!(max_error >= 0))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal3_approximate: error bound must be >= 0");
    size_t nn = hal->node_count;
    uint8_t *ref = fl_calloc_array(nn + 1, 1), *keep = fl_calloc_array(nn + 1, 1);
    uint32_t *stack = fl_alloc_array(nn + 1, sizeof(uint32_t));
    uint32_t *tstart = fl_calloc_array(nn + 2, sizeof(uint32_t));
    uint32_t *tadj = fl_alloc_array(2 * hal->tie_count + 1, sizeof(uint32_t));
    fl_status st = FL_OK;
    if (!ref || !keep || !stack || !tstart || !tadj) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
        goto done;
    }
    /* Tie adjacency (CSR). */
    for (size_t t = 0; t < 2 * hal->tie_count; t++)
        tstart[hal->ties[t] + 1]++;
    for (size_t n = 0; n < nn; n++)
        tstart[n + 1] += tstart[n];
    for (size_t t = 0; t < hal->tie_count; t++) {
        uint32_t a = hal->ties[2 * t], b = hal->ties[2 * t + 1];
        tadj[tstart[a]++] = b;
        tadj[tstart[b]++] = a;
    }
    for (size_t n = nn; n > 0; n--)
        tstart[n] = tstart[n - 1];
    tstart[0] = 0;
    size_t top = 0;
    for (size_t n = 0; n < nn; n++)
        /* Bound 0 asks for the mesh itself: refine everything, also the empty nodes (error 0)
         * and flat parts (error 0) that a positive bound leaves alone. */
        if (hal->nodes[n].error > max_error || max_error == 0)
            refine(ref, stack, &top, hal, (uint32_t)n);
    while (top > 0) {
        uint32_t n = stack[--top];
        if (hal->nodes[n].parent >= 0)
            refine(ref, stack, &top, hal, (uint32_t)hal->nodes[n].parent);
        for (uint32_t i = tstart[n]; i < tstart[n + 1]; i++)
            refine(ref, stack, &top, hal, tadj[i]);
    }
    double e = 0;
    uint32_t lv = 0;
    for (size_t n = 0; n < nn; n++) {
        const fl_hal3_node *nd = &hal->nodes[n];
        keep[n] = !ref[n] && (nd->parent < 0 || ref[nd->parent]);
        if (keep[n]) e = fmax(e, nd->error), lv = nd->level > lv ? nd->level : lv;
    }
    st = cut_mesh(hal, keep, out, err);
    if (st == FL_OK && error) *error = e;
    if (st == FL_OK && level) *level = lv;
done:
    free(ref);
    free(keep);
    free(stack);
    free(tstart);
    free(tadj);
    return st;
}
