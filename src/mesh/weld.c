/* Exact duplicate vertices: equal coordinates found with an open-addressing hash table of the
 * coordinate bits, and welding them into one. */
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "mesh/mesh_internal.h"

/* Hash of the coordinate bits; +0.0 is added first so that -0 and +0 hash (and compare) the
 * same, as == says they are equal. */
static uint64_t point_hash(const double *p)
{
    uint64_t h = 0x9E3779B97F4A7C15ULL;
    for (int k = 0; k < 3; k++) {
        double x = p[k] + 0.0;
        uint64_t bits;
        memcpy(&bits, &x, sizeof bits);
        h ^= bits + 0x9E3779B97F4A7C15ULL + (h << 6) + (h >> 2);
        h *= 0xBF58476D1CE4E5B9ULL;
    }
    return h ^ (h >> 31);
}

fl_status fl_mesh_first_equal_vertex(const fl_mesh *mesh, size_t *first, fl_error *err)
{
    size_t nv = mesh->vertex_count, cap = 16;
    while (cap < 2 * nv && cap < SIZE_MAX / 4)
        cap *= 2;
    size_t *slot = fl_calloc_array(cap, sizeof *slot); /* vertex index + 1, 0 = empty */
    if (!slot) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory finding duplicates");
    for (size_t v = 0; v < nv; v++) {
        const double *p = mesh->xyz + 3 * v;
        for (size_t i = (size_t)point_hash(p) & (cap - 1);; i = (i + 1) & (cap - 1)) {
            if (!slot[i]) {
                slot[i] = v + 1;
                first[v] = v;
                break;
            }
            const double *q = mesh->xyz + 3 * (slot[i] - 1);
            if (p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) {
                first[v] = slot[i] - 1;
                break;
            }
        }
    }
    free(slot);
    return FL_OK;
}

fl_status fl_mesh_count_duplicate_vertices(const fl_mesh *mesh, size_t *count, fl_error *err)
{
    *count = 0;
    size_t *first = fl_alloc_array(mesh->vertex_count, sizeof *first);
    if (!first) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory finding duplicates");
    fl_status st = fl_mesh_first_equal_vertex(mesh, first, err);
    for (size_t v = 0; st == FL_OK && v < mesh->vertex_count; v++)
        *count += first[v] != v;
    free(first);
    return st;
}

fl_status fl_mesh_weld(const fl_mesh *mesh, fl_mesh *out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "no output mesh given");
    memset(out, 0, sizeof *out);
    fl_status st = fl_mesh_validate(mesh, err);
    if (st != FL_OK) return st;
    size_t nv = mesh->vertex_count, nt = mesh->triangle_count, kept = 0;
    size_t *first = fl_alloc_array(nv, sizeof *first);
    out->xyz = fl_alloc_array(nv, 3 * sizeof(double));
    out->tri = fl_alloc_array(nt, 3 * sizeof(uint32_t));
    if (!first || !out->xyz || !out->tri) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory welding vertices");
    } else {
        st = fl_mesh_first_equal_vertex(mesh, first, err);
    }
    if (st == FL_OK) {
        /* first[v] <= v, so one ascending pass can turn it into the new index */
        for (size_t v = 0; v < nv; v++) {
            if (first[v] == v) {
                memcpy(out->xyz + 3 * kept, mesh->xyz + 3 * v, 3 * sizeof(double));
                first[v] = kept++;
            } else {
                first[v] = first[first[v]];
            }
        }
        for (size_t i = 0; i < 3 * nt; i++)
            out->tri[i] = (uint32_t)first[mesh->tri[i]];
        out->vertex_count = kept;
        out->triangle_count = nt;
        double *shrunk = realloc(out->xyz, (kept ? kept : 1) * 3 * sizeof(double));
        if (shrunk) out->xyz = shrunk;
    }
    free(first);
    if (st != FL_OK) fl_mesh_free(out);
    return st;
}
