/* Meshsweeper's mesh hierarchy by error-bounded edge collapses (Guéziec 2001, §4.2-4.3; the
 * tables are described in collapse_internal.h).
 *
 * Simplification: half-edge collapses u -> v (v keeps its position, so every triangle of the
 * hierarchy has input vertices as corners) in order of increasing edge length, each checked
 * for safety first (collapse_safe). A collapse hands the fine triangles owned by the consumed
 * triangles to the nearest new triangle and grows v's error to reach them (the invariant of
 * collapse_internal.h); this, not the safety checks, is what the queries' exactness rests on,
 * so a mesh of any topology gives correct bounds. Arrays only: triangles, corner lists and
 * ownership lists are indices into growable arrays, no per-node allocation (§4.2). The
 * ownership hand-over is shared with the §5.3 refit (collapse_owners.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "sweep/collapse_internal.h"
#include "sweep/sweep_heap.h"
#include "sweep/sweep_internal.h"

#define RING_MAX 48 /* collapses around vertices of higher valence are skipped */

typedef struct builder {
    const fl_mesh *m;
    fl_vec tris;   /* fl_collapse_tri */
    fl_vec cnext;  /* uint32 per corner (3 per triangle): next corner at the same vertex */
    fl_vec fhead;  /* uint32 per triangle: first fine triangle it owns */
    fl_vec edges;  /* fl_sweep_entry min-heap of candidate collapses: key = squared length */
    fl_vec ends;   /* uint32 pairs: the vertices of candidate edge i (heap entries' node) */
    fl_vec old;    /* uint32: consumed triangles of every collapse */
    fl_vec old_start, new_start; /* uint32 per collapse */
    fl_vec rad;    /* double per triangle: r(t), what its swept sphere must reach */
    fl_vec split;  /* fl_collapse_split per collapse */
    uint32_t *chead; /* per vertex: first corner */
    uint32_t *fnext; /* per fine triangle: next fine triangle of the same owner */
    double *err;     /* per vertex: its error so far (collapse_internal.h) */
    double *err_parent; /* per vertex: the parent's error before contracting it */
    uint32_t *last;  /* per vertex: the last collapse of its chain so far, or NONE */
} builder;

/* A vertex's live triangles, with their neighbour vertices and how many of the triangles
 * share each edge (vertex, neighbour). */
typedef struct ring {
    uint32_t t[RING_MAX];
    size_t n;
    uint32_t nb[2 * RING_MAX];
    int count[2 * RING_MAX];
    size_t nn;
} ring;

static fl_collapse_tri *tri_at(builder *b, uint32_t t)
{
    return (fl_collapse_tri *)b->tris.data + t;
}

static uint32_t *u32_at(fl_vec *v, size_t i)
{
    return (uint32_t *)v->data + i;
}

static const double *vert(const builder *b, uint32_t v)
{
    return b->m->xyz + 3 * (size_t)v;
}

/* ---- candidate edges: the sweep's array binary heap (sweep_heap.h, §4.2) ---- */

/* Queues entry x (its node names a pair in b->ends). */
static int edge_insert(builder *b, fl_sweep_entry x)
{
    if (fl_vec_reserve(&b->edges, b->edges.count + 1)) return -1;
    fl_sweep_heap h = {b->edges.data, b->edges.count};
    fl_sweep_heap_push(&h, x);
    b->edges.count = h.n;
    return 0;
}

static int edge_push(builder *b, uint32_t a, uint32_t c)
{
    const double *p = vert(b, a), *q = vert(b, c);
    uint32_t pair[2] = {a, c};
    double len2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                  (p[2] - q[2]) * (p[2] - q[2]);
    if (b->ends.count / 2 >= UINT32_MAX || fl_vec_push(&b->ends, pair, 2)) return -1;
    return edge_insert(b, (fl_sweep_entry){len2, 0, (uint32_t)(b->ends.count / 2 - 1), 0});
}

static fl_sweep_entry edge_pop(builder *b)
{
    fl_sweep_heap h = {b->edges.data, b->edges.count};
    fl_sweep_entry top = fl_sweep_heap_pop(&h);
    b->edges.count = h.n;
    return top;
}

