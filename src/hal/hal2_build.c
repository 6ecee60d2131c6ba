/* Construction of the 2D flintstone trees (thesis §7.2.1-7.2.2, Algorithm 7.1; HAL paper §3).
 * A polyline v_p..v_s is localized by its flintstone (Def. 7.3): v_q, the vertex left of
 * v_p v_s whose disc D(v_p, v_s; v_q) holds all left vertices, and v_r likewise on the right.
 * Both are found exactly: a candidate is replaced when the next vertex on its side lies strictly
 * outside its circle (fl_incircle). Because every polyline lies in one disc through its end
 * points (HAL Thm. 1), D(v_q) ∩ D(v_r) holds it and the split vertex is the one whose disc has
 * the larger signed radius, i.e. the larger width (Def. 7.4; both grow with the centre's
 * offset towards the vertex). The exactly checked preconditions of Thm. 1 (no vertex on the
 * line outside the segment, v_r inside D(v_q)) can only fail below a root whose disc is not
 * exactly the smallest one; such a node falls back to one plain bounding disc. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "hal/hal2_internal.h"

/* Certificates add this relative margin to cover the rounding of the width formulas (errors
 * of a few ulps of the segment length and width). */
#define WIDTH_MARGIN 1e-10

typedef struct ring_ctx {
    const double *xy;
    uint32_t first, n;
} ring_ctx;

static const double *vtx(const ring_ctx *r, uint32_t k)
{
    return r->xy + 2 * (size_t)(r->first + k % r->n);
}

static uint32_t gidx(const ring_ctx *r, uint32_t k)
{
    return r->first + k % r->n;
}

/* Width (Def. 7.4) of the disc through p, s, k on k's side of p s and that disc's centre.
 * With the chord of half-length h on the x axis and k at (x, y), y > 0, the centre is at
 * height c = (x^2 + y^2 - h^2) / (2y) and the width is R + c, R = sqrt(h^2 + c^2); for c < 0 the
 * equal form h^2 / (R - c) avoids cancellation when the disc is huge and flat. */
static double disc_width(const double *p, const double *s, const double *k, double centre[2])
{
    double mx = p[0] + (s[0] - p[0]) / 2, my = p[1] + (s[1] - p[1]) / 2;
    double dx = s[0] - p[0], dy = s[1] - p[1], len = hypot(dx, dy), h = len / 2;
    double ux = dx / len, uy = dy / len;
    /* x^2 - h^2 = (x - h)(x + h) with x - h = (k - s).u and x + h = (k - p).u, and y from the
     * nearer chord end: computed from k - mid they cancel catastrophically when k nearly
     * coincides with p or s (found by fuzz/fuzz_hal2.c: k 1e-100 from s gave a width of 1.39
     * instead of 3.46, so the certified error missed a vertex; tests/degenerate). */
    double xm = (k[0] - s[0]) * ux + (k[1] - s[1]) * uy;
    double xp = (k[0] - p[0]) * ux + (k[1] - p[1]) * uy;
    const double *e = fabs(xm) < fabs(xp) ? s : p;
    double y = -(k[0] - e[0]) * uy + (k[1] - e[1]) * ux; /* signed: > 0 left of p s */
    double nx = -uy, ny = ux;
    if (y < 0) y = -y, nx = -nx, ny = -ny;
    double c = (xm * xp + y * y) / (2 * y), r = hypot(h, c);
    centre[0] = mx + c * nx;
    centre[1] = my + c * ny;
    if (!(isfinite(centre[0]) && isfinite(centre[1]))) centre[0] = mx, centre[1] = my;
    if (!isfinite(c)) return c > 0 ? INFINITY : 0;
    return c >= 0 ? r + c : h * h / (r - c);
}

/* r^2 of the disc with the given centre: the largest computed squared distance to v_p..v_s. */
static void fit_disc(const ring_ctx *r, uint32_t p, uint32_t s, double disc[3])
{
    disc[2] = 0;
    for (uint32_t k = p; k <= s; k++) {
        const double *v = vtx(r, k);
        double d = fl_hal2_d2(disc, v[0], v[1]);
        if (d > disc[2]) disc[2] = d;
    }
}

/* Distance from v to the segment a b (floating). */
static double segment_distance(const double *a, const double *b, const double *v)
{
    double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((v[0] - a[0]) * dx + (v[1] - a[1]) * dy) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(v[0] - (a[0] + t * dx), v[1] - (a[1] + t * dy));
}

