/* A picture of polygons as a standalone SVG 1.1 file. Coordinates are shifted so the bounding
 * box (plus a margin) starts at the origin and y is flipped, so "up" in the data is up on
 * screen. Each polygon is filled light with the even-odd rule, which leaves its holes empty
 * whatever their orientation; outer rings are then stroked dark and holes in a second colour.
 * Stroke widths are a fixed fraction of the picture, so they look the same at any scale. */
#include <math.h>
#include <stdio.h>

#include "io/io_internal.h"

typedef struct frame {
    double min_x, max_y; /* data corner mapped to (margin, margin) */
    double margin;
    double width, height; /* of the viewBox */
} frame;

static frame make_frame(const fl_polygon *polygon)
{
    double min_x = 0, max_x = 0, min_y = 0, max_y = 0;
    for (size_t i = 0; i < polygon->vertex_count; i++) {
        double x = polygon->xy[2 * i], y = polygon->xy[2 * i + 1];
        if (i == 0 || x < min_x) min_x = x;
        if (i == 0 || x > max_x) max_x = x;
        if (i == 0 || y < min_y) min_y = y;
        if (i == 0 || y > max_y) max_y = y;
    }
    double size = fmax(max_x - min_x, max_y - min_y);
    /* A single point or an overflowing extent still needs a drawable, finite frame. */
    if (!(size > 0) || !isfinite(size)) size = 1;
    frame f = {min_x, max_y, 0.05 * size, 0, 0};
    f.width = (max_x - min_x) + 2 * f.margin;
    f.height = (max_y - min_y) + 2 * f.margin;
    if (!isfinite(f.width)) f.width = 1;
    if (!isfinite(f.height)) f.height = 1;
    return f;
}

/* One ring as a closed subpath. %.9g keeps far more precision than a picture shows. */
static void ring_subpath(FILE *fp, const fl_polygon *polygon, size_t r, const frame *f)
{
    for (size_t i = polygon->ring_start[r]; i < polygon->ring_start[r + 1]; i++) {
        double x = polygon->xy[2 * i] - f->min_x + f->margin;
        double y = f->max_y - polygon->xy[2 * i + 1] + f->margin;
        fprintf(fp, "%s%.9g %.9g", i == polygon->ring_start[r] ? "M" : " L", x, y);
    }
    fputs(" Z", fp);
}

static void ring_strokes(FILE *fp, const fl_polygon *polygon, const frame *f, int holes)
{
    for (size_t p = 0; p < polygon->polygon_count; p++) {
        size_t first = polygon->polygon_start[p], end = polygon->polygon_start[p + 1];
        /* Ring `first` is the outer boundary, the rest are holes. */
        size_t from = holes ? first + 1 : first;
        size_t to = holes ? end : (first < end ? first + 1 : end);
        for (size_t r = from; r < to; r++) {
            fputs("<path d=\"", fp);
            ring_subpath(fp, polygon, r, f);
            fputs("\"/>\n", fp);
        }
    }
}

fl_status fl_svg_polygon_write(FILE *fp, const fl_polygon *polygon)
{
    frame f = make_frame(polygon);
    /* Scale the picture so its longer side is 800 pixels. */
    double longer = fmax(f.width, f.height);
    double px_w = 800 * f.width / longer, px_h = 800 * f.height / longer;
    double stroke = 0.002 * longer;
    fprintf(fp,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"%.1f\" "
            "height=\"%.1f\" viewBox=\"0 0 %.9g %.9g\">\n",
            px_w, px_h, f.width, f.height);
    fprintf(fp, "<title>%zu polygons, %zu rings, %zu vertices</title>\n", polygon->polygon_count,
            polygon->ring_count, polygon->vertex_count);
    fprintf(fp, "<rect width=\"%.9g\" height=\"%.9g\" fill=\"white\"/>\n", f.width, f.height);
    fputs("<g fill=\"#cfe0f3\" fill-rule=\"evenodd\" stroke=\"none\">\n", fp);
    for (size_t p = 0; p < polygon->polygon_count; p++) {
        fputs("<path d=\"", fp);
        for (size_t r = polygon->polygon_start[p]; r < polygon->polygon_start[p + 1]; r++) {
            if (r > polygon->polygon_start[p]) fputc(' ', fp);
            ring_subpath(fp, polygon, r, &f);
        }
        fputs("\"/>\n", fp);
    }
    fprintf(fp,
            "</g>\n<g class=\"outer\" fill=\"none\" stroke=\"#1f4e79\" stroke-width=\"%.6g\" "
            "stroke-linejoin=\"round\">\n",
            stroke);
    ring_strokes(fp, polygon, &f, 0);
    fprintf(fp,
            "</g>\n<g class=\"holes\" fill=\"none\" stroke=\"#b03a2e\" stroke-width=\"%.6g\" "
            "stroke-linejoin=\"round\">\n",
            stroke);
    ring_strokes(fp, polygon, &f, 1);
    fputs("</g>\n</svg>\n", fp);
    return ferror(fp) ? FL_ERR_IO : FL_OK;
}
