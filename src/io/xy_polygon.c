/* Polygon rings in text: .xy. Two numbers a line; a blank line ends a ring; '#' comment lines
 * do not. Every ring becomes its own polygon (the format has no way to say "this ring is a
 * hole of that one"), so writing a polygon with holes and reading it back yields the holes as
 * separate polygons. A ring whose last vertex repeats the first exactly is closed explicitly;
 * the repeat is dropped because fl_polygon rings are closed implicitly. */
#include <stdio.h>
#include <string.h>

#include "io/io_internal.h"
#include "io/text_scan.h"

typedef struct ring_reader {
    const char *name;
    fl_text_lines lines;
    int header_seen;
    fl_vec xy;         /* doubles, two a vertex */
    fl_vec ring_start; /* size_t, one per finished ring */
    size_t open_start; /* first vertex of the ring being read */
    long open_line;    /* its line, or 0 when no ring is open */
} ring_reader;

static fl_status close_ring(ring_reader *r, fl_error *err)
{
    if (r->open_line == 0) return FL_OK;
    size_t n = r->xy.count / 2 - r->open_start;
    const double *v = (const double *)r->xy.data + 2 * r->open_start;
    if (n >= 2 && v[0] == v[2 * (n - 1)] && v[1] == v[2 * (n - 1) + 1]) {
        r->xy.count -= 2;
        n--;
    }
    if (n < 3)
        return fl_fail(err, FL_ERR_INPUT, r->name, r->open_line,
                       "ring starting here has %zu distinct vertices; a ring needs at least 3", n);
    if (fl_vec_push(&r->ring_start, &r->open_start, 1))
        return fl_fail(err, FL_ERR_NOMEM, r->name, -1, "out of memory reading rings");
    r->open_line = 0;
    return FL_OK;
}

static fl_status take_vertex(ring_reader *r, const double *v, size_t n, fl_error *err)
{
    if (n != 2)
        return fl_fail(err, FL_ERR_INPUT, r->name, r->lines.line, "expected 2 numbers, got %zu", n);
    if (r->open_line == 0) {
        r->open_start = r->xy.count / 2;
        r->open_line = r->lines.line;
    }
    if (fl_vec_push(&r->xy, v, 2))
        return fl_fail(err, FL_ERR_NOMEM, r->name, r->lines.line, "out of memory reading rings");
    return FL_OK;
}

static fl_status take_line(ring_reader *r, fl_line_kind kind, const double *v, size_t n,
                           fl_error *err)
{
    switch (kind) {
    case FL_LINE_BLANK:
        return close_ring(r, err);
    case FL_LINE_NUMBERS:
        return take_vertex(r, v, n, err);
    case FL_LINE_TEXT:
        if (!r->header_seen && r->xy.count == 0 && r->lines.numeric == 0) {
            r->header_seen = 1;
            return FL_OK;
        }
        return fl_fail(err, FL_ERR_INPUT, r->name, r->lines.line, "'%s' is not a number",
                       r->lines.bad);
    default:
        return FL_OK;
    }
}

/* Turns the finished rings into an fl_polygon with one polygon a ring. */
static fl_status build_polygon(ring_reader *r, fl_polygon *out, fl_error *err)
{
    size_t rings = r->ring_start.count;
    size_t vertices = r->xy.count / 2;
    if (fl_vec_push(&r->ring_start, &vertices, 1))
        return fl_fail(err, FL_ERR_NOMEM, r->name, -1, "out of memory reading rings");
    size_t *poly = fl_alloc_array(rings + 1, sizeof *poly);
    if (!poly) return fl_fail(err, FL_ERR_NOMEM, r->name, -1, "out of memory reading rings");
    for (size_t i = 0; i <= rings; i++)
        poly[i] = i;
    out->vertex_count = vertices;
    out->xy = fl_vec_release(&r->xy);
    out->ring_count = rings;
    out->ring_start = fl_vec_release(&r->ring_start);
    out->polygon_count = rings;
    out->polygon_start = poly;
    return FL_OK;
}

fl_status fl_xy_polygon_parse(const char *name, const char *data, size_t size, fl_polygon *out,
                              fl_error *err)
{
    memset(out, 0, sizeof *out);
    ring_reader r = {.name = name};
    fl_text_lines_init(&r.lines, data, size);
    fl_vec_init(&r.xy, sizeof(double));
    fl_vec_init(&r.ring_start, sizeof(size_t));
    fl_status st;
    for (;;) {
        double v[2];
        size_t n;
        fl_line_kind kind;
        st = fl_text_lines_next(&r.lines, name, v, 2, &n, &kind, err);
        if (st != FL_OK) break;
        if (kind == FL_LINE_EOF) {
            st = close_ring(&r, err);
            break;
        }
        st = take_line(&r, kind, v, n, err);
        if (st != FL_OK) break;
    }
    if (st == FL_OK && r.ring_start.count == 0)
        st = fl_fail(err, FL_ERR_INPUT, name, -1,
                     "no rings: expected blocks of lines with 2 numbers, blocks separated by a "
                     "blank line");
    if (st == FL_OK) st = build_polygon(&r, out, err);
    fl_vec_free(&r.xy);
    fl_vec_free(&r.ring_start);
    return st;
}

fl_status fl_xy_polygon_write(FILE *fp, const fl_polygon *polygon)
{
    for (size_t r = 0; r < polygon->ring_count; r++) {
        if (r > 0) fputc('\n', fp);
        for (size_t i = polygon->ring_start[r]; i < polygon->ring_start[r + 1]; i++)
            fprintf(fp, "%.17g %.17g\n", polygon->xy[2 * i], polygon->xy[2 * i + 1]);
    }
    return ferror(fp) ? FL_ERR_IO : FL_OK;
}
