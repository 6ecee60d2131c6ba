/* Locked constriction and non-Hamiltonian Delaunay triangulations (thesis §5.4). When no
 * boundary edge of the pruned Delaunay triangulation is removable but points remain inside,
 * the graph is augmented with the extra edges of γ([-1,1],[c0,1]) for c0 = -1/L, -2/L, ..., -1
 * and constriction continues on it. A boundary edge a-b may then be deleted with respect to any
 * inside vertex c joined to both a and b; the edges crossing triangle a b c leave the graph
 * (they are flipped away, flip2.c), and the deletion goes ahead only when no point lies inside
 * a b c, which keeps the boundary a simple polygon through every point it had.
 *
 * The extra edges come from the definition (Def. 3.1-3.3): for an edge u-w whose every disc
 * touching u and w holds a point (not Delaunay), the largest empty neighbourhood is the
 * symmetric lens N_γ(c,c), c < 0, of two discs of radius r/(1-|c|) with centres on opposite
 * sides. A point p seeing u-w under the angle θ lies in that lens exactly when θ is obtuse and
 * sin θ < 1 - |c|, so c1' = min over obtuse-seeing p of sin θ - 1 and u-w belongs to
 * γ([-1,1],[c0,1]) iff c1' >= c0 (no point may lie on the open segment: it is always in N_γ).
 * Obtuse-seeing points lie in the disc with diameter u-w, and the points of the Delaunay
 * triangulation inside any disc are connected by its edges, so a search through Delaunay
 * neighbours inside that disc finds them all. Only edges at an inside vertex matter (the third
 * vertex of a deletion is inside); they are looked for among the vertices a few graph steps
 * away, more steps for smaller c0. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reconstruct/constrict2_internal.h"

/* A symmetric adjacency in compressed rows. */
typedef struct csr {
    size_t *start;
    uint32_t *nb;
} csr;

static void csr_free(csr *g)
{
    free(g->start);
    free(g->nb);
    g->start = NULL;
    g->nb = NULL;
}

static int cmp_u32(const void *x, const void *y)
{
    uint32_t a = *(const uint32_t *)x, b = *(const uint32_t *)y;
    return (a > b) - (a < b);
}

/* Rows of a planar graph hold about six entries: insertion sort beats qsort's call overhead
 * there; long rows (a hub vertex) still go to qsort. */
static void sort_row(uint32_t *a, size_t n)
{
    if (n > 24) {
        qsort(a, n, sizeof *a, cmp_u32);
        return;
    }
    for (size_t i = 1; i < n; i++) {
        uint32_t x = a[i];
        size_t j = i;
        for (; j > 0 && a[j - 1] > x; j--) a[j] = a[j - 1];
        a[j] = x;
    }
}

/* Builds the adjacency of `m` undirected edges (pairs) on n vertices, rows sorted, repeats
 * removed. 0, or -1 when out of memory. */
static int csr_build(csr *g, size_t n, const uint32_t *edges, size_t m)
{
    g->start = fl_calloc_array(n + 1, sizeof *g->start);
    g->nb = fl_alloc_array(2 * m + 1, sizeof *g->nb);
    size_t *fill = fl_alloc_array(n + 1, sizeof *fill);
    if (!g->start || !g->nb || !fill) {
        free(fill);
        return -1;
    }
    for (size_t i = 0; i < 2 * m; i++)
        g->start[edges[i] + 1]++;
    for (size_t v = 0; v < n; v++)
        g->start[v + 1] += g->start[v];
    memcpy(fill, g->start, (n + 1) * sizeof *fill);
    for (size_t i = 0; i < m; i++) {
        g->nb[fill[edges[2 * i]]++] = edges[2 * i + 1];
        g->nb[fill[edges[2 * i + 1]]++] = edges[2 * i];
    }
    size_t out = 0;
    for (size_t v = 0; v < n; v++) {
        size_t from = g->start[v], to = g->start[v + 1];
        sort_row(g->nb + from, to - from);
        g->start[v] = out;
        for (size_t i = from; i < to; i++)
            if (i == from || g->nb[i] != g->nb[i - 1]) g->nb[out++] = g->nb[i];
    }
    g->start[n] = out;
    free(fill);
    return 0;
}

static int csr_has(const csr *g, uint32_t v, uint32_t w)
{
    size_t lo = g->start[v], hi = g->start[v + 1];
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (g->nb[mid] == w) return 1;
        if (g->nb[mid] < w)
            lo = mid + 1;
        else
            hi = mid;
    }
    return 0;
}

/* Scratch for the searches: a visit stamp per vertex and a queue. */
typedef struct scratch {
    uint32_t *stamp, *queue, *depth;
    uint32_t now;
} scratch;

