/* Certified Hausdorff distance between meshes or polylines, Guéziec 2001 §6: the public calls.
 *
 * Each direction h(A,B) starts from A's vertices as samples with points on B (the exact closest
 * points through one Meshsweeper cursor per direction, §5.1, or, where that cannot raise the
 * lower bound, the nearest point on nearby candidate elements), bounds every simplex of A from
 * above
 * (hausdorff_refine.c) and then refines only the simplices whose bound can still exceed the
 * current lower bound. Both directions get their vertex pass first; the one with the larger
 * lower bound is refined first (§6: "we can determine early ... which of the maximum
 * distances dominates"), so that the other one is mostly closed by the shared threshold
 * without a single split. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sweep/hausdorff_internal.h"

/* A shape as the refinement sees it: vertices lifted to 3D and k-corner simplices. */
typedef struct hd_shape {
    size_t nv;
    const double *xyz; /* nv * 3 */
    size_t ns;
    const uint32_t *idx; /* ns * k */
    int k;
} hd_shape;

static void dir_free(hd_dir *d)
{
    fl_sweep_cursor_free(d->cursor);
    fl_vec_free(&d->samples);
    fl_vec_free(&d->leaves);
    free(d->used);
    free(d->simplices);
    free(d->b_adj);
}

/* One side of an element for the adjacency: an edge (triangles) or an end (segments). */
typedef struct hd_side {
    uint32_t lo, hi, elem, slot;
} hd_side;

static int side_cmp(const void *x, const void *y)
{
    const hd_side *a = x, *b = y;
    if (a->lo != b->lo) return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi) return a->hi < b->hi ? -1 : 1;
    return (a->elem > b->elem) - (a->elem < b->elem);
}

/* Elements sharing a side are neighbours; where more than two share one (non-manifold), each
 * gets the next in the sorted run, cyclically. Only a heuristic for candidate elements. */
