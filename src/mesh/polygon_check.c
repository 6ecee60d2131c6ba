/* fl_polygon_check: simplicity by a box tree over the edges with exact segment tests,
 * orientation by the exact turn at an extreme vertex, shoelace areas, holes inside. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "mesh/bvh.h"
#include "mesh/intersect.h"

static fl_status validate_polygon(const fl_polygon *pg, fl_error *err)
{
    if (!pg) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "no polygon given");
    if (!pg->vertex_count && !pg->ring_count && !pg->polygon_count) return FL_OK; /* empty */
    if ((pg->vertex_count && !pg->xy) || !pg->ring_start || !pg->polygon_start)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "polygon arrays are NULL");
    if (pg->ring_start[0] != 0 || pg->ring_start[pg->ring_count] != pg->vertex_count)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "rings must cover vertices 0..%zu exactly",
                       pg->vertex_count);
    for (size_t r = 0; r < pg->ring_count; r++)
        if (pg->ring_start[r] > pg->ring_start[r + 1])
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "ring %zu has a negative length", r);
    if (pg->polygon_start[0] != 0 || pg->polygon_start[pg->polygon_count] != pg->ring_count)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "polygons must cover rings 0..%zu exactly",
                       pg->ring_count);
    for (size_t p = 0; p < pg->polygon_count; p++)
        if (pg->polygon_start[p] >= pg->polygon_start[p + 1])
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "polygon %zu has no outer ring", p);
    for (size_t i = 0; i < 2 * pg->vertex_count; i++)
        if (!isfinite(pg->xy[i]))
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "vertex %zu has a non-finite coordinate",
                           i / 2);
    if (pg->vertex_count >= (size_t)1 << 31)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "too many polygon vertices (%zu)",
                       pg->vertex_count);
    return FL_OK;
}

/* Edge i runs from vertex i to the next vertex of its ring (cyclically). */
typedef struct edge_ctx {
    const fl_polygon *pg;
    uint32_t *ring_of; /* ring of each vertex */
    size_t bad_pairs;
    uint32_t first[2]; /* the first bad pair found */
} edge_ctx;

static uint32_t edge_end(const edge_ctx *c, uint32_t e)
{
    size_t r = c->ring_of[e];
    return e + 1 < c->pg->ring_start[r + 1] ? e + 1 : (uint32_t)c->pg->ring_start[r];
}

/* Consecutive edges (a,b), (b,c) meet where they should not iff c lies on the ray from b
 * through a: collinear, and on a's side of b along an axis where a and b differ. */
static int folds_back(const double *a, const double *b, const double *c)
{
    /* a zero-length edge meets its neighbours only at its point; repeated vertices make the
     * ring non-simple on their own */
    if ((a[0] == b[0] && a[1] == b[1]) || (c[0] == b[0] && c[1] == b[1])) return 0;
    if (fl_orient2d(a, b, c) != 0) return 0;
    int k = a[0] != b[0] ? 0 : 1;
    return (a[k] > b[k]) == (c[k] > b[k]) && c[k] != b[k];
}

static int check_edge_pair(void *user, uint32_t e, uint32_t f)
{
    edge_ctx *c = user;
    const double *xy = c->pg->xy;
    uint32_t e1 = edge_end(c, e), f1 = edge_end(c, f);
    int bad;
    if (e1 == f)
        bad = folds_back(xy + 2 * (size_t)e, xy + 2 * (size_t)f, xy + 2 * (size_t)f1);
    else if (f1 == e)
        bad = folds_back(xy + 2 * (size_t)f, xy + 2 * (size_t)e, xy + 2 * (size_t)e1);
    else
        bad = fl_segments_intersect2(xy + 2 * (size_t)e, xy + 2 * (size_t)e1, xy + 2 * (size_t)f,
                                     xy + 2 * (size_t)f1);
    if (bad && c->bad_pairs++ == 0) c->first[0] = e < f ? e : f, c->first[1] = e < f ? f : e;
    return 0;
}

