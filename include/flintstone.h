/*
 * flintstone — closed object boundaries from scattered points.
 *
 * The one public header. Conventions (see docs/architecture.md):
 *  - Plain data at the boundary: flat arrays of doubles and uint32_t indices, counts, and an
 *    options struct where "all zero" is a documented, safe default.
 *  - Errors are values: every fallible call returns fl_status and, when err is not NULL, fills
 *    it with a message a user can act on. No call aborts or prints.
 *  - Results that own memory are released with the one matching fl_*_free; freeing a zeroed or
 *    already-freed struct is a no-op.
 *  - No global state; every function is re-entrant.
 */
#ifndef FLINTSTONE_H
#define FLINTSTONE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ==== core ================================================================================ */

/* Status of a call. The numeric values are also the CLI's exit codes (FL_ERR_NOMEM exits 3). */
typedef enum fl_status {
    FL_OK = 0,
    FL_ERR_USAGE = 1,     /* a caller error: bad argument or option value */
    FL_ERR_INPUT = 2,     /* the input data is malformed or unsuitable (NaN, too few points...) */
    FL_ERR_ALGORITHM = 3, /* the algorithm could not complete; the message says why */
    FL_ERR_IO = 4,        /* a file could not be opened, read or written */
    FL_ERR_NOMEM = 5      /* an allocation failed or a size would overflow */
} fl_status;

/* Where and why a call failed. `file` is empty and `line`/`offset` are -1 when unknown.
 * For text files `line` is 1-based; for binary files `offset` is the byte offset. */
typedef struct fl_error {
    fl_status status;
    char file[512];
    long line;
    long long offset;
    char message[512];
} fl_error;

/* Progress callback: `fraction` in [0,1] of `stage` (a short static string). Return nonzero to
 * ask the running call to stop; it then returns FL_ERR_ALGORITHM with message "cancelled". */
typedef int (*fl_progress_fn)(void *user, const char *stage, double fraction);

/* Library version, e.g. "0.1.0". */
const char *fl_version(void);

/* A short name for a status, e.g. "bad input". */
const char *fl_status_string(fl_status status);

/* Formats `err` as "<file>:<line>: <message>" (or the parts that are known) into buf. */
void fl_error_format(const fl_error *err, char *buf, size_t size);

/* A point set: `count` points of dimension `dim` (2 or 3), coordinates interleaved in
 * `coords` (count*dim doubles). */
typedef struct fl_points {
    size_t count;
    int dim;
    double *coords;
} fl_points;

void fl_points_free(fl_points *points);

/* A triangle mesh: `vertex_count` vertices (xyz interleaved) and `triangle_count` triangles of
 * three 0-based vertex indices each, counter-clockwise seen from outside for oriented meshes. */
typedef struct fl_mesh {
    size_t vertex_count;
    double *xyz;
    size_t triangle_count;
    uint32_t *tri;
} fl_mesh;

void fl_mesh_free(fl_mesh *mesh);

/* Planar polygons with holes. The vertices of all rings are in `xy` (vertex_count pairs).
 * Ring r spans vertices ring_start[r] .. ring_start[r+1]-1 (ring_start has ring_count+1
 * entries) and is closed implicitly (its last vertex is not a repeat of the first).
 * Polygon p spans rings polygon_start[p] .. polygon_start[p+1]-1 (polygon_count+1 entries);
 * its first ring is the outer boundary, the others are holes. */
typedef struct fl_polygon {
    size_t vertex_count;
    double *xy;
    size_t ring_count;
    size_t *ring_start;
    size_t polygon_count;
    size_t *polygon_start;
} fl_polygon;

void fl_polygon_free(fl_polygon *polygon);

/* ==== predicates ========================================================================== */
/* (section owned by src/predicates) */

/* end of predicates */


/* ==== io ================================================================================== */
/* (section owned by src/io) */

/* Readers choose the format by the file's extension (case-insensitive) and read the whole
 * file in one linear pass. Every parse error names the file and the line (text) or byte
 * offset (binary) and what is wrong. NaN/Inf coordinates and out-of-range indices are rejected
 * with FL_ERR_INPUT; a file that cannot be opened is FL_ERR_IO. On failure *out is zeroed.
 *
 * Points:   .xyz .xy .txt .csv (whitespace or commas, '#' comments, CRLF, optional header
 *           line; 2 or 3 numbers a line, the same on every line), .ply, .off, .obj (vertices).
 * Meshes:   .off, .obj (polygons fan-triangulated; v, v/vt, v//vn, v/vt/vn; negative indices),
 *           .ply (ascii, binary little/big endian; any scalar types, properties in any order),
 *           .stl (ascii and binary; coincident vertices welded exactly).
 * Polygons: .xy (one ring a block; a blank line separates rings; each ring is its own polygon),
 *           .geojson (Polygon, MultiPolygon, Feature, FeatureCollection; holes kept). */
fl_status fl_read_points(const char *path, fl_points *out, fl_error *err);
fl_status fl_read_mesh(const char *path, fl_mesh *out, fl_error *err);
fl_status fl_read_polygon(const char *path, fl_polygon *out, fl_error *err);

