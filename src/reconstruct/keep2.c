/* Constrained constriction (thesis §5.7): edges F the user requires on the boundary. Each edge
 * of F is brought into the triangulation before constriction starts, by flipping away the
 * Delaunay edges that cross it, and the triangulation is then made constrained Delaunay.
 * §5.7 makes this exchange lazily, when a boundary triangle v_i v_j v_k crossed by an F edge
 * v_j v_l is selected: v_i v_k leaves the graph and v_i v_j v_l becomes the boundary triangle;
 * doing it up front gives triangles on F directly (those of the constrained Delaunay
 * triangulation, where the lazy exchange would pick the one with the selected edge).
 * Edges of F are then never removable, never flipped, and never crossed by an extra edge of the
 * augmentation, so no deletion can take them out of the graph. */
#include "reconstruct/constrict2_internal.h"

static fl_status add_partner(c2_state *s, uint32_t p, uint32_t q, size_t i, fl_error *err)
{
    uint32_t *nb = s->keep_nb + 2 * (size_t)p;
    if (nb[0] == q || nb[1] == q) return FL_OK;
    if (nb[0] == C2_NONE)
        nb[0] = q;
    else if (nb[1] == C2_NONE)
        nb[1] = q;
    else
        return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                       "kept edge %zu: point %u would have three kept edges, but a simple "
                       "polygon passes each point once (two edges)",
                       i, s->orig[p]);
    return FL_OK;
}

fl_status c2_keep_edges(c2_state *s, const uint32_t *rep, const uint32_t *keep, size_t count,
                        fl_error *err)
{
    s->keep_nb = fl_alloc_array(2 * s->n, sizeof *s->keep_nb);
    if (!s->keep_nb) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for kept edges");
    for (size_t i = 0; i < 2 * s->n; i++)
        s->keep_nb[i] = C2_NONE;
    for (size_t i = 0; i < count; i++) {
        uint32_t p = keep[2 * i], q = keep[2 * i + 1];
        if (p >= s->n_input || q >= s->n_input)
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "kept edge %zu (%u-%u): index out of range (%zu points)", i, p, q,
                           s->n_input);
        p = rep[p], q = rep[q];
        if (p == q)
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "kept edge %zu (%u-%u) joins a point to itself (or to a duplicate)", i,
                           keep[2 * i], keep[2 * i + 1]);
        fl_status st = add_partner(s, p, q, i, err);
        if (st == FL_OK) st = add_partner(s, q, p, i, err);
        if (st != FL_OK) return st;
    }
    for (size_t i = 0; i < count; i++) {
        uint32_t p = rep[keep[2 * i]], q = rep[keep[2 * i + 1]];
        int r = c2_insert_segment(s, p, q);
        if (r < 0) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for kept edges");
        if (r == 0)
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "kept edge %zu (%u-%u) crosses another kept edge or passes through "
                           "a point",
                           i, keep[2 * i], keep[2 * i + 1]);
    }
    if (c2_restore_delaunay(s))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for kept edges");
    return FL_OK;
}
