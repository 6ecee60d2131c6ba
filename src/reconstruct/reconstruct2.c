/* fl_reconstruct2: the public entry of 2D boundary construction. Builds the Delaunay
 * triangulation, sets up the pruned-graph state on it, runs constriction (constrict2.c), the
 * augmentation when locked (augment2.c), and extracts the polygon and its triangles. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay_internal.h"
#include "reconstruct/constrict2_internal.h"

static void state_free(c2_state *s)
{
    free(s->adj);
    free(s->dt_copy);
    if (!s->lent) {
        free(s->alive);
        free(s->on_boundary);
        free(s->bnext);
    }
    free(s->vtri);
    free(s->btri);
    free(s->keep_nb);
    free(s->orig);
    free(s->inv);
    free(s->xy_store);
    free(s->g_start);
    free(s->g_nb);
    c2_heap_free(&s->heap);
    free(s->tri); /* after the heap: the spare memory in it may hold the parked entries */
    memset(s, 0, sizeof *s);
}

int c2_keep_dt(c2_state *s)
{
    c2_settle_adj(s);
    if (s->dt_copy) return 0;
    if (!s->vtri) s->vtri = fl_alloc_array(s->n, sizeof *s->vtri);
    if (!s->vtri) return -1;
    s->dt_copy = fl_alloc_array(3 * s->dt_count, sizeof *s->dt_copy);
    if (!s->dt_copy) return -1;
    memcpy(s->dt_copy, s->tri, 3 * s->dt_count * sizeof *s->tri);
    for (size_t v = 0; v < s->n; v++)
        s->vtri[v] = C2_NONE;
    for (size_t t = 0; t < s->tcount; t++)
        for (int k = 0; k < 3 && s->alive[t]; k++)
            s->vtri[s->tri[3 * t + k]] = (uint32_t)t;
    return 0;
}

/* inv[] (input index -> internal index, duplicates included), made only when input indices
 * must be mapped in (kept edges); constriction itself never needs it. */
static fl_status make_inv(c2_state *s, const fl_dt2_ranked *dt, fl_error *err)
{
    s->inv = fl_alloc_array(s->n_input, sizeof *s->inv);
    if (!s->inv)
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for %zu points", s->n_input);
    for (size_t r = 0; r < s->n; r++)
        s->inv[s->orig[r]] = (uint32_t)r;
    /* duplicate_of[v] <= v, so the first of its kind is mapped already */
    for (size_t v = 0; v < s->n_input; v++)
        if (dt->duplicate_of[v] != v) s->inv[v] = s->inv[dt->duplicate_of[v]];
    return FL_OK;
}

/* The per-vertex and per-triangle flags, the boundary links and the queue's parked entries go
 * into the builder's spare memory (the second half of its triangle records, about 24 bytes a
 * point, touched during the build) instead of fresh pages: on this kind of machine the first
 * touch of a page costs a fault of several microseconds, and at 1e6 points these arrays were
 * some 5000 pages. 1 when they fit (always for a triangulation of >= 3 points). */
static int lend_spare(c2_state *s, const fl_dt2_ranked *dt)
{
    size_t n = s->n, tc = s->tcount;
    size_t need = n * sizeof *s->bnext + tc + n;
    if (!dt->spare || dt->spare_bytes < need + 8) return 0;
    unsigned char *p = dt->spare;
    s->bnext = (uint32_t *)(void *)p;
    s->alive = p + n * sizeof *s->bnext;
    s->on_boundary = s->alive + tc;
    memset(s->on_boundary, 0, n);
    size_t used = (need + 7) & ~(size_t)7;
    s->lent = 1;
    c2_heap_lend(&s->heap, p + used, dt->spare_bytes - used);
    return 1;
}

/* Line 2 of Algorithm 5.1: the boundary of γ([-1,1],[0,1]) is the convex hull. The state takes
 * over the triangulation's triangles, neighbours, coordinates and insertion order instead of
 * copying them (the 1e6-point curve spent a tenth of its constriction time in a copy and its
 * page faults, and more in gathering the shuffled input into a spatial order the builder had
 * already made); a copy of the triangles is made only if flips are going to change them
 * (c2_keep_dt). */