/* The plain-disc fallback: centre at the chord's midpoint, split at the farthest vertex. */
static void make_fallback(const ring_ctx *r, uint32_t p, uint32_t s, fl_hal2_node *nd)
{
    const double *a = vtx(r, p), *b = vtx(r, s);
    double worst = -1;
    uint32_t q = p + 1;
    for (uint32_t k = p + 1; k < s; k++) {
        double d = segment_distance(a, b, vtx(r, k));
        if (isnan(d)) d = INFINITY; /* overflowed coordinates: no finite bound */
        if (d > worst) worst = d, q = k;
    }
    nd->kind = FL_HAL2_DISC;
    nd->q = nd->r = q;
    nd->disc[0][0] = a[0] + (b[0] - a[0]) / 2;
    nd->disc[0][1] = a[1] + (b[1] - a[1]) / 2;
    fit_disc(r, p, s, nd->disc[0]);
    nd->width[0] = worst;
    nd->width[1] = 0;
    nd->error = worst + WIDTH_MARGIN * (worst + hypot(b[0] - a[0], b[1] - a[1]));
}

static int on_segment_collinear(const double *a, const double *b, const double *v)
{
    return fmin(a[0], b[0]) <= v[0] && v[0] <= fmax(a[0], b[0]) && fmin(a[1], b[1]) <= v[1] &&
           v[1] <= fmax(a[1], b[1]);
}

/* Def. 7.3: the extreme vertices left (*ql) and right (*qr) of v_p v_s, or UINT32_MAX when a
 * side is empty; returns 1 when some vertex is on the line but off the segment. */
static int extreme_vertices(const ring_ctx *r, uint32_t p, uint32_t s, uint32_t *ql, uint32_t *qr)
{
    const double *a = vtx(r, p), *b = vtx(r, s);
    int off_segment = 0;
    *ql = *qr = UINT32_MAX;
    for (uint32_t k = p + 1; k < s; k++) {
        const double *v = vtx(r, k);
        int o = fl_orient2d(a, b, v);
        if (o > 0) {
            if (*ql == UINT32_MAX || fl_incircle(a, b, vtx(r, *ql), v) < 0) *ql = k;
        } else if (o < 0) {
            if (*qr == UINT32_MAX || fl_incircle(a, b, vtx(r, *qr), v) > 0) *qr = k;
        } else if (!on_segment_collinear(a, b, v)) {
            off_segment = 1;
        }
    }
    return off_segment;
}

/* Fills the flintstone of v_p..v_s (local unrolled indices, s >= p + 2) into nd. */
static void make_flintstone(const ring_ctx *r, uint32_t p, uint32_t s, fl_hal2_node *nd)
{
    const double *a = vtx(r, p), *b = vtx(r, s);
    uint32_t ql, qr;
    int off = extreme_vertices(r, p, s, &ql, &qr);
    int both = ql != UINT32_MAX && qr != UINT32_MAX;
    if (off || (both && fl_incircle(a, b, vtx(r, ql), vtx(r, qr)) < 0)) {
        make_fallback(r, p, s, nd);
        return;
    }
    double len = hypot(b[0] - a[0], b[1] - a[1]);
    if (ql == UINT32_MAX && qr == UINT32_MAX) { /* a collinear run on the segment */
        nd->kind = FL_HAL2_SEGMENT;
        nd->q = nd->r = p + (s - p) / 2;
        nd->disc[0][0] = a[0] + (b[0] - a[0]) / 2;
        nd->disc[0][1] = a[1] + (b[1] - a[1]) / 2;
        fit_disc(r, p, s, nd->disc[0]);
        nd->width[0] = nd->width[1] = 0;
        nd->error = WIDTH_MARGIN * len;
        return;
    }
    double cl[2], cr[2];
    double wl = ql != UINT32_MAX ? disc_width(a, b, vtx(r, ql), cl) : -1;
    double wr = qr != UINT32_MAX ? disc_width(a, b, vtx(r, qr), cr) : -1;
    if (isnan(wl) || isnan(wr)) { /* overflow near DBL_MAX (fuzz_hal2): no usable disc */
        make_fallback(r, p, s, nd);
        return;
    }
    /* Split at the disc of larger signed radius (Alg. 7.1); a lone side is always taken. */
    int left_first = both ? wl >= wr : ql != UINT32_MAX;
    nd->q = left_first ? ql : qr;
    nd->r = both ? (left_first ? qr : ql) : nd->q;
    nd->width[0] = left_first ? wl : wr;
    nd->disc[0][0] = left_first ? cl[0] : cr[0];
    nd->disc[0][1] = left_first ? cl[1] : cr[1];
    fit_disc(r, p, s, nd->disc[0]);
    if (both) {
        nd->kind = FL_HAL2_TWO_DISCS;
        nd->width[1] = left_first ? wr : wl;
        nd->disc[1][0] = left_first ? cr[0] : cl[0];
        nd->disc[1][1] = left_first ? cr[1] : cl[1];
        fit_disc(r, p, s, nd->disc[1]);
    } else {
        nd->kind = FL_HAL2_DISC_HALFPLANE;
        nd->side = ql != UINT32_MAX ? 1 : -1;
        nd->width[1] = 0;
    }
    double w = fmax(nd->width[0], nd->width[1]);
    nd->error = w + WIDTH_MARGIN * (w + len);
}

