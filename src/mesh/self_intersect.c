/* Self-intersections of a triangle mesh: candidate pairs from a box tree over the proper
 * triangles, each decided exactly. Pairs that share vertices are judged by what they have in
 * common beyond the shared vertices (see fl_mesh_report.self_intersections). */
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "mesh/bvh.h"
#include "mesh/intersect.h"
#include "mesh/mesh_internal.h"

int fl_mesh_triangle_degenerate(const fl_mesh *mesh, size_t t)
{
    const uint32_t *f = mesh->tri + 3 * t;
    if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0]) return 1;
    return fl_triangle_degenerate(mesh->xyz + 3 * (size_t)f[0], mesh->xyz + 3 * (size_t)f[1],
                                  mesh->xyz + 3 * (size_t)f[2]);
}

int fl_mesh_triangles_intersect(const fl_mesh *mesh, uint32_t ta, uint32_t tb)
{
    const uint32_t *A = mesh->tri + 3 * (size_t)ta, *B = mesh->tri + 3 * (size_t)tb;
    int shared = 0, ia[3] = {0, 0, 0}, ib[3] = {0, 0, 0};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (A[i] == B[j]) ia[shared] = i, ib[shared] = j, shared++;
#define P(v) (mesh->xyz + 3 * (size_t)(v))
    switch (shared) {
    case 0:
        return fl_triangles_intersect(P(A[0]), P(A[1]), P(A[2]), P(B[0]), P(B[1]), P(B[2]));
    case 1: {
        uint32_t v = A[ia[0]];
        return fl_triangles_meet_beyond_vertex(P(v), P(A[(ia[0] + 1) % 3]), P(A[(ia[0] + 2) % 3]),
                                               P(B[(ib[0] + 1) % 3]), P(B[(ib[0] + 2) % 3]));
    }
    case 2: {
        /* the third vertex of each is the one not shared: index 3 - i - j of the two */
        uint32_t a = A[3 - ia[0] - ia[1]], b = B[3 - ib[0] - ib[1]];
        return fl_triangles_fold_over(P(A[ia[0]]), P(A[ia[1]]), P(a), P(b));
    }
    default: /* the same three vertices: the triangles coincide */
        return 1;
    }
#undef P
}

typedef struct count_ctx {
    const fl_mesh *mesh;
    size_t count, max_pairs;
    fl_vec pairs; /* elements of 2 uint32_t, grown as pairs are found */
    int out_of_memory;
} count_ctx;

static int count_pair(void *user, uint32_t a, uint32_t b)
{
    count_ctx *c = user;
    if (!fl_mesh_triangles_intersect(c->mesh, a, b)) return 0;
    if (c->count < c->max_pairs) {
        uint32_t pair[2] = {a < b ? a : b, a < b ? b : a};
        if (fl_vec_push(&c->pairs, pair, 1)) return c->out_of_memory = 1;
    }
    c->count++;
    return 0;
}

/* Boxes and ids of the proper triangles (degenerate ones take no part). */
static size_t proper_triangle_boxes(const fl_mesh *mesh, double *boxes, uint32_t *ids)
{
    size_t n = 0;
    for (size_t t = 0; t < mesh->triangle_count; t++) {
        if (fl_mesh_triangle_degenerate(mesh, t)) continue;
        double *b = boxes + 6 * n;
        for (int k = 0; k < 3; k++) {
            const double *p = mesh->xyz + 3 * (size_t)mesh->tri[3 * t + k];
            for (int d = 0; d < 3; d++) {
                if (k == 0 || p[d] < b[d]) b[d] = p[d];
                if (k == 0 || p[d] > b[3 + d]) b[3 + d] = p[d];
            }
        }
        ids[n++] = (uint32_t)t;
    }
    return n;
}

fl_status fl_mesh_find_self_intersections(const fl_mesh *mesh, size_t max_pairs,
                                          fl_progress_fn progress, void *user, fl_mesh_pairs *out,
                                          fl_error *err)
{
    memset(out, 0, sizeof *out);
    size_t nt = mesh->triangle_count;
    double *boxes = fl_alloc_array(nt, 6 * sizeof(double));
    uint32_t *ids = fl_alloc_array(nt, sizeof(uint32_t));
    if (!boxes || !ids) {
        free(boxes);
        free(ids);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for self-intersection search");
    }
    size_t n = proper_triangle_boxes(mesh, boxes, ids);
    fl_bvh bvh;
    fl_status st = fl_bvh_build(boxes, ids, n, 4, &bvh, err);
    free(boxes);
    free(ids);
    if (st != FL_OK) return st;
    count_ctx c = {mesh, 0, max_pairs, {NULL, 0, 0, 0}, 0};
    fl_vec_init(&c.pairs, 2 * sizeof(uint32_t));
    if (fl_bvh_self_pairs(&bvh, count_pair, &c, progress, user, "self-intersections"))
        st = c.out_of_memory
                 ? fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory keeping intersecting pairs")
                 : fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
    fl_bvh_free(&bvh);
    if (st != FL_OK) {
        fl_vec_free(&c.pairs);
        return st;
    }
    out->total = c.count;
    out->count = c.pairs.count;
    out->pairs = c.pairs.count ? fl_vec_release(&c.pairs) : NULL;
    fl_vec_free(&c.pairs);
    return FL_OK;
}

fl_status fl_mesh_self_intersections(const fl_mesh *mesh, size_t max_pairs, fl_progress_fn progress,
                                     void *progress_user, fl_mesh_pairs *out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "no output given");
    memset(out, 0, sizeof *out);
    fl_status st = fl_mesh_validate(mesh, err);
    if (st != FL_OK) return st;
    return fl_mesh_find_self_intersections(mesh, max_pairs, progress, progress_user, out, err);
}

void fl_mesh_pairs_free(fl_mesh_pairs *pairs)
{
    if (!pairs) return;
    free(pairs->pairs);
    memset(pairs, 0, sizeof *pairs);
}
