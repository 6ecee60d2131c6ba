/* Fuzzes fl_sweep_build / fl_sweep_polyline_build + fl_sweep_closest on small decoded shapes
 * (meshes of up to 12 vertices and 16 triangles of any topology, 2D/3D polylines of up to 16
 * points) and up to 8 queries; meshes also through the edge-collapse hierarchy and key frames
 * (fl_sweep_keyframes_*), polylines also moved by fl_sweep_polyline_update
 * (fl_sweep_collapse_*: same input rules, same answers). Oracle: the exact answer's distance equals the brute-force
 * minimum over all elements (tests/sweep/sweep_oracle.h, long double, independent code) to a
 * relative 1e-9; inputs beyond the documented |x| <= 1e150 or NaN/Inf must be FL_ERR_INPUT
 * (build) or FL_ERR_USAGE (query). */
#include "fuzz_common.h"
#include "sweep/sweep_oracle.h"

static int out_of_range(const double *c, size_t count, double *maxabs)
{
    int bad = 0;
    for (size_t i = 0; i < count; i++) {
        if (!(fabs(c[i]) <= 1e150)) bad = 1;
        else *maxabs = fmax(*maxabs, fabs(c[i]));
    }
    return bad;
}

/* Every answer against the brute-force minimum over all elements. */
static void check_answers(const fl_closest *res, const double *q, size_t nq, int dim, double tol,
                          double qmax, int kind, const double *pts3, const uint32_t *tri,
                          size_t nv, size_t elements)
{
    for (size_t k = 0; k < nq; k++) {
        double p[3] = {q[dim * k], q[dim * k + 1], dim == 3 ? q[dim * k + 2] : 0};
        ld best = INFINITY;
        for (size_t e = 0; e < elements; e++) {
            ld d = kind == 0 ? oracle_mesh_element(pts3, tri, e, p)
                             : oracle_polyline_element(pts3, nv, e, p);
            if (d < best) best = d;
        }
        /* Squared distances underflow below ~1e-154 (found by this target: distance 0 for a
         * true 2e-300), so that is the absolute resolution. */
        double slack = 1e-9 * (qmax + (double)best) + 1e-150;
        if (res[k].exact) {
            FZ_ASSERT(fabsl((ld)res[k].distance - best) <= slack,
                      "query %zu: distance %.17g, brute force %.17Lg", k, res[k].distance, best);
        } else {
            FZ_ASSERT(tol > 0 && res[k].upper - res[k].lower <= tol * (1 + 1e-12),
                      "inexact answer wider than the tolerance");
            FZ_ASSERT(res[k].lower <= best + slack && best <= res[k].upper + slack,
                      "query %zu: [%.17g, %.17g] misses %.17Lg", k, res[k].lower, res[k].upper,
                      best);
        }
    }
}

/* Moving shapes (docs/sweep.md "Moving shapes"): the shape moves to a second decoded position,
 * a mesh through two key frames to a decoded time, a polyline by fl_sweep_polyline_update;
 * out-of-range positions must be FL_ERR_INPUT, otherwise the answers equal brute force on the
 * moved shape. */