/* ---- triangles and corner lists ---- */

static int tri_add(builder *b, const uint32_t v[3], uint32_t creator)
{
    fl_collapse_tri x = {{v[0], v[1], v[2]}, FL_COLLAPSE_NONE, creator, FL_COLLAPSE_NONE};
    uint32_t t = (uint32_t)b->tris.count, none = FL_COLLAPSE_NONE;
    double zero = 0;
    if (fl_vec_push(&b->tris, &x, 1) || fl_vec_push(&b->fhead, &none, 1) ||
        fl_vec_push(&b->cnext, NULL, 3) || fl_vec_push(&b->rad, &zero, 1))
        return -1;
    for (int k = 0; k < 3; k++) {
        *u32_at(&b->cnext, 3 * (size_t)t + k) = b->chead[v[k]];
        b->chead[v[k]] = 3 * t + (uint32_t)k;
    }
    return 0;
}

static void ring_add_neighbour(ring *r, uint32_t w)
{
    for (size_t i = 0; i < r->nn; i++)
        if (r->nb[i] == w) {
            r->count[i]++;
            return;
        }
    r->nb[r->nn] = w;
    r->count[r->nn++] = 1;
}

/* Gathers x's live triangles (unlinking the corners of consumed ones on the way). Returns 0
 * when x has more than RING_MAX of them or one with a repeated vertex (left alone). */
static int ring_gather(builder *b, uint32_t x, ring *r)
{
    r->n = r->nn = 0;
    uint32_t *link = b->chead + x;
    while (*link != FL_COLLAPSE_NONE) {
        uint32_t c = *link, t = c / 3;
        const fl_collapse_tri *tr = tri_at(b, t);
        if (tr->destroyer != FL_COLLAPSE_NONE) {
            *link = *u32_at(&b->cnext, c);
            continue;
        }
        link = u32_at(&b->cnext, c);
        if (r->n == RING_MAX) return 0;
        if (tr->v[0] == tr->v[1] || tr->v[1] == tr->v[2] || tr->v[0] == tr->v[2]) return 0;
        r->t[r->n++] = t;
        for (int k = 0; k < 3; k++)
            if (tr->v[k] != x) ring_add_neighbour(r, tr->v[k]);
    }
    return r->n > 0;
}

static int ring_count(const ring *r, uint32_t w)
{
    for (size_t i = 0; i < r->nn; i++)
        if (r->nb[i] == w) return r->count[i];
    return 0;
}

/* Whether the ring's triangles form one fan: connected through shared neighbours. */
static int ring_one_fan(const builder *b, const ring *r)
{
    uint32_t todo[RING_MAX];
    size_t n_reached = 1, n_todo = 1;
    uint8_t seen[RING_MAX] = {0};
    seen[0] = 1, todo[0] = 0;
    while (n_todo > 0) {
        const fl_collapse_tri *a = tri_at((builder *)b, r->t[todo[--n_todo]]);
        for (size_t j = 0; j < r->n; j++) {
            if (seen[j]) continue;
            const fl_collapse_tri *c = tri_at((builder *)b, r->t[j]);
            int shared = 0; /* the centre vertex is shared by all: count two common vertices */
            for (int x = 0; x < 3; x++)
                for (int y = 0; y < 3; y++)
                    shared += a->v[x] == c->v[y];
            if (shared < 2) continue;
            seen[j] = 1;
            todo[n_todo++] = (uint32_t)j;
            n_reached++;
        }
    }
    return n_reached == r->n;
}

/* The edges at a vertex are manifold (1 or 2 triangles) and its triangles form one fan with 0
 * or 2 boundary edges: otherwise removing or moving it could change the topology. Returns
 * the number of boundary edges, or -1. */
static int ring_manifold(const builder *b, const ring *r)
{
    int boundary = 0;
    for (size_t i = 0; i < r->nn; i++) {
        if (r->count[i] > 2) return -1;
        boundary += r->count[i] == 1;
    }
    if (boundary != 0 && boundary != 2) return -1;
    return ring_one_fan(b, r) ? boundary : -1;
}

