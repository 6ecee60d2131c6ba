/* The SVG canvas: items collected in data coordinates and written as one standalone SVG 1.1
 * file fitted to their bounding box. The frame follows src/io/svg.c's polygon pictures (longer
 * side fixed, a margin all round, y up, even-odd polygon fill in the same colours), so a
 * polygon drawn here looks like one written by fl_write_polygon; that writer draws one fixed
 * picture, this canvas composes many kinds of items in one. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "render/render_internal.h"

typedef enum item_kind { POINTS, POLYLINE, POLYGON, EDGES, DISC, LENS, SEGMENT, BEZIER } item_kind;

typedef struct svg_item {
    item_kind kind;
    int closed;
    char stroke[48], fill[48];
    double stroke_width, opacity, point_radius;
    double *v;          /* coordinates: xy pairs, (cx, cy, r) for discs, 2 discs for lenses */
    size_t nv;          /* doubles in v */
    size_t *ring_start; /* polygons: ring_count + 1 entries, then polygon_start */
    size_t ring_count, *polygon_start, polygon_count;
} svg_item;

struct fl_svg {
    double size;
    fl_vec items; /* svg_item */
};

fl_status fl_svg_new(double size, fl_svg **out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_svg_new: NULL argument");
    *out = NULL;
    if (size == 0) size = 1000;
    if (!(size >= 16 && size <= 1e6))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "svg: picture size must be in [16, 1e6]");
    fl_svg *s = calloc(1, sizeof *s);
    if (!s) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    s->size = size;
    fl_vec_init(&s->items, sizeof(svg_item));
    *out = s;
    return FL_OK;
}

static void item_release(svg_item *it)
{
    free(it->v);
    free(it->ring_start);
    free(it->polygon_start);
}

void fl_svg_free(fl_svg *svg)
{
    if (!svg) return;
    svg_item *it = svg->items.data;
    for (size_t i = 0; i < svg->items.count; i++)
        item_release(&it[i]);
    fl_vec_free(&svg->items);
    free(svg);
}

/* Colours go into attributes verbatim, so only characters of colour syntax are allowed. */
static int color_ok(const char *c)
{
    if (!*c || strlen(c) >= 48) return 0;
    for (; *c; c++)
        if (!((*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') || (*c >= '0' && *c <= '9') ||
              strchr("#(),.% ", *c)))
            return 0;
    return 1;
}

static fl_status item_style(svg_item *it, const fl_svg_style *st, const char *fill_default,
                            fl_error *err)
{
    fl_svg_style s = {0};
    if (st) s = *st;
    const char *stroke = s.stroke ? s.stroke : "#1f4e79";
    const char *fill = s.fill ? s.fill : fill_default ? fill_default : stroke;
    if (!color_ok(stroke) || !color_ok(fill))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "svg: colours are names, #rrggbb, rgb(...) or none");
    if (!(s.stroke_width >= 0 && s.opacity >= 0 && s.opacity <= 1 && s.point_radius >= 0))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "svg: widths and radii must be >= 0, opacity in [0, 1]");
    strcpy(it->stroke, stroke);
    strcpy(it->fill, fill);
    it->stroke_width = s.stroke_width > 0 ? s.stroke_width : 2;
    it->opacity = s.opacity > 0 ? s.opacity : 1;
    it->point_radius = s.point_radius > 0 ? s.point_radius : 3;
    return FL_OK;
}

/* Validates, copies n doubles and appends the item; on failure the item's arrays are released
 * and nothing is kept. */
