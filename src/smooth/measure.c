/* Measured, not assumed: the interpolation errors at the mesh vertices, the angle between the
 * normals of the two patches along every shared patch edge (tangent-plane continuity) and
 * whether they fold onto the same side (G1 orientation), and the deviation from the mesh. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "smooth/smooth_internal.h"

typedef struct patch_edge {
    uint64_t key;
    uint32_t pe; /* 3 * patch + edge; edge e runs from corner e to corner e+1 */
} patch_edge;

static int cmp_patch_edge(const void *a, const void *b)
{
    const patch_edge *x = a, *y = b;
    if (x->key != y->key) return x->key < y->key ? -1 : 1;
    return x->pe < y->pe ? -1 : x->pe > y->pe;
}

/* Barycentric coordinates of the point at fraction s from corner e to corner e+1, moved by
 * `inward` towards the third corner. */
static void edge_bary(int e, double s, double inward, double *bc)
{
    bc[e] = (1 - s) * (1 - inward);
    bc[(e + 1) % 3] = s * (1 - inward);
    bc[(e + 2) % 3] = inward;
}

static double angle_deg(const double *a, const double *b)
{
    double c[3];
    g1_cross(a, b, c);
    return atan2(sqrt(g1_dot(c, c)), g1_dot(a, b)) * (180 / 3.14159265358979323846);
}

/* Which side of the edge (within the common tangent plane) patch pe lies on at fraction s. */
static double side(const fl_g1_surface *sf, uint32_t pe, double s, const double *n,
                   const double *tangent)
{
    double bc[3], p0[3], p1[3], d[3], c[3];
    int e = (int)(pe % 3);
    const double *ctrl = sf->ctrl + 30 * (pe / 3);
    edge_bary(e, s, 0, bc);
    fl_g1_patch_eval(ctrl, bc[0], bc[1], bc[2], p0, NULL);
    edge_bary(e, s, 1e-5, bc);
    fl_g1_patch_eval(ctrl, bc[0], bc[1], bc[2], p1, NULL);
    g1_sub(p1, p0, d);
    g1_cross(n, tangent, c);
    return g1_dot(d, c);
}

/* Patch A's edge from node x to y at fraction s is patch B's reversed edge at 1 - s. */
static void compare_edge(const fl_g1_surface *sf, uint32_t pa, uint32_t pb, unsigned samples,
                         fl_g1_metrics *m)
{
    int flipped = 0;
    for (unsigned i = 0; i <= samples; i++) {
        double s = (double)i / samples, bc[3], na[3], nb[3], pa0[3], pa1[3], t[3];
        edge_bary((int)(pa % 3), s, 0, bc);
        fl_g1_patch_eval(sf->ctrl + 30 * (pa / 3), bc[0], bc[1], bc[2], pa0, na);
        edge_bary((int)(pb % 3), 1 - s, 0, bc);
        fl_g1_patch_eval(sf->ctrl + 30 * (pb / 3), bc[0], bc[1], bc[2], NULL, nb);
        m->max_edge_normal_jump_deg = fmax(m->max_edge_normal_jump_deg, angle_deg(na, nb));
        if (i == samples) break;
        double sm = (i + 0.5) / samples; /* orientation: inside the edge, off the vertices */
        edge_bary((int)(pa % 3), sm - 1e-6, 0, bc);
        fl_g1_patch_eval(sf->ctrl + 30 * (pa / 3), bc[0], bc[1], bc[2], pa0, na);
        edge_bary((int)(pa % 3), sm + 1e-6, 0, bc);
        fl_g1_patch_eval(sf->ctrl + 30 * (pa / 3), bc[0], bc[1], bc[2], pa1, NULL);
        g1_sub(pa1, pa0, t);
        if (side(sf, pa, sm, na, t) * side(sf, pb, 1 - sm, na, t) >= 0) flipped = 1;
    }
    m->orientation_flips += (size_t)flipped;
}

