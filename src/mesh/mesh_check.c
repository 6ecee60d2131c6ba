/* fl_mesh_check: validates the input, then runs the topology, measure, degeneracy, duplicate
 * and self-intersection checks in turn. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "mesh/halfedge.h"
#include "mesh/mesh_internal.h"

fl_status fl_mesh_validate(const fl_mesh *mesh, fl_error *err)
{
    if (!mesh) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "no mesh given");
    if ((mesh->vertex_count && !mesh->xyz) || (mesh->triangle_count && !mesh->tri))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "mesh counts are set but arrays are NULL");
    for (size_t i = 0; i < 3 * mesh->vertex_count; i++)
        if (!isfinite(mesh->xyz[i]))
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "vertex %zu has a non-finite coordinate",
                           i / 3);
    for (size_t i = 0; i < 3 * mesh->triangle_count; i++)
        if (mesh->tri[i] >= mesh->vertex_count)
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "triangle %zu uses vertex %u but the mesh has %zu vertices", i / 3,
                           mesh->tri[i], mesh->vertex_count);
    return FL_OK;
}

static size_t count_degenerate_faces(const fl_mesh *mesh)
{
    size_t n = 0;
    for (size_t t = 0; t < mesh->triangle_count; t++)
        n += fl_mesh_triangle_degenerate(mesh, t);
    return n;
}

fl_status fl_mesh_check(const fl_mesh *mesh, const fl_mesh_check_options *opt,
                        fl_mesh_report *report, fl_error *err)
{
    static const fl_mesh_check_options defaults;
    if (!report) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "no report given");
    memset(report, 0, sizeof *report);
    if (!opt) opt = &defaults;
    fl_status st = fl_mesh_validate(mesh, err);
    if (st != FL_OK) return st;
    if (fl_progress(opt->progress, opt->progress_user, "topology", 0.0))
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
    fl_halfedges he;
    st = fl_halfedges_build(mesh, &he, err);
    if (st != FL_OK) return st;
    report->vertices = mesh->vertex_count;
    report->faces = mesh->triangle_count;
    st = fl_mesh_topology(&he, report, err);
    fl_halfedges_free(&he);
    if (st == FL_OK) {
        fl_mesh_measures(mesh, report);
        report->degenerate_faces = count_degenerate_faces(mesh);
        st = fl_mesh_count_duplicate_vertices(mesh, &report->duplicate_vertices, err);
    }
    if (st == FL_OK && !opt->skip_self_intersections) {
        fl_mesh_pairs pairs;
        st = fl_mesh_find_self_intersections(mesh, 0, opt->progress, opt->progress_user, &pairs,
                                             err);
        report->self_intersections = pairs.total;
        report->self_intersections_checked = st == FL_OK;
    }
    if (st != FL_OK) fl_mesh_report_free(report);
    return st;
}

void fl_mesh_report_free(fl_mesh_report *report)
{
    if (!report) return;
    free(report->component_genus);
    free(report->component_faces);
    memset(report, 0, sizeof *report);
}
