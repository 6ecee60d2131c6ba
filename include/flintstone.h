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

/* end of io */


/* ==== mesh ================================================================================ */
/* (section owned by src/mesh) */

/* Options of fl_mesh_check. All zero is the default: every check runs, no progress reports. */
typedef struct fl_mesh_check_options {
    int skip_self_intersections; /* nonzero: skip the (most expensive) self-intersection search */
    fl_progress_fn progress;     /* optional; stages "topology", "self-intersections" */
    void *progress_user;         /* passed to progress */
    size_t max_pairs;            /* keep up to this many intersecting triangle pairs in
                                  * fl_mesh_report.intersecting_pairs (0: keep none) */
} fl_mesh_check_options;

/* What fl_mesh_check found. Counts refer to the mesh as given (no welding). Release with
 * fl_mesh_report_free. Definitions:
 *  - A vertex is *referenced* when some triangle uses it; unreferenced vertices are counted
 *    in unreferenced_vertices and take part in nothing else (not in components, not in euler).
 *  - Edges are the undirected vertex pairs {a,b} used by triangle sides. A triangle with a
 *    repeated index contributes its sides as they are (a side {a,a} is an edge of its own).
 *  - Components are maximal sets of triangles connected through shared vertices (the usual
 *    MeshLab notion; two cubes touching at one vertex index are one component). Numbered in
 *    order of their lowest triangle index. */
typedef struct fl_mesh_report {
    size_t vertices;              /* mesh->vertex_count */
    size_t faces;                 /* mesh->triangle_count */
    size_t edges;                 /* distinct undirected edges */
    size_t unreferenced_vertices; /* vertices no triangle uses */
    size_t boundary_edges;        /* edges with exactly one incident triangle */
    size_t nonmanifold_edges;     /* edges with three or more incident triangles */
    size_t nonmanifold_vertices;  /* referenced vertices whose triangles form more than one fan
                                   * (edge-connected set around the vertex), e.g. two cones
                                   * touching at their apex; a triangle repeating an index has
                                   * one corner (fan member) per occurrence */
    size_t misoriented_edges;     /* edges used twice in the same direction */
    int closed;                   /* 1 iff faces > 0 and every edge has exactly two triangles */
    int manifold;                 /* 1 iff no non-manifold edge and no non-manifold vertex */
    int oriented;                 /* 1 iff no directed edge (a->b) is used by two triangles, i.e.
                                   * every two-triangle edge is used once in each direction */
    long long euler;              /* V - E + F over referenced vertices, edges and triangles */
    size_t components;            /* number of components (0 for a mesh without triangles) */
    long long *component_genus;   /* per component: (2 - (V-E+F)) / 2 when the component is
                                   * closed, manifold and oriented, else -1 */
    size_t *component_faces;      /* per component: its number of triangles */
    long long genus;              /* sum of component_genus when none is -1, else -1 */
    size_t degenerate_faces;      /* triangles with a repeated index or three collinear vertices
                                   * (decided exactly: the cross product is the zero vector) */
    size_t duplicate_vertices;    /* vertices whose coordinates equal (==, so -0 equals +0) those
                                   * of a lower-indexed vertex */
    int self_intersections_checked; /* 0 when skipped by the options */
    size_t self_intersections;    /* pairs of non-degenerate triangles that intersect beyond the
                                   * vertices they share, decided exactly on the closed
                                   * triangles: sharing no vertex index, any common point counts
                                   * (touching too); sharing one vertex, any common point other
                                   * than it; sharing an edge, overlap beyond the edge (coplanar
                                   * on the same side); sharing all three (duplicate faces),
                                   * always. Degenerate triangles are not tested. */
    uint32_t *intersecting_pairs; /* 2 per kept pair: triangle indices (lower first), the
                                   * first options.max_pairs pairs found (NULL when none) */
    size_t intersecting_pairs_kept; /* number of pairs in intersecting_pairs */
    double bbox[6];               /* min x, y, z, max x, y, z over all vertices (0 when none) */
    double area;                  /* sum of triangle areas (floating point) */
    double volume;                /* enclosed signed volume (divergence theorem), positive when
                                   * triangles are counter-clockwise seen from outside; NaN
                                   * unless the mesh is closed and oriented */
} fl_mesh_report;

