/* Writing a 2D reconstruction: the boundary polygon (.xy, .geojson), the triangulated interior
 * (.off) or a picture in the style of thesis Figs. 5.2-5.3 (.svg): the points, the Delaunay
 * triangulation in faint lines and the constructed boundary bold. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reconstruct/constrict2_internal.h"

#define PICTURE 1000.0
#define MARGIN 40.0

static fl_status write_polygon(const char *path, const double *xy, const fl_reconstruction2 *rec,
                               fl_error *err)
{
    size_t m = rec->boundary_count;
    size_t ring[2] = {0, m}, poly[2] = {0, 1};
    fl_polygon pg = {m, fl_alloc_array(2 * m, sizeof(double)), 1, ring, 1, poly};
    if (!pg.xy) return fl_fail(err, FL_ERR_NOMEM, path, -1, "out of memory");
    for (size_t i = 0; i < m; i++) {
        pg.xy[2 * i] = xy[2 * (size_t)rec->boundary[i]];
        pg.xy[2 * i + 1] = xy[2 * (size_t)rec->boundary[i] + 1];
    }
    fl_status st = fl_write_polygon(path, &pg, err);
    free(pg.xy);
    return st;
}

static fl_status write_off(const char *path, const double *xy, size_t n,
                           const fl_reconstruction2 *rec, fl_error *err)
{
    fl_mesh mesh = {n, fl_alloc_array(3 * n, sizeof(double)), rec->triangle_count, rec->tri};
    if (!mesh.xyz) return fl_fail(err, FL_ERR_NOMEM, path, -1, "out of memory");
    for (size_t i = 0; i < n; i++) {
        mesh.xyz[3 * i] = xy[2 * i];
        mesh.xyz[3 * i + 1] = xy[2 * i + 1];
        mesh.xyz[3 * i + 2] = 0;
    }
    fl_status st = fl_write_mesh(path, &mesh, err);
    free(mesh.xyz);
    return st;
}

typedef struct view {
    double min_x, max_y, scale;
} view;

static void put(FILE *fp, const view *v, const double *p)
{
    fprintf(fp, "%.6g %.6g", MARGIN + (p[0] - v->min_x) * v->scale,
            MARGIN + (v->max_y - p[1]) * v->scale);
}

static void svg_body(FILE *fp, const double *xy, size_t n, const fl_reconstruction2 *rec,
                     const view *v)
{
    fputs("<path fill=\"none\" stroke=\"#9ab\" stroke-width=\"0.6\" d=\"", fp);
    for (size_t t = 0; t < rec->delaunay_count; t++) {
        const uint32_t *c = rec->delaunay_tri + 3 * t;
        for (int k = 0; k < 3; k++) {
            fputs(k ? " L" : "M", fp);
            put(fp, v, xy + 2 * (size_t)c[k]);
        }
        fputs(" Z\n", fp);
    }
    fputs("\"/>\n<path fill=\"#f3ead6\" fill-opacity=\"0.5\" stroke=\"#222\" "
          "stroke-width=\"2.5\" stroke-linejoin=\"round\" d=\"",
          fp);
    for (size_t i = 0; i < rec->boundary_count; i++) {
        fputs(i ? " L" : "M", fp);
        put(fp, v, xy + 2 * (size_t)rec->boundary[i]);
    }
    fputs(" Z\"/>\n<g fill=\"#c33\">\n", fp);
    for (size_t i = 0; i < n; i++) {
        fputs("<circle r=\"2.5\" cx=\"", fp);
        fprintf(fp, "%.6g\" cy=\"%.6g\"/>\n", MARGIN + (xy[2 * i] - v->min_x) * v->scale,
                MARGIN + (v->max_y - xy[2 * i + 1]) * v->scale);
    }
    fputs("</g>\n", fp);
}

static fl_status write_svg(const char *path, const double *xy, size_t n,
                           const fl_reconstruction2 *rec, fl_error *err)
{
    double min_x = INFINITY, max_x = -INFINITY, min_y = INFINITY, max_y = -INFINITY;
    for (size_t i = 0; i < n; i++) {
        min_x = fmin(min_x, xy[2 * i]), max_x = fmax(max_x, xy[2 * i]);
        min_y = fmin(min_y, xy[2 * i + 1]), max_y = fmax(max_y, xy[2 * i + 1]);
    }
    /* Halved extents stay finite even for coordinates near +-DBL_MAX. */
    double half = fmax(max_x / 2 - min_x / 2, max_y / 2 - min_y / 2);
    if (!(half > 0)) half = 1;
    view v = {min_x, max_y, PICTURE / (2 * half)};
    double w = (max_x - min_x) * v.scale + 2 * MARGIN, h = (max_y - min_y) * v.scale + 2 * MARGIN;
    fl_out_file out;
    fl_status st = fl_out_open(&out, path, 0, err);
    if (st != FL_OK) return st;
    fprintf(out.fp,
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
            "version=\"1.1\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n"
            "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
            w, h, w, h);
    svg_body(out.fp, xy, n, rec, &v);
    fputs("</svg>\n", out.fp);
    return fl_out_commit(&out, err);
}

fl_status fl_write_reconstruction2(const char *path, const double *xy, size_t n,
                                   const fl_reconstruction2 *rec, fl_error *err)
{
    if (!path || !xy || !rec || !rec->boundary)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_write_reconstruction2: NULL argument");
    if (n != rec->point_count)
        return fl_fail(err, FL_ERR_USAGE, path, -1,
                       "%zu points given but the reconstruction was built from %zu", n,
                       rec->point_count);
    char ext[16];
    fl_path_extension(path, ext, sizeof ext);
    if (strcmp(ext, "xy") == 0 || strcmp(ext, "geojson") == 0 || strcmp(ext, "json") == 0)
        return write_polygon(path, xy, rec, err);
    if (strcmp(ext, "off") == 0) return write_off(path, xy, n, rec, err);
    if (strcmp(ext, "svg") == 0) return write_svg(path, xy, n, rec, err);
    return fl_fail(err, FL_ERR_USAGE, path, -1,
                   "unknown output format '.%s' (expected .xy, .geojson, .svg or .off)", ext);
}
