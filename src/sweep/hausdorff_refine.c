/* Certified Hausdorff distance, Guéziec 2001 §6: the upper bound of a simplex of A from the
 * closest points of its corners, and the refinement that splits only the simplices whose bound
 * can still exceed the current lower bound.
 *
 * The upper bound (docs/hausdorff.md has the full proof). Let the corners p_0..p_{k-1} of a
 * simplex s of A (k = 3 triangle, k = 2 segment) have points c_i on B (their closest points,
 * or for candidate-only samples some point of B) at distances d_i = |p_i - c_i|, computed on
 * elements t_i of B. A point of s is x = sum_i l_i p_i with barycentrics l_i >= 0 summing to
 * 1, and d(x, B) <= min_i |x - c_i| because every c_i lies on B. §6 / Fig. 9 bounds that
 * minimum exactly by cutting s with the bisector planes of the c_i. We use a relaxation of it
 * and a bound through B's elements, which need no bisector construction (so no fragile
 * intersection points whose rounding would have to be bounded) and have closed forms:
 *
 *  (1) Mean-square bound. A minimum is at most any weighted mean, so
 *        d(x, B)^2 <= sum_i l_i |x - c_i|^2 = sum_i l_i d_i^2 + sum_{i<j} l_i l_j k_ij,
 *        k_ij = 2 (c_i - c_j).(p_i - p_j) - |p_i - p_j|^2
 *      (expand x - c_i = (p_i - c_i) + (x - p_i); the cross terms pair up because
 *      sum_i l_i (x - p_i) = 0, and sum_i l_i |x - p_i|^2 = sum_{i<j} l_i l_j |p_i - p_j|^2).
 *      With K = max(0, max k_ij) and sum_{i<j} l_i l_j = (1 - sum_i l_i^2) / 2, the dual
 *      bound of mean_square_bound() holds for every real mu (max a_i + K/3 at worst). For a
 *      simplex of size h the excess over max d_i is O(h^2 / d) where the c_i are close (Fig.
 *      9's first case) — the order of the bisector bound — and O(h |c_i - c_j| / d) across a
 *      bisector.
 *  (3) Fixed-element bound (fixed_element_bound). For any element t of B, d(x, B) <= d(x, t),
 *      which is convex in x (distance to a convex set): its maximum over s is at a corner, so
 *      max_i d(p_i, t) bounds s. Tried for the corners' own elements. It contains the earlier
 *      same-element bound (2) (all c_i on t: d(p_i, t) <= d_i) and also closes pieces that
 *      straddle an edge of B: what counts is the overshoot past the edge, not the piece size.
 *
 * Rounding. Every quantity is a short sum of products of coordinate differences; its
 * absolute error is a few ulps of the sum of the magnitudes of its terms. The bound adds
 * 32 ulps of those magnitudes to the squared bound, then 8 ulps relative and 128 ulps of the
 * largest coordinate absolute (c_i itself is a rounded point of B). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "sweep/hausdorff_internal.h"
#include "sweep/sweep_internal.h"

#define HD_ULP 1.1102230246251565e-16

double hd_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double dist2(const double *a, const double *b)
{
    double s = 0;
    for (int x = 0; x < 3; x++)
        s += (a[x] - b[x]) * (a[x] - b[x]);
    return s;
}

/* The sample at p by a cursor query: exact. */
static fl_status query_sample(hd_run *run, hd_dir *dir, const double *p, hd_sample *smp,
                              fl_error *err)
{
    fl_closest r;
    fl_status st = fl_sweep_cursor_closest(dir->cursor, p, 0.0, &r, err);
    if (st) return st;
    memcpy(smp->p, p, sizeof smp->p);
    memcpy(smp->c, r.point, sizeof smp->c);
    if (dir->dim == 2) smp->p[2] = smp->c[2] = 0;
    smp->d = sqrt(dist2(smp->p, smp->c));
    smp->elem = r.element;
    smp->exact = 1;
    run->samples++;
    return FL_OK;
}

