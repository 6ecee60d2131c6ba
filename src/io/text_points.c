/* Point lists in text: .xyz .xy .txt .csv. One point a line, 2 or 3 numbers separated by
 * whitespace, ',' or ';'; '#' starts a comment; blank lines are skipped; the first line that
 * is not a comment may be a header ("x,y,z") when it is not all numbers. Runs of separators
 * count as one, so "1,,2" is two numbers. */
#include <stdio.h>
#include <string.h>

#include "io/io_internal.h"
#include "io/text_scan.h"

typedef struct points_reader {
    const char *name;
    fl_text_lines lines;
    int dim;         /* 0 until the first data line fixes it */
    int header_seen; /* a header is allowed once, before any data */
    fl_vec coords;
} points_reader;

static fl_status take_numbers(points_reader *r, const double *v, size_t n, fl_error *err)
{
    if (r->dim == 0) {
        if (n != 2 && n != 3)
            return fl_fail(err, FL_ERR_INPUT, r->name, r->lines.line,
                           "expected 2 or 3 numbers (x y [z]), got %zu", n);
        r->dim = (int)n;
    } else if (n != (size_t)r->dim) {
        return fl_fail(err, FL_ERR_INPUT, r->name, r->lines.line,
                       "expected %d numbers, got %zu (the first point had %d)", r->dim, n, r->dim);
    }
    if (fl_vec_push(&r->coords, v, n))
        return fl_fail(err, FL_ERR_NOMEM, r->name, r->lines.line, "out of memory reading points");
    return FL_OK;
}

static fl_status take_text(points_reader *r, fl_error *err)
{
    if (r->dim == 0 && !r->header_seen && r->lines.numeric == 0) {
        r->header_seen = 1;
        return FL_OK;
    }
    return fl_fail(err, FL_ERR_INPUT, r->name, r->lines.line, "'%s' is not a number%s",
                   r->lines.bad,
                   r->header_seen && r->dim == 0 ? " (only one header line is allowed)" : "");
}

fl_status fl_text_points_parse(const char *name, const char *data, size_t size, fl_points *out,
                               fl_error *err)
{
    memset(out, 0, sizeof *out);
    points_reader r = {.name = name};
    fl_text_lines_init(&r.lines, data, size);
    fl_vec_init(&r.coords, sizeof(double));
    fl_status st = FL_OK;
    for (;;) {
        double v[3];
        size_t n;
        fl_line_kind kind;
        st = fl_text_lines_next(&r.lines, name, v, 3, &n, &kind, err);
        if (st != FL_OK || kind == FL_LINE_EOF) break;
        if (kind == FL_LINE_TEXT)
            st = take_text(&r, err);
        else if (kind == FL_LINE_NUMBERS)
            st = take_numbers(&r, v, n, err);
        if (st != FL_OK) break;
    }
    if (st == FL_OK && r.coords.count == 0)
        st = fl_fail(err, FL_ERR_INPUT, name, -1, "no points: expected lines of 2 or 3 numbers");
    if (st != FL_OK) {
        fl_vec_free(&r.coords);
        return st;
    }
    out->dim = r.dim;
    out->count = r.coords.count / (size_t)r.dim;
    out->coords = fl_vec_release(&r.coords);
    return FL_OK;
}

fl_status fl_text_points_write(FILE *fp, const fl_points *points)
{
    if (points->dim != 2 && points->dim != 3) return FL_ERR_USAGE;
    /* %.17g prints every double so that strtod reads back exactly the same value. */
    const double *c = points->coords;
    for (size_t i = 0; i < points->count; i++, c += points->dim) {
        if (points->dim == 2)
            fprintf(fp, "%.17g %.17g\n", c[0], c[1]);
        else
            fprintf(fp, "%.17g %.17g %.17g\n", c[0], c[1], c[2]);
    }
    return ferror(fp) ? FL_ERR_IO : FL_OK;
}
