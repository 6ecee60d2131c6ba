/* Functions shared between the files of src/mesh (not public). */
#ifndef FL_MESH_INTERNAL_H
#define FL_MESH_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "flintstone.h"
#include "mesh/halfedge.h"

/* Fills the topological fields of rep (edges ... genus, components arrays). */
fl_status fl_mesh_topology(const fl_halfedges *he, fl_mesh_report *rep, fl_error *err);

/* Fills bbox, area and (when rep->closed && rep->oriented) volume, else volume = NaN. */
void fl_mesh_measures(const fl_mesh *mesh, fl_mesh_report *rep);

/* first[v] = the lowest index of a vertex whose coordinates equal (==) those of v (so
 * first[v] == v for the first of each position). O(V) expected with a hash table. */
fl_status fl_mesh_first_equal_vertex(const fl_mesh *mesh, size_t *first, fl_error *err);

/* Number of vertices whose coordinates equal those of a lower-indexed vertex. */
fl_status fl_mesh_count_duplicate_vertices(const fl_mesh *mesh, size_t *count, fl_error *err);

/* 1 iff triangle t has a repeated index or its three points are collinear (exact). */
int fl_mesh_triangle_degenerate(const fl_mesh *mesh, size_t t);

/* 1 iff proper triangles a != b of the mesh intersect beyond their shared vertices (one
 * candidate pair of the self-intersection count; exposed for brute-force tests). */
int fl_mesh_triangles_intersect(const fl_mesh *mesh, uint32_t a, uint32_t b);

/* Rejects a NULL mesh or arrays (FL_ERR_USAGE), indices >= vertex_count and non-finite
 * coordinates (FL_ERR_INPUT). */
fl_status fl_mesh_validate(const fl_mesh *mesh, fl_error *err);

/* The self-intersection search on a validated mesh: out->total counts the pairs of triangles
 * that intersect beyond their shared vertices (the definition of
 * fl_mesh_report.self_intersections), the first max_pairs are kept. Degenerate triangles are
 * skipped. On failure out holds nothing to free. */
fl_status fl_mesh_find_self_intersections(const fl_mesh *mesh, size_t max_pairs,
                                          fl_progress_fn progress, void *user, fl_mesh_pairs *out,
                                          fl_error *err);

#endif /* FL_MESH_INTERNAL_H */
