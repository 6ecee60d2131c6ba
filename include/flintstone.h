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
/* (section owned by src/predicates; docs/predicates.md)
 *
 * Exact geometric predicates. Each returns the exact sign (-1, 0 or +1) of a determinant for
 * every finite double input (huge, tiny and subnormal values included): a floating-point
 * filter with a proven error bound decides almost every call, and an exact integer evaluation
 * decides the rest. NaN or infinite inputs give an unspecified sign (but no crash). Points are
 * arrays of 2 or 3 coordinates; weighted points carry the weight after the coordinates, (x, y, w)
 * or (x, y, z, w), where w is a squared radius and the lifted coordinate is |p|^2 - w.
 * All functions are pure and re-entrant; the exact stage uses about 20 KB of stack. */

/* +1 if a, b, c are counterclockwise, -1 if clockwise, 0 if collinear:
 * the sign of det[a - c; b - c]. */
int fl_orient2d(const double *a, const double *b, const double *c);

/* +1 if d lies below the plane through a, b, c, where "below" means that a, b, c appear
 * counterclockwise seen from above; -1 if above; 0 if coplanar. The sign of
 * det[a - d; b - d; c - d] (Shewchuk's convention; e.g. a=(0,0,0), b=(1,0,0), c=(0,1,0),
 * d=(0,0,-1) gives +1). */
int fl_orient3d(const double *a, const double *b, const double *c, const double *d);

/* +1 if d lies inside the circle through a, b, c, -1 outside, 0 on it, when
 * fl_orient2d(a, b, c) = +1; the sign flips when a, b, c are clockwise. Precisely the sign of
 * det[a - d, |a - d|^2; b - d, |b - d|^2; c - d, |c - d|^2]. */
int fl_incircle(const double *a, const double *b, const double *c, const double *d);

/* +1 if e lies inside the sphere through a, b, c, d, -1 outside, 0 on it, when
 * fl_orient3d(a, b, c, d) = +1 (the sign flips otherwise): the sign of
 * det[a - e, |a - e|^2; ...; d - e, |d - e|^2]. */
int fl_insphere(const double *a, const double *b, const double *c, const double *d,
                const double *e);

/* Power test on weighted points (x, y, w): +1 if d's lifted point lies below the plane of the
 * lifted a, b, c when fl_orient2d(a, b, c) = +1, i.e. power(d, orthocircle(a, b, c)) < 0 and d
 * is in conflict with triangle abc; the sign flips when a, b, c are clockwise. With equal
 * weights it equals fl_incircle. */
int fl_incircle_weighted(const double *a, const double *b, const double *c, const double *d);

/* The same in 3D on weighted points (x, y, z, w), with fl_orient3d(a, b, c, d) = +1. */
int fl_insphere_weighted(const double *a, const double *b, const double *c, const double *d,
                         const double *e);

/* Symbolically perturbed predicates (Simulation of Simplicity). Each point carries a global
 * index (its position in the caller's input); the indices of one call must be pairwise
 * distinct. The perturbation depends only on (coordinates, index), so all answers of one
 * family are consistent with a single perturbed configuration. Every _sos function returns
 * the unperturbed sign whenever that is nonzero, and for any argument order:
 *  - swapping two arguments together with their indices flips the sign (the result depends
 *    only on the set of (point, index) pairs and the parity of their order);
 *
 * Orientation (Edelsbrunner-Mucke): coordinate j (0-based) of the point with index i is moved
 * by eps^(2^(i*dim + dim-1-j)) for an infinitesimal eps > 0: a lower index moves more, and
 * within a point the last coordinate moves most. Never returns 0, even for coincident points.
 */
int fl_orient2d_sos(const double *a, const double *b, const double *c, uint32_t ia, uint32_t ib,
                    uint32_t ic);
int fl_orient3d_sos(const double *a, const double *b, const double *c, const double *d,
                    uint32_t ia, uint32_t ib, uint32_t ic, uint32_t id);

/* In-circle / in-sphere (Devillers-Teillaud style, for Delaunay and regular triangulations):
 * coordinates are NOT perturbed; only the lifted coordinate is, as if the point with index i
 * had weight w + eps^(2^32 - i): a higher index is perturbed more (is "heavier"). The
 * perturbed determinant is det + sum_k eps_k * cofactor_k, and each cofactor is, up to sign,
 * the orientation of the other points, so a zero determinant is decided by the orientation
 * of the remaining points after dropping the highest-index point, then the next, and so on.
 * Consequences callers can rely on:
 *  - the result is nonzero whenever fl_orient2d(a, b, c) != 0 (fl_orient3d(a, b, c, d) != 0),
 *    and more generally unless all points are collinear (coplanar), when it is 0;
 *  - a point d exactly on the circle through a, b, c (orient2d(a, b, c) = +1) with a higher
 *    index than a, b and c is reported inside (+1): a later-inserted point on the circle is
 *    in conflict;
 *  - the orientation predicates are unperturbed in this family: use fl_orient2d/3d (not _sos)
 *    alongside these, and never call them on flat triangles/tetrahedra.
 * The weighted versions use the same rule on the weight (the lift is |p|^2 - w). */
int fl_incircle_sos(const double *a, const double *b, const double *c, const double *d,
                    uint32_t ia, uint32_t ib, uint32_t ic, uint32_t id);
int fl_insphere_sos(const double *a, const double *b, const double *c, const double *d,
                    const double *e, uint32_t ia, uint32_t ib, uint32_t ic, uint32_t id,
                    uint32_t ie);
int fl_incircle_weighted_sos(const double *a, const double *b, const double *c, const double *d,
                             uint32_t ia, uint32_t ib, uint32_t ic, uint32_t id);
int fl_insphere_weighted_sos(const double *a, const double *b, const double *c, const double *d,
                             const double *e, uint32_t ia, uint32_t ib, uint32_t ic, uint32_t id,
                             uint32_t ie);

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

/* Writes a tetrahedral mesh: `point_count` points xyz[3i..3i+2] and `tet_count` tetrahedra of 4
 * point indices each (all < point_count). By extension: .vtk (legacy ASCII unstructured grid,
 * opens in ParaView) or TetGen's .node/.ele pair (either name may be given; both files
 * "<stem>.node" and "<stem>.ele" are written, 0-based indices with "# firstnumber 0" noted).
 * Written atomically; on failure no target is changed. */
fl_status fl_write_tets(const char *path, const double *xyz, size_t point_count,
                        const uint32_t *tet, size_t tet_count, fl_error *err);

/* end of io */


/* ==== mesh ================================================================================ */
/* (section owned by src/mesh) */

/* end of mesh */


/* ==== delaunay ============================================================================ */
/* (section owned by src/delaunay) */

/* end of delaunay */


#ifdef __cplusplus
}
#endif

#endif /* FLINTSTONE_H */