void hd_note_sample(hd_run *run, hd_dir *dir, uint32_t index)
{
    const hd_sample *smp = (const hd_sample *)dir->samples.data + index;
    if (!smp->exact) return;
    /* The true d(p, B) is at least the measured one minus its rounding (the sweep's own
     * slack is 64 ulps of the coordinates; p is itself a rounded point of A). */
    double lower = fmax(0.0, smp->d - 128 * HD_ULP * run->scale);
    if (lower > dir->lower || dir->lower_sample == UINT32_MAX) {
        dir->lower = fmax(dir->lower, lower);
        dir->lower_sample = index;
    }
}

fl_status hd_measure(hd_run *run, hd_dir *dir, const double *p, uint32_t *index, fl_error *err)
{
    if (dir->samples.count >= UINT32_MAX)
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hausdorff: more than 2^32 samples");
    hd_sample smp;
    fl_status st = query_sample(run, dir, p, &smp, err);
    if (st) return st;
    if (fl_vec_push(&dir->samples, &smp, 1))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    *index = (uint32_t)(dir->samples.count - 1);
    hd_note_sample(run, dir, *index);
    return FL_OK;
}

/* Distance from p to element e of B (triangle, or segment for polylines), as computed; the
 * computed closest point is within tau of the element (same rounding as the sweep's own). */
static double element_closest(const hd_dir *dir, const double *p, uint32_t e, double *q)
{
    const uint32_t *v = dir->b_idx + (size_t)dir->k * e;
    double bary[3], d2;
    if (dir->k == 3)
        d2 = fl_sweep_triangle_closest(p, dir->b_xyz + 3 * (size_t)v[0],
                                       dir->b_xyz + 3 * (size_t)v[1], dir->b_xyz + 3 * (size_t)v[2],
                                       bary, q);
    else
        d2 = fl_sweep_segment_closest(p, dir->b_xyz + 3 * (size_t)v[0],
                                      dir->b_xyz + 3 * (size_t)v[1], bary, q);
    return sqrt(d2);
}

static double element_distance(const hd_dir *dir, const double *p, uint32_t e)
{
    double q[3];
    return element_closest(dir, p, e, q);
}

/* Bound (3), the fixed-element bound: for one element t of B, d(x, B) <= d(x, t), and
 * x -> d(x, t) is convex (the distance to a convex set), so over the simplex its maximum is
 * at a corner: max_{x in s} d(x, B) <= max_i d(p_i, t). Every element t gives a valid bound;
 * this is the smallest over `cand` (n candidates), stopping a candidate as soon as one corner
 * exceeds `best` (the bound to beat). Returns the largest computed corner distance of the best
 * candidate, or INFINITY when none beats `best`. Rounding (added by the caller): the computed
 * closest point q is within tau of t, and |p - q| is computed to a few ulps. This contains
 * bound (2): when every c_i lies on t, d(p_i, t) <= d_i. For a corner whose own sample point
 * c_i was computed on t, d_i = |p_i - c_i| is used: d(p_i, t) <= d_i + d(c_i, t), the same
 * tau. */
static double fixed_element_bound(const hd_dir *dir, const hd_sample *const *c,
                                  const uint32_t *cand, int n, double best)
{
    double found = INFINITY;
    for (int j = 0; j < n; j++) {
        uint32_t e = cand[j];
        int seen = e == FL_SWEEP_NONE;
        for (int i = 0; i < j && !seen; i++)
            seen = cand[i] == e;
        if (seen) continue;
        double m = 0;
        for (int i = 0; i < dir->k && m < best; i++) /* own element: c_i is its point there */
            m = fmax(m, c[i]->elem == e ? c[i]->d : element_distance(dir, c[i]->p, e));
        if (m < best) best = found = m;
    }
    return found;
}

/* A bound from a computed corner distance m to one element: tau for the rounded closest point,
 * 8 ulps relative for |p - q| and its square root, 128 ulps of the coordinates absolute (the
 * corners are themselves rounded midpoints). */
static double element_bound(const hd_run *run, double m, double tau)
{
    return (m + tau) * (1 + 8 * HD_ULP) + 128 * HD_ULP * run->scale;
}

