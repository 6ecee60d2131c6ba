/* The simplices of a γ-graph that have an empty ball (c1' >= 0), built from the Delaunay
 * triangulation (thesis Theorem 3.2).
 *
 * Theorem 3.2 assumes no k+2 points on an empty sphere; here degenerate sets are handled too.
 * Group the Delaunay cells (triangles, tetrahedra) into clusters of cells with one common empty
 * circumsphere (adjacent cells whose in-sphere test is exactly 0). Then:
 *  (a) a facet of the triangulation has, on each side, the apex of the adjacent cell as witness
 *      (gamma_simplex.c): the apex's ball is the cell's empty circumsphere, so no point beats it,
 *      and the points tied with it lie on that sphere, i.e. in the cell's cluster;
 *  (b) any k vertices of a cluster have that cluster's empty sphere, so they form a simplex of
 *      γ([-1,1],[0,1]) although the triangulation joins only some of them; their witnesses are
 *      the cluster's vertices, or, on a side where the cluster has none, the neighbouring cells'
 *      apexes and clusters (the same argument as in (a) across the cluster's boundary);
 *  (c) 3D only: k points in one plane of the convex hull bound an empty half-space; those the
 *      triangulation does not join are enumerated per coplanar group of hull faces, with the
 *      group, the inner cells' apexes and clusters as witnesses.
 * Every simplex with an empty ball falls in (a), (b) or (c), and its summary from these local
 * points equals the summary against all points, so the values match the brute force exactly. */
#include <stdlib.h>
#include <string.h>

#include "graphs/gamma_internal.h"

/* A triangulation seen as cells of dim+1 vertices with neighbours across opposite facets. */
typedef struct cells_view {
    int dim;
    size_t count;
    const uint32_t *cell, *adj;
} cells_view;

typedef struct dt_ctx {
    const double *coords;
    size_t n;
    int dim;
    const fl_gamma_params *params;
    graph_builder *out;
    cells_view cv;
    uint32_t *root;        /* union-find over cells: cells with one common empty sphere */
    size_t *cluster_start; /* CSR over roots: the cells of each cluster */
    uint32_t *cluster_cells;
    uint32_t *stamp; /* per point: last local set it was added to */
    uint32_t epoch;
    fl_vec local; /* uint32_t: the current local point set */
} dt_ctx;

static const double *pt(const dt_ctx *c, uint32_t i)
{
    return c->coords + (size_t)i * c->dim;
}

/* Is the apex of cell u (the vertex not shared with cell t) on t's circumsphere? */
static int same_sphere(const dt_ctx *c, size_t t, size_t u)
{
    const uint32_t *a = c->cv.cell + t * (c->dim + 1), *b = c->cv.cell + u * (c->dim + 1);
    uint32_t apex = UINT32_MAX;
    for (int i = 0; i <= c->dim; i++) {
        int shared = 0;
        for (int j = 0; j <= c->dim; j++)
            shared |= b[i] == a[j];
        if (!shared) apex = b[i];
    }
    if (c->dim == 2) return fl_incircle(pt(c, a[0]), pt(c, a[1]), pt(c, a[2]), pt(c, apex)) == 0;
    return fl_insphere(pt(c, a[0]), pt(c, a[1]), pt(c, a[2]), pt(c, a[3]), pt(c, apex)) == 0;
}

static int build_clusters(dt_ctx *c)
{
    size_t m = c->cv.count, k = (size_t)c->dim + 1;
    c->root = fl_alloc_array(m, sizeof *c->root);
    c->cluster_start = fl_calloc_array(m + 1, sizeof *c->cluster_start);
    c->cluster_cells = fl_alloc_array(m, sizeof *c->cluster_cells);
    if (!c->root || !c->cluster_start || !c->cluster_cells) return -1;
    for (size_t t = 0; t < m; t++)
        c->root[t] = (uint32_t)t;
    for (size_t t = 0; t < m; t++)
        for (size_t i = 0; i < k; i++) {
            uint32_t u = c->cv.adj[t * k + i];
            if (u != UINT32_MAX && u > t && same_sphere(c, t, u))
                fl_uf_union(c->root, (uint32_t)t, u);
        }
    for (size_t t = 0; t < m; t++)
        c->cluster_start[fl_uf_find(c->root, (uint32_t)t) + 1]++;
    for (size_t t = 0; t < m; t++)
        c->cluster_start[t + 1] += c->cluster_start[t];
    size_t *fill = fl_alloc_array(m + 1, sizeof *fill);
    if (!fill) return -1;
    memcpy(fill, c->cluster_start, (m + 1) * sizeof *fill);
    for (size_t t = 0; t < m; t++)
        c->cluster_cells[fill[c->root[t]]++] = (uint32_t)t;
    free(fill);
    return 0;
}

