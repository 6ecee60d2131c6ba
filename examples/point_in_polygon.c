/* Example: exact point-in-polygon queries through a flintstone tree (fl_hal2).
 *
 *   point_in_polygon POLYGON [QUERIES]   classify each query point (prints x y where)
 *   point_in_polygon                     demo: the polygon reconstructed from
 *                                        data/demo/leaf.xy, queried on a 200 x 200 grid
 *
 * POLYGON is a polygon file (.xy rings, .geojson with holes); QUERIES a 2D point file. The tree
 * is built once in O(N log N) and answers each query exactly (the same answer as testing every
 * edge with exact predicates; the flintstones only prune, HAL paper §5.1). The demo checks the
 * answers against the polygon's area: the inside grid cells times the cell area approach it.
 *
 *   cc point_in_polygon.c $(pkg-config --cflags --libs flintstone) -o point_in_polygon
 */
#include <stdio.h>
#include <stdlib.h>

#include "flintstone.h"

#ifndef FL_DEMO_DIR
#define FL_DEMO_DIR "data/demo"
#endif

#define GRID 200

static int report(const fl_error *err)
{
    char msg[1200];
    fl_error_format(err, msg, sizeof msg);
    fprintf(stderr, "error: %s\n", msg);
    return (int)err->status;
}

/* The demo polygon: the boundary through the unordered leaf sample (fl_reconstruct2). */
static fl_status leaf_polygon(fl_polygon *poly, fl_error *err)
{
    fl_points pts;
    fl_status st = fl_read_points(FL_DEMO_DIR "/leaf.xy", &pts, err);
    if (st != FL_OK) return st;
    fl_reconstruction2 rec;
    st = fl_reconstruct2(pts.coords, pts.count, NULL, &rec, err);
    if (st == FL_OK) {
        size_t n = rec.boundary_count;
        poly->xy = malloc(2 * n * sizeof *poly->xy);
        poly->ring_start = malloc(2 * sizeof *poly->ring_start);
        poly->polygon_start = malloc(2 * sizeof *poly->polygon_start);
        if (poly->xy && poly->ring_start && poly->polygon_start) {
            for (size_t i = 0; i < n; i++) {
                poly->xy[2 * i] = pts.coords[2 * rec.boundary[i]];
                poly->xy[2 * i + 1] = pts.coords[2 * rec.boundary[i] + 1];
            }
            poly->vertex_count = n;
            poly->ring_count = poly->polygon_count = 1;
            poly->ring_start[0] = poly->polygon_start[0] = 0;
            poly->ring_start[1] = n;
            poly->polygon_start[1] = 1;
        } else {
            fl_polygon_free(poly);
            st = FL_ERR_NOMEM;
            err->status = st;
            err->file[0] = '\0';
            snprintf(err->message, sizeof err->message, "out of memory");
        }
        fl_reconstruction2_free(&rec);
    }
    fl_points_free(&pts);
    return st;
}

static const char *where_name(uint8_t w)
{
    return w == FL_HAL2_INSIDE ? "inside" : w == FL_HAL2_BOUNDARY ? "boundary" : "outside";
}

/* Queries a GRID x GRID lattice of cell centres over the polygon's bounding box. */
static fl_status grid_demo(const fl_hal2 *hal, fl_error *err)
{
    const fl_polygon *p = &hal->polygon;
    double lo[2] = {p->xy[0], p->xy[1]}, hi[2] = {p->xy[0], p->xy[1]};
    for (size_t i = 0; i < p->vertex_count; i++)
        for (int c = 0; c < 2; c++) {
            if (p->xy[2 * i + c] < lo[c]) lo[c] = p->xy[2 * i + c];
            if (p->xy[2 * i + c] > hi[c]) hi[c] = p->xy[2 * i + c];
        }
    double *q = malloc(2 * GRID * GRID * sizeof *q);
    uint8_t *where = malloc(GRID * GRID);
    fl_status st = FL_ERR_NOMEM;
    if (q && where) {
        double dx = (hi[0] - lo[0]) / GRID, dy = (hi[1] - lo[1]) / GRID;
        for (int j = 0; j < GRID; j++)
            for (int i = 0; i < GRID; i++) {
                q[2 * (j * GRID + i)] = lo[0] + (i + 0.5) * dx;
                q[2 * (j * GRID + i) + 1] = lo[1] + (j + 0.5) * dy;
            }
        st = fl_hal2_contains(hal, q, GRID * GRID, where, err);
        if (st == FL_OK) {
            size_t count[3] = {0, 0, 0};
            for (size_t k = 0; k < GRID * GRID; k++) count[where[k]]++;
            double area = 0; /* shoelace over the one ring */
            for (size_t i = 0, n = p->vertex_count; i < n; i++) {
                size_t k = (i + 1) % n;
                area += p->xy[2 * i] * p->xy[2 * k + 1] - p->xy[2 * k] * p->xy[2 * i + 1];
            }
            printf("%d x %d grid: %zu inside, %zu outside, %zu on the boundary\n", GRID, GRID,
                   count[FL_HAL2_INSIDE], count[FL_HAL2_OUTSIDE], count[FL_HAL2_BOUNDARY]);
            printf("area from the grid %.5f, polygon area %.5f\n",
                   (double)count[FL_HAL2_INSIDE] * dx * dy, area / 2);
        }
    } else {
        fprintf(stderr, "error: out of memory\n");
    }
    free(q);
    free(where);
    return st;
}

static fl_status classify_file(const fl_hal2 *hal, const char *path, fl_error *err)
{
    fl_points pts;
    fl_status st = fl_read_points(path, &pts, err);
    if (st != FL_OK) return st;
    uint8_t *where = malloc(pts.count ? pts.count : 1);
    err->file[0] = '\0';
    if (pts.dim != 2) {
        st = FL_ERR_INPUT;
        snprintf(err->message, sizeof err->message, "%s: need 2D query points", path);
    } else if (!where) {
        st = FL_ERR_NOMEM;
        snprintf(err->message, sizeof err->message, "out of memory");
    } else {
        st = fl_hal2_contains(hal, pts.coords, pts.count, where, err);
    }
    if (st == FL_OK)
        for (size_t k = 0; k < pts.count; k++)
            printf("%.17g %.17g %s\n", pts.coords[2 * k], pts.coords[2 * k + 1],
                   where_name(where[k]));
    err->status = st;
    free(where);
    fl_points_free(&pts);
    return st;
}

int main(int argc, char **argv)
{
    if (argc > 3 || (argc > 1 && argv[1][0] == '-')) {
        fprintf(stderr, "usage: %s [POLYGON [QUERIES]]\n", argv[0]);
        return 1;
    }
    fl_error err = {0};
    fl_polygon poly = {0};
    fl_status st = argc > 1 ? fl_read_polygon(argv[1], &poly, &err) : leaf_polygon(&poly, &err);
    if (st != FL_OK) return report(&err);
    fl_hal2 hal;
    st = fl_hal2_build(&poly, NULL, &hal, &err);
    fl_polygon_free(&poly);
    if (st != FL_OK) return report(&err);
    fprintf(stderr, "%zu rings, %zu vertices, flintstone tree depth %u\n", hal.polygon.ring_count,
            hal.polygon.vertex_count, (unsigned)hal.depth);
    st = argc > 2 ? classify_file(&hal, argv[2], &err) : grid_demo(&hal, &err);
    if (st != FL_OK && st != FL_ERR_NOMEM) report(&err);
    fl_hal2_free(&hal);
    return (int)st;
}