/* Checks a triangle mesh: topology (edges, boundary, manifoldness, orientation, components,
 * Euler characteristic, genus), degeneracies, duplicate vertices, self-intersections and the
 * measures (bbox, area, volume). Runs in O(n log n) expected time for n triangles.
 * `opt` may be NULL (defaults). On success *report is filled and must be released with
 * fl_mesh_report_free. Errors: FL_ERR_INPUT for an index >= vertex_count or a non-finite
 * coordinate, FL_ERR_INPUT when 3 * triangle_count >= 2^32 - 1, FL_ERR_NOMEM,
 * FL_ERR_ALGORITHM "cancelled" when progress asked to stop. On failure *report is zeroed. */
fl_status fl_mesh_check(const fl_mesh *mesh, const fl_mesh_check_options *opt,
                        fl_mesh_report *report, fl_error *err);

void fl_mesh_report_free(fl_mesh_report *report);

/* Welds exactly coincident vertices: out receives the distinct vertex positions (==, so -0
 * equals +0) in order of first occurrence and mesh's triangles re-indexed to them, in the same
 * order (triangles that become degenerate are kept; fl_mesh_check counts them). Vertices no
 * triangle uses are kept too. O(V + T) expected. Release out with fl_mesh_free. Errors:
 * FL_ERR_INPUT for an index >= vertex_count, FL_ERR_NOMEM; on failure *out is zeroed. */
fl_status fl_mesh_weld(const fl_mesh *mesh, fl_mesh *out, fl_error *err);

/* What fl_polygon_check found. Release with fl_polygon_report_free. */
typedef struct fl_polygon_report {
    size_t vertices, rings, polygons;
    size_t holes;                 /* rings that are not the first ring of their polygon */
    int simple;                   /* 1 iff every ring has >= 3 vertices, no two consecutive
                                   * vertices of a ring are equal, and no two edges of any rings
                                   * meet except consecutive edges of one ring at their common
                                   * vertex (decided exactly) */
    size_t edge_intersections;    /* pairs of edges that meet where they should not: edges of
                                   * different rings or non-consecutive edges of one ring with
                                   * a common point; consecutive edges overlapping beyond their
                                   * common vertex. Rings with < 3 vertices take no part. */
    size_t first_crossing[2];     /* when edge_intersections > 0: one such pair of edges, each
                                   * named by the index of its first vertex (lower first) */
    int *ring_orientation;        /* per ring: +1 counter-clockwise, -1 clockwise, 0 when the
                                   * ring is degenerate; exact turn at the lowest-leftmost vertex,
                                   * which is the ring's orientation when the ring is simple */
    double *ring_area;            /* per ring: signed shoelace area (positive when ccw) */
    int orientation;              /* +1: every outer ring ccw and every hole cw (GeoJSON,
                                   * RFC 7946); -1: the reverse (ESRI shapefile); 0: mixed */
    double area;                  /* sum over polygons of |outer| - sum |holes| */
    int holes_inside;             /* 1: every hole lies strictly inside its outer ring; 0: some
                                   * hole does not; -1: not decided because not simple */
} fl_polygon_report;

/* Checks planar polygons: simplicity, ring orientation, areas, holes inside their outer ring.
 * O(n log n) for n vertices when few edges are near each other, plus O(outer ring size) per
 * hole for holes_inside. An all-zero polygon (no vertices, rings or polygons) is valid. On success *report must be
 * released with fl_polygon_report_free. Errors: FL_ERR_INPUT for ring/polygon ranges that do
 * not fit the arrays or non-finite coordinates; FL_ERR_NOMEM. On failure *report is zeroed. */
fl_status fl_polygon_check(const fl_polygon *polygon, fl_polygon_report *report, fl_error *err);

void fl_polygon_report_free(fl_polygon_report *report);

/* end of mesh */


/* ==== delaunay ============================================================================ */
/* (section owned by src/delaunay) */

/* end of delaunay */


#ifdef __cplusplus
}
#endif

#endif /* FLINTSTONE_H */
