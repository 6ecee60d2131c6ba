/* Ball files: one "x y z w" line a ball, read with the text point scanner. */
#include <stdlib.h>
#include <string.h>

#include "io/io_internal.h"

fl_status fl_read_balls(const char *path, fl_balls *out, fl_error *err)
{
    memset(out, 0, sizeof *out);
    char *data;
    size_t size;
    fl_status st = fl_io_slurp(path, &data, &size, err);
    if (st) return st;
    fl_points p;
    st = fl_text_columns_parse(path, data, size, 4, 4, &p, err);
    free(data);
    if (st) return st;
    out->count = p.count;
    out->xyzw = p.coords;
    return FL_OK;
}

fl_status fl_write_balls(const char *path, const fl_balls *balls, fl_error *err)
{
    if (!path || !balls || (!balls->xyzw && balls->count))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_write_balls: NULL argument");
    fl_out_file out;
    fl_status st = fl_out_open(&out, path, 0, err);
    if (st) return st;
    const double *b = balls->xyzw;
    /* %.17g round-trips every double exactly through strtod. */
    for (size_t i = 0; i < balls->count; i++, b += 4)
        fprintf(out.fp, "%.17g %.17g %.17g %.17g\n", b[0], b[1], b[2], b[3]);
    return fl_out_commit(&out, err);
}
