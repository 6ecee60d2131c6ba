/* FL_G1_AUTO: the three-split (§9.6) where it is G1, the six-split (§9.8) where it is not.
 *
 * Why the choice is made per connected component and not per triangle: along a three-split
 * macro edge the boundary is one cubic and both micro patches' cross derivatives are
 * quadratics tied by eq. 9.4 (linear multipliers over the whole edge); along a six-split edge
 * it is two cubics joined C1 at a split point that step 5 moves, with one system per half-edge
 * whose end triple at the split point is searched (docs/smooth.md, "Six-split"). A mixed edge
 * would need the six-split side's two halves to be the three-split cubic subdivided at the
 * split ratio (fixing m and Y_A, two of step 5's unknowns) and the three-split side's single
 * inner point to satisfy both halves' conditions at once: a new joint system the thesis does
 * not give, and which we have not derived. Components do not touch, so choosing per component
 * leaves no seam to prove; the price is that one bad edge puts its whole component on the
 * six-split (whose reflection lines wiggle more on smooth meshes, docs/smooth.md).
 *
 * The decision is measured, not predicted: both schemes are built and their normal jumps along
 * every micro and macro edge sampled (a fold, or eq. 9.3a without solution, also disqualifies);
 * where both are G1 the one with the smaller max deviation from the mesh is kept (issue #11:
 * on CGAL's elephant.off the G1 three-split strays 30.5 mean edge lengths, the six-split
 * 13.6), the three-split on a tie. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "smooth/smooth_internal.h"

enum { AUTO_SAMPLES = 32 }; /* 33 points a patch edge: the test oracle's density */
static const double auto_g1_deg = 1e-7;

/* G1 and interpolating: the three-split can fold a patch over a vertex (its normal there
 * reversed: max_normal_error 2 on CGAL's hand.off and 3torus.off) */
static int is_g1(const fl_g1_metrics *m)
{
    return m->orientation_flips == 0 && m->max_edge_normal_jump_deg < auto_g1_deg &&
           m->max_normal_error < 1e-9 && m->max_vertex_error < 1e-9;
}

/* a measures strictly better than b: G1 first, then fewer folds, then a jump smaller by an
 * order of magnitude (NaN is worst); otherwise the earlier candidate (the three-split, the
 * requested weighting) stays: on CGAL's torus_quad.off the inverse weighting's 6.43e-7 degrees
 * against area's 6.51e-7 came with 6 times the deviation. */
static int better(const fl_g1_metrics *a, const fl_g1_metrics *b)
{
    if (is_g1(a) != is_g1(b)) return is_g1(a);
    if (a->orientation_flips != b->orientation_flips)
        return a->orientation_flips < b->orientation_flips;
    double ja = a->max_edge_normal_jump_deg, jb = b->max_edge_normal_jump_deg;
    if (isnan(jb)) return !isnan(ja);
    return floor(log10(ja)) < floor(log10(jb));
}

/* Builds one scheme and measures its edges; *ok = 0 when the scheme itself failed with
 * FL_ERR_ALGORITHM (another scheme may still work), other failures are returned. */
static fl_status try_scheme(const fl_mesh *m, const fl_g1_surface_options *o, int scheme,
                            fl_g1_surface *s, fl_g1_metrics *met, int *ok, fl_error *err)
{
    fl_g1_surface_options so = *o;
    so.scheme = scheme;
    memset(met, 0, sizeof *met);
    *ok = 0;
    fl_status st = g1_build_checked(m, &so, s, err);
    if (st == FL_ERR_ALGORITHM) {
        fl_g1_surface_free(s);
        return FL_OK;
    }
    if (!st) st = g1_measure_edges(s, AUTO_SAMPLES, met, err);
    if (!st) g1_measure_vertices(s, m, met);
    if (st) {
        fl_g1_surface_free(s);
        return st;
    }
    *ok = 1;
    return FL_OK;
}

/* Where both schemes are G1, the one nearer the mesh: max deviation on a grid of this many
 * segments a patch edge (exact closest points). On CGAL's elephant.off the three-split is G1
 * but 30.5 mean edge lengths away where the six-split is 13.6 (docs/smooth.md, "Auto"). */
enum { AUTO_DEVIATION_SAMPLES = 4 };

/* Replaces *s by c (freeing the old one) and records the choice. */
static void keep(fl_g1_surface *s, fl_g1_surface *c, int six, size_t nt, fl_g1_metrics *best,
                 const fl_g1_metrics *cm)
{
    fl_g1_surface_free(s);
    *s = *c;
    memset(c, 0, sizeof *c);
    s->six_split_triangles = six ? nt : 0;
    *best = *cm;
}

