/* Half-edge / edge-adjacency view of an fl_mesh, in flat arrays (internal; used by the mesh
 * checks, reconstruction, HAL and Meshsweeper).
 *
 * Half-edges are implicit: half-edge h = 3*t + k is side k of triangle t, running from
 * tri[h] to tri[fl_he_next(h)]. It is also the *corner* of t at vertex tri[h]. Nothing is
 * stored per half-edge except its undirected edge and its twin, so the view costs
 * 4 * 3 uint32 per triangle plus 2 per edge and 1 per vertex.
 *
 * Built in O(V + T) time by two stable counting sorts of the (lo, hi) vertex pairs, no
 * hashing and no per-element allocation. The view borrows mesh->tri: the mesh must outlive
 * it and stay unchanged. */
#ifndef FL_MESH_HALFEDGE_H
#define FL_MESH_HALFEDGE_H

#include <stddef.h>
#include <stdint.h>

#include "flintstone.h"

#define FL_HE_NONE UINT32_MAX

typedef struct fl_halfedges {
    size_t vertex_count;
    size_t triangle_count;
    size_t edge_count;
    const uint32_t *tri;      /* borrowed mesh->tri: tri[h] is the origin of half-edge h */
    uint32_t *edge_vertices;  /* 2 per edge: lo <= hi; edges sorted by (lo, hi) */
    uint32_t *edge_start;     /* edge_count + 1 offsets into edge_halfedges */
    uint32_t *edge_halfedges; /* half-edges of edge e: [edge_start[e], edge_start[e+1]),
                               * ascending (so in triangle order) */
    uint32_t *halfedge_edge;  /* 3*T: the undirected edge of each half-edge */
    uint32_t *twin;           /* 3*T: the other half-edge of an edge with exactly two
                               * half-edges (whatever their directions), else FL_HE_NONE */
    uint32_t *vertex_start;   /* vertex_count + 1 offsets into vertex_corners */
    uint32_t *vertex_corners; /* corners (= outgoing half-edges) at vertex v:
                               * [vertex_start[v], vertex_start[v+1]), ascending */
} fl_halfedges;

/* Builds the view. Indices must be < mesh->vertex_count (FL_ERR_INPUT otherwise) and
 * 3 * triangle_count must be < 2^32 - 1 (FL_ERR_INPUT). FL_ERR_NOMEM on allocation failure.
 * On failure *he is zeroed; fl_halfedges_free on it is a no-op. */
fl_status fl_halfedges_build(const fl_mesh *mesh, fl_halfedges *he, fl_error *err);

void fl_halfedges_free(fl_halfedges *he);

static inline uint32_t fl_he_next(uint32_t h)
{
    return h % 3 == 2 ? h - 2 : h + 1;
}
static inline uint32_t fl_he_prev(uint32_t h)
{
    return h % 3 == 0 ? h + 2 : h - 1;
}
static inline uint32_t fl_he_face(uint32_t h)
{
    return h / 3;
}

/* Number of triangles on the edge of half-edge h (1 = boundary, 2 = manifold interior). */
static inline uint32_t fl_he_edge_valence(const fl_halfedges *he, uint32_t h)
{
    uint32_t e = he->halfedge_edge[h];
    return he->edge_start[e + 1] - he->edge_start[e];
}

/* The triangle across side k of triangle t when that edge has exactly two triangles, else
 * FL_HE_NONE. */
static inline uint32_t fl_he_neighbor(const fl_halfedges *he, uint32_t t, int k)
{
    uint32_t tw = he->twin[3 * t + (uint32_t)k];
    return tw == FL_HE_NONE ? FL_HE_NONE : tw / 3;
}

#endif /* FL_MESH_HALFEDGE_H */
