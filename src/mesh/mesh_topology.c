/* Topological checks on the half-edge view: edge valences, orientation, vertex fans,
 * components, Euler characteristic and genus. Everything is linear in the mesh size. */
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "mesh/halfedge.h"
#include "mesh/mesh_internal.h"

/* Edge valences and directions. Marks the edge's lo vertex in `bad_vertex` when the edge is a
 * boundary, non-manifold or misoriented edge, so its component can be flagged later. */
static void classify_edges(const fl_halfedges *he, fl_mesh_report *rep, unsigned char *bad_vertex)
{
    for (size_t e = 0; e < he->edge_count; e++) {
        uint32_t b = he->edge_start[e], n = he->edge_start[e + 1] - b;
        uint32_t lo = he->edge_vertices[2 * e], forward = 0;
        for (uint32_t i = 0; i < n; i++)
            forward += he->tri[he->edge_halfedges[b + i]] == lo;
        int bad = 0;
        if (n == 1) rep->boundary_edges++, bad = 1;
        if (n >= 3) rep->nonmanifold_edges++, bad = 1;
        if (forward > 1 || n - forward > 1) rep->misoriented_edges++, bad = 1;
        if (bad) bad_vertex[lo] = 1;
    }
}

/* A vertex is manifold when its corners form one fan: corners of two triangles sharing a
 * two-triangle edge through the vertex are joined; the number of resulting sets is the
 * number of fans (two cones touching at their apex give two). `parent` has 3T entries. */
static void count_vertex_fans(const fl_halfedges *he, uint32_t *parent, fl_mesh_report *rep,
                              unsigned char *bad_vertex)
{
    uint32_t nh = (uint32_t)(3 * he->triangle_count);
    for (uint32_t h = 0; h < nh; h++)
        parent[h] = h;
    for (uint32_t h = 0; h < nh; h++) {
        uint32_t t = he->twin[h];
        if (t == FL_HE_NONE || t < h) continue;
        if (he->tri[t] == he->tri[h]) { /* same direction: corners pair up directly */
            fl_uf_union(parent, h, t);
            fl_uf_union(parent, fl_he_next(h), fl_he_next(t));
        } else {
            fl_uf_union(parent, h, fl_he_next(t));
            fl_uf_union(parent, fl_he_next(h), t);
        }
    }
    for (size_t v = 0; v < he->vertex_count; v++) {
        uint32_t fans = 0;
        for (uint32_t i = he->vertex_start[v]; i < he->vertex_start[v + 1]; i++)
            fans += fl_uf_find(parent, he->vertex_corners[i]) == he->vertex_corners[i];
        if (fans == 0) rep->unreferenced_vertices++;
        if (fans > 1) rep->nonmanifold_vertices++, bad_vertex[v] = 1;
    }
}

/* Components through shared vertices; returns per-vertex component ids in `comp`
 * (FL_HE_NONE for unreferenced vertices) and their number. `parent` has V entries. */
static size_t label_components(const fl_halfedges *he, uint32_t *parent, uint32_t *comp)
{
    size_t nv = he->vertex_count, count = 0;
    for (size_t v = 0; v < nv; v++)
        parent[v] = (uint32_t)v, comp[v] = FL_HE_NONE;
    for (size_t t = 0; t < he->triangle_count; t++) {
        fl_uf_union(parent, he->tri[3 * t], he->tri[3 * t + 1]);
        fl_uf_union(parent, he->tri[3 * t], he->tri[3 * t + 2]);
    }
    /* number roots in triangle order so component 0 holds triangle 0 */
    for (size_t t = 0; t < he->triangle_count; t++) {
        uint32_t r = fl_uf_find(parent, he->tri[3 * t]);
        if (comp[r] == FL_HE_NONE) comp[r] = (uint32_t)count++;
    }
    for (size_t v = 0; v < nv; v++)
        if (he->vertex_start[v] < he->vertex_start[v + 1])
            comp[v] = comp[fl_uf_find(parent, (uint32_t)v)];
    return count;
}

/* Per component: V - E + F and whether it is a closed oriented manifold; then the genus. */
static fl_status component_genus(const fl_halfedges *he, const uint32_t *comp,
                                 const unsigned char *bad_vertex, fl_mesh_report *rep,
                                 fl_error *err)
{
    size_t nc = rep->components;
    long long *chi = fl_calloc_array(nc, sizeof *chi);
    unsigned char *bad = fl_calloc_array(nc, 1);
    rep->component_genus = fl_calloc_array(nc, sizeof *rep->component_genus);
    rep->component_faces = fl_calloc_array(nc, sizeof *rep->component_faces);
    if (!chi || !bad || !rep->component_genus || !rep->component_faces) {
        free(chi);
        free(bad);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory labelling components");
    }
    for (size_t v = 0; v < he->vertex_count; v++) {
        if (comp[v] == FL_HE_NONE) continue;
        chi[comp[v]]++;
        bad[comp[v]] |= bad_vertex[v];
    }
    for (size_t e = 0; e < he->edge_count; e++)
        chi[comp[he->edge_vertices[2 * e]]]--;
    for (size_t t = 0; t < he->triangle_count; t++) {
        uint32_t c = comp[he->tri[3 * t]];
        chi[c]++;
        rep->component_faces[c]++;
    }
    rep->genus = 0;
    for (size_t c = 0; c < nc; c++) {
        /* a closed orientable connected surface has chi = 2 - 2g (thesis §2, Euler) */
        long long g = (!bad[c] && chi[c] <= 2 && chi[c] % 2 == 0) ? (2 - chi[c]) / 2 : -1;
        rep->component_genus[c] = g;
        if (g < 0 || rep->genus < 0)
            rep->genus = -1;
        else
            rep->genus += g;
    }
    if (nc == 0) rep->genus = -1;
    free(chi);
    free(bad);
    return FL_OK;
}

fl_status fl_mesh_topology(const fl_halfedges *he, fl_mesh_report *rep, fl_error *err)
{
    size_t nv = he->vertex_count, nh = 3 * he->triangle_count;
    unsigned char *bad_vertex = fl_calloc_array(nv, 1);
    uint32_t *parent = fl_alloc_array(nh > nv ? nh : nv, sizeof(uint32_t));
    uint32_t *comp = fl_alloc_array(nv, sizeof(uint32_t));
    fl_status st = FL_OK;
    if (!bad_vertex || !parent || !comp) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory checking mesh topology");
        goto done;
    }
    rep->edges = he->edge_count;
    classify_edges(he, rep, bad_vertex);
    count_vertex_fans(he, parent, rep, bad_vertex);
    rep->closed = he->triangle_count > 0 && rep->boundary_edges == 0 && rep->nonmanifold_edges == 0;
    rep->manifold = rep->nonmanifold_edges == 0 && rep->nonmanifold_vertices == 0;
    rep->oriented = rep->misoriented_edges == 0;
    rep->euler = (long long)(nv - rep->unreferenced_vertices) - (long long)he->edge_count +
                 (long long)he->triangle_count;
    rep->components = label_components(he, parent, comp);
    st = component_genus(he, comp, bad_vertex, rep, err);
done:
    free(bad_vertex);
    free(parent);
    free(comp);
    return st;
}