fl_status hd_adjacency(hd_dir *dir, const uint32_t *idx, size_t ns, fl_error *err)
{
    size_t k = (size_t)dir->k, n = ns * k;
    hd_side *sd = fl_alloc_array(n, sizeof *sd);
    dir->b_adj = fl_alloc_array(n, sizeof *dir->b_adj);
    if (!sd || !dir->b_adj) {
        free(sd);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    for (size_t e = 0; e < ns; e++)
        for (size_t i = 0; i < k; i++) {
            uint32_t a = idx[k * e + i], b = k == 3 ? idx[k * e + (i + 1) % 3] : a;
            hd_side s = {a < b ? a : b, a < b ? b : a, (uint32_t)e, (uint32_t)i};
            sd[k * e + i] = s;
            dir->b_adj[k * e + i] = FL_SWEEP_NONE;
        }
    qsort(sd, n, sizeof *sd, side_cmp);
    for (size_t i = 0, j; i < n; i = j) {
        for (j = i + 1; j < n && sd[j].lo == sd[i].lo && sd[j].hi == sd[i].hi;)
            j++;
        if (j - i < 2) continue;
        for (size_t m = i; m < j; m++) {
            const hd_side *o = sd + (m + 1 < j ? m + 1 : i);
            dir->b_adj[k * sd[m].elem + sd[m].slot] = o->elem;
        }
    }
    free(sd);
    return FL_OK;
}

/* Measures used vertex v of A into its sample slot (from the samples `near` when it can) and
 * marks it measured (used = 2); reports progress now and then. */
static fl_status measure_vertex(hd_run *run, hd_dir *d, const hd_shape *a, size_t v,
                                const uint32_t *near, int n, size_t *done, fl_error *err)
{
    hd_sample *smp = (hd_sample *)d->samples.data + v;
    fl_status st = hd_sample_near(run, d, a->xyz + 3 * v, near, n, smp, err);
    if (st) return st;
    hd_note_sample(run, d, (uint32_t)v);
    d->used[v] = 2;
    if ((++*done & 4095) == 0 && fl_progress(run->progress, run->progress_user, "hausdorff", 0))
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
    return FL_OK;
}

/* The vertex pass of one direction: A's used vertices as samples, then A's simplices with
 * their bounds. Samples 0..nv-1 are A's vertices (unused ones are placeholders). */
static fl_status dir_init(hd_run *run, hd_dir *d, const hd_shape *a, const hd_shape *bshape,
                          const fl_sweep *b, fl_error *err)
{
    d->k = a->k;
    d->dim = fl_sweep_dim(b);
    d->b_xyz = bshape->xyz;
    d->b_idx = bshape->idx;
    d->lower_sample = UINT32_MAX;
    fl_vec_init(&d->samples, sizeof(hd_sample));
    fl_vec_init(&d->leaves, sizeof(hd_simplex));
    d->used = fl_calloc_array(a->nv, sizeof *d->used);
    d->simplices = fl_alloc_array(a->ns, sizeof *d->simplices);
    fl_status st = fl_sweep_cursor_new(b, &d->cursor, err);
    if (st) return st;
    if (!d->used || !d->simplices || fl_vec_reserve(&d->samples, a->nv))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    st = hd_adjacency(d, bshape->idx, bshape->ns, err);
    if (st) return st;
    for (size_t t = 0; t < a->ns * (size_t)a->k; t++)
        d->used[a->idx[t]] = 1;
    /* Not yet samples: unused vertices stay so (they keep their position so that a kept field
     * can measure them); used ones are measured in place below. */
    for (size_t v = 0; v < a->nv; v++) {
        hd_sample none = {{0, 0, 0}, {0, 0, 0}, 0, FL_SWEEP_NONE, 0};
        memcpy(none.p, a->xyz + 3 * v, sizeof none.p);
        fl_vec_push(&d->samples, &none, 1); /* reserved above */
    }
    /* Every 8th used vertex by a cursor query, in file order (coherent, §5.1): the lower bound
     * gets near its final value. Then the rest triangle by triangle, from the elements of the
     * corners already measured (hd_sample_near): a vertex whose distance there is within the
     * lower bound needs no query, and cannot be the maximum (its true distance is at most the
     * lower bound at that time), so the vertex pass still finds the largest vertex distance. */
    size_t done = 0;
    for (size_t v = 0; st == FL_OK && v < a->nv; v += 8)
        if (d->used[v]) st = measure_vertex(run, d, a, v, NULL, 0, &done, err);
    for (size_t t = 0; st == FL_OK && t < a->ns; t++) {
        uint32_t near[3];
        int n = 0;
        for (int i = 0; st == FL_OK && i < a->k; i++) {
            uint32_t v = a->idx[(size_t)a->k * t + (size_t)i];
            if (d->used[v] == 1) st = measure_vertex(run, d, a, v, near, n, &done, err);
            near[n++] = v;
        }
    }
    d->simplex_count = a->ns;
    for (size_t t = 0; st == FL_OK && t < a->ns; t++) {
        hd_simplex *s = d->simplices + t;
        s->v[2] = 0;
        s->tried = 0;
        for (int i = 0; i < a->k; i++)
            s->v[i] = a->idx[(size_t)a->k * t + (size_t)i];
        s->upper = hd_simplex_bound(run, d, s, 0);
    }
    return st;
}

/* Largest |coordinate| and bounding-box diagonal over the used vertices of both shapes. */
static void measure_extent(const hd_shape *sh, double *scale, double *lo, double *hi)
{
    for (size_t t = 0; t < sh->ns * (size_t)sh->k; t++) {
        const double *p = sh->xyz + 3 * (size_t)sh->idx[t];
        for (int x = 0; x < 3; x++) {
            *scale = fmax(*scale, fabs(p[x]));
            lo[x] = fmin(lo[x], p[x]);
            hi[x] = fmax(hi[x], p[x]);
        }
    }
}

static fl_status check_options(const fl_hausdorff_options *o, fl_error *err)
{
    if (!(o->precision >= 0) || !(o->relative >= 0) || !(o->budget_seconds >= 0) ||
        isinf(o->precision) || isinf(o->relative) || isinf(o->budget_seconds))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "hausdorff: precision, relative and budget must be finite and >= 0");
    return FL_OK;
}

