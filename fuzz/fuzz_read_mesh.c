/* Fuzzes every mesh reader (off, obj, ply ascii/binary, stl ascii/binary) through
 * fl_parse_mesh: the first byte picks the format. On success every index is in range and every
 * coordinate finite; on failure the output is zeroed. Small meshes read go on to fl_mesh_check
 * so the checker sees reader-shaped input too. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const formats[] = {"off", "obj", "ply", "stl"};
    if (size < 1) return 0;
    const char *fmt = formats[data[0] % 4];
    fl_mesh m;
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st = fl_parse_mesh(fmt, "fuzz", data + 1, size - 1, &m, &err);
    fz_check_status(st, &err, "fl_parse_mesh");
    if (st != FL_OK) {
        FZ_ASSERT(m.vertex_count == 0 && m.triangle_count == 0 && !m.xyz && !m.tri,
                  "output not zeroed on failure");
        return 0;
    }
    for (size_t i = 0; i < 3 * m.vertex_count; i++)
        FZ_ASSERT(isfinite(m.xyz[i]), "coordinate %zu not finite", i);
    for (size_t i = 0; i < 3 * m.triangle_count; i++)
        FZ_ASSERT(m.tri[i] < m.vertex_count, "index %u >= %zu", m.tri[i], m.vertex_count);
    if (m.triangle_count <= 64) {
        fl_mesh_report rep;
        st = fl_mesh_check(&m, NULL, &rep, &err);
        fz_check_status(st, &err, "fl_mesh_check");
        if (st == FL_OK) fl_mesh_report_free(&rep);
    }
    fl_mesh_free(&m);
    return 0;
}