/* Counts improperly meeting edge pairs over the rings with >= 3 vertices and keeps one. */
static fl_status count_edge_intersections(const fl_polygon *pg, fl_polygon_report *rep,
                                          fl_error *err)
{
    size_t nv = pg->vertex_count, n = 0;
    double *boxes = fl_alloc_array(nv, 6 * sizeof(double));
    uint32_t *ids = fl_alloc_array(nv, sizeof(uint32_t));
    edge_ctx c = {pg, fl_alloc_array(nv, sizeof(uint32_t)), 0, {0, 0}};
    fl_status st = FL_OK;
    if (!boxes || !ids || !c.ring_of) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory checking polygon edges");
        goto done;
    }
    for (size_t r = 0; r < pg->ring_count; r++)
        for (size_t v = pg->ring_start[r]; v < pg->ring_start[r + 1]; v++)
            c.ring_of[v] = (uint32_t)r;
    for (size_t r = 0; r < pg->ring_count; r++) {
        if (pg->ring_start[r + 1] - pg->ring_start[r] < 3) continue;
        for (size_t v = pg->ring_start[r]; v < pg->ring_start[r + 1]; v++) {
            const double *a = pg->xy + 2 * v, *b = pg->xy + 2 * (size_t)edge_end(&c, (uint32_t)v);
            double *bx = boxes + 6 * n;
            bx[0] = fmin(a[0], b[0]), bx[1] = fmin(a[1], b[1]), bx[2] = 0.0;
            bx[3] = fmax(a[0], b[0]), bx[4] = fmax(a[1], b[1]), bx[5] = 0.0;
            ids[n++] = (uint32_t)v;
        }
    }
    fl_bvh bvh;
    st = fl_bvh_build(boxes, ids, n, 4, &bvh, err);
    if (st == FL_OK) {
        fl_bvh_self_pairs(&bvh, check_edge_pair, &c, NULL, NULL, NULL);
        fl_bvh_free(&bvh);
        rep->edge_intersections = c.bad_pairs;
        rep->first_crossing[0] = c.first[0], rep->first_crossing[1] = c.first[1];
    }
done:
    free(boxes);
    free(ids);
    free(c.ring_of);
    return st;
}

/* Orientation of ring [s, e): the exact turn at its lowest-leftmost vertex, skipping
 * neighbours that repeat it. That vertex is convex in a simple ring, so the turn there is the
 * ring's orientation. */
static int ring_orientation(const double *xy, size_t s, size_t e)
{
    size_t n = e - s, m = s;
    if (n < 3) return 0;
    for (size_t i = s + 1; i < e; i++)
        if (xy[2 * i] < xy[2 * m] || (xy[2 * i] == xy[2 * m] && xy[2 * i + 1] < xy[2 * m + 1]))
            m = i;
    const double *v = xy + 2 * m;
    size_t p = m, q = m;
    for (size_t k = 0; k < n; k++) {
        p = p == s ? e - 1 : p - 1;
        if (xy[2 * p] != v[0] || xy[2 * p + 1] != v[1]) break;
    }
    for (size_t k = 0; k < n; k++) {
        q = q + 1 == e ? s : q + 1;
        if (xy[2 * q] != v[0] || xy[2 * q + 1] != v[1]) break;
    }
    return fl_orient2d(xy + 2 * p, v, xy + 2 * q);
}

/* Shoelace area relative to the ring's first vertex (smaller terms, less cancellation). */
static double ring_signed_area(const double *xy, size_t s, size_t e)
{
    double sum = 0.0;
    for (size_t i = s + 1; i + 1 < e; i++) {
        double ax = xy[2 * i] - xy[2 * s], ay = xy[2 * i + 1] - xy[2 * s + 1];
        double bx = xy[2 * i + 2] - xy[2 * s], by = xy[2 * i + 3] - xy[2 * s + 1];
        sum += ax * by - ay * bx;
    }
    return 0.5 * sum;
}

