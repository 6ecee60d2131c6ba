/* Non-rigid motion of the edge-collapse hierarchy (Guéziec 2001, §5.3, "the second method":
 * per-vertex displacement magnitudes, "edge contractions are applied in sequence. For each
 * contraction, the maximum displacement magnitude is measured for incident vertices. The
 * bounding volumes are inflated accordingly"), and a refit that replays the sequence at the new
 * positions (what §5.3's first method does for each key frame).
 *
 * The inflation, derived (docs/sweep.md "Deformation" has the same proof). The errors were
 * measured at reference positions x (the build's, or the last refit's); the mesh now has
 * positions x', d_p = |x'_p − x_p|. A present coarse triangle t (made by collapse k, u -> v)
 * owns fine triangles whose vertices p satisfy d(p, t) ≤ r(t) ≤ e_k(v) (collapse_internal.h).
 * Write c = Σ b_i c_i for p's closest point on t; c' = Σ b_i c'_i lies on the moved t' and
 * |c' − c| ≤ max_i d_{c_i}, so d(p', t') ≤ |p' − p| + |p − c| + |c − c'|
 *                                     ≤ d_p + r(t) + max over t's corners of d.
 * Both displacement terms are bounded by one per-vertex value G, replayed along the sequence
 * like the errors: G(x) = d_x at the start; collapse k (u -> v) sets
 *     G(v) = max(G(v), G(w) for every corner w of the triangles k consumed).
 * Claim: for t made by k, every vertex of a fine triangle t owns and every corner of t has
 * d ≤ G_k(v) (v's value after k). Corners: t's corners are corners of consumed triangles (u
 * replaced by v, itself a corner), and G ≥ d always. Owned vertices: they were owned by a
 * consumed triangle t_o, which is fine (its vertices are its corners) or was made by an earlier
 * collapse j into one of its corners v_o, where by induction they have d ≤ G_j(v_o) ≤ G at k
 * (G only grows). Hence with E = e + 2 G — per vertex, updated at v only and growing along
 * v's chain exactly like the errors — d(p', t') ≤ E_k(v), and the cursor's argument of
 * collapse_internal.h (ε(t) = max current E at t's corners ≥ E_k(v) while k is in effect)
 * holds word for word: the swept sphere of t' with radius ε contains every deformed vertex it
 * stands for, hence (convex) every deformed fine triangle. Fine triangles stay exact leaves
 * and every distance is computed on the moved positions, so the answers are exact for the
 * deformed mesh. The replay reads the fixed tables only: O(V + Σ consumed) with no geometry.
 *
 * The displacements are measured from the reference, not from the last update, so the
 * inflation never accumulates over updates, but it grows with the distance from the reference:
 * fl_sweep_collapse_refit makes the current positions the reference (the ownership and errors
 * replayed with their distances, no simplification), and updating back to the reference
 * positions restores the measured errors exactly. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "sweep/collapse_internal.h"
#include "sweep/sweep_internal.h"

/* Keeps the measured state the first time the mesh leaves it. */
static int keep_reference(fl_sweep_collapse *h)
{
    if (h->xyz_ref) return 0;
    size_t nv = h->vertex_count ? h->vertex_count : 1;
    double *x = fl_alloc_array(nv, 3 * sizeof *x), *s = fl_alloc_array(nv, sizeof *s);
    double *p = fl_alloc_array(nv, sizeof *p);
    if (!x || !s || !p) {
        free(x), free(s), free(p);
        return -1;
    }
    memcpy(x, h->xyz, 3 * h->vertex_count * sizeof *x);
    memcpy(s, h->err_self, h->vertex_count * sizeof *s);
    memcpy(p, h->err_parent, h->vertex_count * sizeof *p);
    h->xyz_ref = x, h->err_self_ref = s, h->err_parent_ref = p;
    return 0;
}

static double inflated(double measured, double g, double scale)
{
    return g > 0 ? fl_sweep_widen(measured + 2 * g, scale) : measured;
}

/* The §5.3 replay: g holds d per vertex and becomes G (see above); the errors in use become
 * the measured ones inflated by 2 G at the same moment of the sequence. */
static void inflate(fl_sweep_collapse *h, double *g)
{
    for (size_t k = 0; k < h->split_count; k++) {
        uint32_t u = h->split[k].u, v = h->split[k].v;
        double m = g[v];
        for (uint32_t i = h->old_start[k]; i < h->old_start[k + 1]; i++)
            for (int c = 0; c < 3; c++)
                m = fmax(m, g[h->tri[h->old[i]].v[c]]);
        h->err_parent[u] = inflated(h->err_parent_ref[u], g[v], h->scale); /* v before k */
        g[v] = m;
    }
    /* a contracted vertex is never a target again: its final G is its G when contracted */
    for (size_t x = 0; x < h->vertex_count; x++)
        h->err_self[x] = inflated(h->err_self_ref[x], g[x], h->scale);
}

