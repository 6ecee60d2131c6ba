/* One watertight mesh from all patches of a surface, and the measured quality of a surface:
 * interpolation, normal continuity across every patch edge, deviation from the mesh. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "smooth/smooth_internal.h"

/* Open-addressing map from an undirected node pair to the first of the density - 1 mesh
 * vertices sampled inside that patch edge (ordered from the smaller node). */
typedef struct edge_map {
    uint64_t *key;
    uint32_t *value;
    size_t mask;
} edge_map;

static int edge_map_init(edge_map *e, size_t entries)
{
    size_t cap = 16;
    while (cap < 2 * entries)
        cap *= 2;
    e->key = fl_alloc_array(cap, sizeof *e->key);
    e->value = fl_alloc_array(cap, sizeof *e->value);
    e->mask = cap - 1;
    if (!e->key || !e->value) return -1;
    memset(e->key, 0xff, cap * sizeof *e->key);
    return 0;
}

/* Slot of key (an empty slot holds UINT64_MAX); the map never fills (capacity >= 2 entries). */
static size_t edge_map_slot(const edge_map *e, uint64_t key)
{
    size_t i = (size_t)((key * 0x9E3779B97F4A7C15ULL) >> 20) & e->mask;
    while (e->key[i] != key && e->key[i] != UINT64_MAX)
        i = (i + 1) & e->mask;
    return i;
}

typedef struct tess {
    const fl_g1_surface *s;
    unsigned n;
    fl_vec xyz, nrm, tri;
    uint32_t *node_vertex; /* node -> mesh vertex, UINT32_MAX before its first use */
    edge_map edges;
} tess;

static int add_vertex(tess *t, const double *ctrl, double u, double v, double w, uint32_t *id)
{
    double p[3], nn[3];
    fl_g1_patch_eval(ctrl, u, v, w, p, nn);
    if (t->xyz.count / 3 >= UINT32_MAX) return -1;
    *id = (uint32_t)(t->xyz.count / 3);
    return fl_vec_push(&t->xyz, p, 3) || fl_vec_push(&t->nrm, nn, 3) ? -1 : 0;
}

/* Mesh vertex of grid point (a, b) of patch p (barycentric a/n, b/n, c/n on its corners):
 * corners and edge points are shared with the neighbouring patches through nodes and edges. */
static int grid_vertex(tess *t, size_t p, unsigned a, unsigned b, uint32_t *id)
{
    unsigned n = t->n, c = n - a - b;
    const uint32_t *nd = t->s->corner + 3 * p;
    const double *ctrl = t->s->ctrl + 30 * p;
    double u = (double)a / n, v = (double)b / n, w = (double)c / n;
    int corner = a == n ? 0 : b == n ? 1 : c == n ? 2 : -1;
    if (corner >= 0) {
        uint32_t *slot = t->node_vertex + nd[corner];
        if (*slot == UINT32_MAX && add_vertex(t, ctrl, u, v, w, slot)) return -1;
        *id = *slot;
        return 0;
    }
    /* On an edge: its end nodes (from, to) and the steps from `from`. */
    uint32_t from, to;
    unsigned step;
    if (c == 0) {
        from = nd[0], to = nd[1], step = b;
    } else if (a == 0) {
        from = nd[1], to = nd[2], step = c;
    } else if (b == 0) {
        from = nd[2], to = nd[0], step = a;
    } else {
        return add_vertex(t, ctrl, u, v, w, id);
    }
    if (from > to) {
        uint32_t x = from;
        from = to;
        to = x;
        step = n - step;
    }
    uint64_t key = (uint64_t)from << 32 | to;
    size_t slot = edge_map_slot(&t->edges, key);
    if (t->edges.key[slot] != key) {
        if (t->xyz.count / 3 + n > UINT32_MAX) return -1;
        t->edges.key[slot] = key;
        t->edges.value[slot] = (uint32_t)(t->xyz.count / 3);
        /* Evaluate the whole edge from this patch, in order from `from`. */
        for (unsigned s = 1; s < n; s++) {
            double bc[3] = {0, 0, 0};
            int i_from = from == nd[0] ? 0 : from == nd[1] ? 1 : 2;
            int i_to = to == nd[0] ? 0 : to == nd[1] ? 1 : 2;
            bc[i_from] = (double)(n - s) / n;
            bc[i_to] = (double)s / n;
            uint32_t unused;
            if (add_vertex(t, ctrl, bc[0], bc[1], bc[2], &unused)) return -1;
        }
    }
    *id = t->edges.value[slot] + step - 1;
    return 0;
}

/* Grid point (a, b) of a patch has local number a (2n + 3 - a) / 2 + b. */
static size_t local_index(unsigned n, unsigned a, unsigned b)
{
    return (size_t)a * (2 * n + 3 - a) / 2 + b;
}

static int tessellate_patch(tess *t, size_t p, uint32_t *local)
{
    unsigned n = t->n;
    for (unsigned a = 0; a <= n; a++)
        for (unsigned b = 0; a + b <= n; b++)
            if (grid_vertex(t, p, a, b, local + local_index(n, a, b))) return -1;
    for (unsigned a = 0; a < n; a++)
        for (unsigned b = 0; a + b < n; b++) {
            uint32_t lo[3] = {local[local_index(n, a, b)], local[local_index(n, a + 1, b)],
                              local[local_index(n, a, b + 1)]};
            if (fl_vec_push(&t->tri, lo, 3)) return -1;
            if (a + b + 2 <= n) {
                uint32_t up[3] = {lo[1], local[local_index(n, a + 1, b + 1)], lo[2]};
                if (fl_vec_push(&t->tri, up, 3)) return -1;
            }
        }
    return 0;
}

fl_status fl_g1_surface_tessellate(const fl_g1_surface *surface, unsigned density, fl_mesh *out,
                                   double **normals, fl_error *err)
{
    if (out) memset(out, 0, sizeof *out);
    if (normals) *normals = NULL;
    if (!surface || !out || !normals || density == 0 || density > 4096)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "NULL argument or density not in 1..4096");
    tess t = {.s = surface, .n = density};
    fl_vec_init(&t.xyz, sizeof(double));
    fl_vec_init(&t.nrm, sizeof(double));
    fl_vec_init(&t.tri, sizeof(uint32_t));
    t.node_vertex = fl_alloc_array(surface->node_count ? surface->node_count : 1, sizeof(uint32_t));
    uint32_t *local = fl_alloc_array(local_index(density, density, 0) + 1, sizeof *local);
    int bad = !t.node_vertex || !local || edge_map_init(&t.edges, 3 * surface->patch_count);
    if (!bad) memset(t.node_vertex, 0xff, surface->node_count * sizeof(uint32_t));
    for (size_t p = 0; !bad && p < surface->patch_count; p++)
        bad = tessellate_patch(&t, p, local);
    free(local);
    free(t.node_vertex);
    free(t.edges.key);
    free(t.edges.value);
    if (bad) {
        fl_vec_free(&t.xyz);
        fl_vec_free(&t.nrm);
        fl_vec_free(&t.tri);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory (or more than 2^32 vertices)");
    }
    out->vertex_count = t.xyz.count / 3;
    out->triangle_count = t.tri.count / 3;
    out->xyz = fl_vec_release(&t.xyz);
    out->tri = fl_vec_release(&t.tri);
    *normals = fl_vec_release(&t.nrm);
    return FL_OK;
}