static void check_motion(fz_in *in, int kind, int dim, int closed, const double *pts,
                         const uint32_t *tri, size_t nv, size_t nt, double qmax, fl_sweep *sw)
{
    double moved[3 * 16], frames[2 * 3 * 16], now3[3 * 16], q[3 * 8];
    size_t count = (size_t)dim * nv, nq = fz_byte(in) % 9;
    fz_coords(in, moved, count);
    double t = fz_byte(in) / 255.0, mmax = 0;
    int bad = out_of_range(moved, count, &mmax);
    fz_coords(in, q, (size_t)dim * nq);
    int qbad = out_of_range(q, (size_t)dim * nq, &mmax);
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_sweep_keyframes *kf = NULL;
    const fl_sweep *use = sw;
    fl_status st;
    if (kind == 0) {
        memcpy(frames, pts, count * sizeof *pts);
        memcpy(frames + count, moved, count * sizeof *pts);
        fl_mesh m = {nv, (double *)pts, nt, (uint32_t *)tri};
        st = fl_sweep_keyframes_new(&m, frames, 2, NULL, &kf, &err);
        if (st == FL_OK) st = fl_sweep_keyframes_set_time(kf, t, &err);
        if (st == FL_OK) st = fl_sweep_keyframes_vertices(kf, now3, &err);
        use = fl_sweep_keyframes_sweep(kf);
    } else {
        st = fl_sweep_polyline_update(sw, moved, &err);
        for (size_t i = 0; i < nv; i++)
            for (int c = 0; c < 3; c++)
                now3[3 * i + c] = c < dim ? moved[(size_t)dim * i + c] : 0;
    }
    fz_check_status(st, &err, "moving shape");
    FZ_ASSERT(bad ? st == FL_ERR_INPUT : st == FL_OK, "moving shape gave %d: %s", (int)st,
              err.message);
    if (st == FL_OK && !qbad) {
        fl_closest res[8];
        st = fl_sweep_closest(use, q, nq, 0, res, &err);
        FZ_ASSERT(st == FL_OK, "closest on the moved shape failed: %s", err.message);
        size_t elements = kind == 0 ? nt : closed ? nv : nv - 1;
        check_answers(res, q, nq, dim, 0, fmax(qmax, mmax), kind, now3, tri, nv, elements);
    }
    fl_sweep_keyframes_free(kf);
}

/* §4.4 on the collapse hierarchy, first query: the k nearest are as many as min(k, triangles),
 * sorted, each at its brute-force distance, the first at the brute-force minimum; the hits
 * within the k-th distance are within it. */