static double max_corner_distance(const hd_dir *dir, const hd_simplex *s, const hd_sample **c)
{
    const hd_sample *smp = dir->samples.data;
    double maxd = 0;
    for (int i = 0; i < dir->k; i++) {
        c[i] = smp + s->v[i];
        maxd = fmax(maxd, c[i]->d);
    }
    return maxd;
}

fl_status hd_try_centroid_element(hd_run *run, hd_dir *dir, hd_simplex *s, fl_error *err)
{
    const hd_sample *c[3];
    double y[3] = {0, 0, 0};
    max_corner_distance(dir, s, c);
    for (int i = 0; i < dir->k; i++)
        for (int x = 0; x < 3; x++)
            y[x] += c[i]->c[x] / dir->k;
    s->tried = 1;
    fl_closest r;
    fl_status st = fl_sweep_cursor_closest(dir->cursor, y, 0.0, &r, err);
    if (st) return st;
    run->samples++;
    double tau = 256 * HD_ULP * run->scale;
    double m = fixed_element_bound(dir, c, &r.element, 1, INFINITY);
    if (m < INFINITY) s->upper = fmin(s->upper, element_bound(run, m, tau));
    return FL_OK;
}

/* Bound (1) on max over the simplex of sum_i l_i a_i + K sum_{i<j} l_i l_j (a_i = d_i^2):
 * since sum_{i<j} l_i l_j = (1 - sum_i l_i^2) / 2 for weights summing to 1, for any real mu
 *   Q <= sum_i (l_i (a_i - mu) - K l_i^2 / 2) + mu + K/2
 *     <= sum_i max(0, a_i - mu)^2 / (2K) + mu + K/2
 * (each term maximized alone over l_i >= 0; Lagrangian duality). Valid for every mu, so the
 * rounding of the mu chosen does not matter; the water-filling mu below is the minimizer. It
 * gives max a_i + K/3 when the a_i are equal and max a_i itself when the others are K lower:
 * on a slope the excess vanishes once the piece is small enough. Returns the bound and mu. */
static double mean_square_bound(const double *a, int k, double K, double *mu_out)
{
    double s[3] = {a[0], a[1], a[2]}, amax = fmax(fmax(a[0], a[1]), a[2]);
    *mu_out = amax;
    if (!(K > 0)) return amax;
    for (int i = 0; i < k; i++) /* descending */
        for (int j = i + 1; j < k; j++)
            if (s[j] > s[i]) {
                double t = s[i];
                s[i] = s[j], s[j] = t;
            }
    double sum = 0, mu = amax;
    for (int m = 1; m <= k; m++) {
        sum += s[m - 1];
        mu = (sum - K) / m;
        if (m == k || s[m] <= mu) break;
    }
    double q = mu + K / 2;
    /* (a - mu)^2 underflowed to 0 for distances near 1e-117 (4th powers of lengths), which made
     * the bound of a segment between two zero-distance corners 0 instead of K/4 (found by
     * fuzz/fuzz_hausdorff.c); dividing first keeps it in range. */
    for (int i = 0; i < k; i++)
        if (a[i] > mu) q += (a[i] - mu) * ((a[i] - mu) / (2 * K));
    *mu_out = mu;
    return fmax(q, amax);
}