static fl_status add_item(fl_svg *svg, svg_item *it, const double *v, size_t n,
                          const fl_svg_style *st, const char *fill_default, fl_error *err)
{
    fl_status s = FL_OK;
    if (!svg || (n && !v)) s = fl_fail(err, FL_ERR_USAGE, NULL, -1, "svg: NULL argument");
    if (s == FL_OK) s = item_style(it, st, fill_default, err);
    for (size_t i = 0; s == FL_OK && i < n; i++)
        if (!isfinite(v[i])) s = fl_fail(err, FL_ERR_INPUT, NULL, -1, "svg: non-finite coordinate");
    if (s) {
        item_release(it);
        return s;
    }
    it->v = fl_alloc_array(n ? n : 1, sizeof(double));
    if (!it->v || fl_vec_reserve(&svg->items, svg->items.count + 1)) {
        item_release(it);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    if (n) memcpy(it->v, v, n * sizeof(double));
    it->nv = n;
    fl_vec_push(&svg->items, it, 1);
    return FL_OK;
}

fl_status fl_svg_add_points(fl_svg *svg, const double *xy, size_t n, const fl_svg_style *style,
                            fl_error *err)
{
    svg_item it = {.kind = POINTS};
    if (n > SIZE_MAX / 2) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "svg: too many points");
    return add_item(svg, &it, xy, 2 * n, style, NULL, err);
}

fl_status fl_svg_add_polyline(fl_svg *svg, const double *xy, size_t n, int closed,
                              const fl_svg_style *style, fl_error *err)
{
    svg_item it = {.kind = POLYLINE, .closed = closed != 0};
    if (n > SIZE_MAX / 2) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "svg: too many points");
    return add_item(svg, &it, xy, 2 * n, style, "none", err);
}

static fl_status check_polygon(const fl_polygon *p, fl_error *err)
{
    if (!p || (p->vertex_count && !p->xy) || !p->ring_start || !p->polygon_start)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_svg_add_polygon: NULL argument");
    if (p->ring_start[0] != 0 || p->ring_start[p->ring_count] != p->vertex_count ||
        p->polygon_start[0] != 0 || p->polygon_start[p->polygon_count] != p->ring_count)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "svg: polygon ranges do not fit its arrays");
    for (size_t r = 0; r < p->ring_count; r++)
        if (p->ring_start[r] > p->ring_start[r + 1])
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "svg: ring %zu ends before it starts", r);
    for (size_t q = 0; q < p->polygon_count; q++)
        if (p->polygon_start[q] > p->polygon_start[q + 1])
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "svg: polygon %zu ends before it starts",
                           q);
    return FL_OK;
}

fl_status fl_svg_add_polygon(fl_svg *svg, const fl_polygon *polygon, const fl_svg_style *style,
                             fl_error *err)
{
    fl_status s = check_polygon(polygon, err);
    if (s) return s;
    svg_item it = {.kind = POLYGON};
    it.ring_count = polygon->ring_count;
    it.polygon_count = polygon->polygon_count;
    it.ring_start = fl_alloc_array(polygon->ring_count + 1, sizeof(size_t));
    it.polygon_start = fl_alloc_array(polygon->polygon_count + 1, sizeof(size_t));
    if (!it.ring_start || !it.polygon_start) {
        item_release(&it);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    memcpy(it.ring_start, polygon->ring_start, (it.ring_count + 1) * sizeof(size_t));
    memcpy(it.polygon_start, polygon->polygon_start, (it.polygon_count + 1) * sizeof(size_t));
    return add_item(svg, &it, polygon->xy, 2 * polygon->vertex_count, style, "#cfe0f3", err);
}

/* Edges are resolved to their end points here (4 doubles an edge). */
fl_status fl_svg_add_edges(fl_svg *svg, const double *xy, size_t n, const uint32_t *edges,
                           size_t edge_count, const fl_svg_style *style, fl_error *err)
{
    if ((edge_count && (!edges || !xy)) || edge_count > SIZE_MAX / 4)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_svg_add_edges: NULL argument");
    double *seg = fl_alloc_array(edge_count ? edge_count : 1, 4 * sizeof(double));
    if (!seg) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    for (size_t e = 0; e < 2 * edge_count; e++) {
        if (edges[e] >= n) {
            free(seg);
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "svg: edge %zu uses point %u of %zu", e / 2,
                           edges[e], n);
        }
        seg[2 * e] = xy[2 * (size_t)edges[e]];
        seg[2 * e + 1] = xy[2 * (size_t)edges[e] + 1];
    }
    svg_item it = {.kind = EDGES};
    fl_status s = add_item(svg, &it, seg, 4 * edge_count, style, "none", err);
    free(seg);
    return s;
}

/* A disc whose box overflows (centre -1e308, radius 1e308) made the picture's frame infinite and
 * wrote "-inf" into the SVG (found by fuzz/fuzz_render.c). */