/* A normal of triangle (a, p, c), up to a positive factor: the edges are scaled by a power of
 * two to about 1 first, so that the products neither overflow (coordinates up to 1e150) nor
 * underflow (1e-300): otherwise no collapse would pass the fold-over test at those scales. */
static void normal(const double *a, const double *p, const double *c, double *n)
{
    double e[3], f[3], m = 0;
    for (int i = 0; i < 3; i++) {
        e[i] = p[i] - a[i], f[i] = c[i] - a[i];
        m = fmax(m, fmax(fabs(e[i]), fabs(f[i])));
    }
    if (m > 0 && m < INFINITY) {
        double scale = ldexp(1.0, -ilogb(m));
        for (int i = 0; i < 3; i++)
            e[i] *= scale, f[i] *= scale;
    }
    n[0] = e[1] * f[2] - e[2] * f[1];
    n[1] = e[2] * f[0] - e[0] * f[2];
    n[2] = e[0] * f[1] - e[1] * f[0];
}

/* Whether collapsing u into v keeps the surface's topology and does not fold it over. These
 * checks only protect the quality of the simplified mesh; the bounds hold for any collapse.
 * The fold-over test is a floating-point normal comparison: a heuristic, not a combinatorial
 * decision of the output (which comes from the radii). */
static int collapse_safe(const builder *b, uint32_t u, uint32_t v, const ring *ru,
                         const ring *rv)
{
    int bu = ring_manifold(b, ru), bv = ring_manifold(b, rv), uv = ring_count(ru, v);
    if (bu < 0 || bv < 0 || uv == 0) return 0;
    if (bu && uv != 1) return 0; /* a boundary vertex only slides along its boundary */
    size_t common = 0; /* link condition: common neighbours = the apexes of the edge uv */
    for (size_t i = 0; i < ru->nn; i++)
        if (ru->nb[i] != v && ring_count(rv, ru->nb[i])) common++;
    if (common != (size_t)uv) return 0;
    if (ru->n == (size_t)uv) return 0; /* nothing would be left to own the fine triangles */
    if (rv->n + ru->n - 2 * (size_t)uv > RING_MAX) return 0;
    for (size_t i = 0; i < ru->n; i++) {
        const fl_collapse_tri *t = tri_at((builder *)b, ru->t[i]);
        if (t->v[0] == v || t->v[1] == v || t->v[2] == v) continue;
        const double *p[3], *q[3];
        for (int k = 0; k < 3; k++) {
            p[k] = vert(b, t->v[k]);
            q[k] = vert(b, t->v[k] == u ? v : t->v[k]);
        }
        double n0[3], n1[3];
        normal(p[0], p[1], p[2], n0);
        normal(q[0], q[1], q[2], n1);
        double d = n0[0] * n1[0] + n0[1] * n1[1] + n0[2] * n1[2];
        double l0 = sqrt(n0[0] * n0[0] + n0[1] * n0[1] + n0[2] * n0[2]);
        double l1 = sqrt(n1[0] * n1[0] + n1[1] * n1[1] + n1[2] * n1[2]);
        if (!(d > 0.5 * l0 * l1)) return 0; /* flips, turns by more than 60°, or degenerates */
    }
    return 1;
}

/* Records collapse k (u -> v) in the vertex errors and chains (collapse_internal.h): v's
 * error grows to reach the new triangles' fine ones; k follows the last collapses of u's and
 * v's chains. */
static int record_errors(builder *b, uint32_t k, uint32_t u, uint32_t v, uint32_t first,
                         uint32_t end)
{
    fl_collapse_split x = {u, v, FL_COLLAPSE_NONE};
    if (fl_vec_push(&b->split, &x, 1)) return -1;
    fl_collapse_grow_error(b->rad.data, first, end, u, v, b->err, b->err_parent);
    fl_collapse_split *s = b->split.data;
    if (b->last[u] != FL_COLLAPSE_NONE) s[b->last[u]].next = k;
    if (b->last[v] != FL_COLLAPSE_NONE) s[b->last[v]].next = k;
    b->last[v] = k;
    return 0;
}

/* Collapses u into v: consumes u's triangles, makes the new ones (u replaced by v) and hands
 * them the consumed triangles' fine triangles. */
