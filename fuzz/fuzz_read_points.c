/* Fuzzes every point reader through fl_parse_points: the first byte picks the format, the rest
 * is the file. On success every coordinate is finite and the dimension is 2 or 3; on failure
 * the output is zeroed and the error names the cause. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const formats[] = {"xyz", "xy", "txt", "csv", "ply", "off", "obj"};
    if (size < 1) return 0;
    const char *fmt = formats[data[0] % (sizeof formats / sizeof *formats)];
    fl_points p;
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st = fl_parse_points(fmt, "fuzz", data + 1, size - 1, &p, &err);
    fz_check_status(st, &err, "fl_parse_points");
    if (st != FL_OK) {
        FZ_ASSERT(p.count == 0 && p.coords == NULL, "output not zeroed on failure");
        return 0;
    }
    FZ_ASSERT(p.dim == 2 || p.dim == 3, "dim %d", p.dim);
    FZ_ASSERT(p.count == 0 || p.coords, "NULL coords");
    for (size_t i = 0; i < p.count * (size_t)p.dim; i++)
        FZ_ASSERT(isfinite(p.coords[i]), "coordinate %zu not finite", i);
    fl_points_free(&p);
    return 0;
}
