/* Fuzzes the polygon readers (.xy, GeoJSON) through fl_parse_polygon: the first byte picks the
 * format. On success the ring and polygon index arrays are consistent and coordinates finite;
 * fl_polygon_check then runs on the result. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1) return 0;
    const char *fmt = (data[0] & 1) ? "geojson" : "xy";
    fl_polygon p;
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st = fl_parse_polygon(fmt, "fuzz", data + 1, size - 1, &p, &err);
    fz_check_status(st, &err, "fl_parse_polygon");
    if (st != FL_OK) {
        FZ_ASSERT(p.vertex_count == 0 && p.ring_count == 0 && !p.xy, "output not zeroed");
        return 0;
    }
    for (size_t i = 0; i < 2 * p.vertex_count; i++)
        FZ_ASSERT(isfinite(p.xy[i]), "coordinate %zu not finite", i);
    if (p.ring_count) {
        FZ_ASSERT(p.ring_start[0] == 0, "ring_start[0]");
        FZ_ASSERT(p.ring_start[p.ring_count] == p.vertex_count, "ring_start end");
        for (size_t r = 0; r < p.ring_count; r++)
            FZ_ASSERT(p.ring_start[r] < p.ring_start[r + 1], "empty ring %zu", r);
        FZ_ASSERT(p.polygon_count >= 1 && p.polygon_start[0] == 0, "polygon_start[0]");
        FZ_ASSERT(p.polygon_start[p.polygon_count] == p.ring_count, "polygon_start end");
        for (size_t k = 0; k < p.polygon_count; k++)
            FZ_ASSERT(p.polygon_start[k] < p.polygon_start[k + 1], "empty polygon %zu", k);
    }
    if (p.vertex_count <= 256) {
        fl_polygon_report rep;
        st = fl_polygon_check(&p, &rep, &err);
        fz_check_status(st, &err, "fl_polygon_check");
        if (st == FL_OK) fl_polygon_report_free(&rep);
    }
    fl_polygon_free(&p);
    return 0;
}