static int collapse(builder *b, uint32_t u, uint32_t v, const ring *ru, double scale)
{
    uint32_t k = (uint32_t)b->old_start.count, first = (uint32_t)b->tris.count;
    uint32_t start = (uint32_t)b->old.count;
    if (fl_vec_push(&b->old_start, &start, 1) || fl_vec_push(&b->new_start, &first, 1)) return -1;
    for (size_t i = 0; i < ru->n; i++) {
        fl_collapse_tri *t = tri_at(b, ru->t[i]);
        t->destroyer = k;
        if (fl_vec_push(&b->old, ru->t + i, 1)) return -1;
        if (t->v[0] == v || t->v[1] == v || t->v[2] == v) continue;
        uint32_t nv[3];
        for (int c = 0; c < 3; c++)
            nv[c] = t->v[c] == u ? v : t->v[c];
        if (tri_add(b, nv, k)) return -1;
    }
    uint32_t end = (uint32_t)b->tris.count;
    fl_collapse_owners o = {b->m->xyz, b->tris.data, b->rad.data, b->fhead.data, b->fnext, scale};
    fl_collapse_hand_over(&o, ru->t, ru->n, first, end);
    if (record_errors(b, k, u, v, first, end)) return -1;
    b->chead[u] = FL_COLLAPSE_NONE;
    for (uint32_t t = first; t < end; t++)
        for (int c = 0; c < 3; c++)
            if (tri_at(b, t)->v[c] != v && edge_push(b, v, tri_at(b, t)->v[c])) return -1;
    return 0;
}

/* Tries to collapse edge e in whichever direction is safe; 1 if done (ru, rv: u's and v's
 * rings before), 0 if not, -1 out of memory. */
static int try_collapse(builder *b, const uint32_t *e, double scale, ring *ru, ring *rv)
{
    for (int dir = 0; dir < 2; dir++) {
        uint32_t u = e[dir], v = e[1 - dir];
        if (!ring_gather(b, u, ru) || !ring_gather(b, v, rv)) continue;
        if (!collapse_safe(b, u, v, ru, rv)) continue;
        if (b->tris.count + ru->n >= UINT32_MAX - 1 || collapse(b, u, v, ru, scale)) return -1;
        return 1;
    }
    return 0;
}

/* Simplifies in passes: each pass collapses edges shortest first but never two whose
 * neighbourhoods touch (the vertices of both rings are locked for the rest of the pass), so a
 * pass is an independent set of collapses, like a level of the hierarchy, which shortens the
 * chains of "split before" dependencies (random queries on the npm bunny visit 853 triangles
 * instead of 1008 with one greedy order). Edges meeting a locked vertex wait for the next
 * pass; the simplification ends with a pass that collapses nothing. */
static fl_status simplify(builder *b, double scale, const fl_sweep_options *opt, fl_error *err)
{
    ring ru, rv;
    fl_vec later;
    fl_vec_init(&later, sizeof(fl_sweep_entry));
    uint32_t *lock = calloc(b->m->vertex_count ? b->m->vertex_count : 1, sizeof *lock);
    fl_status st = lock ? FL_OK : fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    size_t collapsed = 1;
    for (uint32_t pass = 1; st == FL_OK && collapsed > 0; pass++) {
        collapsed = 0;
        while (st == FL_OK && b->edges.count > 0) {
            fl_sweep_entry x = edge_pop(b);
            uint32_t e[2];
            memcpy(e, u32_at(&b->ends, 2 * (size_t)x.node), sizeof e);
            if (lock[e[0]] == pass || lock[e[1]] == pass) {
                if (fl_vec_push(&later, &x, 1))
                    st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
                continue;
            }
            int r = try_collapse(b, e, scale, &ru, &rv);
            if (r < 0) st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for the hierarchy");
            if (r <= 0) continue;
            collapsed++;
            lock[e[0]] = lock[e[1]] = pass;
            for (size_t i = 0; i < ru.nn; i++) lock[ru.nb[i]] = pass;
            for (size_t i = 0; i < rv.nn; i++) lock[rv.nb[i]] = pass;
        }
        for (size_t i = 0; st == FL_OK && i < later.count; i++)
            if (edge_insert(b, ((fl_sweep_entry *)later.data)[i]))
                st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
        later.count = 0;
        if (st == FL_OK && opt &&
            fl_progress(opt->progress, opt->progress_user, "collapse hierarchy",
                        1.0 - 1.0 / (1.0 + (double)pass)))
            st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
    }
    fl_vec_free(&later);
    free(lock);
    return st;
}

