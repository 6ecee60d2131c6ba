/* The mesh facts the surface schemes rely on: a closed, manifold, oriented triangle mesh
 * (checked with fl_mesh_check) and the pairing of its half-edges. */
#include <math.h>
#include <stdlib.h>

#include "smooth/smooth_internal.h"

fl_status g1_require_closed_mesh(const fl_mesh *mesh, fl_error *err)
{
    if (!mesh || !mesh->xyz || !mesh->tri || mesh->triangle_count == 0)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "empty mesh");
    fl_mesh_check_options opt = {.skip_self_intersections = 1};
    fl_mesh_report rep;
    fl_status st = fl_mesh_check(mesh, &opt, &rep, err);
    if (st) return st;
    if (!rep.closed)
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                     "the mesh is not closed (%zu boundary edges); smoothing needs a closed "
                     "manifold oriented mesh",
                     rep.boundary_edges);
    else if (!rep.manifold)
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                     "the mesh is not manifold (%zu edges, %zu vertices)", rep.nonmanifold_edges,
                     rep.nonmanifold_vertices);
    else if (!rep.oriented)
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                     "the mesh is not consistently oriented (%zu edges)", rep.misoriented_edges);
    else if (rep.degenerate_faces)
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1, "the mesh has %zu degenerate triangles",
                     rep.degenerate_faces);
    else if (rep.unreferenced_vertices)
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                     "the mesh has %zu vertices no triangle uses (no normal there)",
                     rep.unreferenced_vertices);
    fl_mesh_report_free(&rep);
    /* Normals, control points and tessellations overflowed to inf on a mesh at 1e306 (found by
     * fuzz/fuzz_smooth.c); the sweep's range. */
    for (size_t i = 0; st == FL_OK && i < 3 * mesh->vertex_count; i++)
        if (fabs(mesh->xyz[i]) > 1e150)
            st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                         "vertex %zu is beyond the supported range |x| <= 1e150", i / 3);
    return st;
}

typedef struct half_edge_key {
    uint64_t key; /* (min vertex) << 32 | max vertex */
    uint32_t he;
} half_edge_key;

static int cmp_key(const void *a, const void *b)
{
    const half_edge_key *x = a, *y = b;
    if (x->key != y->key) return x->key < y->key ? -1 : 1;
    return x->he < y->he ? -1 : x->he > y->he;
}

fl_status g1_opposite_half_edges(const fl_mesh *mesh, uint32_t **opp, fl_error *err)
{
    size_t nh = 3 * mesh->triangle_count;
    half_edge_key *k = fl_alloc_array(nh, sizeof *k);
    *opp = fl_alloc_array(nh, sizeof **opp);
    if (!k || !*opp) {
        free(k);
        free(*opp);
        *opp = NULL;
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    for (size_t h = 0; h < nh; h++) {
        uint64_t a = mesh->tri[h], b = mesh->tri[3 * (h / 3) + (h + 1) % 3];
        k[h].key = a < b ? (a << 32 | b) : (b << 32 | a);
        k[h].he = (uint32_t)h;
    }
    qsort(k, nh, sizeof *k, cmp_key);
    /* Closed and manifold: the sorted keys come in pairs. */
    for (size_t i = 0; i + 1 < nh; i += 2) {
        (*opp)[k[i].he] = k[i + 1].he;
        (*opp)[k[i + 1].he] = k[i].he;
    }
    free(k);
    return FL_OK;
}