static void collapse_neighbours(const fl_sweep_collapse *col, const double *q, double qmax,
                                const double *pts3, const uint32_t *tri, size_t nt)
{
    uint32_t el[4];
    double d[4];
    size_t n = 0;
    fl_error err;
    fl_status st = fl_sweep_collapse_knearest(col, q, 4, el, d, &n, &err);
    fz_check_status(st, &err, "fl_sweep_collapse_knearest");
    FZ_ASSERT(st == FL_OK && n == (nt < 4 ? nt : 4), "collapse knearest: status %d, %zu found",
              (int)st, n);
    ld best = INFINITY;
    for (size_t e = 0; e < nt; e++) {
        ld x = oracle_mesh_element(pts3, tri, e, q);
        if (x < best) best = x;
    }
    double slack = 1e-9 * (qmax + (double)best) + 1e-150; /* as check_answers */
    for (size_t i = 0; i < n; i++) {
        FZ_ASSERT(el[i] < nt, "collapse knearest: element %u", el[i]);
        ld bf = oracle_mesh_element(pts3, tri, el[i], q);
        FZ_ASSERT(fabsl((ld)d[i] - bf) <= slack, "collapse knearest %zu: %.17g, brute %.17Lg", i,
                  d[i], bf);
        FZ_ASSERT(i > 0 || fabsl((ld)d[0] - best) <= slack, "collapse knearest: not the nearest");
        FZ_ASSERT(i == 0 || d[i] >= d[i - 1] - slack, "collapse knearest: not sorted");
    }
    if (n == 0) return;
    fl_sweep_hits hits = {0};
    st = fl_sweep_collapse_within(col, q, d[n - 1], &hits, &err);
    fz_check_status(st, &err, "fl_sweep_collapse_within");
    FZ_ASSERT(st == FL_OK && hits.count >= 1, "collapse within: status %d, %zu hits", (int)st,
              hits.count);
    for (size_t i = 0; i < hits.count; i++)
        FZ_ASSERT(hits.distance[i] <= d[n - 1], "collapse within: hit beyond the radius");
    fl_sweep_hits_free(&hits);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    uint8_t head = fz_byte(&in);
    int kind = head % 3; /* 0 mesh, 1 polyline 2D, 2 polyline 3D */
    int closed = (head >> 2) & 1;
    double pts[3 * 16], pts3[3 * 16];
    uint32_t tri[3 * 16];
    size_t nv, nt = 0;
    double maxabs = 0;
    int bad;
    fl_sweep *sw = NULL;
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st;
    int dim = kind == 1 ? 2 : 3;
    if (kind == 0) {
        nv = 1 + fz_byte(&in) % 12;
        nt = fz_byte(&in) % 17;
        fz_coords(&in, pts, 3 * nv);
        for (size_t i = 0; i < 3 * nt; i++) tri[i] = fz_byte(&in) % nv;
        bad = out_of_range(pts, 3 * nv, &maxabs) || nt == 0;
        fl_mesh m = {nv, pts, nt, tri};
        st = fl_sweep_build(&m, NULL, &sw, &err);
    } else {
        nv = fz_byte(&in) % 17;
        fz_coords(&in, pts, (size_t)dim * nv);
        bad = out_of_range(pts, (size_t)dim * nv, &maxabs) || nv < 2;
        st = fl_sweep_polyline_build(pts, nv, dim, closed, NULL, &sw, &err);
    }
    fz_check_status(st, &err, "fl_sweep_build");
    if (st != FL_OK) {
        FZ_ASSERT(bad, "valid shape rejected: %s", err.message);
        FZ_ASSERT(st == FL_ERR_INPUT, "bad shape gave %d: %s", (int)st, err.message);
        FZ_ASSERT(sw == NULL, "*out not NULL on failure");
        return 0;
    }
    FZ_ASSERT(!bad, "out-of-range shape accepted");
    FZ_ASSERT(fl_sweep_dim(sw) == dim, "dim");
    for (size_t i = 0; i < nv; i++) { /* 3D layout for the oracle */
        pts3[3 * i] = pts[dim * i];
        pts3[3 * i + 1] = pts[dim * i + 1];
        pts3[3 * i + 2] = dim == 3 ? pts[3 * i + 2] : 0;
    }
    size_t elements = kind == 0 ? nt : closed ? nv : nv - 1;
    FZ_ASSERT(fl_sweep_element_count(sw) == elements, "element count");
    double q[3 * 8];
    size_t nq = fz_byte(&in) % 9;
    fz_coords(&in, q, (size_t)dim * nq);
    double qmax = maxabs;
    int qbad = out_of_range(q, (size_t)dim * nq, &qmax);
    fl_closest res[8];
    double tol = (head & 8) ? 0.0 : 0.25;
    st = fl_sweep_closest(sw, q, nq, tol, res, &err);
    fz_check_status(st, &err, "fl_sweep_closest");
    if (qbad) {
        FZ_ASSERT(st == FL_ERR_USAGE, "bad query gave %d", (int)st);
    } else {
        FZ_ASSERT(st == FL_OK, "closest failed: %s", err.message);
        check_answers(res, q, nq, dim, tol, qmax, kind, pts3, tri, nv, elements);
    }
    if (kind == 0) { /* the edge-collapse hierarchy: accepts what fl_sweep_build accepts */
        fl_mesh m = {nv, pts, nt, tri};
        fl_sweep_collapse *col = NULL;
        st = fl_sweep_collapse_build(&m, NULL, &col, &err);
        fz_check_status(st, &err, "fl_sweep_collapse_build");
        FZ_ASSERT(st == FL_OK, "collapse build failed where the spatial one did not: %s",
                  err.message);
        st = fl_sweep_collapse_closest(col, q, nq, tol, res, &err);
        fz_check_status(st, &err, "fl_sweep_collapse_closest");
        if (qbad) {
            FZ_ASSERT(st == FL_ERR_USAGE, "collapse: bad query gave %d", (int)st);
        } else {
            FZ_ASSERT(st == FL_OK, "collapse closest failed: %s", err.message);
            check_answers(res, q, nq, dim, tol, qmax, kind, pts3, tri, nv, elements);
            if (nq > 0) collapse_neighbours(col, q, qmax, pts3, tri, nt);
        }
        fl_sweep_collapse_free(col);
    }
    check_motion(&in, kind, dim, closed, pts, tri, nv, nt, fmax(qmax, maxabs), sw);
    fl_sweep_free(sw);
    return 0;
}
