/* Fuzzes fl_mesh_check and fl_mesh_self_intersections on decoded meshes of up to 10 vertices and
 * 16 triangles (any topology: open, non-manifold, repeated faces, inconsistently oriented,
 * degenerate). Oracle: edge, boundary-edge, non-manifold-edge and misoriented-edge counts are
 * recounted by brute force over all triangle pairs (for meshes whose triangles repeat no index,
 * where the definitions are unambiguous); the self-intersection count equals the total of
 * fl_mesh_self_intersections; closed/oriented flags follow from the counts. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    uint8_t head = fz_byte(&in);
    size_t nv = fz_byte(&in) % 11, nt = fz_byte(&in) % 17;
    double xyz[3 * 10];
    uint32_t tri[3 * 16];
    int bad = fz_coords(&in, xyz, 3 * nv);
    int repeats = 0;
    for (size_t i = 0; i < 3 * nt; i++) {
        uint8_t b = fz_byte(&in);
        /* Rarely an out-of-range index, which must be a clean FL_ERR_INPUT. */
        tri[i] = (b == 255 || nv == 0) ? (uint32_t)nv + b : (uint32_t)(b % nv);
    }
    int oob = 0;
    for (size_t i = 0; i < 3 * nt; i++) oob |= tri[i] >= nv;
    for (size_t t = 0; t < nt; t++) {
        const uint32_t *v = tri + 3 * t;
        repeats |= v[0] == v[1] || v[1] == v[2] || v[0] == v[2];
    }
    fl_mesh m = {nv, xyz, nt, tri};
    fl_mesh_check_options opt = {0};
    opt.skip_self_intersections = head & 1;
    fl_mesh_report rep;
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st = fl_mesh_check(&m, &opt, &rep, &err);
    fz_check_status(st, &err, "fl_mesh_check");
    if (st != FL_OK) {
        FZ_ASSERT(bad || oob, "valid mesh rejected: %s", err.message);
        FZ_ASSERT(st == FL_ERR_INPUT, "bad mesh gave %d: %s", (int)st, err.message);
        return 0;
    }
    FZ_ASSERT(!oob, "out-of-range index accepted");
    FZ_ASSERT(!bad, "NaN/Inf accepted");
    FZ_ASSERT(rep.vertices == nv && rep.faces == nt, "counts");
    size_t comp_faces = 0;
    for (size_t c = 0; c < rep.components; c++) comp_faces += rep.component_faces[c];
    FZ_ASSERT(comp_faces == nt, "component faces sum %zu != %zu", comp_faces, nt);
    if (!repeats) {
        /* Brute force: every directed edge of every triangle, grouped by undirected edge. */
        size_t edges = 0, boundary = 0, nonman = 0, misor = 0;
        for (size_t e = 0; e < 3 * nt; e++) {
            uint32_t a = tri[e], b = tri[e - e % 3 + (e % 3 + 1) % 3];
            int first = 1, uses = 0, same_dir = 0;
            for (size_t f = 0; f < 3 * nt; f++) {
                uint32_t c = tri[f], d = tri[f - f % 3 + (f % 3 + 1) % 3];
                if (!((c == a && d == b) || (c == b && d == a))) continue;
                if (f < e) first = 0;
                uses++;
                if (c == a && d == b) same_dir++;
            }
            if (!first) continue;
            edges++;
            if (uses == 1) boundary++;
            if (uses >= 3) nonman++;
            /* Used twice in one direction (only meaningful for two-triangle edges). */
            if (uses == 2 && (same_dir == 2 || same_dir == 0)) misor++;
        }
        FZ_ASSERT(rep.edges == edges, "edges %zu, brute force %zu", rep.edges, edges);
        FZ_ASSERT(rep.boundary_edges == boundary, "boundary %zu vs %zu", rep.boundary_edges,
                  boundary);
        FZ_ASSERT(rep.nonmanifold_edges == nonman, "nonmanifold %zu vs %zu",
                  rep.nonmanifold_edges, nonman);
        FZ_ASSERT(rep.closed == (nt > 0 && boundary == 0 && nonman == 0), "closed flag");
        if (nonman == 0)
            FZ_ASSERT(rep.misoriented_edges == misor, "misoriented %zu vs %zu",
                      rep.misoriented_edges, misor);
    }
    if (!opt.skip_self_intersections) {
        fl_mesh_pairs pairs;
        st = fl_mesh_self_intersections(&m, 4, NULL, NULL, &pairs, &err);
        FZ_ASSERT(st == FL_OK, "self_intersections: %s", err.message);
        FZ_ASSERT(pairs.total == rep.self_intersections, "%zu pairs vs report %zu", pairs.total,
                  rep.self_intersections);
        FZ_ASSERT(pairs.count == (pairs.total < 4 ? pairs.total : 4), "kept pairs");
        for (size_t k = 0; k < pairs.count; k++)
            FZ_ASSERT(pairs.pairs[2 * k] < pairs.pairs[2 * k + 1] &&
                          pairs.pairs[2 * k + 1] < nt, "pair order");
        fl_mesh_pairs_free(&pairs);
    }
    fl_mesh_report_free(&rep);
    return 0;
}
