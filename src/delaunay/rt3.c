/* Public entry points of the 3D regular (weighted Delaunay) triangulation. It shares the
 * pipeline of the Delaunay triangulation (dt3_build.c) with the power test in place of the
 * in-sphere test; what differs is that points can be hidden, both on arrival (no tetrahedron
 * in conflict) and later (a new point's cavity swallows all tetrahedra around an old vertex). */
#include <stdlib.h>
#include <string.h>

#include "delaunay/dt3_internal.h"

fl_status fl_rt3_build(const double *xyzw, size_t n, const fl_rt3_options *opt, fl_rt3 *out,
                       fl_error *err)
{
    static const fl_rt3_options defaults = {0};
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_rt3_build: out is NULL");
    memset(out, 0, sizeof *out);
    if (!opt) opt = &defaults;
    dt3_output r;
    fl_status st =
        dt3_build(xyzw, n, 1, opt->progress, opt->progress_user, opt->want_ortho, &r, err);
    if (st != FL_OK) return st;
    out->point_count = n;
    out->vertex_count = r.vertex_count;
    out->duplicate_of = r.duplicate_of;
    out->hidden_count = r.hidden.count;
    out->hidden = fl_vec_release(&r.hidden);
    out->tet_count = r.tet_count;
    out->tet = r.tet;
    out->adj = r.adj;
    out->hull_face_count = r.hull_face_count;
    out->hull_faces = r.hull_faces;
    out->ortho = r.centers;
    return FL_OK;
}

fl_status fl_rt3_verify(const double *xyzw, const fl_rt3 *rt, fl_error *err)
{
    if (!xyzw || !rt || !rt->duplicate_of)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_rt3_verify: NULL argument");
    uint8_t *kept = fl_alloc_array(rt->point_count, 1);
    if (!kept && rt->point_count) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    for (size_t i = 0; i < rt->point_count; i++)
        kept[i] = rt->duplicate_of[i] == i;
    for (size_t h = 0; h < rt->hidden_count; h++)
        if (rt->hidden[h] < rt->point_count) kept[rt->hidden[h]] = 0;
    fl_status st = dt3_verify(xyzw, rt->point_count, 1, kept, rt->tet_count, rt->tet, rt->adj,
                              rt->hull_face_count, rt->hull_faces, err);
    if (st == FL_OK)
        st = dt3_verify_hidden(xyzw, rt->point_count, rt->hidden_count, rt->hidden, rt->tet_count,
                               rt->tet, rt->adj, err);
    free(kept);
    return st;
}

void fl_rt3_free(fl_rt3 *rt)
{
    if (!rt) return;
    free(rt->duplicate_of);
    free(rt->hidden);
    free(rt->tet);
    free(rt->adj);
    free(rt->hull_faces);
    free(rt->ortho);
    memset(rt, 0, sizeof *rt);
}