fl_status g1_measure_edges(const fl_g1_surface *sf, unsigned samples, fl_g1_metrics *m,
                          fl_error *err)
{
    size_t ne = 3 * sf->patch_count;
    patch_edge *pe = fl_alloc_array(ne, sizeof *pe);
    if (!pe) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    for (size_t i = 0; i < ne; i++) {
        uint64_t a = sf->corner[i], b = sf->corner[3 * (i / 3) + (i + 1) % 3];
        pe[i].key = a < b ? (a << 32 | b) : (b << 32 | a);
        pe[i].pe = (uint32_t)i;
    }
    qsort(pe, ne, sizeof *pe, cmp_patch_edge);
    for (size_t i = 0; i + 1 < ne; i++)
        if (pe[i].key == pe[i + 1].key) {
            compare_edge(sf, pe[i].pe, pe[i + 1].pe, samples, m);
            i++;
        }
    free(pe);
    return FL_OK;
}

void g1_measure_vertices(const fl_g1_surface *sf, const fl_mesh *mesh, fl_g1_metrics *m)
{
    for (size_t p = 0; p < sf->patch_count; p++)
        for (int c = 0; c < 3; c++) {
            uint32_t v = sf->corner[3 * p + c];
            if (v >= mesh->vertex_count) continue;
            double bc[3] = {c == 0, c == 1, c == 2}, pt[3], n[3], d[3];
            fl_g1_patch_eval(sf->ctrl + 30 * p, bc[0], bc[1], bc[2], pt, n);
            g1_sub(pt, mesh->xyz + 3 * v, d);
            m->max_vertex_error = fmax(m->max_vertex_error, sqrt(g1_dot(d, d)));
            g1_sub(n, sf->normal + 3 * v, d);
            m->max_normal_error = fmax(m->max_normal_error, sqrt(g1_dot(d, d)));
        }
}

static double mean_edge_length(const fl_mesh *mesh)
{
    double sum = 0;
    for (size_t h = 0; h < 3 * mesh->triangle_count; h++) {
        double d[3];
        g1_sub(mesh->xyz + 3 * mesh->tri[h], mesh->xyz + 3 * mesh->tri[3 * (h / 3) + (h + 1) % 3],
               d);
        sum += sqrt(g1_dot(d, d));
    }
    return sum / (3.0 * (double)mesh->triangle_count);
}

fl_status g1_measure_deviation(const fl_g1_surface *sf, const fl_mesh *mesh, unsigned samples,
                               fl_g1_metrics *m, fl_error *err)
{
    fl_sweep *sw = NULL;
    fl_sweep_cursor *cur = NULL;
    fl_status st = fl_sweep_build(mesh, NULL, &sw, err);
    if (!st) st = fl_sweep_cursor_new(sw, &cur, err);
    double worst = 0;
    for (size_t p = 0; !st && p < sf->patch_count; p++)
        for (unsigned a = 0; !st && a <= samples; a++)
            for (unsigned b = 0; !st && a + b <= samples; b++) {
                double q[3];
                fl_closest r;
                fl_g1_patch_eval(sf->ctrl + 30 * p, (double)a / samples, (double)b / samples,
                                 (double)(samples - a - b) / samples, q, NULL);
                st = fl_sweep_cursor_closest(cur, q, 0, &r, err);
                if (!st) worst = fmax(worst, r.distance);
            }
    fl_sweep_cursor_free(cur);
    fl_sweep_free(sw);
    m->max_deviation = worst / mean_edge_length(mesh);
    return st;
}

fl_status fl_g1_surface_measure(const fl_g1_surface *surface, const fl_mesh *mesh, unsigned samples,
                                fl_g1_metrics *out, fl_error *err)
{
    if (out) memset(out, 0, sizeof *out);
    if (!surface || !mesh || !out || samples < 2 || mesh->triangle_count == 0 ||
        surface->vertex_count != mesh->vertex_count)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "NULL argument, fewer than 2 samples, or a mesh that is not the one the "
                       "surface was built from");
    g1_measure_vertices(surface, mesh, out);
    fl_status st = g1_measure_edges(surface, samples, out, err);
    /* The deviation grid stops at 8 segments a patch edge: it costs samples^2 / 2 closest
     * points a patch, while only the edge jumps need dense sampling (a jump can sit between
     * samples; the distance of a cubic patch from the mesh varies slowly inside it). */
    if (!st) st = g1_measure_deviation(surface, mesh, samples < 8 ? samples : 8, out, err);
    return st;
}