/* Grows subtrees depth first from the pending polylines stack[0..top-1] (Algorithm 7.1, depth
 * first instead of level by level: the nodes are the same). The stack needs room for one entry
 * a vertex of the ring; hal->nodes for one node a vertex. */
static void grow(fl_hal2 *hal, fl_hal2_ring *rg, hal2_pending *stack, size_t top)
{
    ring_ctx r = {hal->polygon.xy, rg->first, rg->count};
    while (top > 0) {
        hal2_pending w = stack[--top];
        size_t id = hal->node_count++;
        fl_hal2_node *nd = &hal->nodes[id];
        memset(nd, 0, sizeof *nd);
        make_flintstone(&r, w.p, w.s, nd);
        if (nd->q <= w.p || nd->q >= w.s) make_fallback(&r, w.p, w.s, nd); /* keeps p < q < s */
        *w.slot = (int32_t)id;
        uint32_t q = nd->q;
        nd->p = gidx(&r, w.p);
        nd->s = gidx(&r, w.s);
        nd->r = gidx(&r, nd->r);
        nd->edges = w.s - w.p;
        nd->level = w.level;
        nd->child[0] = nd->child[1] = -1;
        nd->q = gidx(&r, q);
        if (w.level > rg->depth) rg->depth = w.level;
        if (q - w.p >= 2) stack[top++] = (hal2_pending){w.p, q, w.level + 1, &nd->child[0]};
        if (w.s - q >= 2) stack[top++] = (hal2_pending){q, w.s, w.level + 1, &nd->child[1]};
    }
}

void fl_hal2_build_ring(fl_hal2 *hal, uint32_t ring, uint32_t *order, hal2_pending *stack)
{
    fl_hal2_ring *rg = &hal->rings[ring];
    for (uint32_t k = 0; k < rg->count; k++)
        order[k] = rg->first + k;
    uint32_t i, j;
    fl_hal2_sbd(hal->polygon.xy, order, rg->count, &i, &j, rg->disc);
    if (i > j) {
        uint32_t t = i;
        i = j;
        j = t;
    }
    rg->root[0] = i;
    rg->root[1] = j;
    rg->child[0] = rg->child[1] = -1;
    rg->depth = 0;
    uint32_t li = i - rg->first, lj = j - rg->first;
    size_t top = 0;
    if (lj - li >= 2) stack[top++] = (hal2_pending){li, lj, 1, &rg->child[0]};
    if (li + rg->count - lj >= 2)
        stack[top++] = (hal2_pending){lj, li + rg->count, 1, &rg->child[1]};
    grow(hal, rg, stack, top);
}

void fl_hal2_rebuild_node(fl_hal2 *hal, uint32_t ring, int32_t *slot, uint32_t p, uint32_t s,
                          uint32_t level, hal2_pending *stack)
{
    fl_hal2_ring *rg = &hal->rings[ring];
    stack[0] = (hal2_pending){p, s, level, slot};
    grow(hal, rg, stack, 1);
}

