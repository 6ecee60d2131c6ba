/* The distance field of a Hausdorff computation (Guéziec 2001 §6, Fig. 10-C): the refined
 * sample mesh with the measured distance at every sample, and its PLY writer with per-vertex
 * pseudo colours (blue low, red high). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sweep/hausdorff_internal.h"

fl_status hd_field_from_dir(const hd_dir *dir, fl_hausdorff_field *f, fl_error *err)
{
    const hd_sample *smp = dir->samples.data;
    size_t nv = dir->samples.count, nt = dir->k == 3 ? dir->leaves.count : 0;
    f->mesh.xyz = fl_alloc_array(nv, 3 * sizeof(double));
    f->distance = fl_alloc_array(nv, sizeof(double));
    f->mesh.tri = nt ? fl_alloc_array(nt, 3 * sizeof(uint32_t)) : NULL;
    if (!f->mesh.xyz || !f->distance || (nt && !f->mesh.tri))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    f->mesh.vertex_count = nv;
    f->mesh.triangle_count = nt;
    for (size_t i = 0; i < nv; i++) {
        memcpy(f->mesh.xyz + 3 * i, smp[i].p, 3 * sizeof(double));
        f->distance[i] = smp[i].d;
        if (smp[i].elem == FL_SWEEP_NONE) { /* a vertex no simplex uses: measure it now (the
                                             * field promises every vertex's distance) */
            fl_closest r;
            fl_status st = fl_sweep_cursor_closest(dir->cursor, smp[i].p, 0.0, &r, err);
            if (st) return st;
            double d2 = 0;
            for (int k = 0; k < dir->dim; k++)
                d2 += (smp[i].p[k] - r.point[k]) * (smp[i].p[k] - r.point[k]);
            f->distance[i] = sqrt(d2);
        }
    }
    const hd_simplex *leaf = dir->leaves.data;
    for (size_t t = 0; t < nt; t++)
        memcpy(f->mesh.tri + 3 * t, leaf[t].v, 3 * sizeof(uint32_t));
    return FL_OK;
}

/* Blue (t = 0) through green (t = 0.5) to red (t = 1). */
static void pseudo_colour(double t, int *rgb)
{
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    double r = t < 0.5 ? 0 : 2 * t - 1, g = t < 0.5 ? 2 * t : 2 - 2 * t,
           b = t < 0.5 ? 1 - 2 * t : 0;
    rgb[0] = (int)lround(255 * r);
    rgb[1] = (int)lround(255 * g);
    rgb[2] = (int)lround(255 * b);
}

fl_status fl_hausdorff_write_field_ply(const char *path, const fl_hausdorff_field *f, double lo,
                                       double hi, fl_error *err)
{
    if (!path || !f || (f->mesh.vertex_count && (!f->mesh.xyz || !f->distance)))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hausdorff: bad field or path");
    size_t nv = f->mesh.vertex_count, nt = f->mesh.triangle_count;
    if (!(lo < hi)) {
        lo = nv ? f->distance[0] : 0;
        hi = lo;
        for (size_t i = 0; i < nv; i++)
            lo = fmin(lo, f->distance[i]), hi = fmax(hi, f->distance[i]);
    }
    double span = hi > lo ? hi - lo : 1;
    fl_out_file out;
    fl_status st = fl_out_open(&out, path, 0, err);
    if (st) return st;
    fprintf(out.fp,
            "ply\nformat ascii 1.0\ncomment flintstone hausdorff distance field, blue %.17g "
            "red %.17g\nelement vertex %zu\nproperty double x\nproperty double y\n"
            "property double z\nproperty double quality\nproperty uchar red\n"
            "property uchar green\nproperty uchar blue\nelement face %zu\n"
            "property list uchar uint vertex_indices\nend_header\n",
            lo, hi, nv, nt);
    for (size_t i = 0; i < nv; i++) {
        int rgb[3];
        const double *p = f->mesh.xyz + 3 * i;
        pseudo_colour((f->distance[i] - lo) / span, rgb);
        fprintf(out.fp, "%.17g %.17g %.17g %.17g %d %d %d\n", p[0], p[1], p[2], f->distance[i],
                rgb[0], rgb[1], rgb[2]);
    }
    for (size_t t = 0; t < nt; t++) {
        const uint32_t *v = f->mesh.tri + 3 * t;
        fprintf(out.fp, "3 %u %u %u\n", v[0], v[1], v[2]);
    }
    return fl_out_commit(&out, err);
}