static int disc_box_finite(const double *d)
{
    return isfinite(d[0] - d[2]) && isfinite(d[0] + d[2]) && isfinite(d[1] - d[2]) &&
           isfinite(d[1] + d[2]);
}

fl_status fl_svg_add_disc(fl_svg *svg, double cx, double cy, double radius,
                          const fl_svg_style *style, fl_error *err)
{
    if (!(radius >= 0)) return fl_fail(err, FL_ERR_INPUT, NULL, -1, "svg: disc radius < 0");
    double v[3] = {cx, cy, radius};
    if (!disc_box_finite(v))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "svg: the disc exceeds the double range");
    svg_item it = {.kind = DISC};
    return add_item(svg, &it, v, 3, style, "none", err);
}

fl_status fl_svg_add_lens(fl_svg *svg, const double d0[3], const double d1[3],
                          const fl_svg_style *style, fl_error *err)
{
    if (!d0 || !d1) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_svg_add_lens: NULL argument");
    if (!(d0[2] >= 0 && d1[2] >= 0))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "svg: disc radius < 0");
    if (!disc_box_finite(d0) || !disc_box_finite(d1))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "svg: a disc exceeds the double range");
    double v[6] = {d0[0], d0[1], d0[2], d1[0], d1[1], d1[2]};
    svg_item it = {.kind = LENS};
    return add_item(svg, &it, v, 6, style, "#cfe0f3", err);
}

fl_status fl_svg_add_disc_halfplane(fl_svg *svg, const double disc[3], const double a[2],
                                    const double b[2], int side, const fl_svg_style *style,
                                    fl_error *err)
{
    if (!disc || !a || !b)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_svg_add_disc_halfplane: NULL argument");
    if (!(disc[2] >= 0)) return fl_fail(err, FL_ERR_INPUT, NULL, -1, "svg: disc radius < 0");
    if (!disc_box_finite(disc))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "svg: the disc exceeds the double range");
    if (side != 1 && side != -1)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "svg: side must be +1 or -1");
    if (a[0] == b[0] && a[1] == b[1])
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "svg: the half-plane's line needs a != b");
    double v[8] = {disc[0], disc[1], disc[2], a[0], a[1], b[0], b[1], side};
    svg_item it = {.kind = SEGMENT};
    return add_item(svg, &it, v, 8, style, "#cfe0f3", err);
}

fl_status fl_svg_add_bezier(fl_svg *svg, const double *ctrl, size_t segments,
                            const fl_svg_style *style, fl_error *err)
{
    if (segments == 0 || segments > SIZE_MAX / 8)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "svg: a Bézier path needs >= 1 segment");
    svg_item it = {.kind = BEZIER};
    return add_item(svg, &it, ctrl, 2 * (3 * segments + 1), style, "none", err);
}

/* ---- writing -------------------------------------------------------------------------------- */

typedef struct svg_frame {
    double min_x, max_y, half; /* as in src/io/svg.c: halves keep extents finite */
    double size, margin, width, height;
} svg_frame;

static void box_add(double b[4], double x0, double y0, double x1, double y1)
{
    b[0] = fmin(b[0], x0);
    b[1] = fmin(b[1], y0);
    b[2] = fmax(b[2], x1);
    b[3] = fmax(b[3], y1);
}

static void item_box(const svg_item *it, double b[4])
{
    const double *v = it->v;
    if (it->kind == DISC || it->kind == SEGMENT) { /* a segment lies in its disc */
        box_add(b, v[0] - v[2], v[1] - v[2], v[0] + v[2], v[1] + v[2]);
    } else if (it->kind == LENS) {
        /* The lens lies in both discs, so in the intersection of their boxes. */
        double x0 = fmax(v[0] - v[2], v[3] - v[5]), x1 = fmin(v[0] + v[2], v[3] + v[5]);
        double y0 = fmax(v[1] - v[2], v[4] - v[5]), y1 = fmin(v[1] + v[2], v[4] + v[5]);
        if (x0 <= x1 && y0 <= y1) box_add(b, x0, y0, x1, y1);
    } else {
        for (size_t i = 0; i + 1 < it->nv; i += 2)
            box_add(b, v[i], v[i + 1], v[i], v[i + 1]);
    }
}

