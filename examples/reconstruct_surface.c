/* Example: reconstruct a closed surface through a 3D point sample and write it as a mesh.
 *
 *   reconstruct_surface [POINTS] [OUT]     (defaults: data/demo/peanut.xyz, surface.off)
 *
 * POINTS is any point file fl_read_points reads (.xyz .txt .csv .ply .off .obj); OUT is a mesh
 * file chosen by extension (.off .obj .ply .stl). fl_reconstruct3 constricts the Delaunay
 * tetrahedralization until every point is on the boundary (Veltkamp's thesis, ch. 5); the
 * boundary is then checked with fl_mesh_check (closed, oriented, genus 0) before it is written.
 *
 *   cc reconstruct_surface.c $(pkg-config --cflags --libs flintstone) -o reconstruct_surface
 */
#include <stdio.h>
#include <stdlib.h>

#include "flintstone.h"

#ifndef FL_DEMO_DIR
#define FL_DEMO_DIR "data/demo"
#endif

static int report(const fl_error *err)
{
    char msg[1200];
    fl_error_format(err, msg, sizeof msg);
    fprintf(stderr, "error: %s\n", msg);
    return (int)err->status;
}

/* The boundary as a standalone mesh: only the points it uses, renumbered in first-use order. */
static fl_status boundary_mesh(const fl_points *pts, const fl_reconstruction3 *rec, fl_mesh *mesh)
{
    uint32_t *map = malloc(pts->count * sizeof *map);
    mesh->xyz = malloc(pts->count * 3 * sizeof *mesh->xyz);
    mesh->tri = malloc(rec->triangle_count * 3 * sizeof *mesh->tri);
    if (!map || !mesh->xyz || !mesh->tri) {
        free(map);
        return FL_ERR_NOMEM;
    }
    for (size_t i = 0; i < pts->count; i++) map[i] = UINT32_MAX;
    mesh->vertex_count = 0;
    for (size_t k = 0; k < rec->triangle_count * 3; k++) {
        uint32_t p = rec->tri[k];
        if (map[p] == UINT32_MAX) {
            map[p] = (uint32_t)mesh->vertex_count++;
            for (int c = 0; c < 3; c++) mesh->xyz[3 * map[p] + c] = pts->coords[3 * p + c];
        }
        mesh->tri[k] = map[p];
    }
    mesh->triangle_count = rec->triangle_count;
    free(map);
    return FL_OK;
}

int main(int argc, char **argv)
{
    const char *in = argc > 1 ? argv[1] : FL_DEMO_DIR "/peanut.xyz";
    const char *out = argc > 2 ? argv[2] : "surface.off";
    if (argc > 3 || (argc > 1 && argv[1][0] == '-')) {
        fprintf(stderr, "usage: %s [POINTS.xyz] [OUT.off]\n", argv[0]);
        return 1;
    }
    fl_error err;
    fl_points pts;
    if (fl_read_points(in, &pts, &err) != FL_OK) return report(&err);
    if (pts.dim != 3) {
        fprintf(stderr, "error: %s: need 3D points, got %dD\n", in, pts.dim);
        fl_points_free(&pts);
        return FL_ERR_INPUT;
    }
    fl_reconstruction3 rec;
    fl_mesh mesh = {0, NULL, 0, NULL};
    fl_mesh_report check = {0};
    fl_status st = fl_reconstruct3(pts.coords, pts.count, NULL, &rec, &err);
    if (st == FL_OK) {
        st = boundary_mesh(&pts, &rec, &mesh);
        if (st != FL_OK) fprintf(stderr, "error: out of memory\n");
    }
    if (st == FL_OK) st = fl_mesh_check(&mesh, NULL, &check, &err);
    if (st == FL_OK) st = fl_write_mesh(out, &mesh, &err);
    if (st == FL_OK) {
        printf("%s: %zu points -> %zu boundary triangles, %zu interior tetrahedra, volume %g\n",
               in, pts.count, rec.triangle_count, rec.tet_count, rec.volume);
        printf("boundary: %s, %s, genus %lld; %zu of %zu distinct points on it%s%s\n",
               check.closed ? "closed" : "OPEN", check.oriented ? "oriented" : "NOT oriented",
               check.genus, rec.boundary_vertex_count, rec.unique_count,
               rec.all_on_boundary ? "" : "; ", rec.reason);
        printf("wrote %s\n", out);
    } else if (st != FL_ERR_NOMEM) {
        report(&err);
    }
    fl_mesh_report_free(&check);
    fl_mesh_free(&mesh);
    fl_reconstruction3_free(&rec);
    fl_points_free(&pts);
    return (int)st;
}