static void next_stamp(scratch *sc, size_t n)
{
    if (++sc->now == 0) {
        memset(sc->stamp, 0, n * sizeof *sc->stamp);
        sc->now = 1;
    }
}

/* c1' of edge u-w (see the file comment); -2 when a point lies on the open segment. The
 * search stops as soon as the edge is known to be outside γ([-1,1],[c0,1]) (c1' < c0), returning
 * a value below c0: far pairs have many points in their disc, and one close to the segment
 * usually turns up within a few steps. */
static double lens_param(const c2_state *s, const csr *dt, scratch *sc, uint32_t u, uint32_t w,
                         double c0)
{
    const double *pu = c2_pt(s, u), *pw = c2_pt(s, w);
    double min_sin = 1;
    int e; /* products are taken in a frame scaled by 2^-e, |u - w| ~ 1: no overflow */
    frexp(fmax(fabs(pu[0] - pw[0]), fabs(pu[1] - pw[1])), &e);
    /* Multiplying by a power of two rounds exactly like ldexp (both are exact unless the
     * result is subnormal) and costs a multiplication instead of a libm call. */
    const double scale = ldexp(1.0, -e);
    size_t head = 0, tail = 0;
    next_stamp(sc, s->n);
    sc->stamp[u] = sc->stamp[w] = sc->now;
    sc->queue[tail++] = u;
    sc->queue[tail++] = w;
    while (head < tail) {
        uint32_t v = sc->queue[head++];
        for (size_t i = dt->start[v]; i < dt->start[v + 1]; i++) {
            uint32_t p = dt->nb[i];
            if (sc->stamp[p] == sc->now) continue;
            sc->stamp[p] = sc->now;
            const double *pp = c2_pt(s, p);
            double ax = (pu[0] - pp[0]) * scale, ay = (pu[1] - pp[1]) * scale;
            double bx = (pw[0] - pp[0]) * scale, by = (pw[1] - pp[1]) * scale;
            double dot = ax * bx + ay * by;
            if (dot > 0) continue; /* outside the disc with diameter u-w: θ acute */
            sc->queue[tail++] = p;
            if (dot == 0) continue;
            if (fl_orient2d(pu, pw, pp) == 0) return -2;
            /* |a|, |b| <= |u - w| ~ 1 here (p is in the disc on u-w), so the squares only
             * underflow for p within ~1e-154 of u or w; hypot takes over then. */
            double aa = ax * ax + ay * ay, bb = bx * bx + by * by;
            double len = aa > 0x1p-900 && bb > 0x1p-900 ? sqrt(aa * bb)
                                                         : hypot(ax, ay) * hypot(bx, by);
            double sin_t = fabs(ax * by - ay * bx) / len;
            if (sin_t < min_sin) min_sin = sin_t;
            if (min_sin - 1 < c0) return min_sin - 1;
        }
    }
    return min_sin < 1 ? min_sin - 1 : 0;
}

typedef struct edges {
    uint32_t *e;
    size_t count, cap;
} edges;

static int edges_add(edges *l, uint32_t a, uint32_t b)
{
    if (l->count == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 1024;
        uint32_t *e = fl_realloc_array(l->e, 2 * cap, sizeof *e);
        if (!e) return -1;
        l->e = e;
        l->cap = cap;
    }
    l->e[2 * l->count] = a;
    l->e[2 * l->count + 1] = b;
    l->count++;
    return 0;
}

/* Extra edges of γ([-1,1],[c0,1]) at inside vertex u towards the vertices at most `hops` steps
 * away in the locked graph. */
static int extra_edges_at(const c2_state *s, const csr *dt, const csr *base, scratch *near,
                          scratch *lens, uint32_t u, int hops, double c0, edges *out)
{
    size_t head = 0, tail = 0;
    next_stamp(near, s->n);
    near->stamp[u] = near->now;
    near->depth[u] = 0;
    near->queue[tail++] = u;
    while (head < tail) {
        uint32_t v = near->queue[head++];
        if (near->depth[v] >= (uint32_t)hops) continue;
        for (size_t i = base->start[v]; i < base->start[v + 1]; i++) {
            uint32_t w = base->nb[i];
            if (near->stamp[w] == near->now) continue;
            near->stamp[w] = near->now;
            near->depth[w] = near->depth[v] + 1;
            near->queue[tail++] = w;
            if (near->depth[w] < 2 || (s->on_boundary[w] == 0 && w < u)) continue;
            if (lens_param(s, dt, lens, u, w, c0) >= c0 && edges_add(out, u, w)) return -1;
        }
    }
    return 0;
}