static fl_status state_init(c2_state *s, fl_dt2_ranked *dt, fl_reconstruct2_criterion criterion,
                            int want_inv, fl_error *err)
{
    size_t n = dt->unique_count, tc = dt->triangle_count;
    memset(s, 0, sizeof *s);
    s->n = n;
    s->n_input = dt->point_count;
    s->unique_count = n;
    s->tcount = tc;
    s->criterion = criterion;
    s->lazy_adj = criterion != FL_RECONSTRUCT2_VORONOI_SKELETON;
    s->dt_count = tc;
    s->tri = dt->tri;
    s->adj = dt->adj;
    s->orig = dt->order;
    s->xy = s->xy_store = dt->xy;
    s->heap.orig = s->orig;
    s->heap.xy = s->xy;
    dt->tri = dt->adj = dt->order = NULL;
    dt->xy = NULL;
    fl_status st = want_inv ? make_inv(s, dt, err) : FL_OK;
    if (st != FL_OK) return st;
    /* duplicate_of (n_input >= n entries, written by the duplicate detection) is not read after
     * make_inv: it becomes btri, and later the result's polygon, without fresh pages */
    s->btri = dt->duplicate_of;
    dt->duplicate_of = NULL;
    if (!lend_spare(s, dt)) {
        s->alive = fl_alloc_array(tc, 1);
        s->on_boundary = fl_calloc_array(n, 1);
        s->bnext = fl_alloc_array(n, sizeof *s->bnext);
    }
    if (!s->alive || !s->on_boundary || !s->bnext)
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for %zu points", n);
    memset(s->alive, 1, tc);
    for (size_t i = 0; i < n; i++)
        s->bnext[i] = s->btri[i] = C2_NONE;
    for (size_t t = 0; t < tc; t++)
        for (int k = 0; k < 3; k++)
            if (s->adj[3 * t + k] == C2_NONE) s->btri[s->tri[3 * t + (k + 1) % 3]] = (uint32_t)t;
    for (size_t i = 0; i < dt->hull_count; i++) {
        uint32_t v = dt->hull[i];
        s->on_boundary[v] = 1;
        s->bnext[v] = dt->hull[(i + 1) % dt->hull_count];
    }
    s->boundary_count = dt->hull_count;
    return FL_OK;
}

static fl_status push_hull(c2_state *s, const fl_dt2_ranked *dt, fl_error *err)
{
    for (size_t i = 0; i < dt->hull_count; i++)
        if (c2_push_candidates(s, dt->hull[i]))
            return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for the heap");
    return FL_OK;
}

/* Why not every point made it, in words a user can act on (empty when all did). */
static void explain(const c2_state *s, const fl_reconstruct2_options *o, double c0_tried,
                    fl_reconstruction2 *out)
{
    size_t inside = s->unique_count - s->boundary_count;
    out->all_on_boundary = 0;
    if (inside > 0) {
        if (o->extra_levels < 0)
            snprintf(out->reason, sizeof out->reason,
                     "constriction of the Delaunay triangulation locked with %zu point(s) inside "
                     "and augmentation is disabled",
                     inside);
        else
            snprintf(out->reason, sizeof out->reason,
                     "constriction locked with %zu point(s) inside, even with the edges of "
                     "gamma([-1,1],[%g,1])%s",
                     inside, c0_tried, o->keep_count ? "; the kept edges may block it" : "");
        return;
    }
    for (size_t i = 0; i < s->n_input && s->keep_nb; i++) {
        uint32_t v = s->inv[i];
        if (s->orig[v] != i) continue; /* a duplicate */
        for (int j = 0; j < 2; j++) {
            uint32_t w = s->keep_nb[2 * (size_t)v + j];
            if (w == C2_NONE || s->bnext[v] == w || s->bnext[w] == v) continue;
            snprintf(out->reason, sizeof out->reason,
                     "kept edge %zu-%u ends up inside the polygon, not on its boundary: no "
                     "constriction keeps it",
                     i, s->orig[w]);
            return;
        }
    }
    out->all_on_boundary = 1;
}

/* Hands over *buf (room for at least `count` entries) trimmed to `count`; *buf becomes NULL. */
static uint32_t *take(uint32_t **buf, size_t count)
{
    uint32_t *p = *buf, *q = realloc(p, count ? count * sizeof *p : 1);
    *buf = NULL;
    return q ? q : p;
}

/* The result's polygon and triangles go into memory the state no longer needs (btri: one entry
 * per vertex; adj: three per Delaunay triangle, and the living triangles are a subset): fresh
 * pages cost a page fault each on first touch, about a tenth of this function's time at 1e6
 * points. Neither is read from here on (the listing reads bnext, the triangles tri). */
