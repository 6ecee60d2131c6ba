/* G1 boundary curves of cubic Bézier segments through the vertices of closed polygons
 * (thesis §9.2): a tangent estimated at every vertex, inner control points by the projection
 * heuristic, and a repair where the G1 orientation condition fails. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"

/* Index of the vertex after / before i inside ring [lo, hi). */
static size_t ring_next(size_t i, size_t lo, size_t hi)
{
    return i + 1 < hi ? i + 1 : lo;
}
static size_t ring_prev(size_t i, size_t lo, size_t hi)
{
    return i > lo ? i - 1 : hi - 1;
}

static void normalize2(double *v)
{
    double n = hypot(v[0], v[1]);
    v[0] /= n;
    v[1] /= n;
}

/* §9.2 methods 1-3: weights 1 (length: the sum is v_{i+1} - v_{i-1}), 1/|d| (uniform: unit
 * vectors) and 1/|d|^2 (inverse length) on the two edge vectors d. */
static void estimate_tangent(const double *a, const double *v, const double *b, int weighting,
                             double *t)
{
    double d0[2] = {v[0] - a[0], v[1] - a[1]}, d1[2] = {b[0] - v[0], b[1] - v[1]};
    double l0 = hypot(d0[0], d0[1]), l1 = hypot(d1[0], d1[1]);
    /* Divide, and scale the inverse weights by l0 l1: 1 / l and 1 / l^2 overflowed to inf for
     * an edge of 2e-323 and the tangent became NaN (found by fuzz/fuzz_smooth.c). Only the
     * direction of t matters. */
    double u0[2] = {d0[0] / l0, d0[1] / l0}, u1[2] = {d1[0] / l1, d1[1] / l1};
    if (weighting == FL_G1_WEIGHT_UNIFORM) {
        t[0] = u0[0] + u1[0];
        t[1] = u0[1] + u1[1];
    } else if (weighting == FL_G1_WEIGHT_INVERSE) { /* u0 / l0 + u1 / l1, times l0 l1 */
        t[0] = u0[0] * l1 + u1[0] * l0;
        t[1] = u0[1] * l1 + u1[1] * l0;
    } else {
        t[0] = d0[0] + d1[0];
        t[1] = d0[1] + d1[1];
    }
    double tl = hypot(t[0], t[1]);
    if (!(tl > 0 && isfinite(tl))) {
        /* A turn of 180 degrees minus a rounding error (a and b 1e-208 apart, 6 from v): the
         * weighted sum cancels to the zero vector and the tangent became NaN (found by
         * fuzz/fuzz_smooth.c). Take the perpendicular of the bisector e_a + e_b of the unit
         * vectors towards the neighbours (no cancellation: |e_a + e_b| is near 2), pointing
         * towards b rather than a. */
        double ea[2] = {-d0[0] / l0, -d0[1] / l0}, eb[2] = {d1[0] / l1, d1[1] / l1};
        t[0] = -(ea[1] + eb[1]);
        t[1] = ea[0] + eb[0];
        if ((eb[0] - ea[0]) * t[0] + (eb[1] - ea[1]) * t[1] < 0) t[0] = -t[0], t[1] = -t[1];
    }
    normalize2(t);
}

/* The orientation condition of §9.2: the projections of v_{i-1} and v_{i+1} on the tangent
 * line lie on opposite sides of v_i, so P'(1) and Q'(0) point the same way. The tangent is a
 * constructed (rounded) vector, so this is a floating-point test on it; the uniform tangent
 * that repairs a failure satisfies it with margin 1 + cos(turn angle) > 0. */
static int orientation_ok(const double *a, const double *v, const double *b, const double *t)
{
    double back = (a[0] - v[0]) * t[0] + (a[1] - v[1]) * t[1];
    double fwd = (b[0] - v[0]) * t[0] + (b[1] - v[1]) * t[1];
    return back < 0 && fwd > 0;
}

static fl_status check_ring(const fl_polygon *p, size_t lo, size_t hi, fl_error *err)
{
    if (hi - lo < 3)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "ring with %zu vertices (at least 3 needed)",
                       hi - lo);
    for (size_t i = lo; i < hi; i++) {
        const double *v = p->xy + 2 * i;
        const double *a = p->xy + 2 * ring_prev(i, lo, hi), *b = p->xy + 2 * ring_next(i, lo, hi);
        if (!isfinite(v[0]) || !isfinite(v[1]))
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "vertex %zu is not finite", i);
        /* Control points and samples are sums of products of coordinates: beyond 1e150 they
         * overflowed to inf (found by fuzz/fuzz_smooth.c); the sweep's range. */
        if (fabs(v[0]) > 1e150 || fabs(v[1]) > 1e150)
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "vertex %zu is beyond the supported range |x| <= 1e150", i);
        if (v[0] == b[0] && v[1] == b[1])
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "vertices %zu and %zu coincide", i,
                           ring_next(i, lo, hi));
        /* A ring that turns back by exactly 180 degrees at v has no tangent whose projections
         * separate the neighbours: a, v, b collinear (exact) with v outside segment ab. */
        if (fl_orient2d(a, v, b) == 0 && fl_diametral(a, b, v, 2) > 0)
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "the ring turns back on itself at vertex %zu (a 180-degree spike)", i);
    }
    return FL_OK;
}