static size_t cluster_size(const dt_ctx *c, uint32_t root)
{
    return c->cluster_start[root + 1] - c->cluster_start[root];
}

static void local_begin(dt_ctx *c)
{
    c->local.count = 0;
    if (++c->epoch == 0) { /* wrapped: forget all stamps */
        memset(c->stamp, 0, c->n * sizeof *c->stamp);
        c->epoch = 1;
    }
}

static int local_add(dt_ctx *c, uint32_t p)
{
    if (c->stamp[p] == c->epoch) return 0;
    c->stamp[p] = c->epoch;
    return fl_vec_push(&c->local, &p, 1);
}

/* Adds the vertices of cell t and, if t shares its sphere with other cells, of its cluster. */
static int local_add_cell(dt_ctx *c, uint32_t t)
{
    size_t k = (size_t)c->dim + 1;
    uint32_t r = c->root[t];
    if (cluster_size(c, r) == 1) {
        for (size_t i = 0; i < k; i++)
            if (local_add(c, c->cv.cell[t * k + i])) return -1;
        return 0;
    }
    for (size_t j = c->cluster_start[r]; j < c->cluster_start[r + 1]; j++)
        for (size_t i = 0; i < k; i++)
            if (local_add(c, c->cv.cell[(size_t)c->cluster_cells[j] * k + i])) return -1;
    return 0;
}

/* Evaluates simplex s against the current local set and keeps it when accepted. */
static int evaluate(dt_ctx *c, const uint32_t *s_in)
{
    uint32_t s[3];
    memcpy(s, s_in, (size_t)c->dim * sizeof *s);
    for (int i = 1; i < c->dim; i++) /* canonical order: the frame's rounding depends on it */
        for (int j = i; j > 0 && s[j - 1] > s[j]; j--) {
            uint32_t t = s[j];
            s[j] = s[j - 1];
            s[j - 1] = t;
        }
    gamma_frame f;
    if (!gamma_frame_init(&f, c->coords, c->dim, s)) return 0;
    gamma_summary sum;
    gamma_summary_init(&sum);
    const uint32_t *l = c->local.data;
    for (size_t i = 0; i < c->local.count; i++)
        gamma_summary_add(&sum, &f, c->coords, l[i]);
    gamma_value v;
    gamma_summary_value(&sum, &f, c->coords, &v);
    if (v.never || !v.delaunay || !gamma_params_accept(c->params, &v)) return 0;
    return graph_builder_add(c->out, s, v.c0, v.c1);
}

/* (a) every facet of the triangulation, once. */
static int triangulation_facets(dt_ctx *c)
{
    size_t k = (size_t)c->dim + 1;
    for (size_t t = 0; t < c->cv.count; t++)
        for (size_t i = 0; i < k; i++) {
            uint32_t u = c->cv.adj[t * k + i], s[3];
            if (u != UINT32_MAX && u < t) continue;
            for (size_t j = 1, m = 0; j < k; j++)
                s[m++] = c->cv.cell[t * k + (i + j) % k];
            local_begin(c);
            if (local_add_cell(c, (uint32_t)t) || (u != UINT32_MAX && local_add_cell(c, u)))
                return -1;
            if (evaluate(c, s)) return -1;
        }
    return 0;
}

/* Calls evaluate on every dim-subset of the vertex list v[0..m-1]. */
static int all_subsets(dt_ctx *c, const uint32_t *v, size_t m)
{
    uint32_t s[3];
    for (size_t a = 0; a < m; a++)
        for (size_t b = a + 1; b < m; b++) {
            s[0] = v[a];
            s[1] = v[b];
            if (c->dim == 2) {
                if (evaluate(c, s)) return -1;
                continue;
            }
            for (size_t d = b + 1; d < m; d++) {
                s[2] = v[d];
                if (evaluate(c, s)) return -1;
            }
        }
    return 0;
}