static void run_init(hd_run *run, const fl_hausdorff_options *o, const hd_shape *a,
                     const hd_shape *b)
{
    double lo[3] = {DBL_MAX, DBL_MAX, DBL_MAX}, hi[3] = {-DBL_MAX, -DBL_MAX, -DBL_MAX};
    memset(run, 0, sizeof *run);
    measure_extent(a, &run->scale, lo, hi);
    measure_extent(b, &run->scale, lo, hi);
    double diag = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                       (hi[2] - lo[2]) * (hi[2] - lo[2]));
    run->precision =
        o->precision > 0 ? o->precision : (o->relative > 0 ? o->relative : 1e-3) * diag;
    /* Below this size the rounding slack of the bound (~1e-14 of the coordinates) dominates
     * any gain from splitting further. */
    run->min_edge = fmax(1e-10 * diag, 1e-10 * run->scale);
    if (!(run->min_edge > 0)) run->min_edge = DBL_MIN;
    run->deadline = o->budget_seconds > 0 ? hd_now() + o->budget_seconds : 0;
    run->max_samples = o->max_samples ? o->max_samples : 100000000;
    run->both_directions = o->both_directions;
    run->keep_field = o->keep_field;
    run->progress = o->progress;
    run->progress_user = o->progress_user;
    run->progress_total = (double)(a->ns + b->ns);
}

static void fill_result(const hd_run *run, const hd_dir *ab, const hd_dir *ba,
                        fl_hausdorff_result *r)
{
    r->h_ab[0] = ab->lower, r->h_ab[1] = ab->upper;
    r->h_ba[0] = ba->lower, r->h_ba[1] = ba->upper;
    r->hausdorff[0] = fmax(ab->lower, ba->lower);
    r->hausdorff[1] = fmax(ab->upper, ba->upper);
    r->where_on_b = ba->lower > ab->lower;
    const hd_dir *w = r->where_on_b ? ba : ab;
    const hd_sample *s = (const hd_sample *)w->samples.data + w->lower_sample;
    memcpy(r->where[0], s->p, sizeof s->p);
    memcpy(r->where[1], s->c, sizeof s->c);
    r->samples = run->samples;
    r->precision = run->precision;
    r->reached = r->hausdorff[1] - r->hausdorff[0];
    double need = r->hausdorff[1] - r->hausdorff[0];
    if (run->both_directions) need = fmax(ab->upper - ab->lower, ba->upper - ba->lower);
    r->budget_exhausted = run->exhausted && need > run->precision;
}

/* Both directions on shapes a and b with their hierarchies sa, sb. */
static fl_status hausdorff(const hd_shape *a, const hd_shape *b, const fl_sweep *sa,
                           const fl_sweep *sb, const fl_hausdorff_options *o,
                           fl_hausdorff_result *out, fl_error *err)
{
    hd_run run;
    run_init(&run, o, a, b);
    hd_dir ab = {0}, ba = {0};
    fl_status st = dir_init(&run, &ab, a, b, sb, err);
    if (st == FL_OK) st = dir_init(&run, &ba, b, a, sa, err);
    if (st == FL_OK) {
        hd_dir *first = ab.lower >= ba.lower ? &ab : &ba, *second = first == &ab ? &ba : &ab;
        st = hd_refine(&run, first, &second->lower, err);
        if (st == FL_OK) st = hd_refine(&run, second, &first->lower, err);
    }
    if (st == FL_OK) fill_result(&run, &ab, &ba, out);
    if (st == FL_OK && o->keep_field) {
        st = hd_field_from_dir(&ab, &out->field_ab, err);
        if (st == FL_OK) st = hd_field_from_dir(&ba, &out->field_ba, err);
    }
    dir_free(&ab);
    dir_free(&ba);
    if (st == FL_OK) fl_progress(o->progress, o->progress_user, "hausdorff", 1);
    return st;
}

