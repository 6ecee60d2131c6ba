/* Public entry points of the 3D Delaunay triangulation (include/flintstone.h, "delaunay").
 * The algorithm lives in dt3_build.c and dt3_mesh.c; see docs/delaunay3d.md. */
#include <stdlib.h>
#include <string.h>

#include "delaunay/dt3_internal.h"

fl_status fl_dt3_build(const double *xyz, size_t n, const fl_dt3_options *opt, fl_dt3 *out,
                       fl_error *err)
{
    static const fl_dt3_options defaults = {0};
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_dt3_build: out is NULL");
    memset(out, 0, sizeof *out);
    if (!opt) opt = &defaults;
    dt3_output r;
    fl_status st =
        dt3_build(xyz, n, 0, opt->progress, opt->progress_user, opt->want_circumcenters, &r, err);
    if (st != FL_OK) return st;
    out->point_count = n;
    out->unique_count = r.vertex_count;
    out->duplicate_of = r.duplicate_of;
    out->tet_count = r.tet_count;
    out->tet = r.tet;
    out->adj = r.adj;
    out->hull_face_count = r.hull_face_count;
    out->hull_faces = r.hull_faces;
    out->circumcenters = r.centers;
    fl_vec_free(&r.hidden);
    return FL_OK;
}

fl_status fl_dt3_verify(const double *xyz, const fl_dt3 *dt, fl_error *err)
{
    if (!xyz || !dt || !dt->duplicate_of)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_dt3_verify: NULL argument");
    uint8_t *kept = fl_alloc_array(dt->point_count, 1);
    if (!kept && dt->point_count) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    for (size_t i = 0; i < dt->point_count; i++)
        kept[i] = dt->duplicate_of[i] == i;
    fl_status st = dt3_verify(xyz, dt->point_count, 0, kept, dt->tet_count, dt->tet, dt->adj,
                              dt->hull_face_count, dt->hull_faces, err);
    free(kept);
    return st;
}

void fl_dt3_free(fl_dt3 *dt)
{
    if (!dt) return;
    free(dt->duplicate_of);
    free(dt->tet);
    free(dt->adj);
    free(dt->hull_faces);
    free(dt->circumcenters);
    memset(dt, 0, sizeof *dt);
}
