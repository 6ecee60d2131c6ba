/* Extraction of the constriction result: boundary triangles, interior tetrahedra, the points
 * left inside and the volume; and the debug-build check that the boundary is a sphere. */
#include <stdlib.h>
#include <string.h>

#include "reconstruct/constrict3_internal.h"

static size_t count_boundary_faces(const constrict3_state *s)
{
    size_t f = 0;
    for (size_t t = 0; t < s->tet_count; t++) {
        if (s->removed[t]) continue;
        for (int k = 0; k < 4; k++) {
            uint32_t nb = s->adj[4 * t + k];
            f += nb == UINT32_MAX || s->removed[nb];
        }
    }
    return f;
}

/* Writes the boundary faces of the region (counterclockwise from outside the region, since
 * they are counterclockwise from outside their tetrahedron) into tri, which has room. */
static void write_boundary_faces(const constrict3_state *s, uint32_t *tri)
{
    size_t f = 0;
    for (size_t t = 0; t < s->tet_count; t++) {
        if (s->removed[t]) continue;
        for (int k = 0; k < 4; k++) {
            uint32_t nb = s->adj[4 * t + k];
            if (nb != UINT32_MAX && !s->removed[nb]) continue;
            for (int i = 0; i < 3; i++)
                tri[3 * f + i] = s->tet[4 * t + constrict3_face[k][i]];
            f++;
        }
    }
}

/* Volume of a positively oriented tetrahedron: fl_orient3d > 0 means the determinant
 * [t1-t0, t2-t0, t3-t0] is negative (include/flintstone.h). */
static double tet_volume(const double *p, const uint32_t *t)
{
    const double *a = p + 3 * (size_t)t[0], *b = p + 3 * (size_t)t[1];
    const double *c = p + 3 * (size_t)t[2], *d = p + 3 * (size_t)t[3];
    double u[3], v[3], w[3];
    for (int i = 0; i < 3; i++) {
        u[i] = b[i] - a[i];
        v[i] = c[i] - a[i];
        w[i] = d[i] - a[i];
    }
    double det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                 u[2] * (v[0] * w[1] - v[1] * w[0]);
    return -det / 6.0;
}

int constrict3_extract(const constrict3_state *s, const uint32_t *duplicate_of, size_t n,
                       fl_reconstruction3 *out)
{
    size_t faces = count_boundary_faces(s);
    out->tri = fl_alloc_array(faces, 3 * sizeof *out->tri);
    out->tet = fl_alloc_array(s->region_count, 4 * sizeof *out->tet);
    size_t inside = 0;
    for (size_t i = 0; i < n; i++)
        inside += duplicate_of[i] == i && s->bfaces[i] == 0;
    out->inside = fl_alloc_array(inside, sizeof *out->inside);
    if ((!out->tri && faces) || (!out->tet && s->region_count) || (!out->inside && inside))
        return -1;
    write_boundary_faces(s, out->tri);
    out->triangle_count = faces;
    out->tet_count = 0;
    out->volume = 0;
    for (size_t t = 0; t < s->tet_count; t++) {
        if (s->removed[t]) continue;
        memcpy(out->tet + 4 * out->tet_count++, s->tet + 4 * t, 4 * sizeof *out->tet);
        out->volume += tet_volume(s->p, s->tet + 4 * t);
    }
    out->points_inside = 0;
    for (size_t i = 0; i < n; i++)
        if (duplicate_of[i] == i && s->bfaces[i] == 0)
            out->inside[out->points_inside++] = (uint32_t)i;
    out->boundary_vertex_count = s->on_boundary;
    out->all_on_boundary = inside == 0;
    return 0;
}

int constrict3_boundary_is_sphere(const constrict3_state *s, size_t n)
{
    size_t faces = count_boundary_faces(s);
    uint32_t *tri = fl_alloc_array(faces, 3 * sizeof *tri);
    if (!tri)
        return 1; /* cannot check without memory; the caller's run reports NOMEM if it matters */
    write_boundary_faces(s, tri);
    /* fl_mesh holds a mutable pointer, but fl_mesh_check only reads the coordinates */
    fl_mesh mesh = {n, (double *)(uintptr_t)s->p, faces, tri};
    fl_mesh_check_options opt = {1, NULL, NULL};
    fl_mesh_report rep;
    int ok = 1;
    if (fl_mesh_check(&mesh, &opt, &rep, NULL) == FL_OK) {
        ok = rep.closed && rep.manifold && rep.oriented && rep.components == 1 && rep.genus == 0;
        fl_mesh_report_free(&rep);
    }
    free(tri);
    return ok;
}