double hd_simplex_bound(const hd_run *run, const hd_dir *dir, const hd_simplex *s, double enough)
{
    const hd_sample *c[3];
    double maxd = max_corner_distance(dir, s, c), mag = 0, kmax = 0;
    for (int i = 0; i < dir->k; i++)
        for (int j = i + 1; j < dir->k; j++) {
            double cc = 0, e2 = 0;
            for (int x = 0; x < 3; x++) {
                double dc = c[i]->c[x] - c[j]->c[x], dp = c[i]->p[x] - c[j]->p[x];
                cc += dc * dp;
                e2 += dp * dp;
            }
            kmax = fmax(kmax, 2 * cc - e2);
            mag += 2 * sqrt(dist2(c[i]->c, c[j]->c) * e2) + e2;
        }
    double a[3] = {0, 0, 0};
    for (int i = 0; i < dir->k; i++)
        a[i] = c[i]->d * c[i]->d;
    double mu, u2 = mean_square_bound(a, dir->k, kmax, &mu);
    u2 += 32 * HD_ULP * (maxd * maxd + mag + fabs(mu) + kmax);
    double u1 = sqrt(u2), b1 = u1 * (1 + 8 * HD_ULP) + 128 * HD_ULP * run->scale;
    if (b1 <= enough) return b1;
    /* (3) with the corners' own elements (an edge or vertex of B lies on several elements, so
     * every corner's is tried); it only replaces (1) where it is smaller after its slack. */
    double tau = 256 * HD_ULP * run->scale;
    uint32_t cand[3] = {c[0]->elem, c[1]->elem, dir->k == 3 ? c[2]->elem : FL_SWEEP_NONE};
    double m = fixed_element_bound(dir, c, cand, dir->k, u1 - tau);
    return m < INFINITY ? element_bound(run, m, tau) : b1;
}

/* ---- a max-heap of simplices by bound, for the refinement of one simplex of A ---- */

static void heap_up(hd_simplex *h, size_t i)
{
    while (i > 0 && h[(i - 1) / 2].upper < h[i].upper) {
        hd_simplex t = h[i];
        h[i] = h[(i - 1) / 2];
        h[(i - 1) / 2] = t;
        i = (i - 1) / 2;
    }
}

static void heap_down(hd_simplex *h, size_t n, size_t i)
{
    for (;;) {
        size_t l = 2 * i + 1, r = l + 1, m = i;
        if (l < n && h[l].upper > h[m].upper) m = l;
        if (r < n && h[r].upper > h[m].upper) m = r;
        if (m == i) return;
        hd_simplex t = h[i];
        h[i] = h[m];
        h[m] = t;
        i = m;
    }
}

static int heap_push(fl_vec *heap, const hd_simplex *s)
{
    if (fl_vec_push(heap, s, 1)) return -1;
    heap_up(heap->data, heap->count - 1);
    return 0;
}

static hd_simplex heap_pop(fl_vec *heap)
{
    hd_simplex *h = heap->data;
    hd_simplex top = h[0];
    h[0] = h[--heap->count];
    heap_down(h, heap->count, 0);
    return top;
}

/* ---- refinement ---- */

typedef struct refine {
    hd_run *run;
    hd_dir *dir;
    const double *other_lower;
    double closed; /* largest bound among the finished simplices */
    fl_vec heap;
} refine;

static double threshold(const refine *rf)
{
    double t = rf->dir->lower;
    if (!rf->run->both_directions && rf->other_lower) t = fmax(t, *rf->other_lower);
    return t + rf->run->precision;
}

/* A simplex is final: its bound counts towards the direction's upper bound. */
static fl_status finish(refine *rf, const hd_simplex *s, fl_error *err)
{
    rf->closed = fmax(rf->closed, s->upper);
    if (rf->run->keep_field && fl_vec_push(&rf->dir->leaves, s, 1))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    return FL_OK;
}

static void check_budget(hd_run *run)
{
    if (run->max_samples && run->samples >= run->max_samples) run->exhausted = 1;
    if (run->deadline > 0 && (++run->splits & 63) == 0 && hd_now() > run->deadline)
        run->exhausted = 1;
}

/* Longest-edge bisection: the new corner is the midpoint of the longest edge, so children
 * stay well shaped and the new sample lies next to the previous ones (a coherent path for the
 * cursor, §5.1 / Fig. 8). Returns the squared length of the longest edge. */
static double longest_edge(const hd_dir *dir, const hd_simplex *s, int *ei)
{
    const hd_sample *smp = dir->samples.data;
    double best = -1;
    for (int i = 0; i < (dir->k == 3 ? 3 : 1); i++) {
        double l = dist2(smp[s->v[i]].p, smp[s->v[(i + 1) % dir->k]].p);
        if (l > best) best = l, *ei = i;
    }
    return best;
}

/* The nearest point to p on the elements of the samples `near` and their neighbours across
 * edges: a point of B, so d(p, B) <= best->d. 0 when there is no candidate. */