/* ---- building and the public entry points ---- */

static fl_status check_input(const fl_mesh *m, fl_error *err)
{
    if (!m || !m->xyz || !m->tri)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "mesh or its arrays are NULL");
    if (m->triangle_count == 0 || m->triangle_count >= ((size_t)1 << 31))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "the mesh needs 1 to 2^31-1 triangles, not %zu",
                       m->triangle_count);
    if (m->vertex_count >= UINT32_MAX)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "too many vertices: %zu", m->vertex_count);
    for (size_t i = 0; i < 3 * m->vertex_count; i++)
        if (!fl_sweep_coord_ok(m->xyz[i]))
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "vertex %zu has a coordinate that is not finite or beyond 1e150", i / 3);
    for (size_t i = 0; i < 3 * m->triangle_count; i++)
        if (m->tri[i] >= m->vertex_count)
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "triangle %zu: vertex index %u >= %zu",
                           i / 3, m->tri[i], m->vertex_count);
    return FL_OK;
}

static void builder_free(builder *b)
{
    fl_vec_free(&b->tris);
    fl_vec_free(&b->cnext);
    fl_vec_free(&b->fhead);
    fl_vec_free(&b->edges);
    fl_vec_free(&b->ends);
    fl_vec_free(&b->old);
    fl_vec_free(&b->old_start);
    fl_vec_free(&b->new_start);
    fl_vec_free(&b->rad);
    fl_vec_free(&b->split);
    free(b->chead);
    free(b->fnext);
    free(b->err);
    free(b->err_parent);
    free(b->last);
}

/* The input triangles (each owning itself) and every input edge as a candidate. */
static int builder_start(builder *b, const fl_mesh *m)
{
    fl_vec_init(&b->tris, sizeof(fl_collapse_tri));
    fl_vec_init(&b->cnext, sizeof(uint32_t));
    fl_vec_init(&b->fhead, sizeof(uint32_t));
    fl_vec_init(&b->edges, sizeof(fl_sweep_entry));
    fl_vec_init(&b->ends, sizeof(uint32_t));
    fl_vec_init(&b->old, sizeof(uint32_t));
    fl_vec_init(&b->old_start, sizeof(uint32_t));
    fl_vec_init(&b->new_start, sizeof(uint32_t));
    fl_vec_init(&b->rad, sizeof(double));
    fl_vec_init(&b->split, sizeof(fl_collapse_split));
    b->m = m;
    size_t nv = m->vertex_count ? m->vertex_count : 1;
    b->chead = fl_alloc_array(nv, sizeof *b->chead);
    b->fnext = fl_alloc_array(m->triangle_count, sizeof *b->fnext);
    b->err = calloc(nv, sizeof *b->err);
    b->err_parent = calloc(nv, sizeof *b->err_parent);
    b->last = fl_alloc_array(nv, sizeof *b->last);
    if (!b->chead || !b->fnext || !b->err || !b->err_parent || !b->last ||fl_vec_reserve(&b->tris, 3 * m->triangle_count) ||
        fl_vec_reserve(&b->edges, 3 * m->triangle_count))
        return -1;
    for (size_t v = 0; v < m->vertex_count; v++)
        b->chead[v] = b->last[v] = FL_COLLAPSE_NONE;
    for (size_t t = 0; t < m->triangle_count; t++) {
        if (tri_add(b, m->tri + 3 * t, FL_COLLAPSE_NONE)) return -1;
        *u32_at(&b->fhead, t) = (uint32_t)t;
        b->fnext[t] = FL_COLLAPSE_NONE;
        for (int k = 0; k < 3; k++) {
            uint32_t a = m->tri[3 * t + k], c = m->tri[3 * t + (k + 1) % 3];
            if (a < c && edge_push(b, a, c)) return -1; /* each undirected edge about once */
            if (a > c && edge_push(b, c, a)) return -1;
        }
    }
    return 0;
}