/* Checks the polygon's ranges and coordinates; the ring count limit keeps indices in int32. */
static fl_status check_polygon(const fl_polygon *pg, size_t *max_ring, fl_error *err)
{
    if (pg->vertex_count > 0x7FFFFFFF)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "hal2: more than 2^31 vertices");
    if ((pg->vertex_count && !pg->xy) || (pg->ring_count && !pg->ring_start) ||
        (pg->polygon_count && !pg->polygon_start))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "hal2: polygon arrays missing");
    if (pg->ring_count &&
        (pg->ring_start[0] != 0 || pg->ring_start[pg->ring_count] != pg->vertex_count))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "hal2: rings do not span the vertices");
    if (pg->polygon_count &&
        (pg->polygon_start[0] != 0 || pg->polygon_start[pg->polygon_count] != pg->ring_count))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "hal2: polygons do not span the rings");
    for (size_t p = 0; p < pg->polygon_count; p++)
        if (pg->polygon_start[p + 1] < pg->polygon_start[p])
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "hal2: polygon %zu has a bad range", p);
    *max_ring = 0;
    for (size_t r = 0; r < pg->ring_count; r++) {
        if (pg->ring_start[r + 1] < pg->ring_start[r] + 3)
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "hal2: ring %zu has fewer than 3 vertices",
                           r);
        size_t n = pg->ring_start[r + 1] - pg->ring_start[r];
        if (n > *max_ring) *max_ring = n;
    }
    for (size_t k = 0; k < 2 * pg->vertex_count; k++)
        if (!isfinite(pg->xy[k]))
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "hal2: vertex %zu is not finite", k / 2);
    return FL_OK;
}

static fl_status copy_polygon(const fl_polygon *pg, fl_polygon *out)
{
    out->vertex_count = pg->vertex_count;
    out->ring_count = pg->ring_count;
    out->polygon_count = pg->polygon_count;
    out->xy = fl_alloc_array(2 * pg->vertex_count + 1, sizeof(double));
    out->ring_start = fl_alloc_array(pg->ring_count + 1, sizeof(size_t));
    out->polygon_start = fl_alloc_array(pg->polygon_count + 1, sizeof(size_t));
    if (!out->xy || !out->ring_start || !out->polygon_start) return FL_ERR_NOMEM;
    if (pg->vertex_count) memcpy(out->xy, pg->xy, 2 * pg->vertex_count * sizeof(double));
    if (pg->ring_count)
        memcpy(out->ring_start, pg->ring_start, (pg->ring_count + 1) * sizeof(size_t));
    else
        out->ring_start[0] = 0;
    if (pg->polygon_count)
        memcpy(out->polygon_start, pg->polygon_start, (pg->polygon_count + 1) * sizeof(size_t));
    else
        out->polygon_start[0] = 0;
    return FL_OK;
}

fl_status fl_hal2_build(const fl_polygon *polygon, const fl_hal2_options *opt, fl_hal2 *out,
                        fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal2_build: out is NULL");
    memset(out, 0, sizeof *out);
    if (!polygon) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal2_build: polygon is NULL");
    size_t max_ring = 0;
    fl_status st = check_polygon(polygon, &max_ring, err);
    if (st != FL_OK) return st;
    uint32_t *order = fl_alloc_array(max_ring + 1, sizeof(uint32_t));
    hal2_pending *stack = fl_alloc_array(max_ring + 1, sizeof(hal2_pending));
    out->rings = fl_calloc_array(polygon->ring_count + 1, sizeof(fl_hal2_ring));
    out->nodes = fl_alloc_array(polygon->vertex_count + 1, sizeof(fl_hal2_node));
    if (!order || !stack || !out->rings || !out->nodes || copy_polygon(polygon, &out->polygon)) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal2_build: out of memory");
        goto done;
    }
    for (size_t r = 0; r < polygon->ring_count; r++) {
        if (opt && fl_progress(opt->progress, opt->progress_user, "flintstones",
                               (double)r / (double)polygon->ring_count)) {
            st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
            goto done;
        }
        out->rings[r].first = (uint32_t)polygon->ring_start[r];
        out->rings[r].count = (uint32_t)(polygon->ring_start[r + 1] - polygon->ring_start[r]);
        fl_hal2_build_ring(out, (uint32_t)r, order, stack);
        if (out->rings[r].depth > out->depth) out->depth = out->rings[r].depth;
    }
done:
    free(order);
    free(stack);
    if (st != FL_OK) fl_hal2_free(out);
    return st;
}

void fl_hal2_free(fl_hal2 *hal)
{
    if (!hal) return;
    fl_polygon_free(&hal->polygon);
    free(hal->rings);
    free(hal->nodes);
    memset(hal, 0, sizeof *hal);
}