/* Exact crossing-number test of point p against ring [s, e); p must not be on the ring. */
static int point_in_ring(const double *p, const double *xy, size_t s, size_t e)
{
    int inside = 0;
    for (size_t i = s; i < e; i++) {
        const double *a = xy + 2 * i, *b = xy + 2 * (i + 1 == e ? s : i + 1);
        if ((a[1] > p[1]) == (b[1] > p[1])) continue;
        /* the edge crosses the horizontal line through p; it crosses to the right of p iff p
         * is left of the edge directed upward */
        int o = fl_orient2d(a, b, p);
        if ((b[1] > a[1]) ? o > 0 : o < 0) inside = !inside;
    }
    return inside;
}

static void summarize_rings(const fl_polygon *pg, fl_polygon_report *rep)
{
    int outer_ccw = 1, outer_cw = 1;
    for (size_t p = 0; p < pg->polygon_count; p++) {
        double area = 0.0;
        for (size_t r = pg->polygon_start[p]; r < pg->polygon_start[p + 1]; r++) {
            size_t s = pg->ring_start[r], e = pg->ring_start[r + 1];
            int hole = r != pg->polygon_start[p], o = ring_orientation(pg->xy, s, e);
            rep->ring_orientation[r] = o;
            rep->ring_area[r] = ring_signed_area(pg->xy, s, e);
            area += hole ? -fabs(rep->ring_area[r]) : fabs(rep->ring_area[r]);
            outer_ccw &= o == (hole ? -1 : 1);
            outer_cw &= o == (hole ? 1 : -1);
            if (hole && rep->holes_inside == 1 && e > s) {
                size_t os = pg->ring_start[pg->polygon_start[p]];
                size_t oe = pg->ring_start[pg->polygon_start[p] + 1];
                if (!point_in_ring(pg->xy + 2 * s, pg->xy, os, oe)) rep->holes_inside = 0;
            }
        }
        rep->area += area;
    }
    rep->orientation = outer_ccw ? 1 : outer_cw ? -1 : 0;
}

fl_status fl_polygon_check(const fl_polygon *polygon, fl_polygon_report *report, fl_error *err)
{
    if (!report) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "no report given");
    memset(report, 0, sizeof *report);
    fl_status st = validate_polygon(polygon, err);
    if (st != FL_OK) return st;
    const fl_polygon *pg = polygon;
    report->vertices = pg->vertex_count;
    report->rings = pg->ring_count;
    report->polygons = pg->polygon_count;
    report->holes = pg->ring_count - pg->polygon_count;
    report->ring_orientation = fl_calloc_array(pg->ring_count, sizeof(int));
    report->ring_area = fl_calloc_array(pg->ring_count, sizeof(double));
    if (!report->ring_orientation || !report->ring_area) {
        fl_polygon_report_free(report);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory checking polygon");
    }
    st = count_edge_intersections(pg, report, err);
    if (st != FL_OK) {
        fl_polygon_report_free(report);
        return st;
    }
    int short_ring = 0, repeated = 0;
    for (size_t r = 0; r < pg->ring_count; r++) {
        size_t s = pg->ring_start[r], e = pg->ring_start[r + 1];
        short_ring |= e - s < 3;
        for (size_t i = s; i < e; i++) {
            size_t j = i + 1 == e ? s : i + 1;
            repeated |= pg->xy[2 * i] == pg->xy[2 * j] && pg->xy[2 * i + 1] == pg->xy[2 * j + 1];
        }
    }
    report->simple = !short_ring && !repeated && report->edge_intersections == 0;
    report->holes_inside = report->simple ? 1 : -1;
    summarize_rings(pg, report);
    return FL_OK;
}

void fl_polygon_report_free(fl_polygon_report *report)
{
    if (!report) return;
    free(report->ring_orientation);
    free(report->ring_area);
    memset(report, 0, sizeof *report);
}
