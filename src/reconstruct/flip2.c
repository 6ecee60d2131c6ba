/* Segments in the pruned triangulation: the walk from a vertex along a segment, and insertion of
 * a segment by edge flips (Sloan 1993: flip the crossing edges whose quadrilateral is convex
 * until none crosses). Used where the graph has edges the triangulation lacks: the extra edges
 * of γ([-1,1],[c0,1]) in augmented constriction (thesis §5.4) and kept edges (§5.7). Every
 * decision is an exact orientation test; no input point lies on an inserted segment (that is
 * checked), which is what makes Sloan's flipping terminate. */
#include <stdlib.h>

#include "reconstruct/constrict2_internal.h"

static int orient(const c2_state *s, uint32_t a, uint32_t b, uint32_t c)
{
    return fl_orient2d(c2_pt(s, a), c2_pt(s, b), c2_pt(s, c));
}

/* For collinear a, x, b: whether x and b lie on the same side of a (decided coordinatewise). */
static int same_ray(const c2_state *s, uint32_t a, uint32_t x, uint32_t b)
{
    const double *pa = c2_pt(s, a), *px = c2_pt(s, x), *pb = c2_pt(s, b);
    for (int i = 0; i < 2; i++)
        if ((px[i] > pa[i]) != (pb[i] > pa[i]) || (px[i] < pa[i]) != (pb[i] < pa[i])) return 0;
    return 1;
}

/* The first triangle of a's fan in counterclockwise order: rotate clockwise until the region's
 * boundary (or all the way round for a vertex inside). */
static uint32_t fan_first(const c2_state *s, uint32_t a)
{
    uint32_t start = s->vtri[a], t = start;
    for (;;) {
        int k = c2_corner(s, t, a);
        uint32_t u = s->adj[3 * (size_t)t + (k + 2) % 3]; /* across a -> tri[k+1] */
        if (u == C2_NONE || u == start) return t;
        t = u;
    }
}

typedef struct walk {
    uint32_t *edges; /* crossing edges as vertex pairs (right, left of a->b) */
    uint32_t *slots; /* triangles met, the corridor the flips stay in */
    size_t ecount, scount, cap;
} walk;

static int walk_add(walk *w, uint32_t t, uint32_t x, uint32_t y)
{
    if (w->scount + 1 > w->cap) {
        size_t cap = w->cap ? 2 * w->cap : 16;
        uint32_t *e = fl_realloc_array(w->edges, 2 * cap, sizeof *e);
        if (!e) return -1;
        w->edges = e;
        uint32_t *sl = fl_realloc_array(w->slots, cap, sizeof *sl);
        if (!sl) return -1;
        w->slots = sl;
        w->cap = cap;
    }
    w->slots[w->scount++] = t;
    if (x != C2_NONE) {
        w->edges[2 * w->ecount] = x;
        w->edges[2 * w->ecount + 1] = y;
        w->ecount++;
    }
    return 0;
}

/* The triangle of a's fan whose open wedge holds b; 1 found, 0 when b is a neighbour already
 * (*t_out = C2_NONE) or when the way from a to b is blocked (a point on the ray, or b not in
 * the region near a): then returns -1. */
static int find_wedge(const c2_state *s, uint32_t a, uint32_t b, uint32_t *t_out)
{
    uint32_t first = fan_first(s, a), t = first;
    do {
        int k = c2_corner(s, t, a);
        uint32_t x = s->tri[3 * (size_t)t + (k + 1) % 3], y = s->tri[3 * (size_t)t + (k + 2) % 3];
        if (x == b || y == b) return 0;
        int o1 = orient(s, a, x, b), o2 = orient(s, a, y, b);
        if ((o1 == 0 && same_ray(s, a, x, b)) || (o2 == 0 && same_ray(s, a, y, b))) return -1;
        if (o1 > 0 && o2 < 0) {
            *t_out = t;
            return 1;
        }
        t = s->adj[3 * (size_t)t + (k + 1) % 3];
    } while (t != C2_NONE && t != first);
    return -1;
}

/* Walks from a to b through living triangles, recording the crossed edges. 1 when b is reached
 * crossing only interior, non-kept edges and no vertex; 0 when a-b is an edge; -1 blocked;
 * -2 out of memory. */
