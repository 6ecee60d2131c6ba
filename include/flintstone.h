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

/* Releases points->coords and zeroes *points; NULL, a zeroed or an already-freed struct is a
 * no-op. */
void fl_points_free(fl_points *points);

/* A triangle mesh: `vertex_count` vertices (xyz interleaved) and `triangle_count` triangles of
 * three 0-based vertex indices each, counter-clockwise seen from outside for oriented meshes. */
typedef struct fl_mesh {
    size_t vertex_count;
    double *xyz;
    size_t triangle_count;
    uint32_t *tri;
} fl_mesh;

/* Releases the mesh's arrays and zeroes *mesh; NULL or a zeroed struct is a no-op. */
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

/* Releases the polygon's arrays and zeroes *polygon; NULL or a zeroed struct is a no-op. */
void fl_polygon_free(fl_polygon *polygon);

/* Balls (weighted points): `count` balls, centre and weight interleaved in xyzw (4 doubles a
 * ball); the weight is the squared radius (it may be negative or zero for weighted points). */
typedef struct fl_balls {
    size_t count;
    double *xyzw;
} fl_balls;

/* Releases balls->xyzw and zeroes *balls; NULL or a zeroed struct is a no-op. */
void fl_balls_free(fl_balls *balls);

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

/* The diametral-ball test in dim 2 or 3: +1 if p lies outside the closed ball with diameter ab,
 * 0 on its sphere, -1 strictly inside; exactly the sign of (p - a).(p - b). (The Gabriel test,
 * and the two-point case of a smallest enclosing disc.) Returns 0 for other dims. */
int fl_diametral(const double *a, const double *b, const double *p, int dim);

/* Symbolically perturbed predicates (Simulation of Simplicity). Each point carries a global
 * index (its position in the caller's input); the indices of one call must be pairwise
 * distinct. The perturbation depends only on (coordinates, index), so all answers of one
 * family are consistent with a single perturbed configuration. Every _sos function:
 *  - returns the unperturbed sign whenever that is nonzero;
 *  - flips its sign when two arguments are swapped together with their indices (the result
 *    depends only on the set of (point, index) pairs and the parity of their order).
 *
 * Orientation (Edelsbrunner-Mucke): coordinate j (0-based) of the point with index i is moved
 * by eps^(2^(i*dim + dim-1-j)) for an infinitesimal eps > 0: a lower index moves more, and
 * within a point the last coordinate moves most. Never returns 0, even for coincident points. */
int fl_orient2d_sos(const double *a, const double *b, const double *c, uint32_t ia, uint32_t ib,
                    uint32_t ic);
int fl_orient3d_sos(const double *a, const double *b, const double *c, const double *d,
                    uint32_t ia, uint32_t ib, uint32_t ic, uint32_t id);

/* In-circle / in-sphere (Devillers-Teillaud style, for Delaunay and regular triangulations):
 * coordinates are NOT perturbed; only the lifted coordinate is, as if the point with index i
 * had weight w + eps^(2^32 - i): a higher index is perturbed more (is "heavier"). The
 * determinant is linear in the lift, and the coefficient of point k's perturbation is, up to
 * a sign fixed by k's argument position, the orientation of the other points; so a zero
 * determinant is decided by the orientation of the points left after dropping the
 * highest-index point, else the next highest, and so on. Callers can rely on:
 *  - the result is nonzero whenever fl_orient2d(a, b, c) != 0 (fl_orient3d(a, b, c, d) != 0);
 *    it is 0 exactly when all the points are collinear (coplanar);
 *  - a point d exactly on the circle through a, b, c (orient2d(a, b, c) = +1) with a higher
 *    index than a, b and c is reported inside (+1): a later-inserted cocircular point is in
 *    conflict;
 *  - coordinates are unperturbed in this family, so it pairs with the plain fl_orient2d/3d,
 *    not with fl_orient*_sos (a different perturbation). On a flat triangle/tetrahedron the
 *    answer is still consistent with the perturbed lifted points but describes no circle.
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
 * Points:   .xyz .xy .txt .csv (whitespace, ',' or ';', '#' comments, CRLF, optional header
 *           line; 2 or 3 numbers a line, the same on every line), .ply, .off, .obj (vertices).
 *           Text numbers follow the C library's LC_NUMERIC ('.' in the "C" locale, which the
 *           flintstone command never changes).
 * Meshes:   .off, .obj (polygons fan-triangulated; v, v/vt, v//vn, v/vt/vn; negative indices),
 *           .ply (ascii, binary little/big endian; any scalar types, properties in any order),
 *           .stl (ascii and binary; coincident vertices welded exactly).
 * Polygons: .xy (one ring a block; a blank line separates rings; each ring is its own polygon),
 *           .geojson or .json (Polygon, MultiPolygon, Feature, FeatureCollection,
 *           GeometryCollection; holes kept; rings must be closed; other geometries skipped).
 * See docs/formats.md for every rule. */
fl_status fl_read_points(const char *path, fl_points *out, fl_error *err);
fl_status fl_read_mesh(const char *path, fl_mesh *out, fl_error *err);
fl_status fl_read_polygon(const char *path, fl_polygon *out, fl_error *err);

/* The same readers on a buffer already in memory (for embedding and fuzzing). `format` is an
 * extension without the dot, any case ("ply", "PLY", ...); `name` is used in error messages.
 * `data` need not be NUL-terminated. */
fl_status fl_parse_points(const char *format, const char *name, const void *data, size_t size,
                          fl_points *out, fl_error *err);
fl_status fl_parse_mesh(const char *format, const char *name, const void *data, size_t size,
                        fl_mesh *out, fl_error *err);
fl_status fl_parse_polygon(const char *format, const char *name, const void *data, size_t size,
                           fl_polygon *out, fl_error *err);

/* Writers choose the format by extension and write atomically (temporary file, then rename):
 * on failure the target is untouched. Points: .xyz .txt, .xy (2D only), .ply (2D gets z = 0).
 * Meshes: .off .obj .ply (binary little endian) .stl (binary). Polygons: .xy (holes come back
 * as separate polygons), .geojson/.json (exact, holes kept), .svg (a picture of the rings).
 * Text coordinates are written with %.17g, so reading them back gives the same doubles. */
fl_status fl_write_points(const char *path, const fl_points *points, fl_error *err);
fl_status fl_write_mesh(const char *path, const fl_mesh *mesh, fl_error *err);
fl_status fl_write_polygon(const char *path, const fl_polygon *polygon, fl_error *err);

/* Balls as text, one "x y z w" line each (.xyzw, .txt or .csv; '#' comments, an optional header
 * line, separators as for points). Read and write like points; NaN/Inf rejected. */
fl_status fl_read_balls(const char *path, fl_balls *out, fl_error *err);
fl_status fl_write_balls(const char *path, const fl_balls *balls, fl_error *err);

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