int c2_push_graph_candidates(c2_state *s, uint32_t a)
{
    csr g = {s->g_start, s->g_nb};
    uint32_t b = s->bnext[a];
    for (size_t i = g.start[a]; i < g.start[a + 1]; i++) {
        uint32_t c = g.nb[i];
        if (s->on_boundary[c] || !csr_has(&g, c, b) || !c2_keep_allows(s, a, b, c)) continue;
        if (fl_orient2d(c2_pt(s, a), c2_pt(s, b), c2_pt(s, c)) <= 0) continue;
        c2_entry e = {c2_key(s, a, b, c, C2_NONE), a, b, c, 0};
        if (c2_heap_push(&s->heap, e)) return -1;
    }
    return 0;
}

/* Edges of the living triangulation (at the lock) and of the Delaunay triangulation. */
static int collect_graphs(const c2_state *s, csr *base, csr *dt)
{
    edges l = {0};
    size_t cap = 3 * (s->tcount > s->dt_count ? s->tcount : s->dt_count) + 1;
    l.e = fl_alloc_array(cap, 2 * sizeof *l.e);
    if (!l.e) return -1;
    l.cap = cap;
    int r = 0;
    for (size_t t = 0; t < s->tcount && !r; t++)
        for (int k = 0; k < 3 && s->alive[t] && !r; k++)
            r = edges_add(&l, s->tri[3 * t + k], s->tri[3 * t + (k + 1) % 3]);
    if (!r) r = csr_build(base, s->n, l.e, l.count);
    l.count = 0;
    const uint32_t *dtt = c2_dt_tri(s);
    for (size_t t = 0; t < s->dt_count && !r; t++)
        for (int k = 0; k < 3 && !r; k++)
            r = edges_add(&l, dtt[3 * t + k], dtt[3 * t + (k + 1) % 3]);
    if (!r) r = csr_build(dt, s->n, l.e, l.count);
    free(l.e);
    return r;
}

/* The graph for one c0: the locked triangulation's edges plus the extra edges. */
static int build_level(c2_state *s, const csr *dt, const csr *base, scratch sc[2], double c0,
                       int hops)
{
    edges l = {0};
    for (size_t v = 0; v < s->n; v++)
        for (size_t i = base->start[v]; i < base->start[v + 1]; i++)
            if (v < base->nb[i] && edges_add(&l, (uint32_t)v, base->nb[i])) goto fail;
    for (size_t v = 0; v < s->n; v++) {
        if (s->on_boundary[v] || s->vtri[v] == C2_NONE) continue;
        if (extra_edges_at(s, dt, base, &sc[0], &sc[1], (uint32_t)v, hops, c0, &l)) goto fail;
    }
    free(s->g_start);
    free(s->g_nb);
    csr g = {0};
    int r = csr_build(&g, s->n, l.e, l.count);
    s->g_start = g.start;
    s->g_nb = g.nb;
    free(l.e);
    return r;
fail:
    free(l.e);
    return -1;
}

fl_status c2_augment(c2_state *s, int levels, double *c0_used, fl_progress_fn progress,
                     void *progress_user, fl_error *err)
{
    csr base = {0}, dt = {0};
    scratch sc[2] = {{0}, {0}};
    fl_status st = FL_OK;
    *c0_used = NAN;
    if (c2_keep_dt(s)) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for flips");
    for (int i = 0; i < 2; i++) {
        sc[i].stamp = fl_calloc_array(s->n, sizeof(uint32_t));
        sc[i].queue = fl_alloc_array(s->n + 2, sizeof(uint32_t));
        sc[i].depth = fl_alloc_array(s->n, sizeof(uint32_t));
    }
    if (!sc[0].stamp || !sc[0].queue || !sc[0].depth || !sc[1].stamp || !sc[1].queue ||
        !sc[1].depth || collect_graphs(s, &base, &dt)) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for the augmented graph");
        goto done;
    }
    s->augmented = 1;
    for (int k = 1; k <= levels && s->boundary_count < s->unique_count; k++) {
        double c0 = k == levels ? -1.0 : -(double)k / levels;
        int hops = k + 2 < 8 ? k + 2 : 8;
        c2_heap_clear(&s->heap);
        int r = build_level(s, &dt, &base, sc, c0, hops);
        for (size_t v = 0; v < s->n && !r; v++)
            if (s->on_boundary[v]) r = c2_push_candidates(s, (uint32_t)v);
        if (r) {
            st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for the augmented graph");
            goto done;
        }
        if ((st = c2_constrict(s, progress, progress_user, err)) != FL_OK) goto done;
        if (s->boundary_count == s->unique_count) *c0_used = c0;
    }
done:
    for (int i = 0; i < 2; i++) {
        free(sc[i].stamp);
        free(sc[i].queue);
        free(sc[i].depth);
    }
    csr_free(&base);
    csr_free(&dt);
    return st;
}
