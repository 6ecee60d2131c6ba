/* Fuzzes the ball reader. fl_read_balls is fl_io_slurp + the 4-column text scanner, so the
 * target calls that scanner on the buffer directly (same code path after the slurp). */
#include "fuzz_common.h"
#include "io/io_internal.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fl_points p;
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st = fl_text_columns_parse("fuzz", (const char *)data, size, 4, 4, &p, &err);
    fz_check_status(st, &err, "fl_text_columns_parse(4)");
    if (st != FL_OK) return 0;
    FZ_ASSERT(p.dim == 4, "dim %d", p.dim);
    for (size_t i = 0; i < 4 * p.count; i++) FZ_ASSERT(isfinite(p.coords[i]), "not finite");
    fl_points_free(&p);
    return 0;
}