static svg_frame make_frame(const fl_svg *svg)
{
    double b[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY};
    const svg_item *it = svg->items.data;
    for (size_t i = 0; i < svg->items.count; i++)
        item_box(&it[i], b);
    if (!(b[0] <= b[2])) b[0] = b[1] = b[2] = b[3] = 0; /* nothing drawn: an empty picture */
    double half_w = b[2] / 2 - b[0] / 2, half_h = b[3] / 2 - b[1] / 2;
    svg_frame f = {b[0], b[3], fmax(half_w, half_h), svg->size, 0.05 * svg->size, 0, 0};
    if (!(f.half > 0)) f.half = 1; /* a single point: any scale draws it */
    f.width = f.size * (half_w / f.half) + 2 * f.margin;
    f.height = f.size * (half_h / f.half) + 2 * f.margin;
    return f;
}

static double fx(const svg_frame *f, double x)
{
    return f->margin + f->size * ((x / 2 - f->min_x / 2) / f->half);
}

static double fy(const svg_frame *f, double y)
{
    return f->margin + f->size * ((f->max_y / 2 - y / 2) / f->half);
}

static double flen(const svg_frame *f, double r)
{
    return f->size * (r / 2 / f->half);
}

static void style_attrs(FILE *fp, const svg_item *it, int stroked)
{
    if (stroked)
        fprintf(fp,
                " stroke=\"%s\" stroke-width=\"%.4g\" stroke-linejoin=\"round\" "
                "stroke-linecap=\"round\"",
                it->stroke, it->stroke_width);
    else
        fputs(" stroke=\"none\"", fp);
    fprintf(fp, " fill=\"%s\"", it->fill);
    if (it->opacity < 1) fprintf(fp, " opacity=\"%.4g\"", it->opacity);
}

static void write_pairs(FILE *fp, const svg_frame *f, const double *v, size_t pairs, int closed)
{
    for (size_t i = 0; i < pairs; i++)
        fprintf(fp, "%s%.7g %.7g", i == 0 ? "M" : " L", fx(f, v[2 * i]), fy(f, v[2 * i + 1]));
    if (closed && pairs) fputs(" Z", fp);
}

static void write_polygon(FILE *fp, const svg_frame *f, const svg_item *it)
{
    for (size_t p = 0; p < it->polygon_count; p++) {
        fputs("<path fill-rule=\"evenodd\"", fp);
        style_attrs(fp, it, 1);
        fputs(" d=\"", fp);
        for (size_t r = it->polygon_start[p]; r < it->polygon_start[p + 1]; r++) {
            if (r > it->polygon_start[p]) fputc(' ', fp);
            size_t a = it->ring_start[r], n = it->ring_start[r + 1] - a;
            write_pairs(fp, f, it->v + 2 * a, n, 1);
        }
        fputs("\"/>\n", fp);
    }
}

/* The lens d0 ∩ d1 (HAL §3: a flintstone is bounded by two circular arcs). With u the unit
 * vector from c0 to c1 at distance d, the chord through the two intersection points crosses
 * the centre line at a = (d^2 + r0^2 - r1^2) / (2d) from c0. The boundary is circle 1's arc
 * on c0's side (the larger arc iff a > d) and circle 0's arc on c1's side (larger iff a < 0);
 * both run counter-clockwise in data coordinates. The y flip into the picture's y-down frame
 * keeps the picture unmirrored, so they still look counter-clockwise there, which is SVG's
 * negative-angle direction: sweep flag 0.
 * Returns the number of elements written (0 for disjoint discs). */