/* (b) all k-subsets of each cluster of more than one cell. */
static int cluster_chords(dt_ctx *c)
{
    size_t k = (size_t)c->dim + 1;
    fl_vec verts;
    fl_vec_init(&verts, sizeof(uint32_t));
    int rc = 0;
    for (size_t r = 0; r < c->cv.count && !rc; r++) {
        if (c->root[r] != r || cluster_size(c, (uint32_t)r) == 1) continue;
        local_begin(c);
        rc = local_add_cell(c, (uint32_t)r);
        verts.count = 0;
        rc = rc || fl_vec_push(&verts, c->local.data, c->local.count);
        for (size_t j = c->cluster_start[r]; j < c->cluster_start[r + 1] && !rc; j++)
            for (size_t i = 0; i < k && !rc; i++) {
                uint32_t u = c->cv.adj[(size_t)c->cluster_cells[j] * k + i];
                if (u != UINT32_MAX && c->root[u] != r) rc = local_add_cell(c, u);
            }
        if (!rc) rc = all_subsets(c, verts.data, verts.count);
    }
    fl_vec_free(&verts);
    return rc;
}

typedef struct hull_edge {
    uint32_t a, b, face;
} hull_edge;

static int hull_edge_cmp(const void *pa, const void *pb)
{
    const hull_edge *x = pa, *y = pb;
    if (x->a != y->a) return x->a < y->a ? -1 : 1;
    if (x->b != y->b) return x->b < y->b ? -1 : 1;
    return x->face < y->face ? -1 : x->face > y->face;
}

/* Hull face f (an index into cells' facets: cell * 4 + corner) as three vertices. */
static void hull_face(const dt_ctx *c, uint32_t f, uint32_t *v)
{
    size_t t = f / 4, i = f % 4;
    for (size_t j = 1, m = 0; j < 4; j++)
        v[m++] = c->cv.cell[t * 4 + (i + j) % 4];
}

/* Unites hull faces that share an edge and lie in one plane; `face` lists them. */
static int group_coplanar_faces(dt_ctx *c, const uint32_t *face, size_t nf, uint32_t *root)
{
    hull_edge *e = fl_alloc_array(nf, 3 * sizeof *e);
    if (!e) return -1;
    for (size_t f = 0; f < nf; f++) {
        root[f] = (uint32_t)f;
        uint32_t v[3];
        hull_face(c, face[f], v);
        for (int k = 0; k < 3; k++) {
            uint32_t a = v[k], b = v[(k + 1) % 3];
            e[3 * f + k] = (hull_edge){a < b ? a : b, a < b ? b : a, (uint32_t)f};
        }
    }
    qsort(e, 3 * nf, sizeof *e, hull_edge_cmp);
    for (size_t i = 0; i + 1 < 3 * nf; i++) {
        if (e[i].a != e[i + 1].a || e[i].b != e[i + 1].b) continue;
        uint32_t v[3], w[3], other = UINT32_MAX;
        hull_face(c, face[e[i].face], v);
        hull_face(c, face[e[i + 1].face], w);
        for (int k = 0; k < 3; k++)
            if (w[k] != e[i].a && w[k] != e[i].b) other = w[k];
        if (gamma_side3(pt(c, v[0]), pt(c, v[1]), pt(c, v[2]), pt(c, other)) == 0)
            fl_uf_union(root, e[i].face, e[i + 1].face);
    }
    free(e);
    return 0;
}

/* The local set and vertices of one coplanar group, then all its triples. */
static int hull_group(dt_ctx *c, const uint32_t *face, const uint32_t *root, size_t nf, uint32_t g,
                      fl_vec *verts)
{
    local_begin(c);
    for (size_t f = 0; f < nf; f++) {
        if (root[f] != g) continue;
        uint32_t v[3];
        hull_face(c, face[f], v);
        for (int k = 0; k < 3; k++)
            if (local_add(c, v[k])) return -1;
    }
    verts->count = 0;
    if (c->local.count < 4) return 0; /* one triangle: already a facet of the triangulation */
    if (fl_vec_push(verts, c->local.data, c->local.count)) return -1;
    for (size_t f = 0; f < nf; f++)
        if (root[f] == g && local_add_cell(c, face[f] / 4)) return -1;
    return all_subsets(c, verts->data, verts->count);
}

