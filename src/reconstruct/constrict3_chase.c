/* Reaching the last inside points of 3D constriction without carving the whole surface.
 *
 * Algorithm 5.1 keeps removing the removable tetrahedron of smallest key until every point is on
 * the boundary. On points sampled from a surface, a few points (often one of a close pair) end up
 * buried: every tetrahedron around them is covered by others, so no removal brings them in, and
 * the heap then only holds two-face removals (§5.3), ordered over the WHOLE boundary. Measured on
 * the demo peanut (docs/reconstruct3d.md, "Quality"): 1499 of 1500 points were on the boundary
 * after 2700 removals, and the 2300 removals that followed until the last point joined cut slits
 * to the medial axis everywhere (area 23.6 -> 36.4, one-sided Hausdorff 0.13 -> 0.56).
 *
 * Two measures, both taken only while constriction is stalled - `limit` removals in a row
 * without a new boundary point:
 *  1. Augmentation as soon as it is needed (§5.4: "adaptively add (k-1)-simplices of a
 *     γ([-1,1],[c0,1]) when necessary"), not only when the heap is empty: the unlocking flips
 *     (constrict3_unlock.c) whose γ-indicator is below the key of the heap's root are made; the
 *     augmented graph's triangles compete with the Delaunay ones by the same selection rule
 *     (§5.4: a γ([-1,1],[c1,1]) can offer smaller γ-indicators, "better choices for deletion").
 *  2. If no such flip exists, focus: only tetrahedra within `radius` face steps of a tetrahedron
 *     with an inside vertex may be removed (the others wait in `deferred`), so the removals that
 *     dig towards a buried point happen next to it; the radius doubles whenever nothing near is
 *     removable, and everything deferred returns to the heap once a point joins the boundary.
 * Neither changes which removals are allowed (the shelling rules of constrict3.c), only their
 * order, so every guarantee (closed, manifold, genus 0, points never leave the boundary) holds.
 * The limit starts at CHASE_STALL, doubles after every stall that found no flip (a long
 * fruitless chase makes O(log T) passes) and returns to CHASE_STALL after flips: keeping it
 * large there made the chase too late on a resampled peanut (area 25.7 -> 97.3). At most one
 * O(T) pass per CHASE_STALL removals; on the real point sets of docs/reconstruct3d.md, <= 12. */
#include <stdlib.h>
#include <string.h>

#include "reconstruct/constrict3_internal.h"

#define NONE UINT32_MAX

/* Removals in a row without a new boundary point before constriction counts as stalled. On the
 * demo peanut the longest run before the last points were buried was 106, most runs are < 30. */
#define CHASE_STALL 64
#define CHASE_RADIUS 2

/* The stall limit after flips: CHASE_STALL, but T/128 removals on triangulations of more than
 * 2^16 tetrahedra, so that the O(T) passes of a stall cost O(1) amortized per removal there
 * (10^6 surface points made about 1 350 flips, each followed by a pass after 64 removals: the
 * reconstruction took 4.7x the Delaunay time, 2.85x with this floor, bench/recon3_scale.c, with
 * the same points left inside and about as many removals). Smaller inputs - the peanut and the
 * quality tests, where the timing of the chase decides the shape - keep 64. */
static size_t stall_floor(const constrict3_state *s)
{
    return s->tet_count > ((size_t)1 << 16) ? s->tet_count >> 7 : CHASE_STALL;
}

void constrict3_chase_init(constrict3_chase *c, size_t on_boundary)
{
    memset(c, 0, sizeof *c);
    c->limit = CHASE_STALL;
    c->last_on = on_boundary;
}

void constrict3_chase_free(constrict3_chase *c)
{
    free(c->near);
    constrict3_heap_free(&c->deferred);
    memset(c, 0, sizeof *c);
}

/* near[t] = 1 for region tetrahedra within c->radius face steps, through region tetrahedra, of
 * one with a vertex not on the boundary (breadth-first). */
static int mark_near(const constrict3_state *s, constrict3_chase *c)
{
    free(c->near);
    c->near = fl_calloc_array(s->tet_count, 1);
    uint32_t *queue = fl_alloc_array(s->tet_count + 1, sizeof *queue);
    uint32_t *dist = fl_alloc_array(s->tet_count + 1, sizeof *dist);
    int rc = -1;
    if (!c->near || !queue || !dist) goto done;
    c->near_count = s->tet_count;
    size_t head = 0, tail = 0;
    for (size_t t = 0; t < s->tet_count; t++) {
        const uint32_t *v = s->tet + 4 * t;
        if (s->removed[t] ||
            (s->bfaces[v[0]] && s->bfaces[v[1]] && s->bfaces[v[2]] && s->bfaces[v[3]]))
            continue;
        c->near[t] = 1;
        dist[t] = 0;
        queue[tail++] = (uint32_t)t;
    }
    while (head < tail) {
        uint32_t t = queue[head++];
        if (dist[t] >= c->radius) continue;
        for (int k = 0; k < 4; k++) {
            uint32_t nb = s->adj[4 * (size_t)t + k];
            if (nb == NONE || s->removed[nb] || c->near[nb]) continue;
            c->near[nb] = 1;
            dist[nb] = dist[t] + 1;
            queue[tail++] = nb;
        }
    }
    rc = 0;
done:
    free(queue);
    free(dist);
    return rc;
}

static int restore_deferred(constrict3_chase *c, constrict3_heap *h)
{
    for (size_t i = 0; i < c->deferred.count; i++)
        if (constrict3_heap_push(h, c->deferred.a[i]) != 0) return -1;
    c->deferred.count = 0;
    return 0;
}

int constrict3_chase_before(constrict3_state *s, constrict3_chase *c, constrict3_heap *h,
                            constrict3_entry e, constrict3_push_fn push, void *ctx,
                            size_t *flips)
{
    /* tetrahedra made by flips after the last marking hold an inside point: near */
    if (c->focus && e.tet < c->near_count && !c->near[e.tet])
        return constrict3_heap_push(&c->deferred, e) != 0 ? -1 : 1;
    if (++c->stall < c->limit) return 0;
    c->stall = 0;
    size_t made = 0;
    if (constrict3_unlock(s, push, ctx, e.key, &made) != 0) return -1;
    *flips += made;
    if (made) {
        c->limit = stall_floor(s);
        /* e is still valid unless a flip rewrote its slot (then push() re-entered it) */
        if (!s->removed[e.tet] && e.version == s->version[e.tet] &&
            constrict3_heap_push(h, e) != 0)
            return -1;
        return 1;
    }
    c->limit *= 2;
    if (!c->focus) {
        c->focus = 1;
        c->radius = CHASE_RADIUS;
        if (mark_near(s, c) != 0) return -1;
        if (!c->near[e.tet]) return constrict3_heap_push(&c->deferred, e) != 0 ? -1 : 1;
    }
    return 0;
}

int constrict3_chase_widen(constrict3_state *s, constrict3_chase *c, constrict3_heap *h)
{
    if (!c->focus || c->deferred.count == 0) return 0;
    c->radius *= 2;
    if (mark_near(s, c) != 0 || restore_deferred(c, h) != 0) return -1;
    return 1;
}

int constrict3_chase_after(const constrict3_state *s, constrict3_chase *c, constrict3_heap *h)
{
    if (s->on_boundary == c->last_on) return 0;
    c->last_on = s->on_boundary;
    c->stall = 0;
    if (!c->focus) return 0;
    c->focus = 0;
    return restore_deferred(c, h);
}