static int candidate_sample(const hd_dir *dir, const double *p, const uint32_t *near, int n,
                            hd_sample *best)
{
    const hd_sample *smp = dir->samples.data;
    uint32_t cand[3 * 4];
    int m = 0, k = dir->k;
    for (int j = 0; j < n && j < 3; j++) {
        uint32_t e = smp[near[j]].elem;
        if (e == FL_SWEEP_NONE) continue;
        cand[m++] = e;
        for (int i = 0; i < k; i++)
            cand[m++] = dir->b_adj[(size_t)k * e + (size_t)i];
    }
    hd_sample none = {{p[0], p[1], p[2]}, {0, 0, 0}, INFINITY, FL_SWEEP_NONE, 0};
    *best = none;
    for (int j = 0; j < m; j++) {
        int seen = cand[j] == FL_SWEEP_NONE;
        for (int i = 0; i < j && !seen; i++)
            seen = cand[i] == cand[j];
        if (seen) continue;
        double q[3], d = element_closest(dir, p, cand[j], q);
        if (d < best->d) {
            best->d = d;
            best->elem = cand[j];
            memcpy(best->c, q, sizeof q);
        }
    }
    if (best->elem == FL_SWEEP_NONE) return 0;
    if (dir->dim == 2) best->p[2] = best->c[2] = 0;
    best->d = sqrt(dist2(best->p, best->c));
    return 1;
}

/* A cursor query costs dozens of distance evaluations (~54 on the benchmark meshes); the
 * elements of nearby samples and their neighbours usually hold the closest point too. When
 * the nearest point q on those candidates is already no farther than the direction's lower
 * bound, the exact distance (<= |p - q|) cannot raise the lower bound, so q is kept as an
 * inexact sample: a point of B, which is all bounds (1) and (3) need (their proofs use c_i in
 * B and the elements as candidates, never that c_i is the closest). Inexact samples never
 * touch the lower bound (hd_note_sample). The field (keep_field) wants exact distances. */
fl_status hd_sample_near(hd_run *run, hd_dir *dir, const double *p, const uint32_t *near, int n,
                         hd_sample *out, fl_error *err)
{
    if (!run->keep_field && dir->b_adj && dir->lower_sample != UINT32_MAX &&
        candidate_sample(dir, p, near, n, out) && out->d <= dir->lower) {
        run->samples++;
        return FL_OK;
    }
    return query_sample(run, dir, p, out, err);
}

/* The sample at the midpoint `mid` of corners a and b, from their elements when it can. */
static fl_status measure_midpoint(refine *rf, const double *mid, uint32_t a, uint32_t b,
                                  uint32_t *m, fl_error *err)
{
    hd_dir *dir = rf->dir;
    if (dir->samples.count >= UINT32_MAX)
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hausdorff: more than 2^32 samples");
    uint32_t near[2] = {a, b};
    hd_sample smp;
    fl_status st = hd_sample_near(rf->run, dir, mid, near, 2, &smp, err);
    if (st) return st;
    if (fl_vec_push(&dir->samples, &smp, 1))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    *m = (uint32_t)(dir->samples.count - 1);
    hd_note_sample(rf->run, dir, *m);
    return FL_OK;
}

static fl_status split(refine *rf, const hd_simplex *s, int ei, fl_error *err)
{
    hd_dir *dir = rf->dir;
    int k = dir->k;
    uint32_t a = s->v[ei], b = s->v[(ei + 1) % k], m = 0;
    const hd_sample *smp = dir->samples.data;
    double mid[3];
    for (int x = 0; x < 3; x++)
        mid[x] = 0.5 * (smp[a].p[x] + smp[b].p[x]);
    fl_status st = measure_midpoint(rf, mid, a, b, &m, err);
    if (st) return st;
    hd_simplex c0 = *s, c1 = *s;
    c0.tried = c1.tried = 1; /* only A's own simplices try it: a split's corners are new */
    c0.v[(ei + 1) % k] = m;  /* keeps a, replaces b: orientation preserved */
    c1.v[ei] = m;
    /* A child whose bound (1) is already below the threshold is final: (3) is not needed. */
    double t = threshold(rf);
    c0.upper = hd_simplex_bound(rf->run, dir, &c0, t);
    c1.upper = hd_simplex_bound(rf->run, dir, &c1, t);
    if (heap_push(&rf->heap, &c0) || heap_push(&rf->heap, &c1))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    return FL_OK;
}