fl_status fl_hausdorff_meshes(const fl_mesh *a, const fl_mesh *b, const fl_hausdorff_options *opt,
                              fl_hausdorff_result *out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hausdorff: NULL result");
    memset(out, 0, sizeof *out);
    if (!a || !b) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hausdorff: NULL mesh");
    fl_hausdorff_options o = {0};
    if (opt) o = *opt;
    fl_status st = check_options(&o, err);
    if (st) return st;
    fl_sweep *sa = NULL, *sb = NULL;
    st = fl_sweep_build(a, NULL, &sa, err); /* validates A (indices, coordinates) */
    if (st == FL_OK) st = fl_sweep_build(b, NULL, &sb, err);
    if (st == FL_OK) {
        hd_shape ha = {a->vertex_count, a->xyz, a->triangle_count, a->tri, 3};
        hd_shape hb = {b->vertex_count, b->xyz, b->triangle_count, b->tri, 3};
        st = hausdorff(&ha, &hb, sa, sb, &o, out, err);
    }
    fl_sweep_free(sa);
    fl_sweep_free(sb);
    if (st) fl_hausdorff_result_free(out);
    return st;
}

/* A polyline as a shape: points lifted to 3D, segments i -> i+1 (and n-1 -> 0 if closed). */
static fl_status polyline_shape(const double *p, size_t n, int closed, int dim, hd_shape *sh,
                                double **xyz, uint32_t **idx, fl_error *err)
{
    size_t ns = closed ? n : n - 1;
    *xyz = fl_alloc_array(n, 3 * sizeof **xyz);
    *idx = fl_alloc_array(ns, 2 * sizeof **idx);
    if (!*xyz || !*idx) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    for (size_t i = 0; i < n; i++)
        for (int x = 0; x < 3; x++)
            (*xyz)[3 * i + (size_t)x] = x < dim ? p[(size_t)dim * i + (size_t)x] : 0;
    for (size_t i = 0; i < ns; i++) {
        (*idx)[2 * i] = (uint32_t)i;
        (*idx)[2 * i + 1] = (uint32_t)((i + 1) % n);
    }
    hd_shape s = {n, *xyz, ns, *idx, 2};
    *sh = s;
    return FL_OK;
}

fl_status fl_hausdorff_polylines(const double *a, size_t na, int closed_a, const double *b,
                                 size_t nb, int closed_b, int dim, const fl_hausdorff_options *opt,
                                 fl_hausdorff_result *out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hausdorff: NULL result");
    memset(out, 0, sizeof *out);
    if (!a || !b) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hausdorff: NULL polyline");
    fl_hausdorff_options o = {0};
    if (opt) o = *opt;
    fl_status st = check_options(&o, err);
    if (st) return st;
    fl_sweep *sa = NULL, *sb = NULL;
    double *xa = NULL, *xb = NULL;
    uint32_t *ia = NULL, *ib = NULL;
    hd_shape ha, hb;
    st = fl_sweep_polyline_build(a, na, dim, closed_a, NULL, &sa, err); /* validates */
    if (st == FL_OK) st = fl_sweep_polyline_build(b, nb, dim, closed_b, NULL, &sb, err);
    if (st == FL_OK) st = polyline_shape(a, na, closed_a, dim, &ha, &xa, &ia, err);
    if (st == FL_OK) st = polyline_shape(b, nb, closed_b, dim, &hb, &xb, &ib, err);
    if (st == FL_OK) st = hausdorff(&ha, &hb, sa, sb, &o, out, err);
    free(xa);
    free(xb);
    free(ia);
    free(ib);
    fl_sweep_free(sa);
    fl_sweep_free(sb);
    if (st) fl_hausdorff_result_free(out);
    return st;
}

void fl_hausdorff_result_free(fl_hausdorff_result *r)
{
    if (!r) return;
    fl_hausdorff_field *f[2] = {&r->field_ab, &r->field_ba};
    for (int i = 0; i < 2; i++) {
        fl_mesh_free(&f[i]->mesh);
        free(f[i]->distance);
        memset(f[i], 0, sizeof *f[i]);
    }
}
