/* Boundary construction by constriction of the 2D Delaunay triangulation (thesis §5.2,
 * Algorithm 5.1): start from the convex hull, repeatedly delete the removable boundary edge with
 * the smallest key together with its triangle, until every point is on the boundary. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reconstruct/constrict2_internal.h"

int c2_push_candidates(c2_state *s, uint32_t a)
{
    uint32_t b = s->bnext[a], t = s->btri[a];
    if (c2_is_kept(s, a, b)) return 0; /* §5.7: edges of F are never removable */
    if (s->augmented) return c2_push_graph_candidates(s, a);
    int k = c2_corner(s, t, a);
    uint32_t c = s->tri[3 * (size_t)t + (k + 2) % 3];
    /* §5.2: removable only when the opposite vertex is not on the boundary yet, so that the
     * new boundary a -> c -> b is again a simple polygon. */
    if (s->on_boundary[c] || !c2_keep_allows(s, a, b, c)) return 0;
    /* A γ-indicator that certainly parks is not computed now (heap2.c): on a closed curve a
     * third of the keys are those of the thin triangles across the curve, never popped. */
    c2_entry e = {0, a, b, c, 0};
    if (s->criterion == FL_RECONSTRUCT2_GAMMA &&
        c2_gamma_at_least(c2_pt(s, a), c2_pt(s, b), c2_pt(s, c), c2_heap_first_bar()))
        e.lazy = 1;
    else
        e.key = c2_key(s, a, b, c, t);
    return c2_heap_push(&s->heap, e);
}

/* Clears the links between triangle t and its neighbours. */
static void unlink_face(c2_state *s, uint32_t t)
{
    size_t base = 3 * (size_t)t;
    for (int k = 0; k < 3; k++) {
        uint32_t u = s->adj[base + k];
        if (u == C2_NONE) continue;
        for (int j = 0; j < 3; j++)
            if (s->adj[3 * (size_t)u + j] == t) s->adj[3 * (size_t)u + j] = C2_NONE;
        s->adj[base + k] = C2_NONE;
    }
}

void c2_settle_adj(c2_state *s)
{
    if (!s->lazy_adj) return;
    for (size_t t = 0; t < s->tcount; t++) {
        uint32_t *adj = s->adj + 3 * t;
        if (!s->alive[t]) {
            adj[0] = adj[1] = adj[2] = C2_NONE;
            continue;
        }
        for (int k = 0; k < 3; k++)
            if (adj[k] != C2_NONE && !s->alive[adj[k]]) adj[k] = C2_NONE;
    }
    s->lazy_adj = 0;
}

int c2_delete_face(c2_state *s, uint32_t t, uint32_t a)
{
    size_t base = 3 * (size_t)t;
    int ka = c2_corner(s, t, a);
    uint32_t b = s->tri[base + (ka + 1) % 3], c = s->tri[base + (ka + 2) % 3];
    uint32_t n1 = s->adj[base + (ka + 1) % 3]; /* across c -> a: gets boundary edge a -> c */
    uint32_t n2 = s->adj[base + ka];           /* across b -> c: gets boundary edge c -> b */
    s->alive[t] = 0;
    if (!s->lazy_adj) unlink_face(s, t);
    s->on_boundary[c] = 1;
    s->boundary_count++;
    s->bnext[a] = c;
    s->bnext[c] = b;
    s->btri[a] = n1;
    s->btri[c] = n2;
    if (s->vtri) {
        s->vtri[a] = n1;
        s->vtri[c] = n2;
        s->vtri[b] = s->btri[b];
    }
    if (c2_push_candidates(s, a) || c2_push_candidates(s, c)) return -1;
    return 0;
}

/* Third vertex of the living face on boundary edge a -> b. */
static uint32_t face_apex(const c2_state *s, uint32_t a)
{
    uint32_t t = s->btri[a];
    return s->tri[3 * (size_t)t + (c2_corner(s, t, a) + 2) % 3];
}

/* Line 5 of Algorithm 5.1 and the deletion of line 6 for one popped entry. In augmented mode
 * the triangle a b c need not be a face: its sides a-c and c-b are brought into the
 * triangulation by flips (which drops every edge crossing them, §5.4), and it is deleted when
 * it then is a face, i.e. when no point lies inside it. Returns 0, or -1 when out of memory. */
static int try_delete(c2_state *s, c2_entry e)
{
    if (!s->on_boundary[e.a] || s->bnext[e.a] != e.b || s->on_boundary[e.c]) return 0;
    if (c2_is_kept(s, e.a, e.b) || !c2_keep_allows(s, e.a, e.b, e.c)) return 0;
    if (face_apex(s, e.a) != e.c) {
        if (!s->augmented) return 0;
        int r = c2_insert_segment(s, e.a, e.c);
        if (r == 1) r = c2_insert_segment(s, e.b, e.c);
        if (r != 1) return r < 0 ? -1 : 0;
        if (face_apex(s, e.a) != e.c) return 0; /* a point lies inside a b c */
    } else if (s->criterion == FL_RECONSTRUCT2_VORONOI_SKELETON && !s->augmented) {
        /* The skeleton key grows when a neighbour goes; re-queue with the current value. */
        double key = c2_key(s, e.a, e.b, e.c, s->btri[e.a]);
        if (key != e.key) {
            e.key = key;
            return c2_heap_push(&s->heap, e);
        }
    }
    return c2_delete_face(s, s->btri[e.a], e.a);
}

fl_status c2_constrict(c2_state *s, fl_progress_fn progress, void *progress_user, fl_error *err)
{
    size_t steps = 0;
    while (s->boundary_count < s->unique_count && s->heap.count > 0) {
        if ((++steps & 4095) == 0 &&
            fl_progress(progress, progress_user, "constriction",
                        (double)s->boundary_count / (double)s->unique_count))
            return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
        c2_entry e;
        if (c2_heap_pop(&s->heap, &e) || try_delete(s, e))
            return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory during constriction");
    }
    return FL_OK;
}