static int write_lens(FILE *fp, const svg_frame *f, const svg_item *it)
{
    const double *d0 = it->v, *d1 = it->v + 3;
    double dx = d1[0] - d0[0], dy = d1[1] - d0[1], d = hypot(dx, dy);
    if (d >= d0[2] + d1[2]) return 0;
    if (d + fmin(d0[2], d1[2]) <= fmax(d0[2], d1[2])) { /* one disc holds the other */
        const double *s = d0[2] <= d1[2] ? d0 : d1;
        fprintf(fp, "<circle cx=\"%.7g\" cy=\"%.7g\" r=\"%.7g\"", fx(f, s[0]), fy(f, s[1]),
                flen(f, s[2]));
        style_attrs(fp, it, 1);
        fputs("/>\n", fp);
        return 1;
    }
    double a = (d * d + d0[2] * d0[2] - d1[2] * d1[2]) / (2 * d);
    double h = sqrt(fmax(0, d0[2] * d0[2] - a * a));
    double ux = dx / d, uy = dy / d, mx = d0[0] + a * ux, my = d0[1] + a * uy;
    double p[2] = {mx - h * uy, my + h * ux}, q[2] = {mx + h * uy, my - h * ux};
    fprintf(fp, "<path d=\"M%.7g %.7g A%.7g %.7g 0 %d 0 %.7g %.7g A%.7g %.7g 0 %d 0 %.7g %.7g Z\"",
            fx(f, p[0]), fy(f, p[1]), flen(f, d1[2]), flen(f, d1[2]), a > d, fx(f, q[0]),
            fy(f, q[1]), flen(f, d0[2]), flen(f, d0[2]), a < 0, fx(f, p[0]), fy(f, p[1]));
    style_attrs(fp, it, 1);
    fputs("/>\n", fp);
    return 1;
}

/* The disc (v[0..2]) on side v[7] of the line v[3..4] -> v[5..6]: with t the line's unit
 * direction, nl its left normal and s the centre's signed distance (c - a).nl, the line meets
 * the circle at P, Q = c - s nl -+ h t, h = sqrt(r^2 - s^2). Returns 0 when that part is empty,
 * 1 when it is the whole disc (|s| >= r), 2 for a proper circular segment (P, Q filled, and
 * *large = 1 when the segment holds the centre). */
static int segment_shape(const double *v, double p[2], double q[2], int *large)
{
    double tx = v[5] - v[3], ty = v[6] - v[4], len = hypot(tx, ty), side = v[7];
    tx /= len;
    ty /= len;
    double s = (v[0] - v[3]) * -ty + (v[1] - v[4]) * tx, r = v[2];
    if (fabs(s) >= r) return side * s > 0 ? 1 : 0;
    double h = sqrt(r * r - s * s), fx0 = v[0] + s * ty, fy0 = v[1] - s * tx;
    p[0] = fx0 - h * tx;
    p[1] = fy0 - h * ty;
    q[0] = fx0 + h * tx;
    q[1] = fy0 + h * ty;
    *large = side * s > 0;
    return 2;
}

/* The segment's outline: the chord P -> Q, then the arc back to P through the chosen side.
 * On the left side that arc runs counter-clockwise in data coordinates (sweep 0 in the
 * unmirrored y-down picture, see write_lens), on the right side clockwise (sweep 1). */
static int write_segment(FILE *fp, const svg_frame *f, const svg_item *it)
{
    double p[2], q[2];
    int large, shape = segment_shape(it->v, p, q, &large);
    if (shape == 0) return 0;
    /* The chord's construction overflowed for a disc near the double range and "-inf" went
     * into the file (found by fuzz/fuzz_render.c): draw the whole disc then (it contains the
     * part). */
    if (shape == 2 && !(isfinite(p[0]) && isfinite(p[1]) && isfinite(q[0]) && isfinite(q[1])))
        shape = 1;
    if (shape == 1) {
        fprintf(fp, "<circle cx=\"%.7g\" cy=\"%.7g\" r=\"%.7g\"", fx(f, it->v[0]), fy(f, it->v[1]),
                flen(f, it->v[2]));
    } else {
        double r = flen(f, it->v[2]);
        fprintf(fp, "<path d=\"M%.7g %.7g L%.7g %.7g A%.7g %.7g 0 %d %d %.7g %.7g Z\"", fx(f, p[0]),
                fy(f, p[1]), fx(f, q[0]), fy(f, q[1]), r, r, large, it->v[7] > 0 ? 0 : 1,
                fx(f, p[0]), fy(f, p[1]));
    }
    style_attrs(fp, it, 1);
    fputs("/>\n", fp);
    return 1;
}