static fl_status extract(c2_state *s, const fl_dt2_ranked *dt, fl_reconstruction2 *out,
                         fl_error *err)
{
    size_t live = 0;
    for (size_t t = 0; t < s->tcount; t++)
        live += s->alive[t];
    out->boundary = take(&s->btri, s->boundary_count);
    out->tri = take(&s->adj, 3 * live);
    /* hull vertices never leave the boundary */
    if (c2_boundary_order(s, dt->hull[0], out->boundary))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for the result");
    double area2 = 0;
    for (size_t i = 0, m = s->boundary_count; i < m; i++) {
        const double *p = c2_pt(s, out->boundary[i]);
        const double *q = c2_pt(s, out->boundary[i + 1 < m ? i + 1 : 0]);
        area2 += p[0] * q[1] - p[1] * q[0];
    }
    for (size_t i = 0; i < s->boundary_count; i++)
        out->boundary[i] = s->orig[out->boundary[i]];
    out->boundary_count = s->boundary_count;
    size_t j = 0;
    for (size_t t = 0; t < s->tcount; t++)
        if (s->alive[t]) {
            for (int k = 0; k < 3; k++)
                out->tri[3 * j + k] = s->orig[s->tri[3 * t + k]];
            j++;
        }
    out->triangle_count = live;
    out->area = area2 / 2;
    return FL_OK;
}

static fl_status run(const double *xy, size_t n, const fl_reconstruct2_options *o,
                     fl_reconstruction2 *out, fl_dt2_ranked *dt, c2_state *s, fl_error *err)
{
    fl_dt2_options dopt = {o->progress, o->progress_user, 0};
    fl_status st = fl_dt2_build_ranked(xy, n, &dopt, dt, err);
    if (st != FL_OK) return st;
    if ((st = state_init(s, dt, o->criterion, o->keep_count > 0, err)) != FL_OK) return st;
    if (o->keep_count && (st = c2_keep_edges(s, s->inv, o->keep, o->keep_count, err)) != FL_OK)
        return st;
    if ((st = push_hull(s, dt, err)) != FL_OK) return st;
    if ((st = c2_constrict(s, o->progress, o->progress_user, err)) != FL_OK) return st;
    double c0 = NAN, tried = 0;
    if (s->boundary_count < s->unique_count && o->extra_levels >= 0) {
        int levels = o->extra_levels ? o->extra_levels : 10;
        st = c2_augment(s, levels, &c0, o->progress, o->progress_user, err);
        if (st != FL_OK) return st;
        tried = -1;
    }
    out->point_count = n;
    out->unique_count = dt->unique_count;
    out->augmented_c0 = c0;
    explain(s, o, tried, out);
    if ((st = extract(s, dt, out, err)) != FL_OK) return st;
    out->delaunay_count = s->dt_count;
    uint32_t **dtt = s->dt_copy ? &s->dt_copy : &s->tri;
    for (size_t i = 0; i < 3 * s->dt_count; i++)
        (*dtt)[i] = s->orig[(*dtt)[i]];
    /* the spare memory behind the triangles (the state's flags) is not read any more */
    out->delaunay_tri = take(dtt, 3 * s->dt_count);
    return FL_OK;
}

fl_status fl_reconstruct2(const double *xy, size_t n, const fl_reconstruct2_options *opt,
                          fl_reconstruction2 *out, fl_error *err)
{
    if (out) memset(out, 0, sizeof *out);
    if (!out || (!xy && n > 0))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_reconstruct2: NULL buffer");
    fl_reconstruct2_options o = {0};
    if (opt) o = *opt;
    if (o.criterion < FL_RECONSTRUCT2_GAMMA || o.criterion > FL_RECONSTRUCT2_VORONOI_SKELETON)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "unknown constriction criterion %d",
                       (int)o.criterion);
    if (o.keep_count && !o.keep)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "keep_count is %zu but keep is NULL",
                       o.keep_count);
    fl_dt2_ranked dt = {0};
    c2_state s;
    memset(&s, 0, sizeof s);
    fl_status st = run(xy, n, &o, out, &dt, &s, err);
    state_free(&s);
    fl_dt2_ranked_free(&dt);
    if (st != FL_OK) fl_reconstruction2_free(out);
    return st;
}

fl_status fl_reconstruct2_criterion_parse(const char *text, fl_reconstruct2_criterion *criterion,
                                          fl_error *err)
{
    static const char *names[] = {"gamma", "area-change", "voronoi-skeleton"};
    for (int i = 0; i < 3; i++)
        if (text && criterion && strcmp(text, names[i]) == 0) {
            *criterion = (fl_reconstruct2_criterion)i;
            return FL_OK;
        }
    return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                   "unknown criterion '%s' (expected gamma, area-change or voronoi-skeleton)",
                   text ? text : "(null)");
}

void fl_reconstruction2_free(fl_reconstruction2 *rec)
{
    if (!rec) return;
    free(rec->boundary);
    free(rec->tri);
    free(rec->delaunay_tri);
    memset(rec, 0, sizeof *rec);
}
