/* Writers for graphs: an SVG picture of a 2D graph (points as dots, edges as lines, like the
 * thesis's Figures 3.3-3.6), and edge/triangle lists as Wavefront .obj or ASCII .ply. All go
 * through core's atomic output files. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "graphs/gamma_internal.h"

static void write_svg(FILE *fp, const double *xy, size_t n, const fl_graph *g)
{
    double lo[2] = {0, 0}, hi[2] = {1, 1};
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 2; k++) {
            lo[k] = i ? fmin(lo[k], xy[2 * i + k]) : xy[k];
            hi[k] = i ? fmax(hi[k], xy[2 * i + k]) : xy[k];
        }
    double ext = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(ext > 0)) ext = 1;
    /* A 480-unit picture with a margin; y flipped so the plot reads like the paper's. */
    double scale = 440 / ext, w = (hi[0] - lo[0]) * scale + 40, h = (hi[1] - lo[1]) * scale + 40;
    double dot = 2.5, stroke = 1.0;
#define SX(x) (20 + ((x)-lo[0]) * scale)
#define SY(y) (h - 20 - ((y)-lo[1]) * scale)
    fprintf(fp, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    fprintf(fp,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
            "viewBox=\"0 0 %.2f %.2f\">\n<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
            w, h, w, h);
    fprintf(fp, "<g stroke=\"black\" stroke-width=\"%.2f\" stroke-linecap=\"round\">\n", stroke);
    int k = g->simplex_size;
    for (size_t s = 0; s < g->simplex_count; s++)
        for (int e = 0; e < (k == 2 ? 1 : k); e++) {
            uint32_t a = g->simplices[s * k + e], b = g->simplices[s * k + (e + 1) % k];
            fprintf(fp, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", SX(xy[2 * a]),
                    SY(xy[2 * a + 1]), SX(xy[2 * b]), SY(xy[2 * b + 1]));
        }
    fprintf(fp, "</g>\n<g fill=\"black\">\n");
    for (size_t i = 0; i < n; i++)
        fprintf(fp, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.1f\"/>\n", SX(xy[2 * i]),
                SY(xy[2 * i + 1]), dot);
    fprintf(fp, "</g>\n</svg>\n");
#undef SX
#undef SY
}

static void write_obj(FILE *fp, const double *coords, size_t n, const fl_graph *g)
{
    int dim = g->dim, k = g->simplex_size;
    fprintf(fp, "# flintstone graph: %zu vertices, %zu %s\n", n, g->simplex_count,
            k == 2 ? "edges" : "triangles");
    for (size_t i = 0; i < n; i++)
        fprintf(fp, "v %.17g %.17g %.17g\n", coords[i * dim], coords[i * dim + 1],
                dim == 3 ? coords[i * dim + 2] : 0.0);
    for (size_t s = 0; s < g->simplex_count; s++) {
        fputs(k == 2 ? "l" : "f", fp);
        for (int j = 0; j < k; j++)
            fprintf(fp, " %u", g->simplices[s * k + j] + 1);
        fputc('\n', fp);
    }
}

static void write_ply(FILE *fp, const double *coords, size_t n, const fl_graph *g)
{
    int dim = g->dim, k = g->simplex_size;
    fprintf(fp, "ply\nformat ascii 1.0\ncomment flintstone graph\n");
    fprintf(fp, "element vertex %zu\nproperty double x\nproperty double y\nproperty double z\n", n);
    if (k == 2)
        fprintf(fp, "element edge %zu\nproperty int vertex1\nproperty int vertex2\n",
                g->simplex_count);
    else
        fprintf(fp, "element face %zu\nproperty list uchar int vertex_indices\n", g->simplex_count);
    fprintf(fp, "end_header\n");
    for (size_t i = 0; i < n; i++)
        fprintf(fp, "%.17g %.17g %.17g\n", coords[i * dim], coords[i * dim + 1],
                dim == 3 ? coords[i * dim + 2] : 0.0);
    for (size_t s = 0; s < g->simplex_count; s++) {
        if (k == 3) fputs("3 ", fp);
        for (int j = 0; j < k; j++)
            fprintf(fp, j ? " %u" : "%u", g->simplices[s * k + j]);
        fputc('\n', fp);
    }
}

fl_status fl_write_graph(const char *path, const double *coords, size_t n, const fl_graph *graph,
                         fl_error *err)
{
    if (!path || !graph || (n && !coords))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_write_graph: NULL argument");
    if (graph->dim != 2 && graph->dim != 3)
        return fl_fail(err, FL_ERR_USAGE, path, -1, "graph has dimension %d", graph->dim);
    for (size_t i = 0; i < graph->simplex_count * (size_t)graph->simplex_size; i++)
        if (graph->simplices[i] >= n)
            return fl_fail(err, FL_ERR_USAGE, path, -1,
                           "graph refers to point %u but only %zu points were given",
                           graph->simplices[i], n);
    char ext[16];
    fl_path_extension(path, ext, sizeof ext);
    int svg = strcmp(ext, "svg") == 0, obj = strcmp(ext, "obj") == 0, ply = strcmp(ext, "ply") == 0;
    if (!svg && !obj && !ply)
        return fl_fail(err, FL_ERR_USAGE, path, -1,
                       "unknown graph format \".%s\"; use .svg (2D), .obj or .ply", ext);
    if (svg && graph->dim != 2)
        return fl_fail(err, FL_ERR_USAGE, path, -1,
                       "an SVG picture needs a 2D graph; write 3D graphs as .obj or .ply");
    fl_out_file out;
    fl_status st = fl_out_open(&out, path, 0, err);
    if (st != FL_OK) return st;
    if (svg)
        write_svg(out.fp, coords, n, graph);
    else if (obj)
        write_obj(out.fp, coords, n, graph);
    else
        write_ply(out.fp, coords, n, graph);
    return fl_out_commit(&out, err);
}