/* Both G1 with the same weighting: keeps in *s the one with the smaller max deviation from the
 * mesh (the three-split, already in *s, on a tie or NaN). */
static fl_status keep_nearer(const fl_mesh *m, fl_g1_surface *s, fl_g1_surface *six,
                             fl_error *err)
{
    fl_g1_metrics d3 = {0}, d6 = {0};
    fl_status st = g1_measure_deviation(s, m, AUTO_DEVIATION_SAMPLES, &d3, err);
    if (!st) st = g1_measure_deviation(six, m, AUTO_DEVIATION_SAMPLES, &d6, err);
    if (!st && d6.max_deviation < d3.max_deviation) {
        fl_g1_surface_free(s);
        *s = *six;
        memset(six, 0, sizeof *six);
        s->six_split_triangles = m->triangle_count;
    }
    fl_g1_surface_free(six);
    return st;
}

/* The auto choice on one connected mesh: the three-split and the six-split, with the
 * requested normal weighting and then with the other two (§9.4 methods 1-3: a different
 * estimate changes which edges are nearly dependent; on CGAL's rotor.off the six-split is
 * G1 with the uniform and inverse weightings, not with area). The first weighting with a G1
 * scheme decides: if both are G1 the one nearer the mesh (keep_nearer), else the G1 one; with
 * no G1 scheme at all, the best measured. */
static fl_status build_component(const fl_mesh *m, const fl_g1_surface_options *o,
                                 fl_g1_surface *s, fl_error *err)
{
    static const int order[4][3] = {
        {FL_G1_WEIGHT_SIZE, FL_G1_WEIGHT_UNIFORM, FL_G1_WEIGHT_INVERSE},
        {FL_G1_WEIGHT_SIZE, FL_G1_WEIGHT_UNIFORM, FL_G1_WEIGHT_INVERSE},
        {FL_G1_WEIGHT_UNIFORM, FL_G1_WEIGHT_SIZE, FL_G1_WEIGHT_INVERSE},
        {FL_G1_WEIGHT_INVERSE, FL_G1_WEIGHT_SIZE, FL_G1_WEIGHT_UNIFORM}};
    static const int schemes[2] = {FL_G1_THREE_SPLIT, FL_G1_SIX_SPLIT};
    fl_g1_metrics best = {0};
    int have = 0;
    for (int w = 0; w < 3; w++)
        for (int k = 0; k < 2; k++) {
            fl_g1_surface_options ow = *o;
            ow.weighting = order[o->weighting][w];
            fl_g1_surface c = {0};
            fl_g1_metrics cm;
            int ok;
            fl_status st = try_scheme(m, &ow, schemes[k], &c, &cm, &ok, err);
            if (st) {
                fl_g1_surface_free(s);
                return st;
            }
            if (!ok) continue;
            /* *s is this weighting's G1 three-split: compare deviations */
            if (k == 1 && have && is_g1(&best) && is_g1(&cm)) {
                st = keep_nearer(m, s, &c, err);
                if (st) fl_g1_surface_free(s);
                return st;
            }
            if (have && !better(&cm, &best)) {
                fl_g1_surface_free(&c);
                if (k == 1 && is_g1(&best)) return FL_OK;
                continue;
            }
            keep(s, &c, k == 1, m->triangle_count, &best, &cm);
            have = 1;
            if (k == 1 && is_g1(&best)) return FL_OK;
        }
    if (!have)
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                       "auto: neither the three-split nor the six-split could be built");
    return FL_OK;
}

/* Component of every vertex (root = smallest vertex index, fl_uf) and the number of them. */
static uint32_t *vertex_components(const fl_mesh *m, size_t *count)
{
    uint32_t *root = fl_alloc_array(m->vertex_count, sizeof *root);
    if (!root) return NULL;
    for (size_t v = 0; v < m->vertex_count; v++)
        root[v] = (uint32_t)v;
    for (size_t t = 0; t < m->triangle_count; t++) {
        fl_uf_union(root, m->tri[3 * t], m->tri[3 * t + 1]);
        fl_uf_union(root, m->tri[3 * t], m->tri[3 * t + 2]);
    }
    *count = 0;
    for (size_t v = 0; v < m->vertex_count; v++)
        *count += fl_uf_find(root, (uint32_t)v) == v;
    return root;
}

/* The triangles of component c as a mesh of their own; vmap/tmap: local -> global index.
 * (The mesh is closed and manifold, so vertex-connected components are edge-connected.) */