/* §9.2: p1 = p0 + tension (p3* - p0), p3* the projection of p3 on the tangent line at p0, and
 * symmetrically p2 (tension 1/3 in the thesis). */
static void segment_controls(const double *p0, const double *t0, const double *p3, const double *t3,
                             double tension, double *c)
{
    double s0 = (p3[0] - p0[0]) * t0[0] + (p3[1] - p0[1]) * t0[1];
    double s3 = (p0[0] - p3[0]) * t3[0] + (p0[1] - p3[1]) * t3[1];
    c[0] = p0[0];
    c[1] = p0[1];
    c[2] = p0[0] + tension * s0 * t0[0];
    c[3] = p0[1] + tension * s0 * t0[1];
    c[4] = p3[0] + tension * s3 * t3[0];
    c[5] = p3[1] + tension * s3 * t3[1];
    c[6] = p3[0];
    c[7] = p3[1];
}

static fl_status copy_structure(const fl_polygon *p, fl_g1_curve *c)
{
    c->vertex_count = p->vertex_count;
    c->ring_count = p->ring_count;
    c->polygon_count = p->polygon_count;
    c->ctrl = fl_alloc_array(p->vertex_count, 8 * sizeof(double));
    c->tangent = fl_alloc_array(p->vertex_count, 2 * sizeof(double));
    c->ring_start = fl_alloc_array(p->ring_count + 1, sizeof(size_t));
    c->polygon_start = fl_alloc_array(p->polygon_count + 1, sizeof(size_t));
    if (!c->ctrl || !c->tangent || !c->ring_start || !c->polygon_start) return FL_ERR_NOMEM;
    memcpy(c->ring_start, p->ring_start, (p->ring_count + 1) * sizeof(size_t));
    memcpy(c->polygon_start, p->polygon_start, (p->polygon_count + 1) * sizeof(size_t));
    return FL_OK;
}

fl_status fl_g1_curve_build(const fl_polygon *polygon, const fl_g1_curve_options *opt,
                            fl_g1_curve *out, fl_error *err)
{
    if (out) memset(out, 0, sizeof *out);
    if (!polygon || !out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "NULL argument");
    fl_g1_curve_options o = opt ? *opt : (fl_g1_curve_options){0};
    if (o.weighting < 0 || o.weighting > FL_G1_WEIGHT_INVERSE || !(o.tension >= 0) ||
        o.tension >= 1)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "bad curve options (weighting, tension)");
    double tension = o.tension > 0 ? o.tension : 1.0 / 3.0;
    if (polygon->ring_count == 0)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "the polygon has no ring");
    for (size_t r = 0; r < polygon->ring_count; r++) {
        fl_status st = check_ring(polygon, polygon->ring_start[r], polygon->ring_start[r + 1], err);
        if (st) return st;
    }
    if (copy_structure(polygon, out)) {
        fl_g1_curve_free(out);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    const double *xy = polygon->xy;
    for (size_t r = 0; r < polygon->ring_count; r++) {
        size_t lo = polygon->ring_start[r], hi = polygon->ring_start[r + 1];
        for (size_t i = lo; i < hi; i++) {
            const double *a = xy + 2 * ring_prev(i, lo, hi), *b = xy + 2 * ring_next(i, lo, hi);
            double *t = out->tangent + 2 * i;
            estimate_tangent(a, xy + 2 * i, b, o.weighting, t);
            if (!orientation_ok(a, xy + 2 * i, b, t)) {
                estimate_tangent(a, xy + 2 * i, b, FL_G1_WEIGHT_UNIFORM, t);
                out->orientation_repairs++;
            }
        }
        for (size_t i = lo; i < hi; i++) {
            size_t j = ring_next(i, lo, hi);
            segment_controls(xy + 2 * i, out->tangent + 2 * i, xy + 2 * j, out->tangent + 2 * j,
                             tension, out->ctrl + 8 * i);
        }
    }
    return FL_OK;
}

void fl_g1_curve_free(fl_g1_curve *curve)
{
    if (!curve) return;
    free(curve->ctrl);
    free(curve->tangent);
    free(curve->ring_start);
    free(curve->polygon_start);
    memset(curve, 0, sizeof *curve);
}

