/* Fuzzes the .bez reader (fl_g1_read_bez, docs/formats.md "Bézier nets"). It reads a path, so
 * each input goes through a private temporary file. Invariants: on failure the output is
 * zeroed; on success every control point is finite and every corner node < node_count; writing
 * the surface back (fl_g1_write_bez, %.17g) and reading it again gives bit-identical data; small
 * surfaces tessellate (density 2) into a mesh with finite vertices, unit normals and indices in
 * range, whatever the corner numbering (repeated or unshared corners included). */
#include <unistd.h>

#include "fuzz_common.h"

static char in_path[64], out_path[64];

static void make_paths(void)
{
    if (in_path[0]) return;
    const char *dir = getenv("TMPDIR");
    snprintf(in_path, sizeof in_path, "%.40s/fzbez-%ld-in.bez", dir ? dir : "/tmp",
             (long)getpid());
    snprintf(out_path, sizeof out_path, "%.40s/fzbez-%ld-out.bez", dir ? dir : "/tmp",
             (long)getpid());
}

static int same_surface(const fl_g1_surface *a, const fl_g1_surface *b)
{
    return a->patch_count == b->patch_count && a->node_count == b->node_count &&
           !memcmp(a->ctrl, b->ctrl, a->patch_count * 30 * sizeof(double)) &&
           !memcmp(a->corner, b->corner, a->patch_count * 3 * sizeof(uint32_t));
}

static void check_tessellation(const fl_g1_surface *s)
{
    fl_mesh m;
    double *nrm;
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st = fl_g1_surface_tessellate(s, 2, &m, &nrm, &err);
    fz_check_status(st, &err, "fl_g1_surface_tessellate");
    if (st != FL_OK) return;
    for (size_t i = 0; i < 3 * m.vertex_count; i++)
        FZ_ASSERT(isfinite(m.xyz[i]), "tessellation vertex coordinate %zu not finite", i);
    for (size_t i = 0; i < 3 * m.triangle_count; i++)
        FZ_ASSERT(m.tri[i] < m.vertex_count, "index %u >= %zu", m.tri[i], m.vertex_count);
    for (size_t v = 0; v < m.vertex_count; v++) {
        double l = nrm[3 * v] * nrm[3 * v] + nrm[3 * v + 1] * nrm[3 * v + 1] +
                   nrm[3 * v + 2] * nrm[3 * v + 2];
        FZ_ASSERT(isfinite(l) && (l == 0 || fabs(l - 1) < 1e-9), "normal %zu has |n|^2 %g", v, l);
    }
    free(nrm);
    fl_mesh_free(&m);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    make_paths();
    FILE *f = fopen(in_path, "wb");
    if (!f) return 0;
    size_t put = fwrite(data, 1, size, f);
    if (fclose(f) != 0 || put != size) return 0;
    fl_g1_surface s;
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st = fl_g1_read_bez(in_path, &s, &err);
    fz_check_status(st, &err, "fl_g1_read_bez");
    if (st != FL_OK) {
        FZ_ASSERT(st == FL_ERR_INPUT || st == FL_ERR_NOMEM, "read gave %d: %s", (int)st,
                  err.message);
        FZ_ASSERT(s.patch_count == 0 && !s.ctrl && !s.corner, "output not zeroed on failure");
        return 0;
    }
    FZ_ASSERT(s.patch_count >= 1, "empty surface accepted");
    for (size_t i = 0; i < 30 * s.patch_count; i++)
        FZ_ASSERT(isfinite(s.ctrl[i]), "control coordinate %zu not finite", i);
    for (size_t i = 0; i < 3 * s.patch_count; i++)
        FZ_ASSERT(s.corner[i] < s.node_count, "corner %u >= %zu", s.corner[i], s.node_count);
    st = fl_g1_write_bez(out_path, &s, &err);
    fz_check_status(st, &err, "fl_g1_write_bez");
    FZ_ASSERT(st == FL_OK, "writing a read surface failed: %s", err.message);
    fl_g1_surface r;
    st = fl_g1_read_bez(out_path, &r, &err);
    fz_check_status(st, &err, "fl_g1_read_bez (round trip)");
    FZ_ASSERT(st == FL_OK, "re-reading the written surface failed: %s", err.message);
    FZ_ASSERT(same_surface(&s, &r), "round trip changed the surface");
    fl_g1_surface_free(&r);
    if (s.patch_count <= 64 && s.node_count <= 4096) check_tessellation(&s);
    fl_g1_surface_free(&s);
    return 0;
}