static fl_status extract(const fl_mesh *m, const uint32_t *root, uint32_t c, fl_mesh *sub,
                         uint32_t *local, uint32_t *vmap, uint32_t *tmap)
{
    size_t nv = 0, nt = 0;
    for (size_t v = 0; v < m->vertex_count; v++)
        if (root[v] == c) {
            local[v] = (uint32_t)nv;
            vmap[nv++] = (uint32_t)v;
        }
    for (size_t t = 0; t < m->triangle_count; t++)
        if (root[m->tri[3 * t]] == c) tmap[nt++] = (uint32_t)t;
    sub->vertex_count = nv;
    sub->triangle_count = nt;
    sub->xyz = fl_alloc_array(nv, 3 * sizeof(double));
    sub->tri = fl_alloc_array(nt, 3 * sizeof(uint32_t));
    if (!sub->xyz || !sub->tri) return FL_ERR_NOMEM;
    for (size_t i = 0; i < nv; i++)
        memcpy(sub->xyz + 3 * i, m->xyz + 3 * (size_t)vmap[i], 3 * sizeof(double));
    for (size_t i = 0; i < nt; i++)
        for (int k = 0; k < 3; k++)
            sub->tri[3 * i + k] = local[m->tri[3 * (size_t)tmap[i] + k]];
    return FL_OK;
}

/* Appends component surface c (local numbering) to s from patch *np and node *nn on. */
static fl_status append(fl_g1_surface *s, const fl_g1_surface *c, const uint32_t *vmap,
                        const uint32_t *tmap, size_t *np, size_t *nn)
{
    size_t p0 = *np;
    void *ctrl = realloc(s->ctrl, (p0 + c->patch_count) * 30 * sizeof(double));
    if (ctrl) s->ctrl = ctrl;
    void *corner = realloc(s->corner, (p0 + c->patch_count) * 3 * sizeof(uint32_t));
    if (corner) s->corner = corner;
    void *macro = realloc(s->macro, (p0 + c->patch_count) * sizeof(uint32_t));
    if (macro) s->macro = macro;
    if (!ctrl || !corner || !macro) return FL_ERR_NOMEM;
    memcpy(s->ctrl + 30 * p0, c->ctrl, c->patch_count * 30 * sizeof(double));
    for (size_t p = 0; p < c->patch_count; p++) {
        s->macro[p0 + p] = tmap[c->macro[p]];
        for (int k = 0; k < 3; k++) {
            uint32_t n = c->corner[3 * p + k];
            s->corner[3 * (p0 + p) + k] =
                n < c->vertex_count ? vmap[n] : (uint32_t)(*nn + (n - c->vertex_count));
        }
    }
    for (size_t v = 0; v < c->vertex_count; v++)
        memcpy(s->normal + 3 * (size_t)vmap[v], c->normal + 3 * v, 3 * sizeof(double));
    *np += c->patch_count;
    *nn += c->node_count - c->vertex_count;
    s->orientation_repairs += c->orientation_repairs;
    s->orientation_failures += c->orientation_failures;
    s->singular_edges += c->singular_edges;
    s->quadratic_edges += c->quadratic_edges;
    s->six_split_triangles += c->six_split_triangles;
    return FL_OK;
}

fl_status g1_auto_build(const fl_mesh *m, const fl_g1_surface_options *o, fl_g1_surface *s,
                        fl_error *err)
{
    size_t ncomp = 0;
    uint32_t *root = vertex_components(m, &ncomp);
    if (!root) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    if (ncomp == 1) {
        free(root);
        return build_component(m, o, s, err);
    }
    uint32_t *local = fl_alloc_array(m->vertex_count, sizeof *local);
    uint32_t *vmap = fl_alloc_array(m->vertex_count, sizeof *vmap);
    uint32_t *tmap = fl_alloc_array(m->triangle_count, sizeof *tmap);
    s->vertex_count = m->vertex_count;
    s->normal = fl_alloc_array(m->vertex_count, 3 * sizeof(double));
    fl_status st = local && vmap && tmap && s->normal ? FL_OK : FL_ERR_NOMEM;
    size_t np = 0, nn = m->vertex_count;
    for (size_t c = 0; !st && c < m->vertex_count; c++) {
        if (root[c] != c) continue;
        fl_mesh sub = {0};
        fl_g1_surface cs = {0};
        st = extract(m, root, (uint32_t)c, &sub, local, vmap, tmap);
        if (!st) st = build_component(&sub, o, &cs, err);
        if (!st) st = append(s, &cs, vmap, tmap, &np, &nn);
        fl_g1_surface_free(&cs);
        fl_mesh_free(&sub);
    }
    s->patch_count = np;
    s->node_count = nn;
    free(root);
    free(local);
    free(vmap);
    free(tmap);
    if (st == FL_ERR_NOMEM) return fl_fail(err, st, NULL, -1, "out of memory");
    return st;
}
