/* A picture of polygons as a standalone SVG 1.1 file. Coordinates are shifted so the bounding
 * box (plus a margin) starts at the origin and y is flipped, so "up" in the data is up on
 * screen. Each polygon is filled light with the even-odd rule, which leaves its holes empty
 * whatever their orientation; outer rings are then stroked dark and holes in a second colour.
 * Coordinates are scaled to a picture of fixed size, so stroke widths are fixed too. */
#include <math.h>
#include <stdio.h>

#include "io/io_internal.h"

/* The picture is PICTURE units on its longer side plus MARGIN all round; a unit is a pixel. */
#define PICTURE 1000.0
#define MARGIN 50.0

typedef struct frame {
    double min_x, max_y; /* the data corner drawn at (MARGIN, MARGIN) */
    double half;         /* half the longer extent of the data */
    double width, height;
} frame;

/* Halving before subtracting keeps the extent finite even for coordinates near +-DBL_MAX. */
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
    double half_w = max_x / 2 - min_x / 2, half_h = max_y / 2 - min_y / 2;
    frame f = {min_x, max_y, fmax(half_w, half_h), 0, 0};
    if (!(f.half > 0)) f.half = 1; /* a single point: any scale draws it */
    f.width = PICTURE * (half_w / f.half) + 2 * MARGIN;
    f.height = PICTURE * (half_h / f.half) + 2 * MARGIN;
    return f;
}

/* One ring as a closed subpath, in picture units (a thousandth of the picture is far below
 * what a viewer shows, so %.7g is plenty). */
static void ring_subpath(FILE *fp, const fl_polygon *polygon, size_t r, const frame *f)
{
    double s = PICTURE;
    for (size_t i = polygon->ring_start[r]; i < polygon->ring_start[r + 1]; i++) {
        double x = MARGIN + s * ((polygon->xy[2 * i] / 2 - f->min_x / 2) / f->half);
        double y = MARGIN + s * ((f->max_y / 2 - polygon->xy[2 * i + 1] / 2) / f->half);
        fprintf(fp, "%s%.7g %.7g", i == polygon->ring_start[r] ? "M" : " L", x, y);
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
    double stroke = 0.002 * PICTURE;
    fprintf(fp,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"%.7g\" "
            "height=\"%.7g\" viewBox=\"0 0 %.7g %.7g\">\n",
            f.width, f.height, f.width, f.height);
    fprintf(fp, "<title>%zu polygons, %zu rings, %zu vertices</title>\n", polygon->polygon_count,
            polygon->ring_count, polygon->vertex_count);
    fprintf(fp, "<rect width=\"%.7g\" height=\"%.7g\" fill=\"white\"/>\n", f.width, f.height);
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