/* Writes one item; returns the number of shape elements written (item_elements). */
static size_t write_item(FILE *fp, const svg_frame *f, const svg_item *it)
{
    const double *v = it->v;
    size_t pairs = it->nv / 2;
    switch (it->kind) {
    case POINTS:
        for (size_t i = 0; i < pairs; i++) {
            fprintf(fp, "<circle cx=\"%.7g\" cy=\"%.7g\" r=\"%.4g\"", fx(f, v[2 * i]),
                    fy(f, v[2 * i + 1]), it->point_radius);
            style_attrs(fp, it, 0);
            fputs("/>\n", fp);
        }
        return pairs;
    case POLYLINE:
    case EDGES:
        fputs("<path d=\"", fp);
        if (it->kind == POLYLINE)
            write_pairs(fp, f, v, pairs, it->closed);
        else
            for (size_t e = 0; e < pairs / 2; e++) {
                if (e) fputc(' ', fp);
                write_pairs(fp, f, v + 4 * e, 2, 0);
            }
        fputc('"', fp);
        style_attrs(fp, it, 1);
        fputs("/>\n", fp);
        return 1;
    case POLYGON:
        write_polygon(fp, f, it);
        return it->polygon_count;
    case DISC:
        fprintf(fp, "<circle cx=\"%.7g\" cy=\"%.7g\" r=\"%.7g\"", fx(f, v[0]), fy(f, v[1]),
                flen(f, v[2]));
        style_attrs(fp, it, 1);
        fputs("/>\n", fp);
        return 1;
    case LENS:
        return (size_t)write_lens(fp, f, it);
    case SEGMENT:
        return (size_t)write_segment(fp, f, it);
    case BEZIER:
        fprintf(fp, "<path d=\"M%.7g %.7g", fx(f, v[0]), fy(f, v[1]));
        for (size_t i = 1; i < pairs; i++)
            fprintf(fp, "%s%.7g %.7g", i % 3 == 1 ? " C" : " ", fx(f, v[2 * i]),
                    fy(f, v[2 * i + 1]));
        fputc('"', fp);
        style_attrs(fp, it, 1);
        fputs("/>\n", fp);
        return 1;
    }
    return 0;
}

static void write_all(const fl_svg *svg, FILE *fp)
{
    svg_frame f = make_frame(svg);
    fprintf(fp,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"%.7g\" "
            "height=\"%.7g\" viewBox=\"0 0 %.7g %.7g\">\n",
            f.width, f.height, f.width, f.height);
    fprintf(fp, "<rect width=\"%.7g\" height=\"%.7g\" fill=\"white\"/>\n", f.width, f.height);
    const svg_item *it = svg->items.data;
    for (size_t i = 0; i < svg->items.count; i++)
        write_item(fp, &f, &it[i]);
    fputs("</svg>\n", fp);
}

/* Must agree with write_item: the count is what a reader of the file will find. */
static size_t item_elements(const svg_item *it)
{
    switch (it->kind) {
    case POINTS:
        return it->nv / 2;
    case POLYGON:
        return it->polygon_count;
    case LENS:
        return hypot(it->v[3] - it->v[0], it->v[4] - it->v[1]) < it->v[2] + it->v[5];
    case SEGMENT: {
        double p[2], q[2];
        int large;
        return segment_shape(it->v, p, q, &large) != 0;
    }
    default:
        return 1;
    }
}

size_t fl_svg_element_count(const fl_svg *svg)
{
    size_t n = 0;
    const svg_item *it = svg ? svg->items.data : NULL;
    for (size_t i = 0; svg && i < svg->items.count; i++)
        n += item_elements(&it[i]);
    return n;
}

void fl_svg_size(const fl_svg *svg, double *width, double *height)
{
    svg_frame f = make_frame(svg);
    *width = f.width;
    *height = f.height;
}

fl_status fl_svg_write(const fl_svg *svg, const char *path, fl_error *err)
{
    if (!svg || !path) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_svg_write: NULL argument");
    fl_out_file out;
    fl_status st = fl_out_open(&out, path, 0, err);
    if (st) return st;
    write_all(svg, out.fp);
    return fl_out_commit(&out, err);
}