/* Options of fl_mesh_check. All zero is the default: every check runs, no progress reports. */
typedef struct fl_mesh_check_options {
    int skip_self_intersections; /* nonzero: skip the (most expensive) self-intersection search */
    fl_progress_fn progress;     /* optional; stages "topology", "self-intersections" */
    void *progress_user;         /* passed to progress */
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

/* Releases what fl_mesh_check allocated in *report and zeroes it; NULL is a no-op. */
void fl_mesh_report_free(fl_mesh_report *report);

/* Self-intersecting triangle pairs, as counted by fl_mesh_check. */
typedef struct fl_mesh_pairs {
    size_t total;    /* number of intersecting pairs (= fl_mesh_report.self_intersections) */
    size_t count;    /* pairs kept in `pairs`: min(total, max_pairs) */
    uint32_t *pairs; /* 2 per kept pair: triangle indices, lower first (NULL when count = 0) */
} fl_mesh_pairs;

/* Finds the self-intersecting triangle pairs (definition: fl_mesh_report.self_intersections)
 * and keeps the first max_pairs found (in a deterministic order); so a caller can show where a
 * mesh intersects itself. `progress` may be NULL. Release with fl_mesh_pairs_free. Errors as
 * fl_mesh_check; on failure *out is zeroed. */
fl_status fl_mesh_self_intersections(const fl_mesh *mesh, size_t max_pairs,
                                     fl_progress_fn progress, void *progress_user,
                                     fl_mesh_pairs *out, fl_error *err);

/* Releases pairs->pairs and zeroes *pairs; NULL or a zeroed struct is a no-op. */
void fl_mesh_pairs_free(fl_mesh_pairs *pairs);

/* Welds exactly coincident vertices: out receives the distinct vertex positions (==, so -0
 * equals +0) in order of first occurrence and mesh's triangles re-indexed to them, in the same
 * order (triangles that become degenerate are kept; fl_mesh_check counts them). Vertices no
 * triangle uses are kept too. O(V + T) expected. Release out with fl_mesh_free. Errors:
 * FL_ERR_INPUT for an index >= vertex_count or a non-finite coordinate, FL_ERR_NOMEM; on
 * failure *out is zeroed. */
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
 * hole for holes_inside. An all-zero polygon (no vertices, rings or polygons) is valid.
 * On success *report must be released with fl_polygon_report_free. Errors: FL_ERR_INPUT for
 * ring/polygon ranges that do not fit the arrays or non-finite coordinates; FL_ERR_NOMEM.
 * On failure *report is zeroed. */
fl_status fl_polygon_check(const fl_polygon *polygon, fl_polygon_report *report, fl_error *err);

/* Releases what fl_polygon_check allocated in *report and zeroes it; NULL is a no-op. */
void fl_polygon_report_free(fl_polygon_report *report);

/* end of mesh */


/* ==== delaunay ============================================================================ */
/* (section owned by src/delaunay) */

/* ---- 2D Delaunay triangulation (src/delaunay/dt2.c) ----
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

/* ---- 3D Delaunay triangulation ----
 * Orientation convention (used by every 3D triangulation here): a tetrahedron (t0, t1, t2, t3) is
 * positively oriented in the sense of fl_orient3d, i.e. fl_orient3d(p[t0], p[t1], p[t2], p[t3]) > 0:
 * t3 lies below the plane of t0, t1, t2 seen counterclockwise from above (equivalently the
 * determinant [t1-t0, t2-t0, t3-t0] is negative). The face opposite corner k, listed as
 * (t1,t3,t2), (t0,t2,t3), (t0,t3,t1), (t0,t1,t2) for k = 0..3, is counterclockwise seen from
 * outside the tetrahedron. Every output tetrahedron has nonzero volume, also on degenerate input. */

/* Options of fl_dt3_build; all zero is a safe default. */
typedef struct fl_dt3_options {
    fl_progress_fn progress; /* may be NULL; called with stage "delaunay 3d" */
    void *progress_user;
    int want_circumcenters; /* nonzero: fill fl_dt3.circumcenters */
} fl_dt3_options;

/* A Delaunay triangulation of points in 3D. Vertex indices are indices of the input points. */
typedef struct fl_dt3 {
    size_t point_count;     /* n as given */
    size_t unique_count;    /* distinct points; each is a vertex of the triangulation */
    uint32_t *duplicate_of; /* point_count entries: i when point i is a vertex, else the index of
                               the vertex with the same coordinates */
    size_t tet_count;
    uint32_t *tet; /* 4 point indices per tetrahedron, positively oriented (see above) */
    uint32_t *adj; /* 4 per tetrahedron: the tetrahedron across the face opposite corner k, or
                      UINT32_MAX when that face is on the convex hull */
    size_t hull_face_count;
    uint32_t *hull_faces;  /* 3 point indices per convex hull face, counterclockwise from outside */
    double *circumcenters; /* 3 per tetrahedron when asked for, else NULL */
} fl_dt3;

/* Builds the Delaunay triangulation of the n points xyz[3n] (Bowyer-Watson insertion in a
 * Hilbert BRIO order). Every decision is exact; ties (cospherical, coplanar points) are broken by
 * a symbolic perturbation, so the result is always a valid triangulation of the convex hull in
 * which no point lies strictly inside the circumsphere of any tetrahedron. Duplicate points are
 * merged (duplicate_of). Fails with FL_ERR_INPUT on NaN/Inf coordinates, more than 2^32-3 points
 * or fewer than 4 distinct points; FL_ERR_ALGORITHM when all points are coplanar or collinear (the
 * message says which), or when cancelled; FL_ERR_NOMEM. On failure *out is zeroed. */
fl_status fl_dt3_build(const double *xyz, size_t n, const fl_dt3_options *opt, fl_dt3 *out,
                       fl_error *err);

/* Checks dt against the points it was built from with the exact predicates: every tetrahedron is
 * positively oriented, adjacency is symmetric, the hull is closed and locally convex, the Euler
 * characteristic of the ball is 1, every distinct point is a vertex, and no point lies inside the
 * circumsphere of a neighbouring tetrahedron (by the Delaunay lemma, this makes every sphere
 * empty). FL_OK, or FL_ERR_ALGORITHM naming the first violation. */
fl_status fl_dt3_verify(const double *xyz, const fl_dt3 *dt, fl_error *err);

/* Releases the arrays of *dt and zeroes it; NULL or a zeroed struct is a no-op. */
void fl_dt3_free(fl_dt3 *dt);

/* ---- Regular (weighted Delaunay) triangulation in 3D ----
 * A ball is (x, y, z, w) with w its weight, the squared radius (skin paper §2.1). The power
 * distance of point p to the ball is |p - (x,y,z)|^2 - w. The regular triangulation is the
 * projection of the lower convex hull of the lifted points (x, y, z, x^2+y^2+z^2-w); a ball whose
 * lifted point lies above that hull is hidden (redundant) and is not a vertex. */

/* Options of fl_rt3_build; all zero is a safe default. */
typedef struct fl_rt3_options {
    fl_progress_fn progress; /* may be NULL; called with stage "regular 3d" */
    void *progress_user;
    int want_ortho; /* nonzero: fill fl_rt3.ortho */
} fl_rt3_options;

typedef struct fl_rt3 {
    size_t point_count;     /* n as given */
    size_t vertex_count;    /* balls that are vertices of the triangulation */
    uint32_t *duplicate_of; /* point_count entries: i unless ball i repeats ball j exactly (same
                               centre and weight) and j is kept in its place */
    size_t hidden_count;
    uint32_t *hidden; /* ascending indices of the hidden balls (not duplicates): a ball at the
                         centre of a heavier ball is hidden too */
    size_t tet_count;
    uint32_t *tet; /* as fl_dt3.tet */
    uint32_t *adj; /* as fl_dt3.adj */
    size_t hull_face_count;
    uint32_t *hull_faces; /* as fl_dt3.hull_faces */
    double *ortho;        /* 4 per tetrahedron when asked for: centre x, y, z and weight (squared
                             radius, may be negative) of the ball orthogonal to its 4 balls */
} fl_rt3;

/* Builds the regular triangulation of the n balls xyzw[4n]. Same contract and failures as
 * fl_dt3_build (weights must be finite; 4 distinct centres not in a plane are needed). With all
 * weights equal it is the Delaunay triangulation of the centres. */
fl_status fl_rt3_build(const double *xyzw, size_t n, const fl_rt3_options *opt, fl_rt3 *out,
                       fl_error *err);

/* Checks rt against its balls like fl_dt3_verify with the power test instead of the in-sphere
 * test, and checks that every hidden ball is inside the hull and in conflict with no tetrahedron
 * containing its centre. FL_OK or FL_ERR_ALGORITHM naming the first violation. */
fl_status fl_rt3_verify(const double *xyzw, const fl_rt3 *rt, fl_error *err);

/* Releases the arrays of *rt and zeroes it; NULL or a zeroed struct is a no-op. */
void fl_rt3_free(fl_rt3 *rt);

/* end of delaunay */


/* ==== graphs ============================================================================== */
/* (section owned by src/graphs) — the γ-neighbourhood graph and the classical graphs it unifies
 * (thesis ch. 2.2 and 3). See docs/gamma.md for every parameter regime and the algorithms.
 *
 * The γ-neighbourhood N_γ(c0,c1) of k vertices in kD (an edge in 2D, a triangle in 3D) is built
 * from two balls B0, B1 touching the vertices, of radii r/(1-|c0|) and r/(1-|c1|), where r is the
 * radius of the smallest ball touching them (Def. 3.1). c0, c1 in [-1,1], |c0| <= |c1|;
 * c0*c1 > 0: the centres lie on opposite sides of the vertices' hyperplane, c0*c1 < 0: on the same
 * side; c1 >= 0: the neighbourhood is the union of the open balls, c1 < 0: their intersection.
 * The open simplex is always part of it; |c| = 1 is an open half-space. */

/* Which γ-graph to build. range == 0: γ(c[0], c[1]) joins the vertices of a simplex when one of
 * its (at most two, mirror-symmetric) N_γ(c[0],c[1]) is empty (Def. 3.2); needs c in [-1,1] and
 * |c[0]| <= |c[1]|. range != 0: γ([c[0],c[1]],[c[2],c[3]]) joins them when their largest empty
 * N_γ(c0',c1') has c0' in [c[0],c[1]] and c1' in [c[2],c[3]] (Def. 3.3); needs
 * -1 <= c[0] <= c[1] <= 1 and -1 <= c[2] <= c[3] <= 1.
 * Reductions (§3.2): γ(-1,1) = convex hull, γ([-1,1],[0,1]) = Delaunay (all simplices with an
 * empty ball; equal to the DT on non-degenerate input), γ(0,0) = Gabriel graph (2D),
 * γ(b,b) = circle-based β-skeleton, γ(1,1) empty and γ(-1,-1) complete in general position. */
typedef struct fl_gamma_params {
    int range;
    double c[4];
} fl_gamma_params;

/* How to build it. All zero is a safe default: the fastest exact method for the parameters. */
typedef enum fl_gamma_method {
    FL_GAMMA_AUTO = 0,       /* Delaunay-based when c1' >= 0 suffices (Thm. 3.2), output-sensitive
                                search for non-Delaunay simplices (c1' < 0), brute force last */
    FL_GAMMA_BRUTE_FORCE = 1 /* Theorem 3.1: every k-subset against every point, O(N^(k+1)) */
} fl_gamma_method;

typedef struct fl_graph_options {
    fl_gamma_method method;
    int want_params;         /* nonzero: also return (c0', c1') of every simplex */
    fl_progress_fn progress; /* may be NULL */
    void *progress_user;
} fl_graph_options;

/* A geometric (hyper-)graph on `vertex_count` input points of dimension `dim`: `simplex_count`
 * simplices of `simplex_size` input indices each (2: edges, 3: triangles), each sorted
 * increasingly, the list sorted lexicographically. `params` is NULL or holds (c0', c1') per
 * simplex (γ-graphs with want_params). Free with fl_graph_free. */
typedef struct fl_graph {
    int dim;
    size_t vertex_count;
    int simplex_size;
    size_t simplex_count;
    uint32_t *simplices;
    double *params;
} fl_graph;

/* Releases the arrays of *graph and zeroes it; NULL or a zeroed struct is a no-op. */
void fl_graph_free(fl_graph *graph);

/* Builds a γ-graph of n points (dim 2: edges, dim 3: triangles). coords holds n*dim finite
 * doubles; the points must be pairwise distinct (duplicates are reported with their indices).
 * opt may be NULL. Cost: O(N log N) for ranges with c2 >= 0 in non-degenerate sets (Thm. 3.2),
 * output-sensitive for c1' < 0 in 2D, O(N^(k+1)) brute force otherwise (see docs/gamma.md).
 * On failure *out is zeroed. FL_ERR_USAGE for bad parameters, FL_ERR_INPUT for bad points. */
fl_status fl_gamma_graph(const double *coords, size_t n, int dim, const fl_gamma_params *params,
                         const fl_graph_options *opt, fl_graph *out, fl_error *err);

/* The largest empty neighbourhood of one simplex (k = dim distinct indices) against all n
 * points, in O(N): *c0, *c1 receive (c0', c1') (Def. 3.3) and the return value is 1; it is 0
 * when no N_γ of the simplex is empty (another point lies in the closed simplex, or the vertices
 * are collinear) and -1 on bad arguments. c1' >= 0 exactly when some ball touching the vertices
 * is empty; this is the quantity constriction's γ-indicator derives from (Def. 5.1/5.2). */
int fl_gamma_simplex_params(const double *coords, size_t n, int dim, const uint32_t *simplex,
                            double *c0, double *c1);

/* fl_gamma_simplex_params for `count` simplices at once (dim indices each, in `simplices`):
 * c0[i], c1[i] receive (c0', c1') of simplex i, bit for bit what fl_gamma_simplex_params gives,
 * and found[i] (found may be NULL) 1, or 0 with c0[i] = c1[i] = NaN when no N_γ of it is empty.
 * The points sit in a bucket grid and each simplex visits only the points that can still change
 * its answer (nearest first around its smallest ball; docs/gamma.md "Many simplices"), so a
 * simplex with points on both sides of its hyperplane costs about the points within a few of its
 * radii instead of N; one on the convex hull still scans everything. Errors: FL_ERR_USAGE for
 * NULL arrays or dim other than 2/3; FL_ERR_INPUT for non-finite or coincident points, an index
 * out of range or a repeated vertex (nothing is written then); FL_ERR_NOMEM. */
fl_status fl_gamma_simplices_params(const double *coords, size_t n, int dim,
                                    const uint32_t *simplices, size_t count, double *c0,
                                    double *c1, int *found, fl_error *err);

/* The smallest c1' (Def. 3.3) over `count` simplices (dim indices each), counting a simplex
 * with no empty N_γ as -1: the largest c0 for which γ([-1,1],[c0,1]) contains all of them (3D
 * constriction's augmented_c0). Bit for bit the minimum of fl_gamma_simplex_params over them,
 * but a simplex is evaluated exactly only when a point lies in its lens N_γ(m, m) for the
 * current minimum m (Lemma 3.2; a box query around it), so only the few simplices that lower the
 * minimum pay a long scan (docs/gamma.md "Many simplices"). *argmin (may be NULL) receives the
 * index of a simplex attaining it (count when count is 0, *min_c1 then NaN). Errors as
 * fl_gamma_simplices_params. */
fl_status fl_gamma_simplices_min_c1(const double *coords, size_t n, int dim,
                                    const uint32_t *simplices, size_t count, double *min_c1,
                                    size_t *argmin, fl_error *err);

/* Parses "c0,c1" (range 0) or "c0,c1,c2,c3" (range 1) into *params and validates it. */
fl_status fl_gamma_params_parse(const char *text, fl_gamma_params *params, fl_error *err);

/* The classical graphs of thesis §2.2. */
typedef enum fl_graph_kind {
    FL_GRAPH_CONVEX_HULL, /* edges (2D) / triangles (3D), = γ(-1,1) */
    FL_GRAPH_DELAUNAY,    /* edges / triangles with an empty ball, = γ([-1,1],[0,1]) */
    FL_GRAPH_GABRIEL,     /* edges whose smallest ball is empty (kD, Def. 2.9) */
    FL_GRAPH_RNG,         /* relative neighbourhood graph (Def. 2.8), edges */
    FL_GRAPH_EMST,        /* Euclidean minimum spanning tree (Def. 2.5), edges; ties: lower index */
    FL_GRAPH_NNG,         /* nearest-neighbour graph (Def. 2.4): i joined to its nearest point,
                             ties to the lowest index */
    FL_GRAPH_BETA_CIRCLE, /* β_c(b) skeleton (Def. 2.15), 2D only, b in [-1,1] */
    FL_GRAPH_BETA_LUNE,   /* β_l(b) skeleton (Def. 2.16), 2D only, b in [-1,1] */
    FL_GRAPH_ALPHA_SHAPE  /* α(a) shape (Def. 2.14): simplices touched by a generalized ball of
                             radius 1/a that contains no point in its interior (a < 0), that
                             contains every point (a > 0), or a half-space (a = 0, the hull) */
} fl_graph_kind;

/* Builds a classical graph; `param` is b for the β-skeletons, a for the α-shape, unused
 * otherwise. Same input contract as fl_gamma_graph. */
fl_status fl_classic_graph(const double *coords, size_t n, int dim, fl_graph_kind kind,
                           double param, fl_graph *out, fl_error *err);

/* Parses "ch", "dt", "gabriel", "rng", "emst", "nng", "beta-circle:B", "beta-lune:B",
 * "alpha:A" (the CLI's --kind). */
fl_status fl_graph_kind_parse(const char *text, fl_graph_kind *kind, double *param,
                              fl_error *err);

/* Writes the graph of the n points `coords` (dimension graph->dim) by the extension of path:
 * .svg (2D only: points and edges, like the thesis's Figures 3.3-3.6), .obj (v lines, then l
 * lines for edges or f lines for triangles), .ply (ascii: vertices, then edges or faces).
 * Atomic: on failure the target is untouched. */
fl_status fl_write_graph(const char *path, const double *coords, size_t n, const fl_graph *graph,
                         fl_error *err);

/* end of graphs */

/* ==== reconstruct ========================================================================= */
/* (section owned by src/reconstruct; docs/reconstruct2d.md)
 *
 * Boundary construction by constriction (thesis ch. 5): from scattered points alone, a simple
 * polygon through all of them, found by peeling triangles off the Delaunay triangulation
 * (= γ([-1,1],[0,1])) from the convex hull inward (Algorithm 5.1). A boundary edge v_i v_j may
 * be deleted with its triangle v_i v_j v_k only while v_k is not yet on the boundary (§5.2), so
 * the boundary stays a simple polygon; among the removable edges the one with the smallest key
 * goes first. When no edge is removable but points remain inside ("locked", §4.3.3, or a
 * non-Hamiltonian triangulation, §5.4), the graph is augmented with the extra edges of
 * γ([-1,1],[c0,1]) for c0 = -1/L, -2/L, ..., -1 until every point is on the boundary. */

/* Which key orders the removable boundary edges (thesis §5.2, §4.3.3, §4.3.4 / §5.6). */
typedef enum fl_reconstruct2_criterion {
    FL_RECONSTRUCT2_GAMMA = 0, /* γ-indicator (Def. 5.1, eq. 5.1): 1 - sin θ when the angle θ at
                                  the opposite vertex is acute, sin θ - 1 when obtuse; smallest
                                  first, i.e. the widest-seen vertex first */
    FL_RECONSTRUCT2_AREA_CHANGE = 1, /* Boissonnat's minimal change, eq. 4.1 in 2D:
                                        (|v_i v_k| + |v_k v_j| - |v_i v_j|) / perimeter */
    FL_RECONSTRUCT2_VORONOI_SKELETON = 2 /* shortest Voronoi skeleton (O'Rourke et al.) as a
                                            constriction: delete the triangle whose Voronoi
                                            vertex takes the most skeleton length with it */
} fl_reconstruct2_criterion;

/* Options of fl_reconstruct2; all zero is the default (γ-indicator, no kept edges, augmentation
 * in 10 steps of c0, no progress reports). */
typedef struct fl_reconstruct2_options {
    fl_reconstruct2_criterion criterion;
    const uint32_t *keep; /* keep_count pairs of input indices: edges that must end up on the
                             boundary (constrained constriction, §5.7); may be NULL */
    size_t keep_count;
    int extra_levels; /* augmentation steps: c0 = -k/L for k = 1..L with L = extra_levels;
                         0 means 10 (c0 = -0.1, -0.2, ..., -1 as in Fig. 5.7), < 0 disables
                         augmentation (pure Delaunay constriction) */
    fl_progress_fn progress; /* may be NULL; stage "constriction" */
    void *progress_user;
} fl_reconstruct2_options;

/* The constructed boundary. Indices refer to the input points; of exact duplicates only the
 * first occurrence appears (the others share its place on the boundary). */
typedef struct fl_reconstruction2 {
    size_t point_count;    /* n as given */
    size_t unique_count;   /* distinct points */
    size_t boundary_count; /* vertices of the boundary polygon */
    uint32_t *boundary;    /* the polygon as a counterclockwise vertex cycle (not repeated) */
    size_t triangle_count; /* triangles inside the polygon: boundary_count - 2 plus twice the
                              points left inside (when all_on_boundary is 0) */
    uint32_t *tri;         /* 3 per triangle, counterclockwise; they tile the polygon */
    size_t delaunay_count; /* the Delaunay triangulation constriction started from */
    uint32_t *delaunay_tri;
    int all_on_boundary;   /* 1 when every distinct point is a boundary vertex and every kept
                              edge a boundary edge; 0 otherwise, and `reason` says why */
    double augmented_c0;   /* the c0 of γ([-1,1],[c0,1]) that was needed, NaN when the Delaunay
                              triangulation sufficed */
    double area;           /* area of the polygon (positive) */
    char reason[256];      /* empty when all_on_boundary is 1 */
} fl_reconstruction2;

/* Constructs the boundary polygon of the n points xy[2i], xy[2i+1] by constriction. The result
 * is always a simple counterclockwise polygon together with a triangulation of its interior;
 * when some points cannot be brought onto the boundary (constriction locked even at c0 = -1, or
 * kept edges that make it impossible) the call still succeeds with all_on_boundary = 0, the
 * points left inside the polygon and a reason. `opt` may be NULL. Expected O(n log n).
 * Errors (then *out is zeroed): FL_ERR_USAGE for NULL buffers or a bad criterion;
 * FL_ERR_INPUT for NaN/Inf coordinates, fewer than 3 distinct points, kept edges with an index
 * out of range, joining a point to itself (or its duplicate), crossing each other or passing
 * through a point, or three kept edges at one point; FL_ERR_ALGORITHM when all points are
 * collinear (no polygon has positive area) or when cancelled; FL_ERR_NOMEM. */
fl_status fl_reconstruct2(const double *xy, size_t n, const fl_reconstruct2_options *opt,
                          fl_reconstruction2 *out, fl_error *err);

/* Parses "gamma", "area-change" or "voronoi-skeleton" (the CLI's --criterion). */
fl_status fl_reconstruct2_criterion_parse(const char *text, fl_reconstruct2_criterion *criterion,
                                          fl_error *err);

/* Writes the result by the extension of path: .xy and .geojson/.json (the boundary polygon, via
 * fl_write_polygon), .svg (points, the Delaunay triangulation faint and the boundary bold, like
 * thesis Figs. 5.2-5.3), .off (the interior triangles as a mesh with z = 0; all n input points
 * are its vertices). xy must be the n points rec was built from. Atomic. */
fl_status fl_write_reconstruction2(const char *path, const double *xy, size_t n,
                                   const fl_reconstruction2 *rec, fl_error *err);

/* Frees the arrays and zeroes rec; safe on a zeroed or already-freed struct. */
void fl_reconstruction2_free(fl_reconstruction2 *rec);

/* ---- 3D constriction ----
 * Boundary construction in 3D by constriction (thesis §5.3, Algorithm 5.1): the Delaunay
 * tetrahedralization (= γ([-1,1],[0,1])) is peeled from the convex hull inward, one boundary
 * tetrahedron at a time, so that the boundary stays a closed, oriented 2-manifold of genus 0:
 * a tetrahedron with one boundary triangle goes only while its opposite vertex is not on the
 * boundary, one with two boundary triangles only while its opposite edge is not on the
 * boundary, one with three never. Among the removable tetrahedra the one with the smallest key
 * goes first. Constriction stops when every distinct point is on the boundary (then `extra`
 * more removals). When nothing is removable with points inside ("locked", thesis §4.3.3 /
 * §5.4), 2-3 flips inside the region bring in overlapping tetrahedra of γ([-1,1],[c0,1]) whose
 * opposite vertex is an inside point, and constriction goes on; the region stays a proper
 * tetrahedralization, so the boundary stays an embedded sphere (docs/reconstruct3d.md: a partial
 * §5.4, points no such flip reaches stay inside with a reason). Kept triangles (§5.7) are never
 * deleted. */

/* Which key orders the removable boundary tetrahedra. */
typedef enum fl_reconstruct3_criterion {
    FL_RECONSTRUCT3_GAMMA = 0,      /* γ-indicator (Def. 5.2, eq. 5.2) of the boundary triangle
                                       w.r.t. the opposite vertex: s (1 - r/R) with r the radius
                                       of the triangle's circumcircle, R of the tetrahedron's
                                       circumsphere, s = +1 when the sphere's centre lies on the
                                       opposite vertex's side of the triangle, else -1; summed
                                       over both triangles of two-triangle tetrahedra (§5.3
                                       selection rule); smallest first */
    FL_RECONSTRUCT3_AREA_CHANGE = 1 /* Boissonnat's minimal change, eq. 4.1: (area of the
                                       inner faces - area of the boundary faces) / total area */
} fl_reconstruct3_criterion;

/* Options of fl_reconstruct3; all zero is the default (γ-indicator, stop as soon as every point
 * is on the boundary, no progress reports). */
typedef struct fl_reconstruct3_options {
    fl_reconstruct3_criterion criterion;
    size_t extra; /* removable tetrahedra to remove after every point is on the boundary, by the
                     same rule (the candlestick of thesis Fig. 5.5); 0 stops at once */
    fl_progress_fn progress; /* may be NULL; stage "constriction 3d" (and "delaunay 3d") */
    void *progress_user;
    const uint32_t *keep; /* keep_count triples of input indices: triangles that must end up on
                             the boundary and are never deleted (constrained constriction,
                             §5.7); each must be a face of the Delaunay tetrahedralization.
                             May be NULL */
    size_t keep_count;
    int no_augment; /* 1: when locked, stop and report (pure Delaunay constriction); 0
                       (default): unlock by 2-3 flips that bring overlapping tetrahedra of
                       γ([-1,1],[c0,1]), c0 < 0, into the region (§5.4, docs/reconstruct3d.md) */
} fl_reconstruct3_options;

/* The constructed boundary and its interior. Indices refer to the input points; of exact
 * duplicates only the first occurrence appears (fl_dt3.duplicate_of). */
typedef struct fl_reconstruction3 {
    size_t point_count;    /* n as given */
    size_t unique_count;   /* distinct points */
    size_t triangle_count; /* boundary triangles */
    uint32_t *tri;         /* 3 per triangle, counterclockwise seen from outside; together a
                              closed, oriented 2-manifold of genus 0 */
    size_t tet_count;      /* interior tetrahedra (Delaunay tetrahedra not removed, and those
                              that unlocking flips created, see flip_count) */
    uint32_t *tet;         /* 4 per tetrahedron, positively oriented as in fl_dt3; their faces
                              not shared by two of them are exactly the boundary triangles;
                              together a tetrahedralization of the enclosed volume */
    size_t delaunay_tet_count; /* tetrahedra of the Delaunay tetrahedralization */
    size_t removed_count;      /* tetrahedra removed by constriction (extra ones included) */
    size_t extra_removed;      /* of those, removed after every point was on the boundary */
    size_t boundary_vertex_count; /* distinct points on the boundary */
    size_t points_inside;         /* distinct points strictly inside the boundary */
    uint32_t *inside;             /* their indices (points_inside entries, ascending) */
    int all_on_boundary;          /* 1 iff points_inside == 0 and keep_missing == 0 */
    double volume;                /* sum of the interior tetrahedra's volumes (positive) */
    double augmented_c0; /* c0 of γ([-1,1],[c0,1]) needed (§5.4): the smallest c1' (Def. 3.3,
                            fl_gamma_simplex_params: the triangle is in γ([-1,1],[c0,1]) iff
                            c1' >= c0) of the triangles the unlocking flips added; NaN:
                            Delaunay sufficed or augmentation was not tried */
    char reason[256];    /* empty when all_on_boundary is 1, else why points remain inside */
    size_t flip_count;   /* 2-3 flips made to unlock constriction (0 when never locked or
                            stalled, see docs/reconstruct3d.md) */
    size_t keep_missing; /* distinct kept triangles that are not on the final boundary */
} fl_reconstruction3;

/* Constructs the boundary polyhedron of the n points xyz[3i..3i+2] by constriction of their
 * Delaunay tetrahedralization. On success the result is always a closed, oriented genus-0
 * boundary with a tetrahedralization of its interior; when constriction locks before every
 * point is on the boundary the call still succeeds with all_on_boundary = 0, the points left
 * inside and a reason. `opt` may be NULL. Expected O(n log n) after the Delaunay
 * tetrahedralization. Errors (then *out is zeroed): FL_ERR_USAGE for NULL buffers or a bad
 * criterion; FL_ERR_INPUT for NaN/Inf coordinates, fewer than 4 distinct points, or a kept
 * triangle with an index out of range, a repeated point, or that is not a Delaunay face;
 * FL_ERR_ALGORITHM when all points are coplanar or collinear, or when cancelled;
 * FL_ERR_NOMEM. */
fl_status fl_reconstruct3(const double *xyz, size_t n, const fl_reconstruct3_options *opt,
                          fl_reconstruction3 *out, fl_error *err);

/* Frees the arrays and zeroes rec; safe on a zeroed or already-freed struct. */
void fl_reconstruction3_free(fl_reconstruction3 *rec);

/* end of reconstruct */


/* ==== hal ================================================================================= */
/* (section owned by src/hal; docs/hal.md)
 *
 * Hierarchical approximation and localization of closed polygons by flintstones (thesis ch. 7
 * §7.2, §7.4; HAL paper §3, §5). Every ring of an fl_polygon (outer boundaries and holes alike)
 * gets its own binary flintstone tree: the root holds the two vertices v_i, v_j on the smallest
 * enclosing disc that are farthest apart (level 0, the approximation v_i v_j v_i) and that disc;
 * every other node covers a polyline v_p..v_s of the ring by its flintstone, the intersection of
 * two discs through v_p and v_s (or a disc and a half-plane), and splits it at the vertex v_q of
 * the disc with the larger signed radius. The infix order of a tree is the ring (Fig. 7.5);
 * there are (ring vertices - 2) nodes a ring, so storage is Θ(N). Which side a vertex is on and
 * which disc contains which vertex are decided with the exact predicates; the stored discs are
 * floating point, enlarged so that they provably contain every vertex of their polyline. */

/* Shape of a node's bounding area. */
enum {
    FL_HAL2_TWO_DISCS = 0,      /* disc[0] ∩ disc[1]; vertices on both sides of v_p v_s */
    FL_HAL2_DISC_HALFPLANE = 1, /* disc[0] ∩ the closed half-plane of v_p v_s on side `side` */
    FL_HAL2_SEGMENT = 2,        /* every vertex lies on the segment v_p v_s (a collinear run) */
    FL_HAL2_DISC = 3 /* disc[0] alone: a guard for a polyline in no disc through v_p and v_s,
                        which HAL Thm. 1 excludes; reachable only when the smallest enclosing
                        disc was decided in floating point (coordinates beyond 2^500) */
};

/* One node: the flintstone of the polyline v_p v_(p+1) .. v_s along its ring (indices wrap
 * around the ring), split at v_q into v_p..v_q and v_q..v_s. Vertex indices are global indices
 * into fl_hal2.polygon.xy. */
typedef struct fl_hal2_node {
    uint32_t p, q, s;
    uint32_t r;        /* the extreme vertex on the other side of v_p v_s (Def. 7.3); = q when
                          that side is empty (and for FL_HAL2_SEGMENT, FL_HAL2_DISC) */
    uint32_t edges;    /* edges of v_p..v_s along the ring, >= 2 */
    int32_t child[2];  /* nodes of v_p..v_q and v_q..v_s; -1 when that part is a single edge */
    uint32_t level;    /* approximation level at which v_q appears (the root's polylines: 1) */
    uint8_t kind;      /* FL_HAL2_* above */
    int8_t side;       /* FL_HAL2_DISC_HALFPLANE: fl_orient2d(v_p, v_s, v) of the vertices */
    double disc[2][3]; /* (cx, cy, r^2) of the discs; disc[1] only for FL_HAL2_TWO_DISCS */
    double width[2];   /* Def. 7.4 widths w1 (disc through v_q), w2 (0 for a half-plane) */
    double error;      /* certified bound on the distance of every point of v_p..v_s to the
                          segment v_p v_s: max(w1, w2) plus a 1e-10 relative rounding margin */
} fl_hal2_node;

/* One ring's tree. The ring is vertices first .. first+count-1 of the polygon. */
typedef struct fl_hal2_ring {
    uint32_t first, count;
    uint32_t root[2]; /* v_i, v_j: level 0 */
    int32_t child[2]; /* nodes of v_i..v_j and v_j..v_i; -1 when that part is a single edge */
    double disc[3];   /* smallest enclosing disc (cx, cy, r^2), enlarged to contain the ring */
    uint32_t depth;   /* deepest level of the tree: approximations at levels >= depth are the
                         ring itself */
} fl_hal2_ring;

/* A flintstone forest: a copy of the polygon, one tree per ring, the nodes of all trees. */
typedef struct fl_hal2 {
    fl_polygon polygon;
    fl_hal2_ring *rings; /* polygon.ring_count */
    size_t node_count;
    fl_hal2_node *nodes;
    uint32_t depth; /* max over rings */
} fl_hal2;

/* Options; all zero is the default. */
typedef struct fl_hal2_options {
    fl_progress_fn progress; /* called once a ring; may be NULL */
    void *progress_user;
} fl_hal2_options;

/* Builds the flintstone tree of every ring of `polygon` (Algorithm 7.1). `opt` may be NULL.
 * Rings need at least 3 vertices; repeated and collinear vertices are allowed. Time O(N log N)
 * for balanced splits, O(N^2) worst case (Thm. 7.1); memory Θ(N). Errors (then *out is
 * zeroed): FL_ERR_USAGE for NULL arguments, FL_ERR_INPUT for inconsistent ring/polygon ranges,
 * a ring of fewer than 3 vertices, NaN/Inf coordinates or more than 2^31 vertices;
 * FL_ERR_ALGORITHM when cancelled; FL_ERR_NOMEM. Free with fl_hal2_free. */
fl_status fl_hal2_build(const fl_polygon *polygon, const fl_hal2_options *opt, fl_hal2 *out,
                        fl_error *err);

/* Releases the polygon copy, trees and nodes of *hal and zeroes it; NULL or a zeroed struct is
 * a no-op. */
void fl_hal2_free(fl_hal2 *hal);

/* The level-`level` approximation (§7.2.2): every ring reduced to its tree's vertices of levels
 * 0..level, in ring order, same ring/polygon structure as the input (a ring at level 0 has 2
 * vertices). A level >= hal->depth gives the original polygon. *error (may be NULL) receives the
 * certified error, eq. (e5): the largest error of the nodes just below the cut (0 when nothing
 * was cut); every point of the original rings is within *error of the approximation, polyline
 * by polyline. Free *out with fl_polygon_free. Errors: FL_ERR_USAGE, FL_ERR_NOMEM. */
fl_status fl_hal2_approximate_level(const fl_hal2 *hal, uint32_t level, fl_polygon *out,
                                    double *error, fl_error *err);

/* The adaptive approximation (§7.2.3): a polyline is refined only while its node's error
 * exceeds max_error (>= 0). *error (may be NULL) receives the certified error (<= max_error),
 * *level (may be NULL) the deepest level used. Errors: FL_ERR_USAGE for a negative or NaN
 * max_error or NULL arguments, FL_ERR_NOMEM. */
fl_status fl_hal2_approximate_error(const fl_hal2 *hal, double max_error, fl_polygon *out,
                                    double *error, uint32_t *level, fl_error *err);

/* Dynamic insertion (thesis §7.5): inserts the point xy[0], xy[1] into the ring of vertex
 * `after`, between `after` and the next vertex of that ring. The new vertex gets index after + 1
 * and every later vertex index shifts by one (in hal->polygon and in the trees). The tree is
 * repaired, not rebuilt: flintstones on the path that still hold the new vertex are kept (their
 * discs grown), the subtree under the first one that does not is rebuilt, and the whole ring's
 * tree when its smallest enclosing disc changes its farthest pair. Node indices change. Cost
 * O(N) for the renumbering plus the rebuilt subtree. Errors: FL_ERR_USAGE for NULL or a vertex
 * index out of range, FL_ERR_INPUT for a NaN/Inf point, FL_ERR_NOMEM (hal then unchanged). */
fl_status fl_hal2_insert(fl_hal2 *hal, uint32_t after, const double *xy, fl_error *err);

/* Where a query point is relative to the polygon, by the even-odd rule over all rings. */
enum { FL_HAL2_OUTSIDE = 0, FL_HAL2_INSIDE = 1, FL_HAL2_BOUNDARY = 2 };

/* Hierarchical point inclusion (thesis Lemma 6.1, HAL paper §5.1) for the n points xy[2k],
 * xy[2k+1]: where[k] = FL_HAL2_BOUNDARY when the point lies on an edge (exactly, by
 * fl_orient2d), else FL_HAL2_INSIDE or FL_HAL2_OUTSIDE by the parity of crossings of a
 * rightward ray with all rings. The answers are exactly those of the brute-force test over
 * every edge with exact predicates; the flintstones only prune. Errors: FL_ERR_USAGE for NULL
 * buffers (n > 0), FL_ERR_INPUT for a NaN/Inf query (where[] is then unspecified). */
fl_status fl_hal2_contains(const fl_hal2 *hal, const double *xy, size_t n, uint8_t *where,
                           fl_error *err);

/* Intersecting edge pairs: pairs[2k] is an edge of a, pairs[2k+1] an edge of b; an edge is named
 * by its first vertex (global index; the edge runs to the next vertex of its ring). */
typedef struct fl_hal2_pairs {
    size_t count;
    uint32_t *pairs;
} fl_hal2_pairs;

/* Releases pairs->pairs and zeroes *pairs; NULL or a zeroed struct is a no-op. */
void fl_hal2_pairs_free(fl_hal2_pairs *pairs);

/* Hierarchical intersection (§7.4, HAL paper §5.2): all pairs of closed edges, one of a and one
 * of b, that share at least one point (touching and collinear overlap included, decided
 * exactly), sorted by (edge of a, edge of b). With first_only != 0 the search stops at the first
 * pair found (count is then 0 or 1). *out must be freed with fl_hal2_pairs_free. Errors:
 * FL_ERR_USAGE for NULL arguments, FL_ERR_NOMEM. */
fl_status fl_hal2_intersect(const fl_hal2 *a, const fl_hal2 *b, int first_only, fl_hal2_pairs *out,
                            fl_error *err);

/* end of hal */

/* ==== sweep ============================================================================== */
/* (section owned by src/sweep; docs/sweep.md)
 *
 * Meshsweeper closest-point queries (Guéziec 2001). A hierarchy of bounding elements, each a
 * segment (polylines, §3.1) or a triangle (meshes, §4.1) swept by a sphere of radius ε, is
 * searched by a priority process on distance intervals [d - ε, d + ε] (§3.2). A query returns
 * the exact closest point, or stops early with an interval [lower, upper] that brackets the
 * distance once it is narrower than a tolerance. A hierarchy is immutable after building and
 * may be queried from several threads at once; a cursor (for coherent query streams) belongs
 * to one thread. */

/* An opaque, immutable search hierarchy over the elements (segments or triangles) of a shape. */
typedef struct fl_sweep fl_sweep;

/* Build options; all zero is the default. */
typedef struct fl_sweep_options {
    fl_progress_fn progress; /* may be NULL */
    void *progress_user;
} fl_sweep_options;

/* "No element", e.g. for an early-stopped query that has not yet reached one. */
#define FL_SWEEP_NONE UINT32_MAX

/* The answer to one closest-point query.
 *  - exact = 1: `distance` is the distance from the query to the shape (lower = upper =
 *    distance), `point` the closest point, `element` the segment or triangle containing it
 *    (among equidistant elements, any one) and `bary` its barycentric coordinates there:
 *    triangle t = (v0, v1, v2) gives point = bary[0] v0 + bary[1] v1 + bary[2] v2; polyline
 *    segment i runs from point i to point i+1 (point 0 for the closing segment of a closed
 *    polyline) and point = bary[0] p_i + bary[1] p_i+1, bary[2] = 0. 2D polylines give z = 0.
 *  - exact = 0 (only with a tolerance > 0): the true distance lies in [lower, upper] and
 *    upper - lower <= tolerance; `distance` is the midpoint. element/point/bary describe the
 *    nearest element evaluated so far (element = FL_SWEEP_NONE and point NaN if none).
 *  - reused = 1 when a cursor answered the query in constant time from earlier work: the
 *    previous query's coherence ball (§3.3) or the walk region of a coherent stream (the
 *    members near the last answer, certified by a lower bound on everything else; one
 *    distance measured); `visited` counts the hierarchy nodes whose distance was computed. */
typedef struct fl_closest {
    double distance;
    double point[3];
    uint32_t element;
    double bary[3];
    double lower, upper;
    int exact;
    int reused;
    size_t visited;
} fl_closest;

/* Builds the hierarchy over the triangles of `mesh` (any topology: open, non-manifold,
 * degenerate or repeated triangles and duplicate vertices are fine). Every vertex coordinate
 * must be finite with |x| <= 1e150 (so squared distances cannot overflow; queries too) and
 * every index < vertex_count; at least one triangle, fewer than 2^31.
 * opt may be NULL. Cost O(T log T) time, about 240 bytes a triangle. On failure *out is NULL;
 * FL_ERR_USAGE for NULL arguments, FL_ERR_INPUT for bad meshes, FL_ERR_NOMEM. Free with
 * fl_sweep_free. */
fl_status fl_sweep_build(const fl_mesh *mesh, const fl_sweep_options *opt, fl_sweep **out,
                         fl_error *err);

/* Builds the hierarchy over a polyline of n points of dimension dim (2 or 3), coordinates
 * interleaved in `points` (n*dim finite doubles, |x| <= 1e150). Open (closed = 0): n-1
 * segments, n >= 2; closed: n segments (the last joins point n-1 to point 0), n >= 2. Repeated
 * points are fine. The hierarchy is the iterative end-point fit of §3.1; its cost is
 * O(n log n) for typical curves and O(n^2) at worst (e.g. a spiral). Same errors as
 * fl_sweep_build. */
fl_status fl_sweep_polyline_build(const double *points, size_t n, int dim, int closed,
                                  const fl_sweep_options *opt, fl_sweep **out, fl_error *err);

/* Releases a hierarchy; NULL is a no-op. */
void fl_sweep_free(fl_sweep *sweep);

/* Dimension of the query points (2 for 2D polylines, 3 otherwise) and number of elements. */
int fl_sweep_dim(const fl_sweep *sweep);
size_t fl_sweep_element_count(const fl_sweep *sweep);

/* Answers nq queries (q holds nq*dim finite doubles, |x| <= 1e150, dim = fl_sweep_dim) into
 * results[nq]. tolerance = 0 asks for exact answers; tolerance > 0 lets each query stop once
 * its interval is narrower (see fl_closest). The batch runs through one cursor (below), so
 * queries ordered along a path are much faster (§3.3, §5.1). FL_ERR_USAGE for bad arguments or
 * a bad query (results before it are filled), FL_ERR_NOMEM. */
fl_status fl_sweep_closest(const fl_sweep *sweep, const double *q, size_t nq, double tolerance,
                           fl_closest *results, fl_error *err);

/* A streaming query state for query points that move a little at a time. It owns the
 * priority queue (one array, sized once) and keeps it between queries: a move by δ widens
 * every queued interval by δ and only the regions that reach the front are recomputed (§5.1);
 * it also keeps the coherence ball of the last exact answer (§3.3). It starts over from the
 * root by itself when a query jumps farther than the last distance or the kept queue stops
 * paying, so any query order is correct. */
typedef struct fl_sweep_cursor fl_sweep_cursor;

/* Creates a cursor on `sweep`, which must outlive it. FL_ERR_USAGE, FL_ERR_NOMEM. */
fl_status fl_sweep_cursor_new(const fl_sweep *sweep, fl_sweep_cursor **out, fl_error *err);

/* One query (q holds dim doubles) as in fl_sweep_closest, reusing the previous answer when q
 * lies inside its coherence ball. */
fl_status fl_sweep_cursor_closest(fl_sweep_cursor *cursor, const double *q, double tolerance,
                                  fl_closest *result, fl_error *err);

/* Releases a cursor; NULL is a no-op. */
void fl_sweep_cursor_free(fl_sweep_cursor *cursor);

/* The k elements nearest to q (§4.4), nearest first: elements[i] and distances[i] for
 * i < *found, *found = min(k, element count). Ties are ordered arbitrarily. */
fl_status fl_sweep_knearest(const fl_sweep *sweep, const double *q, size_t k, uint32_t *elements,
                            double *distances, size_t *found, fl_error *err);

/* Elements at distance <= radius from q, nearest first (§4.4). Free with fl_sweep_hits_free. */
typedef struct fl_sweep_hits {
    size_t count;
    uint32_t *element;
    double *distance;
} fl_sweep_hits;

/* Fills *out with every element at distance <= radius (>= 0) from q (dim doubles),
 * nearest first; *out is zeroed on failure. FL_ERR_USAGE for bad arguments, FL_ERR_NOMEM. */
fl_status fl_sweep_within(const fl_sweep *sweep, const double *q, double radius,
                          fl_sweep_hits *out, fl_error *err);

/* Releases the arrays of *hits and zeroes it; NULL or a zeroed struct is a no-op. */
void fl_sweep_hits_free(fl_sweep_hits *hits);

/* end of sweep */


/* ==== hausdorff =========================================================================== */
/* (section owned by src/sweep/hausdorff*.c; docs/hausdorff.md)
 *
 * Certified Hausdorff distance between two triangle meshes or two polylines (Guéziec 2001,
 * §6), on top of the Meshsweeper closest-point cursor. The directed distance h(A,B) is the
 * largest distance from a point of A (any point of its triangles / segments, not only the
 * vertices) to B; the Hausdorff distance is max(h(A,B), h(B,A)). Each is returned as an
 * interval [lower, upper] that contains the true value: `lower` is a distance actually measured
 * from a sample point of the shape (reported in `where`), `upper` is proven for every point of
 * every triangle (docs/hausdorff.md has the proof). Both are widened by the rounding slack of
 * the arithmetic (about 1e-14 of the largest coordinate). */

/* Options; all zero is the default (precision 1e-3 of the bounding-box diagonal, no budget).
 *  - precision > 0: stop once upper - lower <= precision (absolute length); otherwise
 *    relative > 0 asks for relative * (diagonal of the bounding box of both shapes); both 0
 *    means relative = 1e-3. Precisions below ~1e-12 of the coordinates cannot be reached
 *    (rounding slack): the call then stops refining triangles smaller than that and reports
 *    the precision it did reach.
 *  - budget_seconds > 0: stop refining after about that long and return the best intervals
 *    found so far (still certified; budget_exhausted = 1).
 *  - max_samples > 0: the same, after that many samples (0 = 100 million; counted as in the
 *    result's `samples`).
 *  - both_directions = 0 refines only as far as the symmetric distance needs (the direction
 *    that cannot reach the maximum keeps a wider but still certified interval, §6 "decide
 *    early which direction dominates"); nonzero refines each directed interval to precision.
 *  - keep_field nonzero fills the result's field_ab / field_ba (the refined sample meshes). */
typedef struct fl_hausdorff_options {
    double precision;
    double relative;
    double budget_seconds;
    size_t max_samples;
    int both_directions;
    int keep_field;
    fl_progress_fn progress; /* may be NULL; stage "hausdorff" */
    void *progress_user;
} fl_hausdorff_options;

/* A distance field over one shape: the refined sample mesh (every sample is a vertex; for
 * meshes the triangles are the leaves of the refinement, which may have T-junctions; for
 * polylines triangle_count = 0) and distance[i] = the distance from vertex i to the other
 * shape (exact up to rounding). */
typedef struct fl_hausdorff_field {
    fl_mesh mesh;
    double *distance;
} fl_hausdorff_field;

/* The answer. h_ab = h(A,B) (points of A, distances to B), h_ba = h(B,A), hausdorff = the
 * symmetric distance, each [lower, upper]. where[0] is the sample point realizing
 * hausdorff[0] and where[1] its closest point on the other shape; where_on_b = 1 when
 * where[0] lies on B (h_ba dominates). samples counts the sample points measured: vertices and
 * refinement points, whether by a closest-point query or, where that cannot change the bounds,
 * against nearby elements of the other shape (docs/hausdorff.md); reached = hausdorff[1] - hausdorff[0]; precision = the absolute precision asked
 * for. budget_exhausted = 1 when the time or sample budget stopped the refinement before
 * reaching the precision. For 2D polylines z = 0. Free with fl_hausdorff_result_free. */
typedef struct fl_hausdorff_result {
    double h_ab[2], h_ba[2], hausdorff[2];
    double where[2][3];
    int where_on_b;
    size_t samples;
    double precision, reached;
    int budget_exhausted;
    fl_hausdorff_field field_ab, field_ba; /* with keep_field; otherwise zero */
} fl_hausdorff_result;

/* Hausdorff distance between two triangle meshes (same input rules as fl_sweep_build: any
 * topology; vertices used by no triangle are ignored). opt may be NULL. *out is zeroed first.
 * FL_ERR_USAGE for NULL arguments or negative options, FL_ERR_INPUT for bad meshes,
 * FL_ERR_ALGORITHM "cancelled" when the progress callback asks to stop, FL_ERR_NOMEM. */
fl_status fl_hausdorff_meshes(const fl_mesh *a, const fl_mesh *b, const fl_hausdorff_options *opt,
                              fl_hausdorff_result *out, fl_error *err);

/* The same between two polylines of dimension dim (2 or 3): na points in `a` (interleaved,
 * closed_a nonzero joins the last to the first) and nb in `b`, each >= 2 points, as in
 * fl_sweep_polyline_build. */
fl_status fl_hausdorff_polylines(const double *a, size_t na, int closed_a, const double *b,
                                 size_t nb, int closed_b, int dim,
                                 const fl_hausdorff_options *opt, fl_hausdorff_result *out,
                                 fl_error *err);

/* Releases the fields of a result; a zeroed result is a no-op. */
void fl_hausdorff_result_free(fl_hausdorff_result *result);

/* Writes a field as an ASCII PLY with per-vertex `quality` (the distance) and colours from
 * blue (distance <= lo) through green to red (distance >= hi), as Guéziec's Fig. 10; lo = hi
 * = 0 uses the field's own range. Atomic (temporary file renamed). FL_ERR_IO. */
fl_status fl_hausdorff_write_field_ply(const char *path, const fl_hausdorff_field *field,
                                       double lo, double hi, fl_error *err);

/* end of hausdorff */

/* ==== render ============================================================================== */
/* (section owned by src/render; docs/render.md)
 *
 * Pictures of the library's data without any dependency beyond libc and libm.
 *  - 3D: a small software rasterizer into an RGBA8 pixel buffer (fl_image): a z-buffer, an
 *    orthographic or perspective camera looking from (azimuth, elevation) and fitted to the
 *    bounding box of everything drawn, Lambert + Blinn-Phong shading, an optional wireframe
 *    overlay, per-vertex scalars through a colormap, reflection lines (zebra) for smoothness
 *    checks, 2x2 supersampling. Balls and points are ray-cast spheres in the same z-buffer.
 *    Encoding the pixels (PNG) is the caller's business; the flintstone command uses libpng.
 *  - 2D: an SVG canvas that collects points, polylines, polygons, graph edges, discs, lenses
 *    (two intersecting discs, i.e. flintstones) and cubic Bézier paths in data coordinates and
 *    writes one standalone SVG fitted to them (y up, like src/io's polygon pictures).
 * Conventions: z is "up" in 3D; colours are 4 bytes RGBA; the image's first row is its top. */

/* An RGBA8 image: width*height pixels, 4 bytes each, rows top to bottom. Free with
 * fl_image_free (a zeroed image is a no-op). */
typedef struct fl_image {
    uint32_t width, height;
    uint8_t *rgba;
} fl_image;

/* Releases the pixels and zeroes *image; NULL or a zeroed image is a no-op. */
void fl_image_free(fl_image *image);

/* How per-vertex scalars become colours: t = (s - min) / (max - min) clamped to [0, 1]. */
typedef enum fl_render_colormap {
    FL_RENDER_COOLWARM = 0, /* blue (low) -> light grey -> red (high), diverging (Moreland) */
    FL_RENDER_VIRIDIS = 1,  /* dark blue -> green -> yellow, perceptually uniform */
    FL_RENDER_GRAY = 2      /* black -> white */
} fl_render_colormap;

/* The RGBA colour of t in [0, 1] under a colormap (t outside is clamped, NaN gives grey). */
void fl_render_colormap_rgba(fl_render_colormap map, double t, uint8_t rgba[4]);

/* Scene options; all zero is the default: 800x600, azimuth 0 and elevation 0 (looking along -x
 * from +x, z up), perspective with a 30 degree vertical field of view, no supersampling, opaque
 * white background. */
typedef struct fl_render_options {
    uint32_t width, height;    /* pixels, 1..16384 each and at most 2^26 samples in all
                                * (width * height * supersample^2); 0 = 800 x 600 */
    double azimuth, elevation; /* degrees: the camera sits in direction (cos e cos a, cos e sin a,
                                * sin e) from the centre of the scene */
    int orthographic;          /* nonzero: parallel projection */
    double fov;                /* perspective: vertical field of view in degrees, (0, 170);
                                * 0 = 30 */
    int supersample;           /* 0 or 1: one sample a pixel; 2: 2x2 samples averaged */
    double margin;             /* fraction of the image left free on each side; 0 = 0.05 */
    const uint8_t *background; /* 4 bytes RGBA, or NULL for opaque white */
} fl_render_options;

/* How to draw one mesh. All zero: light steel blue, face normals, no wireframe, no zebra. */
typedef struct fl_render_mesh_style {
    const uint8_t *color;      /* 4 bytes RGBA (alpha ignored), NULL = default */
    const double *normals;     /* NULL or 3 per vertex (need not be unit): smooth shading */
    const double *scalars;     /* NULL or 1 per vertex: colour through `colormap` instead */
    double scalar_min, scalar_max; /* the colormap's range; min >= max: the scalars' own range */
    fl_render_colormap colormap;
    int wireframe;             /* nonzero: dark triangle edges about 1 pixel wide on top */
    int zebra;                 /* nonzero: reflection lines (stripes of the reflected view
                                * direction against an environment of parallel light tubes) */
    double zebra_stripes;      /* stripe pairs over a half turn of the reflected ray; 0 = 10 */
} fl_render_mesh_style;

/* Per-vertex normals for smooth shading: the sum of the (area-weighted) normals of the
 * triangles around each vertex, normalized; (0, 0, 0) for a vertex no triangle uses. Triangles
 * are taken as oriented, so a misoriented mesh gets cancelling normals. normals receives 3 per
 * vertex. FL_ERR_INPUT for indices >= vertex_count. */
fl_status fl_render_vertex_normals(const fl_mesh *mesh, double *normals, fl_error *err);

/* A scene under construction. The add calls validate and copy what they need, so the caller's
 * arrays may be released right after. */
typedef struct fl_render fl_render;

/* The camera of a finished scene: a point p maps to pixel coordinates (x right, y down, the
 * pixel (i, j) covers [i, i+1) x [j, j+1)) and a depth through fl_render_project. */
typedef struct fl_render_camera {
    double center[3];                  /* the centre of the scene's bounding box */
    double right[3], up[3], toward[3]; /* orthonormal; toward points from the scene to the eye */
    int orthographic;
    double distance;                   /* perspective: eye = center + distance * toward */
    double scale;                      /* pixels per unit (orthographic) or per unit of x/w */
    double offset[2];                  /* pixel position of the projected centre */
} fl_render_camera;

/* What fl_render_finish produced besides the image. */
typedef struct fl_render_stats {
    uint32_t width, height; /* of the image */
    size_t pixels_covered;  /* pixels where something was drawn (any of their samples) */
    fl_render_camera camera;
} fl_render_stats;

/* Starts an empty scene with the options (NULL = defaults). FL_ERR_USAGE for sizes out of
 * range or a bad field of view, FL_ERR_NOMEM; on failure *out is NULL. */
fl_status fl_render_new(const fl_render_options *opt, fl_render **out, fl_error *err);
/* Releases a scene and everything added to it; NULL is a no-op. */
void fl_render_free(fl_render *render);

/* Adds a triangle mesh (any topology; both sides of every triangle are lit). FL_ERR_INPUT for
 * non-finite coordinates, normals or scalars and for indices >= vertex_count. */
fl_status fl_render_add_mesh(fl_render *render, const fl_mesh *mesh,
                             const fl_render_mesh_style *style, fl_error *err);

/* Adds balls (xyzw, w = squared radius) as shaded spheres; balls with w <= 0 have no extent and
 * are skipped. `color` NULL: warm orange. FL_ERR_INPUT for non-finite values. */
fl_status fl_render_add_balls(fl_render *render, const fl_balls *balls, const uint8_t *color,
                              fl_error *err);

/* Adds n 3D points (xyz) as small spheres of `radius`; radius <= 0 means 0.004 times the
 * diagonal of the points' bounding box (0.01 for a single point). `color` NULL: dark grey. */
fl_status fl_render_add_points(fl_render *render, const double *xyz, size_t n, double radius,
                               const uint8_t *color, fl_error *err);

/* Fits the camera to the bounding box of everything added, rasterizes and fills *image
 * (release with fl_image_free) and, if stats is not NULL, *stats. The scene may be finished
 * again (e.g. after adding more). FL_ERR_INPUT when nothing with an extent was added;
 * FL_ERR_NOMEM. On failure *image is zeroed. */
fl_status fl_render_finish(fl_render *render, fl_image *image, fl_render_stats *stats,
                           fl_error *err);

/* Projects p: out[0], out[1] pixel coordinates, out[2] the distance in front of the eye along
 * the view axis (perspective) or -(p - center).toward (orthographic); smaller is nearer. */
void fl_render_project(const fl_render_camera *camera, const double p[3], double out[3]);

/* Style of one SVG item. NULL strings take the item's default; colours are SVG colour names,
 * "#rrggbb" or "none" (other characters are rejected to keep the file well-formed). Widths and
 * point radii are in picture pixels, so they do not depend on the data's scale. */
typedef struct fl_svg_style {
    const char *stroke;  /* default "#1f4e79" */
    const char *fill;    /* default "none" ("#cfe0f3" for polygons and lenses, stroke colour
                          * for points) */
    double stroke_width; /* 0 = 2 */
    double opacity;      /* 0 = 1 (opaque) */
    double point_radius; /* points: 0 = 3 */
} fl_svg_style;

typedef struct fl_svg fl_svg;

/* A canvas whose picture is `size` pixels on its longer side (0 = 1000) plus a margin of 5%
 * of it all round; data coordinates are fitted to it with y up. */
fl_status fl_svg_new(double size, fl_svg **out, fl_error *err);
void fl_svg_free(fl_svg *svg);

/* n points xy[2i], xy[2i+1] as dots (one <circle> each). */
fl_status fl_svg_add_points(fl_svg *svg, const double *xy, size_t n, const fl_svg_style *style,
                            fl_error *err);
/* A polyline through n points (closed: back to the first), one <path>. */
fl_status fl_svg_add_polyline(fl_svg *svg, const double *xy, size_t n, int closed,
                              const fl_svg_style *style, fl_error *err);
/* Every polygon of `polygon` as one <path> filled with the even-odd rule (holes stay empty). */
fl_status fl_svg_add_polygon(fl_svg *svg, const fl_polygon *polygon, const fl_svg_style *style,
                             fl_error *err);
/* Straight edges between points: edges[2k], edges[2k+1] index xy (n points); one <path>. */
fl_status fl_svg_add_edges(fl_svg *svg, const double *xy, size_t n, const uint32_t *edges,
                           size_t edge_count, const fl_svg_style *style, fl_error *err);
/* A disc (centre, radius in data units, radius >= 0), one <circle>. */
fl_status fl_svg_add_disc(fl_svg *svg, double cx, double cy, double radius,
                          const fl_svg_style *style, fl_error *err);
/* The lens d0 ∩ d1 of two discs (cx, cy, r each; a flintstone, HAL §3) as one <circle> for d1
 * clipped by a <clipPath> of d0. */
fl_status fl_svg_add_lens(fl_svg *svg, const double d0[3], const double d1[3],
                          const fl_svg_style *style, fl_error *err);
/* The part of the disc (cx, cy, r) on one side of the line through a and b (a != b): side +1
 * left of a -> b, -1 right (HAL's disc-and-half-plane flintstones). One <path> (chord and
 * arc), a <circle> when the line misses the disc on that side, nothing when the part is empty. */
fl_status fl_svg_add_disc_halfplane(fl_svg *svg, const double disc[3], const double a[2],
                                    const double b[2], int side, const fl_svg_style *style,
                                    fl_error *err);
/* A path of `segments` cubic Bézier segments through 3*segments+1 control points (xy pairs):
 * segment k has control points 3k .. 3k+3. One <path>. */
fl_status fl_svg_add_bezier(fl_svg *svg, const double *ctrl, size_t segments,
                            const fl_svg_style *style, fl_error *err);

/* Number of SVG shape elements the canvas will write (circles and paths). */
size_t fl_svg_element_count(const fl_svg *svg);
/* Picture size in pixels (margin included) as it would be written now. */
void fl_svg_size(const fl_svg *svg, double *width, double *height);

/* Writes the canvas atomically to path (any extension). FL_ERR_IO on failure, target untouched. */
fl_status fl_svg_write(const fl_svg *svg, const char *path, fl_error *err);

/* end of render */

/* ==== smooth ============================================================================== */
/* (section owned by src/smooth; docs/smooth.md)
 *
 * G1 (tangent-continuous) boundaries through the vertices of a polygon or a closed triangle
 * mesh, after Veltkamp's thesis ch. 8-9: estimated tangents/normals (§9.2, §9.4), cubic Bézier
 * curve segments by the projection heuristic (§9.2), and cubic Bézier triangle surfaces by the
 * three-split scheme (§9.6, Clough-Tocher split with eq. 9.4 across macro edges). The macro
 * patches of steps 1-3 alone are, with the default tension, exactly Vlachos et al.'s PN
 * triangles (only C0 across edges); they are available as a baseline scheme. */

/* How the unit vectors of the neighbouring edges (curves) or triangles (surfaces) are weighted
 * in a tangent or normal estimate (§9.2 methods 1-3, §9.4 methods 1-3). */
typedef enum fl_g1_weighting {
    FL_G1_WEIGHT_DEFAULT = 0, /* by length (curves), by area (surfaces): the thesis's choice */
    FL_G1_WEIGHT_SIZE = 1,    /* by edge length / triangle area */
    FL_G1_WEIGHT_UNIFORM = 2, /* unit vectors summed */
    FL_G1_WEIGHT_INVERSE = 3  /* by inverse length / inverse area */
} fl_g1_weighting;

/* Curve options; all zero is the default. */
typedef struct fl_g1_curve_options {
    int weighting;  /* fl_g1_weighting */
    double tension; /* fraction of the projected chord for the inner control points; 0 = 1/3 */
} fl_g1_curve_options;

/* A closed G1 curve of cubic Bézier segments through every vertex of every ring. Segment i
 * (one a vertex, in the polygon's vertex order) runs from vertex i to the next vertex of its
 * ring; its control points are ctrl[8i .. 8i+7] = p0, p1, p2, p3 (x, y each), p0 and p3 the
 * vertices. tangent[2i..2i+1] is the unit tangent used at vertex i. ring_start and
 * polygon_start copy the polygon's structure. */
typedef struct fl_g1_curve {
    size_t vertex_count;
    double *ctrl;
    double *tangent;
    size_t ring_count;
    size_t *ring_start;
    size_t polygon_count;
    size_t *polygon_start;
    size_t orientation_repairs; /* vertices whose tangent failed the G1 orientation condition
                                 * (§9.2: projections on the same side) and was replaced by the
                                 * uniform (bisector) tangent, which always satisfies it */
} fl_g1_curve;

/* Builds the G1 curve of every ring of `polygon` (each ring at least 3 vertices, finite
 * coordinates with |x| <= 1e150, no two consecutive vertices equal, no ring turning back on itself by 180
 * degrees at a vertex). FL_ERR_INPUT otherwise, FL_ERR_USAGE for bad options, FL_ERR_NOMEM.
 * On failure *out is zeroed. Free with fl_g1_curve_free. */
fl_status fl_g1_curve_build(const fl_polygon *polygon, const fl_g1_curve_options *opt,
                            fl_g1_curve *out, fl_error *err);
void fl_g1_curve_free(fl_g1_curve *curve);

/* Point and first derivative of segment i at parameter s in [0, 1] (either may be NULL). */
void fl_g1_curve_eval(const fl_g1_curve *curve, size_t segment, double s, double point[2],
                      double derivative[2]);

/* The curve sampled as polygons: `per_segment` (>= 1) points a segment (its start vertex
 * first), same ring and polygon structure. Free with fl_polygon_free. */
fl_status fl_g1_curve_sample(const fl_g1_curve *curve, size_t per_segment, fl_polygon *out,
                             fl_error *err);

/* Writes the curve as an SVG picture, one path of cubic Béziers ("M ... C ... Z") a ring,
 * atomically. FL_ERR_IO. */
fl_status fl_g1_curve_write_svg(const char *path, const fl_g1_curve *curve, fl_error *err);

/* Unit vertex normals of a closed oriented mesh (§9.4), weighted by `weighting`, outward for
 * counter-clockwise triangles; normals has 3*vertex_count doubles. A vertex whose weighted
 * sum vanishes (or that no triangle uses) gets FL_ERR_INPUT. */
fl_status fl_g1_vertex_normals(const fl_mesh *mesh, int weighting, double *normals,
                               fl_error *err);

/* Surface schemes. */
typedef enum fl_g1_scheme {
    FL_G1_THREE_SPLIT = 0, /* §9.6: three cubic micro patches a triangle; G1 to rounding on
                            * smooth meshes, not on every coarse one: measure it with
                            * fl_g1_surface_measure (docs/smooth.md has the numbers) */
    FL_G1_MACRO = 1,       /* steps 1-3 only: one cubic patch a triangle = PN triangles (C0) */
    FL_G1_SIX_SPLIT = 2,   /* §9.8: six cubic micro patches a triangle (split at one point
                            * of each edge, the midpoint unless step 5 needs another split
                            * ratio, and the centre), C1 inside each macro triangle, G1
                            * across macro edges by the least-displacement solve of step 5
                            * (docs/smooth.md: G1 on every mesh tested, measure it) */
    FL_G1_TWO_SPLIT = 3,   /* §9.7: pairs of thin triangles (docs/smooth.md: the three-split
                            * would make a micro angle < 15 degrees) split in two at their
                            * common edge, every other triangle three-split. Each pair is one
                            * C1 cross split of its quad (four cubic micro patches), its inner
                            * points solved with the neighbours' by eq. 9.4 as on a three-split
                            * edge: G1 where the three-split is (docs/smooth.md) */
    FL_G1_TWO_SPLIT_AS_PRINTED = 4, /* §9.7 exactly as printed (split at P(1/2,1/2,0), eq. 9.6
                            * least-displacement solve, eq. 9.7 on the neighbours' edges): NOT
                            * G1, eq. 9.6 forces a degenerate corner at every split point and
                            * eq. 9.7 leaves the far end of the outer edges open (docs/smooth.md
                            * derives and measures both); kept for comparison, not for use */
    FL_G1_AUTO = 5 /* per connected component of the mesh: builds the three-split and the
                    * six-split and keeps the one that measures G1 (max normal jump < 1e-7
                    * degrees at 33 points of every patch edge, no fold, normals
                    * interpolated); if both are G1, the one with the smaller max deviation
                    * from the mesh (ties: the three-split); if neither is G1 with the
                    * requested normal weighting, both again with the other two weightings
                    * (surface->normal holds the normals used); else the best measured.
                    * six_split_triangles says how many triangles took the six-split. The two
                    * schemes never meet across an edge (docs/smooth.md, "Auto") */
} fl_g1_scheme;

/* Surface options; all zero is the default. */
typedef struct fl_g1_surface_options {
    int scheme;     /* fl_g1_scheme */
    int weighting;  /* fl_g1_weighting of the normal estimate */
    double tension; /* step 2: fraction of the projected edge for the edge control points;
                     * 0 = 1/3 (the thesis's value) */
} fl_g1_surface_options;

/* A piecewise cubic Bézier triangle surface. Patch p has 10 control points ctrl[30p .. 30p+29]
 * in the order b300 b210 b201 b120 b111 b102 b030 b021 b012 b003 (b_ijk weights corner 0 by
 * i, corner 1 by j, corner 2 by k); its corners are the nodes corner[3p..3p+2],
 * counter-clockwise seen from outside. Node n < vertex_count is mesh vertex n; node
 * vertex_count + t is the split point (centre) of macro triangle t; with the six-split, node
 * vertex_count + triangle_count + e is the midpoint of macro edge e; with the two-split, the
 * four patches of pair k come first (4k .. 4k+3) and their split point is node vertex_count +
 * the smaller triangle index of the pair. macro[p] is the mesh triangle the patch belongs to.
 * Patches sharing an edge share its two end nodes. */
typedef struct fl_g1_surface {
    size_t patch_count;
    double *ctrl;
    uint32_t *corner;
    uint32_t *macro;
    size_t node_count;
    size_t vertex_count;
    double *normal;             /* 3*vertex_count: the vertex normals interpolated */
    size_t orientation_repairs; /* vertex normals altered so that the G1 orientation condition
                                 * holds on every incident edge (§9.6: f, g of eq. 9.3 of the
                                 * right signs; decided exactly by fl_orient3d) */
    size_t orientation_failures; /* vertices where no repair was found (the surface folds
                                  * there), e.g. 3 on CGAL's hand.off */
    size_t singular_edges;      /* three-split: macro edges where eq. 9.4 was dependent and
                                 * the minimal displacement solution was taken; six-split:
                                 * macro edges whose step-5 system was singular (their G1
                                 * conditions may not hold); two-split: plus the pairs whose
                                 * eq. 9.6 system was rank-deficient */
    size_t quadratic_edges;     /* macro edges whose boundary curve was made a degree-raised
                                 * quadratic because eq. 9.4 was (nearly) dependent with the
                                 * thesis's cubic curve (docs/smooth.md) */
    size_t two_split_pairs;     /* two-split: pairs of macro triangles split in two */
    size_t six_split_triangles; /* auto: mesh triangles built with the six-split (the rest
                                 * took the three-split); with auto, the non-vertex nodes of
                                 * each connected component follow those of the previous ones */
} fl_g1_surface;

/* Builds the surface over a closed, manifold, oriented mesh with coordinates |x| <= 1e150
 * (fl_mesh_check; else FL_ERR_INPUT naming what is wrong), interpolating its vertices and estimated normals. O(V + T log T).
 * FL_ERR_USAGE for bad options, FL_ERR_NOMEM. On failure *out is zeroed. */
fl_status fl_g1_surface_build(const fl_mesh *mesh, const fl_g1_surface_options *opt,
                              fl_g1_surface *out, fl_error *err);
void fl_g1_surface_free(fl_g1_surface *surface);

/* Point and unit normal (either may be NULL) of a cubic Bézier triangle with control points
 * ctrl[30] (order as above) at barycentric (u, v, w), u + v + w = 1: de Casteljau, the
 * normal from the cross product of the last stage (exact up to rounding). */
void fl_g1_patch_eval(const double *ctrl, double u, double v, double w, double point[3],
                      double normal[3]);

/* Tessellates every patch with `density` (>= 1) segments an edge into one mesh whose vertices
 * along patch edges are shared, so it is closed when the input was. *normals receives
 * 3*vertex_count unit normals (malloc'd, free() it). Free out with fl_mesh_free. */
fl_status fl_g1_surface_tessellate(const fl_g1_surface *surface, unsigned density, fl_mesh *out,
                                   double **normals, fl_error *err);

/* Measured quality of a surface against the mesh it interpolates. */
typedef struct fl_g1_metrics {
    double max_vertex_error;         /* |patch corner - mesh vertex|, max */
    double max_normal_error;         /* |patch normal at a vertex - estimated normal|, max */
    double max_edge_normal_jump_deg; /* angle between the two patches' normals, max over
                                      * `samples` points of every patch edge */
    size_t orientation_flips;        /* patch edges where the two patches fold onto the same
                                      * side (G1 orientation violated) at some sample */
    double max_deviation;            /* max distance of the patch samples from the mesh,
                                      * divided by the mean edge length */
} fl_g1_metrics;

/* Measures `surface` built from `mesh` with `samples` (>= 2) segments along every patch edge
 * (samples + 1 points) and a grid of min(samples, 8) segments an edge inside each patch for
 * the deviation. FL_ERR_USAGE, FL_ERR_NOMEM. */
fl_status fl_g1_surface_measure(const fl_g1_surface *surface, const fl_mesh *mesh,
                                unsigned samples, fl_g1_metrics *out, fl_error *err);

/* The Bézier control nets as text (.bez, docs/formats.md): written atomically; the reader
 * fills patch_count, ctrl and corner (other fields zero) and reports parse errors by line. */
fl_status fl_g1_write_bez(const char *path, const fl_g1_surface *surface, fl_error *err);
fl_status fl_g1_read_bez(const char *path, fl_g1_surface *out, fl_error *err);

/* end of smooth */


/* ==== hal3 ================================================================================ */
/* (section owned by src/hal, files hal3_*; docs/hal.md "3D")
 *
 * The flintstone tree of a closed, oriented, manifold genus-0 triangle mesh (thesis §7.3-7.4,
 * HAL paper §4-5). Level 0 is the triangle v_i v_j v_k of three vertices on a ball containing
 * all vertices, twice: the three shortest edge paths between them cut the surface into two open
 * polyhedra, one approximated by (i, j, k), the other by (i, k, j). Every node is an approximating
 * triangle (its corners are mesh vertices, oriented like the surface) together with the part of
 * the surface it stands for, bounded by three edge paths between its corners. A node is refined
 * (Algorithm 7.2, level by level) by a three-split at an interior vertex v_q of its part, or by
 * splits at one, two or three sides at a vertex of the side's path when angles are below the
 * threshold; the neighbour across a split side splits at the same vertex. Where shortest paths
 * coalesce the tree's own levels can leave a few sides unmatched; the approximation functions
 * close every cut they return (docs/hal.md "Approximations are closed"), so every level and
 * every adaptive approximation is a closed, oriented, manifold mesh. Pieces left without
 * triangles by coalescing paths stay as nodes with face_count 0 (empty flintstone) so their
 * neighbours' sides stay matched. The leaves are the original triangles. A node's flintstone
 * (Def. 7.5) is built from the balls through its corners and v_q / v_r, stored in floating point
 * enlarged so that it provably contains every original triangle of its subtree. */

/* Shape of a node's flintstone. */
enum {
    FL_HAL3_TWO_BALLS = 0,     /* ball[0] ∩ ball[1] (Def. 7.5 with the ± operator giving ∩) */
    FL_HAL3_BALL_HALFSPACE = 1, /* ball[0] ∩ the closed half-space of the corners' plane on
                                   side `side` (all vertices on one side) */
    FL_HAL3_BALL_UNION = 2,    /* ball[0] ∪ ball[1] (± giving ∪); each triangle of the part
                                  lies in one of the two balls */
    FL_HAL3_BALL = 3,          /* ball[0] alone: corners collinear */
    FL_HAL3_LEAF = 4           /* an original triangle; ball[0] encloses it */
};

/* One node. Children are the nodes child_first .. child_first + child_count - 1 (a leaf has
 * none). */
typedef struct fl_hal3_node {
    uint32_t v[3];         /* corners (mesh vertex indices), counterclockwise from outside */
    uint32_t level;        /* 0 for the two root triangles */
    int32_t parent;        /* -1 for the roots */
    uint32_t child_first, child_count;
    uint32_t face;         /* leaf: its triangle index in hal->mesh; else UINT32_MAX */
    uint32_t face_count;   /* original triangles in the subtree */
    uint32_t split;        /* vertex of the three-split, UINT32_MAX for a side split or leaf */
    uint8_t kind;          /* FL_HAL3_* above */
    int8_t side;           /* FL_HAL3_BALL_HALFSPACE: fl_orient3d(v0, v1, v2, x) of its points */
    double ball[2][4];     /* centre x, y, z and squared radius (enlarged); ball[1] for the two-
                              ball kinds */
    double width[2];       /* Def. 7.6 widths w1, w2 of the balls (w2 = 0 for a half-space) */
    double error;          /* certified bound on the distance of every point of the node's part
                              of the surface to its triangle (0 for a leaf) */
} fl_hal3_node;

/* A flintstone tree: a copy of the mesh, nodes (the two roots are nodes 0 and 1), and the
 * "ties" of Algorithm 7.2: pairs of nodes of one level sharing a side that both split at the
 * same vertex when they are refined (recorded; the approximations close cracks instead). */
typedef struct fl_hal3 {
    fl_mesh mesh;
    size_t node_count;
    fl_hal3_node *nodes;
    size_t tie_count;
    uint32_t *ties;        /* 2 per tie: node indices */
    uint32_t depth;        /* deepest level: the approximation at this level is the mesh */
    double ball[4];        /* the level-0 ball through v_i, v_j, v_k containing every vertex */
    double box[6];         /* axis-aligned bounding box of the used vertices, exact: min x, y,
                              z, then max x, y, z (fl_hal3_intersect answers "apart" at once
                              when the two boxes are disjoint) */
} fl_hal3;

/* Options; all zero is the default. */
typedef struct fl_hal3_options {
    double angle_threshold;  /* radians; angles below it are not split (0: pi/4) */
    fl_progress_fn progress; /* called once a level; may be NULL */
    void *progress_user;
} fl_hal3_options;

/* Builds the flintstone tree of a closed triangle mesh (Algorithm 7.2). `opt` may be NULL.
 * The mesh must be closed, manifold, oriented, connected, of genus 0, without degenerate
 * triangles; otherwise FL_ERR_INPUT names the problem (e.g. "genus 1: the HAL tree needs a
 * sphere-like surface"). Also FL_ERR_INPUT for NaN/Inf coordinates or |x| > 1e150,
 * FL_ERR_USAGE for NULL arguments or a threshold outside [0, pi/3], FL_ERR_ALGORITHM when cancelled or when the
 * refinement cannot proceed (the message says where), FL_ERR_NOMEM. On failure *out is zeroed.
 * Free with fl_hal3_free. */
fl_status fl_hal3_build(const fl_mesh *mesh, const fl_hal3_options *opt, fl_hal3 *out,
                        fl_error *err);

/* Releases the tree's arrays and zeroes *hal; a zeroed struct is a no-op. */
void fl_hal3_free(fl_hal3 *hal);

/* 0 when x is provably outside node's flintstone, 1 when it may be inside (every point of
 * the node's triangles gives 1). */
int fl_hal3_flintstone_may_contain(const fl_hal3 *hal, uint32_t node, const double *x);

/* The level-`level` approximation: the triangles of the nodes of that level and of the leaves
 * above it, on the used vertices (coordinates copied, vertices renumbered in order of first
 * use), closed: where that cut has an unmatched or over-used side, the nodes there are refined
 * and crack loops are filled with triangles on their own vertices, so the result is a closed,
 * oriented, manifold mesh. level >= hal->depth gives the original triangles.
 * *error (may be NULL) receives the largest node error of the cut (0 at the finest level). Free
 * with fl_mesh_free. Errors: FL_ERR_USAGE, FL_ERR_NOMEM. */
fl_status fl_hal3_approximate_level(const fl_hal3 *hal, uint32_t level, fl_mesh *out,
                                    double *error, fl_error *err);

/* The adaptive approximation (§7.3.3): nodes are refined while their error exceeds max_error,
 * then the cut is closed as in fl_hal3_approximate_level (a closed, oriented, manifold mesh;
 * the ties are not propagated, see docs/hal.md "Approximations are closed"); max_error
 * 0 refines every node and gives the mesh itself. *error and *level (each may be NULL) receive
 * the certified error (<= max_error: every point of the surface is within it of the
 * approximation) and the deepest level used. Errors: FL_ERR_USAGE for a negative or NaN
 * max_error, FL_ERR_NOMEM. */
fl_status fl_hal3_approximate_error(const fl_hal3 *hal, double max_error, fl_mesh *out,
                                    double *error, uint32_t *level, fl_error *err);

enum { FL_HAL3_OUTSIDE = 0, FL_HAL3_INSIDE = 1, FL_HAL3_BOUNDARY = 2 };

/* Point-in-polyhedron for the n points xyz[3k..3k+2]: FL_HAL3_BOUNDARY when the point lies on a
 * triangle (exactly), else the parity of the crossings of an axis-parallel ray (towards the
 * nearest face of the bounding box), symbolically perturbed so that it misses every edge,
 * decided with fl_orient2d/fl_orient3d. The tree's hierarchy, laid out once a call with exact
 * (outward-rounded) coordinate bounds per node, prunes the triangles the ray cannot reach; the
 * answers equal the brute-force test's. Errors: FL_ERR_USAGE, FL_ERR_NOMEM, FL_ERR_INPUT for a
 * NaN/Inf query (the answers before it are written). */
fl_status fl_hal3_contains(const fl_hal3 *hal, const double *xyz, size_t n, uint8_t *where,
                           fl_error *err);

/* Intersecting triangle pairs: pairs[2k] a triangle of a, pairs[2k+1] one of b. */
typedef struct fl_hal3_pairs {
    size_t count;
    uint32_t *pairs;
} fl_hal3_pairs;

/* Releases the pairs and zeroes *pairs; a zeroed struct is a no-op. */
void fl_hal3_pairs_free(fl_hal3_pairs *pairs);

/* Hierarchical intersection (§7.4, the ∩/∪ cases): every pair of closed triangles, one of a and
 * one of b, with a common point (decided exactly), sorted. first_only != 0 stops at the first
 * pair. Trees whose bounding boxes (hal->box) are disjoint give no pair without a descent.
 * Errors: FL_ERR_USAGE, FL_ERR_NOMEM. */
fl_status fl_hal3_intersect(const fl_hal3 *a, const fl_hal3 *b, int first_only,
                            fl_hal3_pairs *out, fl_error *err);

/* end of hal3 */

/* ==== skin ================================================================================ */
/* (section owned by src/skin; docs/skin.md)
 *
 * Skin surfaces of ball sets (Edelsbrunner; Cheng & Tan, "Approximating polyhedral objects with
 * deformable smooth surfaces", §6.1). For a ball b = (z, w) (w = squared radius) let
 * b^t = (z, t w); convex combinations of balls are taken in the lifted space
 * (z, |z|^2 - w) (§2.1). The skin body is body^t(B) = union of b^t over b in conv(B) and the
 * skin surface skin^t(B) is its boundary; for 0 < t < 1 it is smooth and body^t(B) is
 * homeomorphic to the union of the balls (Theorem 15). A single ball of radius r gives the
 * sphere of radius sqrt(t) r. */

/* The skin function G of a ball set: G(x) < 0 exactly inside body^t(B), G(x) = 0 on the skin.
 * G(x) = min over b in conv(B) of the power distance of x to b^t; in each mixed cell of the
 * regular triangulation it is a quadric (docs/skin.md derives it). Immutable once built. */
typedef struct fl_skin_function fl_skin_function;

/* Builds G for the n balls xyzw[4n] and shrink factor t in (0, 1). At least one ball needs a
 * positive weight. Up to 8 balls need no triangulation (every subset of at most 4 balls is a
 * candidate simplex); more need 4 centres not in a plane (the regular triangulation, fl_rt3).
 * FL_ERR_USAGE for NULL pointers or t outside (0, 1); FL_ERR_INPUT for NaN/Inf or a value
 * beyond 1e100, no positive weight, coplanar centres (n > 8); FL_ERR_NOMEM. Free with
 * fl_skin_function_free. */
fl_status fl_skin_function_new(const double *xyzw, size_t n, double t, fl_skin_function **out,
                               fl_error *err);

/* G(x) for x[3]. The sign is always right. The value is exact up to rounding wherever
 * G(x) <= 0, and wherever the minimising ball of conv(B) has its centre within
 * sqrt(t * max weight) of x; elsewhere a larger positive number (HUGE_VAL when no ball is that
 * near). */
double fl_skin_function_value(const fl_skin_function *skin, const double x[3]);

/* Releases a skin function; NULL is a no-op. */
void fl_skin_function_free(fl_skin_function *skin);

/* Options of fl_skin_mesh; all zero is the default. */
typedef struct fl_skin_options {
    double t;          /* shrink factor in (0, 1); 0 means 0.5 */
    double cell;       /* grid spacing; 0 means sqrt(t) * (smallest positive radius) / 4,
                        * smaller (down to 1/4 of that) to straddle thin necks (docs/skin.md) */
    size_t max_cubes;  /* refuse grids with more candidate cubes than this; 0 means 5e7 (about 16 bytes a cube);
                        * graded: more octree leaves than this, 0 means the address-space
                        * limit (RLIMIT_AS, the CLI's --max-memory) / 512 bytes a leaf, at
                        * least 3e6; 3e6 without a limit */
    fl_progress_fn progress; /* may be NULL; stage "skin" */
    void *progress_user;
    double grade;      /* 0: the uniform grid above. > 0: a graded grid (octree corners,
                        * exactly triangulated): cells of grade times the local feature size of
                        * the skin (shrunk ball radius, neck waist, ...), at most `cell` (0: the
                        * largest shrunk radius times grade); docs/skin.md */
    int repair;        /* graded grid only: when > 0, the mesh's Euler characteristic and
                        * components are compared with the skin's (fl_balls_union_betti) and,
                        * while they differ, the grid is refined in boxes round the mesh's
                        * local handles and extra small components and the mesh redone, at
                        * most this many times (docs/skin.md, round 17). 0: mesh once */
} fl_skin_options;

/* What fl_skin_mesh measured (optional). */
typedef struct fl_skin_stats {
    double cell;              /* grid spacing used */
    size_t cubes;             /* grid cubes visited (within the balls' bounding boxes; cubes
                                 provably all inside or all outside the skin are skipped) */
    size_t evaluations;       /* evaluations of G (grid points and root-finding steps; vertices
                                 solved in closed form inside one mixed cell need none) */
    double max_vertex_offset; /* largest |G(v)| / |grad G(v)| over the vertices: a first-order
                                 estimate of their distance to the skin */
    unsigned repairs;         /* meshes redone by fl_skin_options.repair */
} fl_skin_stats;

/* Triangulates skin^t(B) of the n balls xyzw[4n]: marching tetrahedra on the Kuhn
 * subdivision of a cubic grid restricted to the balls' bounding boxes, with every vertex placed
 * on the skin along its grid edge: in closed form where the edge lies in one mixed cell (G is
 * one quadric there), else by safeguarded regula falsi to the last bit. The result is a closed,
 * oriented (outward, counter-clockwise) 2-manifold triangle mesh for every input; it has the
 * topology of the skin when the grid resolves its features (necks thinner than the cell can
 * be missed; docs/skin.md). stats may be NULL. Errors as fl_skin_function_new, plus
 * FL_ERR_INPUT when the grid would exceed max_cubes cubes or 2^20 cells along an axis or its
 * spacing is below 1e-12 of a coordinate, FL_ERR_ALGORITHM "cancelled". On failure *out is zeroed. Free with fl_mesh_free. */
fl_status fl_skin_mesh(const double *xyzw, size_t n, const fl_skin_options *opt, fl_mesh *out,
                       fl_skin_stats *stats, fl_error *err);

/* The Euler characteristic of the union of the open balls xyzw[4n] (x, y, z, w; w the squared
 * radius, balls of weight <= 0 are empty) into *chi. The skin body is homotopy equivalent to
 * the union, so a mesh of skin^t(B) has the skin's topology only if its Euler characteristic
 * is 2 * *chi. Computed exactly from the dual (alpha) complex of the balls at alpha = 0: the
 * regular triangulation (fl_rt3_build) and, per simplex, exact tests of its focus against its
 * cofaces (docs/skin.md, "The topology check"). Any number of balls (0 gives 0), duplicates,
 * hidden balls, and centres fewer than 4 or in a plane or on a line are handled.
 * FL_ERR_USAGE for NULL pointers, FL_ERR_INPUT for NaN/Inf or a value beyond 1e100,
 * FL_ERR_NOMEM. */
fl_status fl_balls_union_euler(const double *xyzw, size_t n, long long *chi, fl_error *err);

/* The Betti numbers of the union of the open balls xyzw[4n] (as fl_balls_union_euler): betti[0]
 * its connected components, betti[1] its independent tunnels (the total genus of its boundary),
 * betti[2] its cavities (bounded components of the complement), so that chi = b0 - b1 + b2.
 * A mesh of skin^t(B) has the skin's topology only if it has b0 + b2 components of total genus
 * b1. b0 and b2 come from the same dual complex by union-find over its edges and over the
 * triangles outside it (docs/skin.md, "The topology check"); b1 from chi. Same errors as
 * fl_balls_union_euler; on failure betti is zeroed. */
fl_status fl_balls_union_betti(const double *xyzw, size_t n, long long betti[3], fl_error *err);

/* What fl_skin_mesh_checked decided. */
typedef struct fl_skin_check {
    long long euler;          /* Euler characteristic of the mesh returned (V - F/2: the mesh
                                 is a closed 2-manifold) */
    long long euler_expected; /* 2 chi(union of the balls), fl_balls_union_betti */
    long long components;     /* connected components of the mesh returned */
    long long components_expected; /* b0 + b2 of the union (fl_balls_union_betti): one
                                      boundary per component and one per cavity */
    int topology_ok;          /* 1 when euler == euler_expected and components ==
                                 components_expected */
    int attempts;             /* meshes built, 1 to 3 */
    double grade;             /* grade of the grid of the mesh returned; 0 the uniform grid */
} fl_skin_check;

/* fl_skin_mesh with a topology check. With opt NULL or opt->cell and opt->grade both 0 (the
 * default), meshes on the graded grid of grade 1.5 with opt->repair (0: 3) local refinements,
 * and when the mesh's Euler characteristic
 * is not 2 chi(union of the balls) or its number of components not b0 + b2 of the union
 * (fl_balls_union_betti) retries at grade 0.75, then on the uniform grid of the
 * default cell, keeping the first mesh that matches, else the last (finest) one with
 * check->topology_ok = 0. A graded attempt refused for its size (FL_ERR_INPUT) moves on to the
 * next. With cell or grade given, meshes once as asked and reports the check. check may be
 * NULL; stats are those of the mesh returned. Errors as fl_skin_mesh and
 * fl_balls_union_betti. On failure *out is zeroed. Free with fl_mesh_free. */
fl_status fl_skin_mesh_checked(const double *xyzw, size_t n, const fl_skin_options *opt,
                               fl_mesh *out, fl_skin_stats *stats, fl_skin_check *check,
                               fl_error *err);

/* ---- ε-approximation of a polyhedron by balls (Cheng & Tan §5, §6.2; docs/skin.md) ----
 * B: protecting balls centred on the mesh, each of radius min(0.45 lgs(centre), rho) with lgs
 * the local gap size (§4) and rho = 0.8 epsilon, covering every vertex, edge and triangle, so
 * conditions C1/C2 of Theorem 5 hold. By default they are placed by Algorithm 1 (§4.2: a ball
 * on every vertex, then on each edge and each triangle a ball at the positive vertex of the
 * restricted power diagram of the balls so far, until none is left); the older placement
 * (bisecting edges, 4-splitting triangles) stays available. The result is also verified: the certified Hausdorff distance between the
 * triangulated skin^t(B*) and the input is <= epsilon, their Euler characteristics agree and
 * the skin mesh is closed and manifold, else the construction repeats: with a finer mesher grid
 * (x0.4) after a wrong Euler characteristic (the default cell only), with smaller balls (rho
 * x0.7) after a Hausdorff miss.
 * B_perp (§5): orthogonal balls of the regular-triangulation tetrahedra of B whose orthocentre
 * lies inside the object (ray parity, winding number near degeneracies) and whose weight is
 * positive.
 * B* (§6.2): B_perp plus the orthogonal balls (negative weight) of the vertices, edges and
 * triangles of the regular triangulation whose focus lies in their power face at negative
 * power (the alpha simplices of B with z_X^perp non-empty). */

/* How the protecting balls B are placed (fl_skin_approx_options.placement). */
typedef enum fl_skin_placement {
    FL_SKIN_PLACE_ALGORITHM1 = 0, /* §4.2 Algorithm 1: restricted power diagram vertices */
    FL_SKIN_PLACE_SUBDIVISION = 1 /* bisect edges / 4-split triangles until covered */
} fl_skin_placement;

/* Options of fl_skin_approx; all zero is the default. */
typedef struct fl_skin_approx_options {
    double t;           /* shrink factor of the verified skin, in (0, 1); 0 means 0.5 */
    double cell;        /* mesher grid spacing; 0 means rho / 2 (finer in later rounds) */
    int max_rounds;     /* constructions tried (rho = 0.8 eps and cell rho / 2, then cell
                         * x0.4 or rho x0.7 each, see above); 0 means 3 */
    size_t max_balls;   /* refuse more protecting balls than this (FL_ERR_INPUT); 0 means 1e6 */
    double budget_seconds; /* Hausdorff budget per round (still certified); 0 means 60 */
    fl_progress_fn progress; /* may be NULL; stages "skin balls", "skin", "hausdorff" */
    void *progress_user;
    int placement;      /* fl_skin_placement; 0 (Algorithm 1) is the default */
    double grade;       /* mesher: 0 means the uniform grid, then (same balls) the graded grid
                         * of grade 2.2 (x0.6 a later round) when the topology came out wrong;
                         * > 0 the graded grid of this grade only (fl_skin_options.grade, cells
                         * at most `cell`); < 0 the uniform grid only */
    int repair;         /* local refinements of a graded mesh whose topology is not the union's
                         * (fl_skin_options.repair); 0 means none */
} fl_skin_approx_options;

/* The result of fl_skin_approx. Free with fl_skin_approx_free. */
typedef struct fl_skin_approx {
    fl_balls surface;      /* B: the protecting balls centred on the surface, radii <= rho */
    size_t boundary_balls; /* the first boundary_balls of B are centred on vertices and edges */
    fl_balls perp;         /* B_perp: the union of these approximates the object (§5) */
    fl_balls star;         /* B*: B_perp and the negative-weight orthogonal balls (§6.2) */
    fl_mesh skin;          /* triangulation of skin^t(B*) (fl_skin_mesh) */
    double rho;            /* radius of the surface balls of the last round */
    double t, cell;        /* shrink factor and grid spacing of the skin mesh */
    double grade;          /* grade of the graded grid that made the skin mesh, 0 if uniform */
    double hausdorff[2];   /* certified [lower, upper] Hausdorff distance skin mesh <-> input */
    long long euler;       /* Euler characteristic of the skin mesh */
    long long euler_input; /* Euler characteristic of the input */
    int rounds;            /* constructions done */
    int closed_manifold;   /* the skin mesh is closed, 2-manifold and oriented */
    unsigned repairs;      /* local refinements of the skin mesh's graded grid (its stats) */
    int verified;          /* 1 iff hausdorff[1] <= epsilon, euler == euler_input and
                              closed_manifold */
} fl_skin_approx;

/* Approximates the closed, oriented 2-manifold triangle mesh `mesh` (any genus; fl_mesh_check
 * must find it closed, manifold, oriented, without self-intersections) within epsilon > 0.
 * Returns FL_OK with out->verified = 1 when a round met both checks, FL_OK with verified = 0
 * (and the last round's result) when none did in max_rounds. Errors: FL_ERR_USAGE (NULL
 * pointers, t outside (0, 1), negative options), FL_ERR_INPUT (epsilon not finite and > 0,
 * mesh not a closed oriented manifold or self-intersecting, the skin grid too large),
 * FL_ERR_ALGORITHM "cancelled", FL_ERR_NOMEM. On failure *out is zeroed. */
fl_status fl_skin_approx_build(const fl_mesh *mesh, double epsilon,
                               const fl_skin_approx_options *opt, fl_skin_approx *out,
                               fl_error *err);

/* Releases everything in *approx and zeroes it; NULL or a zeroed struct is a no-op. */
void fl_skin_approx_free(fl_skin_approx *approx);

/* end of skin */


/* ==== sweep_dynamic ======================================================================= */
/* (section owned by src/sweep/rigid.c and src/sweep/deform.c; docs/sweep.md "Moving shapes")
 *
 * Meshsweeper queries against a shape that moves (Guéziec §5.2, §5.3). A rigid motion does not
 * touch the hierarchy: the query is carried into the shape's frame. A deforming mesh keeps its
 * hierarchy too: fl_sweep_update_vertices moves the leaves and updates every bounding volume
 * bottom-up (translate, then bound the sphere radius from the children), so answers stay exact
 * with no rebuild; cursors keep their queues across updates and widen them by the largest
 * vertex displacement (§5.2). An update must not run while the hierarchy is being queried. */

/* A rigid motion x -> R x + t of a shape; r is row-major (r[3*i + j] = R_ij) and must be
 * orthonormal to 1e-12 (a rotation, or a reflection). For a 2D polyline hierarchy the motion
 * must keep the plane z = 0: r[2] = r[5] = r[6] = r[7] = t[2] = 0. */
typedef struct fl_sweep_pose {
    double r[9];
    double t[3];
} fl_sweep_pose;

/* As fl_sweep_closest, for the shape moved by `pose`: q holds nq*dim points in the world frame;
 * distance, element, bary, lower/upper are those of the moved shape and `point` is in the
 * world frame. FL_ERR_INPUT for a bad pose, otherwise as fl_sweep_closest. */
fl_status fl_sweep_closest_posed(const fl_sweep *sweep, const fl_sweep_pose *pose, const double *q,
                                 size_t nq, double tolerance, fl_closest *results, fl_error *err);

/* One query through a cursor for the shape moved by `pose` (which may change from call to
 * call): a shape moving a little at a time is a query moving a little at a time in the shape's
 * frame, and the cursor's kept queue (§5.1) pays off the same way. */
fl_status fl_sweep_cursor_closest_posed(fl_sweep_cursor *cursor, const fl_sweep_pose *pose,
                                        const double *q, double tolerance, fl_closest *result,
                                        fl_error *err);

/* Moves the vertices of a mesh hierarchy (from fl_sweep_build) to xyz (3 * vertex_count
 * doubles, same count and triangles as the built mesh, finite with |x| <= 1e150) and updates
 * its bounding volumes bottom-up in O(T): the answers afterwards are exact for the new mesh.
 * The volumes only stay tight while the motion is locally close to rigid; after a large
 * deformation a rebuild makes queries faster again (never more correct). Cursors on the
 * hierarchy stay valid. FL_ERR_USAGE for NULL or a polyline hierarchy, FL_ERR_INPUT for a bad
 * coordinate (the hierarchy is then unchanged), FL_ERR_NOMEM (unchanged too). */
fl_status fl_sweep_update_vertices(fl_sweep *sweep, const double *xyz, fl_error *err);

/* end of sweep_dynamic */

/* ==== sweep_collapse ====================================================================== */
/* (section owned by src/sweep/collapse*.c; docs/sweep.md "The edge-collapse hierarchy")
 *
 * Meshsweeper's own mesh hierarchy (Guéziec 2001, §4.2-4.3): error-bounded edge collapses
 * simplify the mesh to a base mesh; every triangle of the hierarchy, swept by a sphere of its
 * error radius, bounds the input triangles it stands for; a query refines the base mesh by
 * vertex splits (with their "split before" dependencies) in the order of the priority process
 * of §3.2 and answers exactly, or within a tolerance, like fl_sweep_closest. A cursor keeps
 * the refined mesh between coherent queries (§5.1) and goes back to a start level (the base
 * mesh with its last collapses split again, docs/sweep.md) when that stops paying. Same input rules and results (fl_closest) as fl_sweep_build/fl_sweep_closest;
 * `element` is an input triangle index. A deforming mesh keeps its hierarchy (§5.3):
 * fl_sweep_collapse_update_vertices inflates the error radii by the vertex displacements and
 * fl_sweep_collapse_refit re-measures them at the current positions. Between such updates
 * the hierarchy is read-only and may be shared by threads (an update must not run while it is
 * queried); a cursor belongs to one thread. */

typedef struct fl_sweep_collapse fl_sweep_collapse;
typedef struct fl_sweep_collapse_cursor fl_sweep_collapse_cursor;

/* Sizes of a collapse hierarchy. */
typedef struct fl_sweep_collapse_info {
    size_t fine_triangles; /* input triangles */
    size_t base_triangles; /* triangles of the base (most simplified) mesh */
    size_t splits;         /* vertex splits (= edge collapses performed) */
    size_t triangles;      /* all triangles of the hierarchy, input ones included */
    size_t bytes;          /* memory held by the hierarchy */
    size_t cursor_bytes;   /* memory held by one cursor on it */
} fl_sweep_collapse_info;

/* Builds the edge-collapse hierarchy of `mesh` (any topology; unsafe collapses are skipped, so
 * the base mesh may keep many triangles, e.g. all of a soup of separate triangles). opt may be
 * NULL (progress only). FL_ERR_USAGE, FL_ERR_INPUT (as fl_sweep_build), FL_ERR_NOMEM. Free
 * with fl_sweep_collapse_free. */
fl_status fl_sweep_collapse_build(const fl_mesh *mesh, const fl_sweep_options *opt,
                                  fl_sweep_collapse **out, fl_error *err);

/* Frees a collapse hierarchy (NULL is fine). */
void fl_sweep_collapse_free(fl_sweep_collapse *hierarchy);

/* Fills *info with the hierarchy's sizes. FL_ERR_USAGE for NULL arguments. */
fl_status fl_sweep_collapse_info_get(const fl_sweep_collapse *hierarchy,
                                     fl_sweep_collapse_info *info, fl_error *err);

/* Creates a cursor (the refined mesh and priority queue of coherent queries, §5.1) on a
 * hierarchy, which must outlive it. FL_ERR_USAGE, FL_ERR_NOMEM. */
fl_status fl_sweep_collapse_cursor_new(const fl_sweep_collapse *hierarchy,
                                       fl_sweep_collapse_cursor **out, fl_error *err);

/* One query (q holds 3 doubles) as in fl_sweep_cursor_closest; `reused` = 1 when answered from
 * the last exact answer's §3.3 ball (one distance), `visited` counts the triangles whose
 * distance was computed. FL_ERR_USAGE for NULL
 * arguments, a negative tolerance or a query not finite or beyond 1e150. */
fl_status fl_sweep_collapse_cursor_closest(fl_sweep_collapse_cursor *cursor, const double *q,
                                           double tolerance, fl_closest *result, fl_error *err);

/* Makes the next query through the cursor start from the start level, as a fresh cursor would
 * (the cursor does this by itself when coherence stops paying, §5.1: docs/sweep.md); for
 * callers that know the next query is unrelated. NULL is fine. */
void fl_sweep_collapse_cursor_reset(fl_sweep_collapse_cursor *cursor);

/* Frees a cursor (NULL is fine). */
void fl_sweep_collapse_cursor_free(fl_sweep_collapse_cursor *cursor);

/* Answers nq queries (3 doubles each) in order through one cursor, as fl_sweep_closest. */
fl_status fl_sweep_collapse_closest(const fl_sweep_collapse *hierarchy, const double *q, size_t nq,
                                    double tolerance, fl_closest *results, fl_error *err);

/* One query through a cursor for the mesh moved by `pose` (§5.2; the pose may change from
 * call to call), as fl_sweep_cursor_closest_posed: the query is carried into the mesh's frame,
 * so a mesh moving a little at a time reuses the cursor's refined mesh like a moving query
 * (§5.1); `point` is in the world frame. FL_ERR_INPUT for a bad pose, otherwise as
 * fl_sweep_collapse_cursor_closest. */
fl_status fl_sweep_collapse_cursor_closest_posed(fl_sweep_collapse_cursor *cursor,
                                                 const fl_sweep_pose *pose, const double *q,
                                                 double tolerance, fl_closest *result,
                                                 fl_error *err);

/* The k input triangles nearest to q (§4.4), nearest first, as fl_sweep_knearest: the
 * priority process continues past the first leaf; the cursor keeps the refined mesh, so
 * coherent k-nearest queries reuse it (§5.1). FL_ERR_USAGE for NULL arguments or a bad
 * query, FL_ERR_NOMEM. */
fl_status fl_sweep_collapse_cursor_knearest(fl_sweep_collapse_cursor *cursor, const double *q,
                                            size_t k, uint32_t *elements, double *distances,
                                            size_t *found, fl_error *err);

/* Every input triangle at distance <= radius (>= 0) from q, nearest first (§4.4), as
 * fl_sweep_within (free with fl_sweep_hits_free; *out is zeroed on failure). */
fl_status fl_sweep_collapse_cursor_within(fl_sweep_collapse_cursor *cursor, const double *q,
                                          double radius, fl_sweep_hits *out, fl_error *err);

/* fl_sweep_collapse_cursor_knearest through a temporary cursor (one query from the base mesh). */
fl_status fl_sweep_collapse_knearest(const fl_sweep_collapse *hierarchy, const double *q, size_t k,
                                     uint32_t *elements, double *distances, size_t *found,
                                     fl_error *err);

/* fl_sweep_collapse_cursor_within through a temporary cursor (one query from the base mesh). */
fl_status fl_sweep_collapse_within(const fl_sweep_collapse *hierarchy, const double *q,
                                   double radius, fl_sweep_hits *out, fl_error *err);

/* Moves the vertices of a collapse hierarchy to xyz (3 * vertex_count doubles: vertex_count
 * must be the built mesh's, same triangles, finite with |x| <= 1e150) without rebuilding, §5.3's second
 * method: every vertex's displacement from the positions the errors were measured at (the
 * build's or the last refit's) is propagated along the collapse sequence and inflates the
 * error radii, O(V + T) with no geometry, so the answers afterwards are exact for the new mesh
 * (docs/sweep.md "Deformation"). The inflation grows with the distance from those positions
 * (it does not accumulate over updates: updating back to them restores the measured radii);
 * fl_sweep_collapse_refit tightens it. Cursors on the hierarchy stay valid and exact: their
 * next query replays their current errors and widens their kept intervals by the largest
 * displacement (§5.1, §5.2). FL_ERR_USAGE for NULL, FL_ERR_INPUT for another vertex count or a
 * bad coordinate and
 * FL_ERR_NOMEM (the hierarchy is then unchanged). */
fl_status fl_sweep_collapse_update_vertices(fl_sweep_collapse *hierarchy, const double *xyz,
                                            size_t vertex_count, fl_error *err);

/* Re-measures the error radii at the current vertex positions by replaying the recorded
 * collapse sequence (the ownership of input triangles and their distances, as the build does,
 * but without the simplification), and makes these positions the reference of later
 * fl_sweep_collapse_update_vertices calls: after a large deformation, tighter radii at about a
 * third of a rebuild's cost (docs/sweep.md). Cursors stay valid. FL_ERR_USAGE for NULL,
 * FL_ERR_NOMEM (the hierarchy is then unchanged). */
fl_status fl_sweep_collapse_refit(fl_sweep_collapse *hierarchy, fl_error *err);

/* end of sweep_collapse */

/* ==== sweep_motion ======================================================================== */
/* (section owned by src/sweep/keyframes.c and src/sweep/polyline_motion.c; docs/sweep.md
 * "Moving shapes")
 *
 * More moving shapes for Meshsweeper (Guéziec §5.3). Key frames (§5.3, first method): a mesh
 * whose vertices move linearly between recorded key frames; the hierarchy's base triangles and
 * radii are computed once for every key frame, and at any time in between both are
 * interpolated, the radius with a correction t(1-t)·(spread of the base corners' motion) that
 * keeps every volume a bound (proof in docs/sweep.md), so queries stay exact at every time
 * with O(nodes) arithmetic and no distance computation per time step. Polyline updates: a
 * polyline hierarchy (2D or 3D) takes new point positions and inflates its capsules bottom-up
 * (the polyline analogue of fl_sweep_update_vertices). Rigid motion of a polyline needs no
 * update: fl_sweep_closest_posed. Nothing here may run while the hierarchy is being queried. */

/* A mesh moving through key frames. */
typedef struct fl_sweep_keyframes fl_sweep_keyframes;

/* Records the key frames of a deforming mesh: `mesh` gives the triangles and the vertex count
 * (its own xyz is not used); `frames` holds frame_count >= 1 frames of 3 * vertex_count
 * doubles each (finite, |x| <= 1e150), frame f starting at frames + 3 * vertex_count * f.
 * Builds the hierarchy on frame 0 (fl_sweep_build rules), carries it to every other frame and
 * stores each node's base triangle and exact radius per frame: O(F·T log T) once, 80 bytes a
 * node a frame. The time starts at 0. FL_ERR_USAGE (NULL), FL_ERR_INPUT (bad mesh or
 * coordinate), FL_ERR_NOMEM. Free with fl_sweep_keyframes_free. */
fl_status fl_sweep_keyframes_new(const fl_mesh *mesh, const double *frames, size_t frame_count,
                                 const fl_sweep_options *opt, fl_sweep_keyframes **out,
                                 fl_error *err);

/* Frees the key frames and their hierarchy; NULL is a no-op. */
void fl_sweep_keyframes_free(fl_sweep_keyframes *kf);

/* Moves the mesh to time t in [0, frame_count - 1]: between frames f and f + 1 (s = t - f)
 * vertex i is at (1 - s)·x_f + s·x_{f+1} (computed exactly so, per coordinate), and every
 * bounding volume is interpolated in O(nodes). Queries on fl_sweep_keyframes_sweep are then
 * exact for that mesh; cursors on it stay valid and widen their kept queues by the largest
 * vertex move (§5.2). FL_ERR_USAGE (NULL), FL_ERR_INPUT (t not finite or out of range; the
 * time is then unchanged). */
fl_status fl_sweep_keyframes_set_time(fl_sweep_keyframes *kf, double t, fl_error *err);

/* The hierarchy at the current time, for fl_sweep_closest, cursors, fl_sweep_knearest and
 * fl_sweep_within (never for fl_sweep_update_vertices); owned by kf. */
const fl_sweep *fl_sweep_keyframes_sweep(const fl_sweep_keyframes *kf);

/* The vertex positions at the current time (3 * vertex_count doubles into xyz), the mesh the
 * queries answer for. FL_ERR_USAGE for NULL. */
fl_status fl_sweep_keyframes_vertices(const fl_sweep_keyframes *kf, double *xyz, fl_error *err);

/* Moves the points of a polyline hierarchy (from fl_sweep_polyline_build) to `points` (same
 * count n and dimension as built, n * dim doubles, finite with |x| <= 1e150) and updates its
 * capsules bottom-up in O(n) (each radius the smallest of: old radius inflated by the node's
 * largest point move plus its end points' move, the children's capsules' reach, or the exact
 * radius for nodes of <= 128 segments): answers afterwards are exact for the moved polyline.
 * Cursors stay valid (§5.2). FL_ERR_USAGE for NULL or a mesh hierarchy, FL_ERR_INPUT for a bad
 * coordinate (the hierarchy is then unchanged), FL_ERR_NOMEM (unchanged too). */
fl_status fl_sweep_polyline_update(fl_sweep *sweep, const double *points, fl_error *err);

/* end of sweep_motion */

/* ==== skin_hausdorff ========================================================================= */
/* (section owned by src/skin; docs/skin.md, "Certified Hausdorff distance of the union")
 *
 * The certified Hausdorff distance between the boundary of a union of balls and a closed
 * triangle mesh (issue #12: ∂∪B_perp against ∂O). Both directed distances are bounded by
 * branch and bound with 1-Lipschitz distance functions: the union's boundary is covered by
 * gnomonic (cube-map) patches of every sphere, dropped when they are buried in another ball;
 * the mesh by 4-split pieces of its triangles. Distances to the mesh come from the Meshsweeper
 * hierarchy (fl_sweep), distances to the union's boundary from the balls themselves (outside:
 * min |x - c| - r; inside: the exit of the normal ray from the union, an upper bound). */

/* Options of fl_skin_union_hausdorff; all zero is the default. */
typedef struct fl_skin_union_hausdorff_options {
    double precision;  /* refine until upper - lower of each piece is at most this; 0 means
                        * 1e-3 of the mesh's bounding-box diagonal */
    size_t max_pieces; /* refuse to evaluate more pieces (FL_ERR_ALGORITHM); 0 means 5e7 */
    fl_progress_fn progress; /* may be NULL; stage "union hausdorff" */
    void *progress_user;
} fl_skin_union_hausdorff_options;

/* What fl_skin_union_hausdorff certified: every interval is [lower, upper]. */
typedef struct fl_skin_union_hausdorff_result {
    double hausdorff[2];   /* max of the two directed distances */
    double from_union[2];  /* sup over x on the union's boundary of d(x, mesh) */
    double from_mesh[2];   /* sup over y on the mesh of d(y, union's boundary) */
    size_t pieces;         /* sphere patches and triangle pieces evaluated */
} fl_skin_union_hausdorff_result;

/* Bounds the Hausdorff distance between the boundary of the union of the balls with positive
 * weight in balls (xyzw, w the squared radius) and the triangle mesh `mesh` (its triangles as a
 * surface; normally closed: the inside test of the distance to the union's boundary uses the
 * triangles' normals only as ray directions, so any orientation is correct, only slower).
 * FL_ERR_USAGE for NULL arguments or a negative option, FL_ERR_INPUT for no positive ball,
 * non-finite or huge (> 1e150) coordinates or weights, a mesh fl_sweep_build rejects,
 * FL_ERR_ALGORITHM when more than max_pieces would be needed or "cancelled", FL_ERR_NOMEM. */
fl_status fl_skin_union_hausdorff(const fl_balls *balls, const fl_mesh *mesh,
                                  const fl_skin_union_hausdorff_options *opt,
                                  fl_skin_union_hausdorff_result *out, fl_error *err);

/* end of skin_hausdorff */

#ifdef __cplusplus
}
#endif

#endif /* FLINTSTONE_H */