void fl_g1_curve_eval(const fl_g1_curve *curve, size_t segment, double s, double point[2],
                      double derivative[2])
{
    const double *c = curve->ctrl + 8 * segment;
    double r = 1 - s;
    double b0 = r * r * r, b1 = 3 * r * r * s, b2 = 3 * r * s * s, b3 = s * s * s;
    double d0 = 3 * r * r, d1 = 6 * r * s, d2 = 3 * s * s;
    for (int k = 0; k < 2; k++) {
        if (point) point[k] = b0 * c[k] + b1 * c[2 + k] + b2 * c[4 + k] + b3 * c[6 + k];
        if (derivative)
            derivative[k] =
                d0 * (c[2 + k] - c[k]) + d1 * (c[4 + k] - c[2 + k]) + d2 * (c[6 + k] - c[4 + k]);
    }
}

fl_status fl_g1_curve_sample(const fl_g1_curve *curve, size_t per_segment, fl_polygon *out,
                             fl_error *err)
{
    if (out) memset(out, 0, sizeof *out);
    if (!curve || !out || per_segment == 0)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "NULL argument or zero samples a segment");
    if (curve->vertex_count > SIZE_MAX / per_segment)
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "too many samples");
    size_t n = curve->vertex_count * per_segment;
    out->xy = fl_alloc_array(n, 2 * sizeof(double));
    out->ring_start = fl_alloc_array(curve->ring_count + 1, sizeof(size_t));
    out->polygon_start = fl_alloc_array(curve->polygon_count + 1, sizeof(size_t));
    if (!out->xy || !out->ring_start || !out->polygon_start) {
        fl_polygon_free(out);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    out->vertex_count = n;
    out->ring_count = curve->ring_count;
    out->polygon_count = curve->polygon_count;
    for (size_t r = 0; r <= curve->ring_count; r++)
        out->ring_start[r] = curve->ring_start[r] * per_segment;
    memcpy(out->polygon_start, curve->polygon_start, (curve->polygon_count + 1) * sizeof(size_t));
    for (size_t i = 0; i < curve->vertex_count; i++)
        for (size_t k = 0; k < per_segment; k++)
            fl_g1_curve_eval(curve, i, (double)k / (double)per_segment,
                             out->xy + 2 * (i * per_segment + k), NULL);
    return FL_OK;
}

/* The picture's frame: the control polygon's box (it contains the curve: convex hull
 * property), y flipped so the picture is upright. */
static void control_box(const fl_g1_curve *c, double *box)
{
    box[0] = box[1] = INFINITY;
    box[2] = box[3] = -INFINITY;
    for (size_t i = 0; i < 4 * c->vertex_count; i++) {
        box[0] = fmin(box[0], c->ctrl[2 * i]);
        box[1] = fmin(box[1], c->ctrl[2 * i + 1]);
        box[2] = fmax(box[2], c->ctrl[2 * i]);
        box[3] = fmax(box[3], c->ctrl[2 * i + 1]);
    }
}

fl_status fl_g1_curve_write_svg(const char *path, const fl_g1_curve *curve, fl_error *err)
{
    if (!path || !curve || curve->vertex_count == 0)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "NULL or empty curve");
    fl_out_file out;
    fl_status st = fl_out_open(&out, path, 0, err);
    if (st) return st;
    double box[4];
    control_box(curve, box);
    double w = box[2] - box[0], h = box[3] - box[1], size = fmax(w, h) > 0 ? fmax(w, h) : 1;
    double pad = 0.03 * size, scale = 800 / (size + 2 * pad);
    FILE *fp = out.fp;
    fprintf(fp,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"%.7g\" "
            "height=\"%.7g\" viewBox=\"%.17g %.17g %.17g %.17g\">\n",
            (w + 2 * pad) * scale, (h + 2 * pad) * scale, box[0] - pad, -box[3] - pad, w + 2 * pad,
            h + 2 * pad);
    fprintf(fp,
            "<g transform=\"scale(1,-1)\" fill=\"#dde8f4\" fill-rule=\"evenodd\" "
            "stroke=\"#1f4e79\" stroke-width=\"%.7g\">\n",
            1.5 / scale);
    for (size_t p = 0; p < curve->polygon_count; p++) {
        fputs("<path d=\"", fp);
        for (size_t r = curve->polygon_start[p]; r < curve->polygon_start[p + 1]; r++) {
            size_t lo = curve->ring_start[r], hi = curve->ring_start[r + 1];
            fprintf(fp, "M %.17g %.17g", curve->ctrl[8 * lo], curve->ctrl[8 * lo + 1]);
            for (size_t i = lo; i < hi; i++) {
                const double *c = curve->ctrl + 8 * i;
                fprintf(fp, " C %.17g %.17g %.17g %.17g %.17g %.17g", c[2], c[3], c[4], c[5], c[6],
                        c[7]);
            }
            fputs(" Z ", fp);
        }
        fputs("\"/>\n", fp);
    }
    fputs("</g>\n</svg>\n", fp);
    return fl_out_commit(&out, err);
}
