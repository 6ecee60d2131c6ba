/* Measures of a triangle mesh (floating-point constructions). */
#include <math.h>
#include <stdlib.h>

#include "core/core.h"
#include "mesh/mesh_internal.h"

static void sub3(const double *a, const double *b, double *r)
{
    r[0] = a[0] - b[0], r[1] = a[1] - b[1], r[2] = a[2] - b[2];
}

static void cross3(const double *a, const double *b, double *r)
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

static void bounding_box(const fl_mesh *mesh, double *bbox)
{
    for (int k = 0; k < 6; k++)
        bbox[k] = 0.0;
    for (size_t v = 0; v < mesh->vertex_count; v++) {
        const double *p = mesh->xyz + 3 * v;
        for (int k = 0; k < 3; k++) {
            if (v == 0 || p[k] < bbox[k]) bbox[k] = p[k];
            if (v == 0 || p[k] > bbox[3 + k]) bbox[3 + k] = p[k];
        }
    }
}

void fl_mesh_measures(const fl_mesh *mesh, fl_mesh_report *rep)
{
    bounding_box(mesh, rep->bbox);
    /* Volume by the divergence theorem: the sum of signed tetrahedra (o, a, b, c). Taking o at
     * the box centre instead of the origin keeps the terms small for meshes far from the
     * origin, where the cancellation would otherwise eat the digits. */
    double o[3], area = 0.0, six_volume = 0.0;
    for (int k = 0; k < 3; k++)
        o[k] = 0.5 * (rep->bbox[k] + rep->bbox[3 + k]);
    for (size_t t = 0; t < mesh->triangle_count; t++) {
        const uint32_t *f = mesh->tri + 3 * t;
        double a[3], b[3], c[3], ab[3], ac[3], n[3];
        sub3(mesh->xyz + 3 * (size_t)f[0], o, a);
        sub3(mesh->xyz + 3 * (size_t)f[1], o, b);
        sub3(mesh->xyz + 3 * (size_t)f[2], o, c);
        sub3(b, a, ab);
        sub3(c, a, ac);
        cross3(ab, ac, n);
        area += 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        double bc[3];
        cross3(b, c, bc);
        six_volume += a[0] * bc[0] + a[1] * bc[1] + a[2] * bc[2];
    }
    rep->area = area;
    rep->volume = (rep->closed && rep->oriented) ? six_volume / 6.0 : NAN;
}