static int walk_segment(const c2_state *s, uint32_t a, uint32_t b, walk *w)
{
    uint32_t t;
    int r = find_wedge(s, a, b, &t);
    if (r <= 0) return r;
    int k = c2_corner(s, t, a);
    uint32_t x = s->tri[3 * (size_t)t + (k + 1) % 3], y = s->tri[3 * (size_t)t + (k + 2) % 3];
    uint32_t across = s->adj[3 * (size_t)t + k];
    if (walk_add(w, t, C2_NONE, C2_NONE)) return -2;
    for (;;) {
        /* x is right of a->b and y left; the segment leaves t through x-y. */
        if (across == C2_NONE || c2_is_kept(s, x, y)) return -1;
        t = across;
        if (walk_add(w, t, x, y)) return -2;
        int kz = 3 - c2_corner(s, t, x) - c2_corner(s, t, y);
        uint32_t z = s->tri[3 * (size_t)t + kz];
        if (z == b) return 1;
        int o = orient(s, a, b, z);
        if (o == 0) return -1; /* z lies on the segment */
        if (o > 0) {
            across = s->adj[3 * (size_t)t + c2_corner(s, t, y)];
            y = z;
        } else {
            across = s->adj[3 * (size_t)t + c2_corner(s, t, x)];
            x = z;
        }
    }
}

static void replace_adj(c2_state *s, uint32_t t, uint32_t from, uint32_t to)
{
    if (t == C2_NONE) return;
    for (int j = 0; j < 3; j++)
        if (s->adj[3 * (size_t)t + j] == from) s->adj[3 * (size_t)t + j] = to;
}

static void refresh_boundary(c2_state *s, uint32_t t)
{
    for (int k = 0; k < 3; k++)
        if (s->adj[3 * (size_t)t + k] == C2_NONE) s->btri[s->tri[3 * (size_t)t + (k + 1) % 3]] = t;
}

/* Flips the edge opposite corner k of t. Triangles (r,p,q) and (s,q,p) become (r,p,s) and
 * (s,q,r), keeping slots t and u; the caller has checked that r p s q is strictly convex. */
static void flip(c2_state *s, uint32_t t, int k)
{
    size_t bt = 3 * (size_t)t;
    uint32_t r = s->tri[bt + k], p = s->tri[bt + (k + 1) % 3], q = s->tri[bt + (k + 2) % 3];
    uint32_t u = s->adj[bt + k];
    size_t bu = 3 * (size_t)u;
    int ks = 3 - c2_corner(s, u, p) - c2_corner(s, u, q);
    uint32_t sv = s->tri[bu + ks];
    uint32_t a_qr = s->adj[bt + (k + 1) % 3], a_rp = s->adj[bt + (k + 2) % 3];
    uint32_t a_ps = s->adj[bu + (ks + 1) % 3], a_sq = s->adj[bu + (ks + 2) % 3];
    s->tri[bt] = r, s->tri[bt + 1] = p, s->tri[bt + 2] = sv;
    s->adj[bt] = a_ps, s->adj[bt + 1] = u, s->adj[bt + 2] = a_rp;
    s->tri[bu] = sv, s->tri[bu + 1] = q, s->tri[bu + 2] = r;
    s->adj[bu] = a_qr, s->adj[bu + 1] = t, s->adj[bu + 2] = a_sq;
    replace_adj(s, a_ps, u, t);
    replace_adj(s, a_qr, t, u);
    s->vtri[p] = s->vtri[r] = s->vtri[sv] = t;
    s->vtri[q] = u;
    refresh_boundary(s, t);
    refresh_boundary(s, u);
}

/* Slot of the corridor holding edge p-q, and the corner opposite it there. */
static uint32_t locate(const c2_state *s, const walk *w, uint32_t p, uint32_t q, int *k)
{
    for (size_t i = 0; i < w->scount; i++) {
        uint32_t t = w->slots[i];
        int kp = c2_corner(s, t, p), kq = c2_corner(s, t, q);
        if (kp >= 0 && kq >= 0) {
            *k = 3 - kp - kq;
            return t;
        }
    }
    return C2_NONE;
}