/* Moves the builder's arrays into the hierarchy and lists the base mesh. */
static int builder_finish(builder *b, fl_sweep_collapse *h)
{
    uint32_t end_old = (uint32_t)b->old.count, end_new = (uint32_t)b->tris.count;
    if (fl_vec_push(&b->old_start, &end_old, 1) || fl_vec_push(&b->new_start, &end_new, 1))
        return -1;
    h->tri_count = b->tris.count;
    h->split_count = b->old_start.count - 1;
    h->tri = fl_vec_release(&b->tris);
    h->old = fl_vec_release(&b->old);
    h->old_start = fl_vec_release(&b->old_start);
    h->new_start = fl_vec_release(&b->new_start);
    h->split = fl_vec_release(&b->split);
    h->err_self = b->err, b->err = NULL; /* a contracted vertex's error stops changing */
    h->err_parent = b->err_parent, b->err_parent = NULL;
    size_t base = 0;
    for (size_t t = 0; t < h->tri_count; t++)
        base += h->tri[t].destroyer == FL_COLLAPSE_NONE;
    h->base = fl_alloc_array(base, sizeof *h->base);
    if (!h->tri || !h->old_start || !h->new_start || !h->base ||
        (h->split_count && !h->split))
        return -1;
    for (size_t t = 0; t < h->tri_count; t++)
        if (h->tri[t].destroyer == FL_COLLAPSE_NONE) h->base[h->base_count++] = (uint32_t)t;
    return 0;
}

fl_status fl_sweep_collapse_build(const fl_mesh *mesh, const fl_sweep_options *opt,
                                  fl_sweep_collapse **out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "output pointer is NULL");
    *out = NULL;
    fl_status st = check_input(mesh, err);
    if (st != FL_OK) return st;
    fl_sweep_collapse *h = calloc(1, sizeof *h);
    builder b = {0};
    if (!h || !(h->xyz = fl_alloc_array(mesh->vertex_count ? mesh->vertex_count : 1,
                                        3 * sizeof *h->xyz))) {
        free(h);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for the collapse hierarchy");
    }
    memcpy(h->xyz, mesh->xyz, 3 * mesh->vertex_count * sizeof *h->xyz);
    h->vertex_count = mesh->vertex_count;
    h->fine_count = mesh->triangle_count;
    for (size_t i = 0; i < 3 * mesh->vertex_count; i++)
        h->scale = fmax(h->scale, fabs(mesh->xyz[i]));
    if (builder_start(&b, mesh))
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for the collapse hierarchy");
    if (st == FL_OK) st = simplify(&b, h->scale, opt, err);
    if (st == FL_OK && builder_finish(&b, h))
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for the collapse hierarchy");
    builder_free(&b);
    if (st != FL_OK) {
        fl_sweep_collapse_free(h);
        return st;
    }
    *out = h;
    return FL_OK;
}

void fl_sweep_collapse_free(fl_sweep_collapse *h)
{
    if (!h) return;
    free(h->xyz);
    free(h->tri);
    free(h->new_start);
    free(h->old_start);
    free(h->old);
    free(h->base);
    free(h->split);
    free(h->err_self);
    free(h->err_parent);
    free(h->xyz_ref);
    free(h->err_self_ref);
    free(h->err_parent_ref);
    free(h);
}

size_t fl_collapse_bytes(const fl_sweep_collapse *h)
{
    return sizeof *h + 3 * h->vertex_count * sizeof(double) + h->tri_count * sizeof *h->tri +
           2 * (h->split_count + 1) * sizeof(uint32_t) +
           h->old_start[h->split_count] * sizeof(uint32_t) + h->base_count * sizeof(uint32_t) +
           h->split_count * sizeof *h->split + 2 * h->vertex_count * sizeof(double) +
           (h->xyz_ref ? 5 * h->vertex_count * sizeof(double) : 0); /* §5.3 reference */
}