/* The same readers on a buffer already in memory (for embedding and fuzzing). `format` is an
 * extension without the dot ("ply", "stl", ...); `name` is used in error messages. */
fl_status fl_parse_points(const char *format, const char *name, const void *data, size_t size,
                          fl_points *out, fl_error *err);
fl_status fl_parse_mesh(const char *format, const char *name, const void *data, size_t size,
                        fl_mesh *out, fl_error *err);
fl_status fl_parse_polygon(const char *format, const char *name, const void *data, size_t size,
                           fl_polygon *out, fl_error *err);

/* Writers choose the format by extension and write atomically (temporary file, then rename):
 * on failure the target is untouched. Points: .xyz .xy .ply. Meshes: .off .obj .ply (binary
 * little endian) .stl (binary). Polygons: .xy .geojson .svg (a picture of the rings). */
fl_status fl_write_points(const char *path, const fl_points *points, fl_error *err);
fl_status fl_write_mesh(const char *path, const fl_mesh *mesh, fl_error *err);
fl_status fl_write_polygon(const char *path, const fl_polygon *polygon, fl_error *err);

/* end of io */


/* ==== mesh ================================================================================ */
/* (section owned by src/mesh) */

/* end of mesh */


/* ==== delaunay ============================================================================ */
/* (section owned by src/delaunay) */

/* -- 2D Delaunay triangulation (src/delaunay/dt2.c) --
 * Every combinatorial decision is made with the exact predicates; ties among cocircular points
 * are broken by symbolic perturbation (simulation of simplicity, by input index), so the result
 * is one well-defined triangulation even for grids and points on a circle: all triangles are
 * counterclockwise with nonzero area, they cover the convex hull of the points exactly, and no
 * input point lies strictly inside any triangle's circumcircle. Points on the hull boundary
 * (also collinear ones) are vertices. Expected O(n log n)-ish time, in practice linear after the
 * spatial sort (see docs/delaunay.md). */

/* Options; all zero is the default (no progress reports, no circumcenters). */
typedef struct fl_dt2_options {
    fl_progress_fn progress; /* called during insertion; may be NULL */
    void *progress_user;
    int want_circumcenters; /* nonzero: fill fl_dt2.circumcenters */
} fl_dt2_options;

/* A 2D Delaunay triangulation. Vertex indices refer to the input points; a point with an exact
 * duplicate earlier in the input is represented by that earlier point (duplicate_of). Triangle
 * t has corners tri[3t..3t+2] in counterclockwise order; adj[3t+k] is the triangle across the
 * edge opposite corner k (the edge tri[3t+(k+1)%3] -> tri[3t+(k+2)%3]), or UINT32_MAX when that
 * edge is on the convex hull. triangle_count = 2*unique_count - 2 - hull_count. */
typedef struct fl_dt2 {
    size_t point_count;     /* input points */
    size_t unique_count;    /* distinct points (duplicates merged) */
    uint32_t *duplicate_of; /* point_count entries: the first input point with identical
                               coordinates (-0.0 == +0.0); itself when it is the first */
    size_t triangle_count;
    uint32_t *tri; /* 3 per triangle, counterclockwise */
    uint32_t *adj; /* 3 per triangle: neighbour across the edge opposite corner k or UINT32_MAX */
    size_t hull_count;
    uint32_t *hull;        /* hull_count vertices of the convex hull, counterclockwise, including
                              points in the relative interior of hull edges */
    double *circumcenters; /* 2 per triangle when requested, else NULL (floating point; may be
                              huge or infinite for nearly flat triangles) */
} fl_dt2;

/* Builds the Delaunay triangulation of the n points xy[2i], xy[2i+1]. `opt` may be NULL.
 * On success *out holds the result (free with fl_dt2_free). Errors (then *out is zeroed):
 * FL_ERR_USAGE for NULL buffers; FL_ERR_INPUT for NaN/Inf coordinates, fewer than 3 distinct
 * points, or more than 2^29 points; FL_ERR_ALGORITHM when all distinct points are collinear
 * (the triangulation would be 1-dimensional) or when the progress callback cancelled;
 * FL_ERR_NOMEM. Memory: about 40 bytes per point at peak besides the output. */
fl_status fl_dt2_build(const double *xy, size_t n, const fl_dt2_options *opt, fl_dt2 *out,
                       fl_error *err);

/* Checks `dt` against the points it was built from, with the exact predicates: index ranges
 * and duplicate map, counterclockwise nonzero-area triangles, adjacency symmetry, the hull as
 * the boundary cycle (convex, simple, counterclockwise), the Euler relation
 * V - E + F = 1 with every distinct point a vertex, and the empty-circle property of every
 * triangle (locally at each edge, exact and with symbolic perturbation; by Delaunay's lemma
 * this is global). Returns FL_OK iff all hold, otherwise FL_ERR_ALGORITHM naming the first
 * violation. O(n). */
fl_status fl_dt2_verify(const double *xy, const fl_dt2 *dt, fl_error *err);

/* Frees the arrays of dt and zeroes it; safe on a zeroed or already-freed struct. */
void fl_dt2_free(fl_dt2 *dt);

/* end of delaunay */


#ifdef __cplusplus
}
#endif

#endif /* FLINTSTONE_H */