fl_status fl_sweep_collapse_update_vertices(fl_sweep_collapse *hierarchy, const double *xyz,
                                            size_t vertex_count, fl_error *err)
{
    fl_sweep_collapse *h = hierarchy;
    if (!h || !xyz)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hierarchy and vertices must not be NULL");
    if (vertex_count != h->vertex_count)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                       "%zu vertices given, the hierarchy was built with %zu", vertex_count,
                       h->vertex_count);
    double scale = h->scale;
    size_t bad = fl_sweep_coords_scale(xyz, 3 * h->vertex_count, &scale);
    if (bad < 3 * h->vertex_count)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                       "vertex %zu has a coordinate that is not finite or beyond 1e150", bad / 3);
    double *g = fl_alloc_array(h->vertex_count ? h->vertex_count : 1, sizeof *g);
    if (!g || keep_reference(h)) {
        free(g);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for a hierarchy update");
    }
    h->scale = scale; /* the coordinates only grow the rounding slack: keep the larger */
    double largest = 0;
    for (size_t v = 0; v < h->vertex_count; v++) {
        const double *p = xyz + 3 * v, *r = h->xyz_ref + 3 * v, *o = h->xyz + 3 * v;
        double d2 = 0, m2 = 0;
        for (int c = 0; c < 3; c++) {
            d2 += (p[c] - r[c]) * (p[c] - r[c]);
            m2 += (p[c] - o[c]) * (p[c] - o[c]);
        }
        g[v] = d2 > 0 ? fl_sweep_widen(sqrt(d2), scale) : 0;
        largest = fmax(largest, sqrt(m2));
    }
    inflate(h, g);
    free(g);
    memcpy(h->xyz, xyz, 3 * h->vertex_count * sizeof *h->xyz);
    /* §5.2/§5.1: a kept lower bound drops by at most the largest displacement of this update
     * (every fine triangle moves by at most that much); cursors widen by it */
    if (largest > 0) h->moved += fl_sweep_widen(largest, scale);
    h->updates++;
    return FL_OK;
}

/* Replays the collapse sequence at the current positions (collapse_owners.c, as the build):
 * new ownership, r(t), errors and representatives. Fails only before changing anything. */
fl_status fl_sweep_collapse_refit(fl_sweep_collapse *hierarchy, fl_error *err)
{
    fl_sweep_collapse *h = hierarchy;
    if (!h) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hierarchy must not be NULL");
    size_t nv = h->vertex_count ? h->vertex_count : 1;
    double *rad = calloc(h->tri_count, sizeof *rad);
    uint32_t *fhead = fl_alloc_array(h->tri_count, sizeof *fhead);
    uint32_t *fnext = fl_alloc_array(h->fine_count, sizeof *fnext);
    double *e = calloc(nv, sizeof *e), *ep = calloc(nv, sizeof *ep);
    fl_status st = FL_OK;
    if (!rad || !fhead || !fnext || !e || !ep) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for a hierarchy refit");
    } else {
        for (size_t t = 0; t < h->tri_count; t++) {
            fhead[t] = t < h->fine_count ? (uint32_t)t : FL_COLLAPSE_NONE;
            if (t >= h->fine_count) h->tri[t].rep = FL_COLLAPSE_NONE;
        }
        for (size_t f = 0; f < h->fine_count; f++)
            fnext[f] = FL_COLLAPSE_NONE;
        fl_collapse_owners o = {h->xyz, h->tri, rad, fhead, fnext, h->scale};
        for (size_t k = 0; k < h->split_count; k++) {
            uint32_t first = h->new_start[k], end = h->new_start[k + 1];
            fl_collapse_hand_over(&o, h->old + h->old_start[k],
                                  h->old_start[k + 1] - h->old_start[k], first, end);
            fl_collapse_grow_error(rad, first, end, h->split[k].u, h->split[k].v, e, ep);
        }
        free(h->err_self), free(h->err_parent);
        h->err_self = e, h->err_parent = ep, e = ep = NULL;
        free(h->xyz_ref), free(h->err_self_ref), free(h->err_parent_ref);
        h->xyz_ref = h->err_self_ref = h->err_parent_ref = NULL; /* measured here now */
        h->updates++; /* cursors take the new errors; the geometry did not move */
    }
    free(rad), free(fhead), free(fnext), free(e), free(ep);
    return st;
}
