/* Fuzzes fl_reconstruct2 (up to 48 points, every criterion, with or without augmentation) and
 * fl_reconstruct3 (up to 24 points): the first byte picks which. Invariants from the header
 * contract: NaN/Inf is FL_ERR_INPUT; FL_ERR_ALGORITHM only for collinear (2D) / coplanar (3D)
 * input, checked exactly; on success the 2D boundary is a simple counterclockwise polygon (by
 * fl_polygon_check) tiled by boundary_count - 2 + 2*inside triangles, and the 3D boundary is a
 * closed, manifold, oriented genus-0 surface without self-intersections (by fl_mesh_check). */
#include "fuzz_common.h"

static void fuzz2(fz_in *in, uint8_t head)
{
    size_t n = fz_byte(in) % 49;
    double xy[2 * 48];
    int bad = fz_coords(in, xy, 2 * n);
    fl_reconstruct2_options opt = {0};
    opt.criterion = (fl_reconstruct2_criterion)((head >> 1) % 3);
    opt.extra_levels = (head & 8) ? -1 : (int)((head >> 4) & 3);
    fl_reconstruction2 rec;
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st = fl_reconstruct2(xy, n, &opt, &rec, &err);
    fz_check_status(st, &err, "fl_reconstruct2");
    if (st != FL_OK) {
        if (bad) FZ_ASSERT(st == FL_ERR_INPUT, "NaN/Inf gave %d: %s", (int)st, err.message);
        if (st == FL_ERR_ALGORITHM)
            FZ_ASSERT(fz_collinear2(xy, n), "FL_ERR_ALGORITHM on non-collinear input: %s",
                      err.message);
        return;
    }
    FZ_ASSERT(!bad, "NaN/Inf accepted");
    FZ_ASSERT(rec.boundary_count >= 3, "boundary of %zu vertices", rec.boundary_count);
    size_t inside = rec.unique_count - rec.boundary_count;
    FZ_ASSERT(rec.boundary_count <= rec.unique_count, "more boundary vertices than points");
    FZ_ASSERT(rec.triangle_count == rec.boundary_count - 2 + 2 * inside,
              "%zu triangles for %zu boundary and %zu inner points", rec.triangle_count,
              rec.boundary_count, inside);
    FZ_ASSERT(rec.all_on_boundary == (inside == 0), "all_on_boundary flag");
    double ring[2 * 48];
    for (size_t i = 0; i < rec.boundary_count; i++) {
        FZ_ASSERT(rec.boundary[i] < n, "boundary index");
        ring[2 * i] = xy[2 * rec.boundary[i]];
        ring[2 * i + 1] = xy[2 * rec.boundary[i] + 1];
    }
    size_t rs[2] = {0, rec.boundary_count}, ps[2] = {0, 1};
    fl_polygon poly = {rec.boundary_count, ring, 1, rs, 1, ps};
    fl_polygon_report rep;
    st = fl_polygon_check(&poly, &rep, &err);
    FZ_ASSERT(st == FL_OK, "fl_polygon_check: %s", err.message);
    FZ_ASSERT(rep.simple == 1, "boundary polygon not simple");
    FZ_ASSERT(rep.ring_orientation[0] == 1, "boundary not counterclockwise");
    fl_polygon_report_free(&rep);
    for (size_t t = 0; t < rec.triangle_count; t++) {
        const uint32_t *v = rec.tri + 3 * t;
        FZ_ASSERT(v[0] < n && v[1] < n && v[2] < n, "triangle index");
        FZ_ASSERT(fl_orient2d(xy + 2 * v[0], xy + 2 * v[1], xy + 2 * v[2]) > 0,
                  "triangle %zu not counterclockwise", t);
    }
    fl_reconstruction2_free(&rec);
}

static void fuzz3(fz_in *in, uint8_t head)
{
    size_t n = fz_byte(in) % 25;
    double xyz[3 * 24];
    int bad = fz_coords(in, xyz, 3 * n);
    fl_reconstruct3_options opt = {0};
    opt.criterion = (fl_reconstruct3_criterion)((head >> 1) & 1);
    opt.extra = (head >> 2) & 3;
    fl_reconstruction3 rec;
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st = fl_reconstruct3(xyz, n, &opt, &rec, &err);
    fz_check_status(st, &err, "fl_reconstruct3");
    if (st != FL_OK) {
        if (bad) FZ_ASSERT(st == FL_ERR_INPUT, "NaN/Inf gave %d: %s", (int)st, err.message);
        if (st == FL_ERR_ALGORITHM)
            FZ_ASSERT(fz_coplanar3(xyz, n, 3), "FL_ERR_ALGORITHM on non-coplanar input: %s",
                      err.message);
        return;
    }
    FZ_ASSERT(!bad, "NaN/Inf accepted");
    FZ_ASSERT(rec.boundary_vertex_count + rec.points_inside == rec.unique_count,
              "boundary %zu + inside %zu != unique %zu", rec.boundary_vertex_count,
              rec.points_inside, rec.unique_count);
    fl_mesh m = {n, xyz, rec.triangle_count, rec.tri};
    fl_mesh_report rep;
    st = fl_mesh_check(&m, NULL, &rep, &err);
    FZ_ASSERT(st == FL_OK, "fl_mesh_check: %s", err.message);
    FZ_ASSERT(rep.closed && rep.manifold && rep.oriented, "boundary closed %d manifold %d "
              "oriented %d", rep.closed, rep.manifold, rep.oriented);
    FZ_ASSERT(rep.components == 1 && rep.genus == 0, "components %zu genus %lld", rep.components,
              rep.genus);
    FZ_ASSERT(rep.self_intersections == 0, "%zu self-intersections", rep.self_intersections);
    /* Outward orientation, exactly: every boundary triangle (ccw from outside) is a face of an
     * interior tetrahedron whose fourth vertex lies below it (the floating-point volume is
     * meaningless at 1e100 scales; found by this target). */
    for (size_t t = 0; t < rec.triangle_count; t++) {
        const uint32_t *f = rec.tri + 3 * t;
        int found = 0;
        for (size_t k = 0; k < rec.tet_count && !found; k++) {
            const uint32_t *q = rec.tet + 4 * k;
            int shared = 0;
            uint32_t apex = 0;
            for (int i = 0; i < 4; i++) {
                if (q[i] == f[0] || q[i] == f[1] || q[i] == f[2]) shared++;
                else apex = q[i];
            }
            if (shared != 3) continue;
            found = 1;
            const double *a = xyz + 3 * f[0], *b = xyz + 3 * f[1], *c = xyz + 3 * f[2];
            FZ_ASSERT(fl_orient3d(a, b, c, xyz + 3 * apex) > 0,
                      "boundary triangle %zu faces inwards", t);
        }
        FZ_ASSERT(found, "boundary triangle %zu is on no interior tetrahedron", t);
    }
    fl_mesh_report_free(&rep);
    fl_reconstruction3_free(&rec);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    uint8_t head = fz_byte(&in);
    if (head & 1)
        fuzz3(&in, head);
    else
        fuzz2(&in, head);
    return 0;
}