static int crosses(const c2_state *s, uint32_t a, uint32_t b, uint32_t r, uint32_t q)
{
    return orient(s, a, b, r) * orient(s, a, b, q) < 0 &&
           orient(s, r, q, a) * orient(s, r, q, b) < 0;
}

/* Sloan's loop over a queue (ring buffer over w->edges) of edges crossing a-b. */
static int flip_until_inserted(c2_state *s, uint32_t a, uint32_t b, walk *w)
{
    size_t m = w->ecount, head = 0, count = m;
    size_t budget = 8 * (m + 1) * (m + 1) + 64; /* Sloan: terminates; guard regardless */
    while (count > 0) {
        if (budget-- == 0) return 0;
        uint32_t p = w->edges[2 * head], q = w->edges[2 * head + 1];
        head = (head + 1) % m;
        count--;
        int k;
        uint32_t t = locate(s, w, p, q, &k);
        if (t == C2_NONE) return 0;
        size_t bt = 3 * (size_t)t;
        uint32_t r = s->tri[bt + k], pp = s->tri[bt + (k + 1) % 3], qq = s->tri[bt + (k + 2) % 3];
        uint32_t u = s->adj[bt + k];
        uint32_t sv = s->tri[3 * (size_t)u + 3 - c2_corner(s, u, pp) - c2_corner(s, u, qq)];
        size_t tail = (head + count) % m;
        if (orient(s, r, pp, sv) > 0 && orient(s, sv, qq, r) > 0) {
            flip(s, t, k);
            if (!crosses(s, a, b, r, sv)) continue;
            p = r, q = sv;
        }
        w->edges[2 * tail] = p, w->edges[2 * tail + 1] = q;
        count++;
    }
    return 1;
}

int c2_insert_segment(c2_state *s, uint32_t a, uint32_t b)
{
    if (c2_keep_dt(s)) return -1;
    walk w = {0};
    int r = walk_segment(s, a, b, &w);
    if (r == 1)
        r = flip_until_inserted(s, a, b, &w);
    else
        r = r == 0 ? 1 : r == -1 ? 0 : -1;
    free(w.edges);
    free(w.slots);
    return r;
}

/* Lawson's flips with the kept edges fixed: flip every edge whose opposite vertex lies strictly
 * inside the circumcircle of the triangle across it, until none does. Flipping only strict
 * violations (exact fl_incircle) terminates, and the result is the constrained Delaunay
 * triangulation of the points and the kept edges: the γ([-1,1],[0,1]) of the thesis with the
 * edges of F put in, as close to Delaunay as F allows. 0, or -1 when out of memory. */
int c2_restore_delaunay(c2_state *s)
{
    if (c2_keep_dt(s)) return -1;
    size_t count = 3 * s->tcount, cap = count + 64;
    uint32_t *stack = fl_alloc_array(cap, sizeof *stack);
    if (!stack) return -1;
    for (size_t i = 0; i < count; i++)
        stack[i] = (uint32_t)i;
    while (count > 0) {
        uint32_t e = stack[--count], t = e / 3;
        int k = (int)(e % 3);
        uint32_t u = s->adj[e];
        if (u == C2_NONE || !s->alive[t]) continue;
        const uint32_t *v = s->tri + 3 * (size_t)t;
        uint32_t p = v[(k + 1) % 3], q = v[(k + 2) % 3];
        if (c2_is_kept(s, p, q)) continue;
        uint32_t d = s->tri[3 * (size_t)u + 3 - c2_corner(s, u, p) - c2_corner(s, u, q)];
        if (fl_incircle(c2_pt(s, v[0]), c2_pt(s, v[1]), c2_pt(s, v[2]), c2_pt(s, d)) <= 0) continue;
        flip(s, t, k);
        if (count + 6 > cap) {
            uint32_t *grown = fl_realloc_array(stack, 2 * cap, sizeof *stack);
            if (!grown) {
                free(stack);
                return -1;
            }
            stack = grown;
            cap *= 2;
        }
        for (int j = 0; j < 3; j++) {
            stack[count++] = 3 * t + (uint32_t)j;
            stack[count++] = 3 * u + (uint32_t)j;
        }
    }
    free(stack);
    return 0;
}
