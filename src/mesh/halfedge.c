/* Edge adjacency by counting sort: sorting the 3T half-edges by their (lo, hi) vertex pair with
 * two stable counting sorts (by hi, then by lo) brings the half-edges of each undirected edge
 * together in O(V + T), deterministic, without hashing. */
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "mesh/halfedge.h"

static uint32_t he_lo(const uint32_t *tri, uint32_t h)
{
    uint32_t a = tri[h], b = tri[fl_he_next(h)];
    return a < b ? a : b;
}

static uint32_t he_hi(const uint32_t *tri, uint32_t h)
{
    uint32_t a = tri[h], b = tri[fl_he_next(h)];
    return a < b ? b : a;
}

/* Stable counting sort of `in` (n half-edges) by key(h) in [0, nv) into `out`; `count` has
 * nv + 1 entries of scratch. With start != NULL the bucket offsets are also kept there. */
static void counting_sort(const uint32_t *tri, const uint32_t *in, uint32_t n, size_t nv,
                          uint32_t (*key)(const uint32_t *, uint32_t), uint32_t *count,
                          uint32_t *out)
{
    memset(count, 0, (nv + 1) * sizeof *count);
    for (uint32_t i = 0; i < n; i++)
        count[key(tri, in[i]) + 1]++;
    for (size_t v = 0; v < nv; v++)
        count[v + 1] += count[v];
    for (uint32_t i = 0; i < n; i++)
        out[count[key(tri, in[i])]++] = in[i];
}

/* vertex_start / vertex_corners: the corners at each vertex, ascending. */
static void build_vertex_corners(fl_halfedges *he, uint32_t nh)
{
    size_t nv = he->vertex_count;
    uint32_t *start = he->vertex_start;
    memset(start, 0, (nv + 1) * sizeof *start);
    for (uint32_t h = 0; h < nh; h++)
        start[he->tri[h] + 1]++;
    for (size_t v = 0; v < nv; v++)
        start[v + 1] += start[v];
    for (uint32_t h = 0; h < nh; h++)
        he->vertex_corners[start[he->tri[h]]++] = h;
    /* the placement loop advanced each start to the next bucket's start: shift back */
    memmove(start + 1, start, nv * sizeof *start);
    start[0] = 0;
}

/* Splits the (lo, hi)-sorted half-edges into edges and links twins. */
static fl_status build_edges(fl_halfedges *he, uint32_t nh, fl_error *err)
{
    const uint32_t *s = he->edge_halfedges;
    size_t ne = 0;
    for (uint32_t i = 0; i < nh; i++)
        if (i == 0 || he_lo(he->tri, s[i]) != he_lo(he->tri, s[i - 1]) ||
            he_hi(he->tri, s[i]) != he_hi(he->tri, s[i - 1]))
            ne++;
    he->edge_count = ne;
    he->edge_vertices = fl_alloc_array(ne, 2 * sizeof(uint32_t));
    he->edge_start = fl_alloc_array(ne + 1, sizeof(uint32_t));
    if (!he->edge_vertices || !he->edge_start)
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory building mesh edges");
    size_t e = 0;
    for (uint32_t i = 0; i < nh; e++) {
        uint32_t lo = he_lo(he->tri, s[i]), hi = he_hi(he->tri, s[i]), j = i;
        while (j < nh && he_lo(he->tri, s[j]) == lo && he_hi(he->tri, s[j]) == hi) {
            he->halfedge_edge[s[j]] = (uint32_t)e;
            he->twin[s[j]] = FL_HE_NONE;
            j++;
        }
        if (j - i == 2) {
            he->twin[s[i]] = s[i + 1];
            he->twin[s[i + 1]] = s[i];
        }
        he->edge_vertices[2 * e] = lo;
        he->edge_vertices[2 * e + 1] = hi;
        he->edge_start[e] = i;
        i = j;
    }
    he->edge_start[ne] = nh;
    return FL_OK;
}

fl_status fl_halfedges_build(const fl_mesh *mesh, fl_halfedges *he, fl_error *err)
{
    memset(he, 0, sizeof *he);
    size_t nt = mesh->triangle_count, nv = mesh->vertex_count;
    if (nt > (UINT32_MAX - 1) / 3)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                       "mesh has %zu triangles; at most %u are supported", nt,
                       (UINT32_MAX - 1) / 3);
    uint32_t nh = (uint32_t)(3 * nt);
    for (uint32_t h = 0; h < nh; h++)
        if (mesh->tri[h] >= mesh->vertex_count)
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "triangle %u uses vertex %u but the mesh has %zu vertices", h / 3,
                           mesh->tri[h], mesh->vertex_count);
    he->vertex_count = nv;
    he->triangle_count = nt;
    he->tri = mesh->tri;
    he->halfedge_edge = fl_alloc_array(nh, sizeof(uint32_t));
    he->twin = fl_alloc_array(nh, sizeof(uint32_t));
    he->edge_halfedges = fl_alloc_array(nh, sizeof(uint32_t));
    he->vertex_corners = fl_alloc_array(nh, sizeof(uint32_t));
    he->vertex_start = fl_alloc_array(nv + 1, sizeof(uint32_t));
    uint32_t *scratch = fl_alloc_array(nh, sizeof(uint32_t));
    uint32_t *count = fl_alloc_array(nv + 1, sizeof(uint32_t));
    fl_status st = FL_OK;
    if (!he->halfedge_edge || !he->twin || !he->edge_halfedges || !he->vertex_corners ||
        !he->vertex_start || !scratch || !count) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory building mesh adjacency");
    } else {
        build_vertex_corners(he, nh);
        /* identity order sorted by hi, then stably by lo: (lo, hi) lexicographic */
        for (uint32_t h = 0; h < nh; h++)
            he->edge_halfedges[h] = h;
        counting_sort(he->tri, he->edge_halfedges, nh, nv, he_hi, count, scratch);
        counting_sort(he->tri, scratch, nh, nv, he_lo, count, he->edge_halfedges);
        st = build_edges(he, nh, err);
    }
    free(scratch);
    free(count);
    if (st != FL_OK) fl_halfedges_free(he);
    return st;
}

void fl_halfedges_free(fl_halfedges *he)
{
    free(he->edge_vertices);
    free(he->edge_start);
    free(he->edge_halfedges);
    free(he->halfedge_edge);
    free(he->twin);
    free(he->vertex_start);
    free(he->vertex_corners);
    memset(he, 0, sizeof *he);
}