/* (c) triangles of points in one plane of the convex hull. */
static int hull_groups(dt_ctx *c)
{
    fl_vec faces, verts;
    fl_vec_init(&faces, sizeof(uint32_t));
    fl_vec_init(&verts, sizeof(uint32_t));
    int rc = 0;
    for (size_t t = 0; t < c->cv.count && !rc; t++)
        for (uint32_t i = 0; i < 4 && !rc; i++)
            if (c->cv.adj[t * 4 + i] == UINT32_MAX) {
                uint32_t f = (uint32_t)(t * 4 + i);
                rc = fl_vec_push(&faces, &f, 1);
            }
    uint32_t *root = rc ? NULL : fl_alloc_array(faces.count, sizeof *root);
    rc = rc || !root || group_coplanar_faces(c, faces.data, faces.count, root);
    for (size_t f = 0; f < faces.count && !rc; f++) {
        if (fl_uf_find(root, (uint32_t)f) != f) continue;
        for (size_t h = 0; h < faces.count; h++)
            root[h] = fl_uf_find(root, (uint32_t)h);
        rc = hull_group(c, faces.data, root, faces.count, (uint32_t)f, &verts);
    }
    free(root);
    fl_vec_free(&faces);
    fl_vec_free(&verts);
    return rc;
}

static int run(dt_ctx *c)
{
    c->stamp = fl_calloc_array(c->n, sizeof *c->stamp);
    fl_vec_init(&c->local, sizeof(uint32_t));
    int rc = !c->stamp || build_clusters(c) || triangulation_facets(c) || cluster_chords(c);
    if (!rc && c->dim == 3) rc = hull_groups(c);
    fl_vec_free(&c->local);
    free(c->stamp);
    free(c->root);
    free(c->cluster_start);
    free(c->cluster_cells);
    return rc;
}

/* Are a, b, p collinear? In 3D: iff all three coordinate projections are. */
static int collinear(const double *a, const double *b, const double *p, int dim)
{
    if (dim == 2) return fl_orient2d(a, b, p) == 0;
    for (int k = 0; k < 3; k++) {
        int i = (k + 1) % 3, j = (k + 2) % 3;
        double u[2] = {a[i], a[j]}, v[2] = {b[i], b[j]}, w[2] = {p[i], p[j]};
        if (fl_orient2d(u, v, w) != 0) return 0;
    }
    return 1;
}

/* Are all points on one line (2D) or plane (3D)? Decided exactly; such sets have no
 * triangulation of full dimension. Points are distinct, so points 0 and 1 span a line. */
static int flat_set(const double *coords, size_t n, int dim)
{
    if (n < (size_t)dim + 1) return 1;
    const double *a = coords, *b = coords + dim;
    size_t c = 2;
    while (c < n && collinear(a, b, coords + c * dim, dim))
        c++;
    if (c == n) return 1;
    if (dim == 2) return 0;
    for (size_t d = 2; d < n; d++)
        if (fl_orient3d(a, b, coords + c * 3, coords + d * 3) != 0) return 0;
    return 1;
}

fl_status gamma_delaunay_part(const double *coords, size_t n, int dim, const fl_gamma_params *p,
                              const fl_graph_options *opt, graph_builder *b, fl_error *err)
{
    if (flat_set(coords, n, dim))
        return gamma_brute_force(coords, n, dim, p, GAMMA_DELAUNAY_PART, opt, b, err);
    dt_ctx c;
    memset(&c, 0, sizeof c);
    c.coords = coords;
    c.n = n;
    c.dim = dim;
    c.params = p;
    c.out = b;
    fl_dt2 dt2;
    fl_dt3 dt3;
    memset(&dt2, 0, sizeof dt2);
    memset(&dt3, 0, sizeof dt3);
    fl_status st;
    if (dim == 2) {
        fl_dt2_options o = {opt ? opt->progress : NULL, opt ? opt->progress_user : NULL, 0};
        st = fl_dt2_build(coords, n, &o, &dt2, err);
        c.cv = (cells_view){2, dt2.triangle_count, dt2.tri, dt2.adj};
    } else {
        fl_dt3_options o = {opt ? opt->progress : NULL, opt ? opt->progress_user : NULL, 0};
        st = fl_dt3_build(coords, n, &o, &dt3, err);
        c.cv = (cells_view){3, dt3.tet_count, dt3.tet, dt3.adj};
    }
    if (st == FL_OK && run(&c))
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory building the γ-graph");
    fl_dt2_free(&dt2);
    fl_dt3_free(&dt3);
    return st;
}
