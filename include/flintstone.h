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


#ifdef __cplusplus
}
#endif

#endif /* FLINTSTONE_H */