/* Whether a corner of s lies on B up to the precision. */
static int near_b(const refine *rf, const hd_simplex *s)
{
    const hd_sample *smp = rf->dir->samples.data;
    for (int i = 0; i < rf->dir->k; i++)
        if (smp[s->v[i]].d <= rf->run->precision) return 1;
    return 0;
}

/* Refines one simplex of A best-first until its pieces are all below the threshold. The
 * pieces stay inside it, so consecutive queries are close (coherent cursor). */
static fl_status refine_simplex(refine *rf, const hd_simplex *s0, fl_error *err)
{
    fl_status st = FL_OK;
    rf->heap.count = 0;
    if (heap_push(&rf->heap, s0)) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    while (st == FL_OK && rf->heap.count) {
        const hd_simplex *top = rf->heap.data;
        if (top->upper <= threshold(rf) || rf->run->exhausted) {
            for (size_t i = 0; st == FL_OK && i < rf->heap.count; i++)
                st = finish(rf, (hd_simplex *)rf->heap.data + i, err);
            rf->heap.count = 0;
            break;
        }
        hd_simplex s = heap_pop(&rf->heap);
        /* Cheaper than a split when it closes the simplex: where A lies on B (a mesh against
         * itself or a shared part), the corners' closest points are vertices or edge points
         * of B reported on arbitrary neighbouring triangles. Elsewhere (2) rarely needs it. */
        if (!s.tried && near_b(rf, &s)) {
            st = hd_try_centroid_element(rf->run, rf->dir, &s, err);
            if (st == FL_OK && heap_push(&rf->heap, &s))
                st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
            continue;
        }
        int ei = 0;
        if (sqrt(longest_edge(rf->dir, &s, &ei)) < rf->run->min_edge) {
            st = finish(rf, &s, err);
            continue;
        }
        st = split(rf, &s, ei, err);
        check_budget(rf->run);
    }
    return st;
}

static int by_bound_desc(const void *x, const void *y)
{
    double a = ((const hd_simplex *)x)->upper, b = ((const hd_simplex *)y)->upper;
    return (a < b) - (a > b);
}

static fl_status report(refine *rf, fl_error *err)
{
    hd_run *run = rf->run;
    if (fl_progress(run->progress, run->progress_user, "hausdorff",
                    run->progress_total > 0 ? run->progress_done / run->progress_total : 1))
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
    return FL_OK;
}

fl_status hd_refine(hd_run *run, hd_dir *dir, const double *other_lower, fl_error *err)
{
    refine rf = {run, dir, other_lower, 0.0, {0}};
    fl_vec_init(&rf.heap, sizeof(hd_simplex));
    /* Highest bounds first: they hold the likely maximum, so the lower bound rises early and
     * prunes the rest (§6). */
    qsort(dir->simplices, dir->simplex_count, sizeof *dir->simplices, by_bound_desc);
    fl_status st = FL_OK;
    size_t i = 0;
    for (; st == FL_OK && i < dir->simplex_count; i++) {
        const hd_simplex *s = dir->simplices + i;
        if (s->upper <= threshold(&rf) || run->exhausted) {
            if (!run->keep_field) { /* sorted: every later bound is smaller */
                rf.closed = fmax(rf.closed, s->upper);
                break;
            }
            st = finish(&rf, s, err);
        } else {
            st = refine_simplex(&rf, s, err);
        }
        run->progress_done += 1;
        if (st == FL_OK && (i & 255) == 0) st = report(&rf, err);
    }
    run->progress_done += (double)(dir->simplex_count - i);
    dir->upper = fmax(rf.closed, dir->lower);
    fl_vec_free(&rf.heap);
    return st;
}
