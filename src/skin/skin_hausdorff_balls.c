/* The ball index behind the certified Hausdorff distance of a union of balls
 * (skin_hausdorff.c; method in docs/skin.md, "Certified Hausdorff distance of the union").
 * Every query is exact up to rounding of a few operations on the input's scale; the callers add
 * a slack for that. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "skin/skin_hausdorff.h"

/* at most this many (ball, cell) pairs in the grid: a larger cell is chosen until they fit */
#define GRID_ENTRIES 40000000.0

void skin_ball_grid_free(skin_ball_grid *g)
{
    if (!g) return;
    free(g->xyzr);
    free(g->start);
    free(g->item);
    memset(g, 0, sizeof *g);
}

static size_t clampi(double v, size_t hi)
{
    if (!(v > 0)) return 0; /* also NaN */
    return v >= (double)hi ? hi : (size_t)v;
}

/* Index range [lo, hi] of the cells the box c +- r meets on axis k. */
static void cell_range(const skin_ball_grid *g, const double *c, double r, int k, size_t *lo,
                       size_t *hi)
{
    *lo = clampi(floor((c[k] - r - g->origin[k]) / g->cell), g->dims[k] - 1);
    *hi = clampi(floor((c[k] + r - g->origin[k]) / g->cell), g->dims[k] - 1);
}

/* The cell index of p, or SIZE_MAX when p is outside the grid (then no ball contains it). */
static size_t cell_of(const skin_ball_grid *g, const double *p)
{
    size_t id = 0;
    for (int k = 2; k >= 0; k--) {
        double f = floor((p[k] - g->origin[k]) / g->cell);
        if (!(f >= 0 && f < (double)g->dims[k])) return SIZE_MAX;
        id = id * g->dims[k] + (size_t)f;
    }
    return id;
}

static size_t cell_id(const skin_ball_grid *g, size_t i, size_t j, size_t k)
{
    return (k * g->dims[1] + j) * g->dims[0] + i;
}

/* Chooses the cell: about one ball a cell over the box, coarser when the large balls would
 * list too many pairs. */
static void choose_cell(skin_ball_grid *g, const double lo[3], const double hi[3])
{
    double ext = fmax(fmax(hi[0] - lo[0], hi[1] - lo[1]), hi[2] - lo[2]);
    double vol = fmax(hi[0] - lo[0], ext * 1e-3) * fmax(hi[1] - lo[1], ext * 1e-3) *
                 fmax(hi[2] - lo[2], ext * 1e-3);
    double cell = fmax(cbrt(vol / (double)g->n), ext / 200);
    if (!(cell > 0)) cell = 1;
    for (int it = 0; it < 60; it++) {
        double pairs = 0;
        for (size_t i = 0; i < g->n; i++) {
            double s = 2 * g->xyzr[4 * i + 3] / cell + 2;
            pairs += s * s * s;
        }
        if (pairs <= GRID_ENTRIES) break;
        cell *= 1.5;
    }
    g->cell = cell;
    for (int k = 0; k < 3; k++) {
        g->origin[k] = lo[k] - cell;
        g->dims[k] = (size_t)fmin(floor((hi[k] - lo[k]) / cell) + 3, 1024);
    }
}

static fl_status fill(skin_ball_grid *g, fl_error *err)
{
    size_t cells = g->dims[0] * g->dims[1] * g->dims[2];
    g->start = fl_alloc_array(cells + 1, sizeof(size_t));
    if (!g->start) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (ball grid)");
    memset(g->start, 0, (cells + 1) * sizeof(size_t));
    for (int pass = 0; pass < 2; pass++) {
        for (size_t b = 0; b < g->n; b++) {
            size_t lo[3], hi[3];
            for (int k = 0; k < 3; k++)
                cell_range(g, g->xyzr + 4 * b, g->xyzr[4 * b + 3], k, lo + k, hi + k);
            for (size_t z = lo[2]; z <= hi[2]; z++)
                for (size_t y = lo[1]; y <= hi[1]; y++)
                    for (size_t x = lo[0]; x <= hi[0]; x++) {
                        size_t c = cell_id(g, x, y, z);
                        if (pass == 0)
                            g->start[c + 1]++;
                        else
                            g->item[g->start[c]++] = (uint32_t)b;
                    }
        }
        if (pass == 0) {
            for (size_t c = 0; c < cells; c++) g->start[c + 1] += g->start[c];
            g->item = fl_alloc_array(g->start[cells] ? g->start[cells] : 1, sizeof(uint32_t));
            if (!g->item)
                return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (ball grid)");
        }
    }
    /* pass 1 advanced start[c] to the end of cell c: shift back */
    for (size_t c = cells; c > 0; c--) g->start[c] = g->start[c - 1];
    g->start[0] = 0;
    return FL_OK;
}

fl_status skin_ball_grid_build(const fl_balls *balls, const double lo_in[3],
                               const double hi_in[3], skin_ball_grid *g, fl_error *err)
{
    memset(g, 0, sizeof *g);
    if (balls->count >= UINT32_MAX)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "skin: too many balls");
    g->xyzr = fl_alloc_array(balls->count ? balls->count : 1, 4 * sizeof(double));
    if (!g->xyzr) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (balls)");
    double lo[3], hi[3];
    memcpy(lo, lo_in, sizeof lo);
    memcpy(hi, hi_in, sizeof hi);
    for (size_t i = 0; i < balls->count; i++) {
        const double *b = balls->xyzw + 4 * i;
        for (int k = 0; k < 4; k++)
            if (!(fabs(b[k]) <= (k < 3 ? 1e150 : 1e300))) {
                skin_ball_grid_free(g);
                return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                               "skin: ball %zu has a coordinate or weight that is not finite "
                               "or beyond 1e150",
                               i);
            }
        if (!(b[3] > 0)) continue;
        double *o = g->xyzr + 4 * g->n++;
        memcpy(o, b, 3 * sizeof(double));
        o[3] = sqrt(b[3]);
        for (int k = 0; k < 3; k++)
            if (!(fabs(o[k]) + o[3] <= 1e150)) { /* sphere points are distance queries */
                skin_ball_grid_free(g);
                return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                               "skin: ball %zu reaches beyond 1e150", i);
            }
        g->rmax = fmax(g->rmax, o[3]);
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], b[k] - o[3]);
            hi[k] = fmax(hi[k], b[k] + o[3]);
        }
    }
    if (g->n == 0) {
        skin_ball_grid_free(g);
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "skin: no ball has a positive weight");
    }
    choose_cell(g, lo, hi);
    /* a grid that does not cover every ball would make "no ball here" wrong (ray exit) */
    for (int k = 0; k < 3; k++)
        if (!(isfinite(g->origin[k]) && g->cell > 0 && isfinite(g->cell) &&
              g->origin[k] + (double)g->dims[k] * g->cell >= hi[k])) {
            skin_ball_grid_free(g);
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "skin: the balls and the mesh span too large a range for the grid");
        }
    fl_status st = fill(g, err);
    if (st != FL_OK) skin_ball_grid_free(g);
    return st;
}

static double dist3(const double *a, const double *b)
{
    double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
    return sqrt(d0 * d0 + d1 * d1 + d2 * d2);
}

int skin_ball_grid_buried(const skin_ball_grid *g, const double p[3], double delta, double slack,
                          size_t skip)
{
    size_t c = cell_of(g, p);
    if (c == SIZE_MAX) return 0;
    for (size_t i = g->start[c]; i < g->start[c + 1]; i++) {
        const double *b = g->xyzr + 4 * (size_t)g->item[i];
        if (g->item[i] != skip && dist3(p, b) + delta + slack < b[3]) return 1;
    }
    return 0;
}

int skin_ball_grid_exposed(const skin_ball_grid *g, const double p[3], size_t skip)
{
    size_t c = cell_of(g, p);
    if (c == SIZE_MAX) return 1;
    for (size_t i = g->start[c]; i < g->start[c + 1]; i++) {
        const double *b = g->xyzr + 4 * (size_t)g->item[i];
        if (g->item[i] != skip && dist3(p, b) < b[3]) return 0;
    }
    return 1;
}

/* min of |p - c| - r over the balls listed in the cells at Chebyshev index distance exactly
 * `ring` from (ci, cj, ck). */
static double ring_min(const skin_ball_grid *g, const double *p, const size_t *ci, size_t ring)
{
    double best = HUGE_VAL;
    long lo[3], hi[3];
    for (int k = 0; k < 3; k++) {
        lo[k] = (long)ci[k] - (long)ring;
        hi[k] = (long)ci[k] + (long)ring;
        if (lo[k] < 0) lo[k] = 0;
        if (hi[k] >= (long)g->dims[k]) hi[k] = (long)g->dims[k] - 1;
    }
    for (long z = lo[2]; z <= hi[2]; z++)
        for (long y = lo[1]; y <= hi[1]; y++)
            for (long x = lo[0]; x <= hi[0]; x++) {
                size_t d = (size_t)labs(x - (long)ci[0]);
                if ((size_t)labs(y - (long)ci[1]) > d) d = (size_t)labs(y - (long)ci[1]);
                if ((size_t)labs(z - (long)ci[2]) > d) d = (size_t)labs(z - (long)ci[2]);
                if (d != ring) continue;
                size_t c = cell_id(g, (size_t)x, (size_t)y, (size_t)z);
                for (size_t i = g->start[c]; i < g->start[c + 1]; i++) {
                    const double *b = g->xyzr + 4 * (size_t)g->item[i];
                    best = fmin(best, dist3(p, b) - b[3]);
                }
            }
    return best;
}

double skin_ball_grid_signed(const skin_ball_grid *g, const double p[3])
{
    size_t ci[3];
    int inside = 1;
    for (int k = 0; k < 3; k++) {
        double f = floor((p[k] - g->origin[k]) / g->cell);
        inside &= f >= 0 && f < (double)g->dims[k];
        ci[k] = clampi(f, g->dims[k] - 1);
    }
    double best = HUGE_VAL;
    if (inside) {
        /* A ball not listed within ring k has its box outside the (2k+1)^3 cells around p's
         * cell, so it is at least k cells away: stop once the best is that close. */
        /* (ring k costs (2k+1)^3 cell visits: far points take the plain scan below) */
        for (size_t k = 0; k <= 6; k++) {
            best = fmin(best, ring_min(g, p, ci, k));
            if (best <= (double)k * g->cell) return best;
        }
    }
    for (size_t i = 0; i < g->n; i++) best = fmin(best, dist3(p, g->xyzr + 4 * i) - g->xyzr[4 * i + 3]);
    return best;
}

double skin_ball_grid_ray_exit(const skin_ball_grid *g, const double p[3], const double dir[3],
                               double slack)
{
    /* The ray leaves the union where it leaves every ball holding the current point: jump to
     * the farthest exit of those balls and repeat. Each jump passes the exit of a ball for
     * good, so there are at most n of them. */
    double s = 0;
    for (size_t it = 0; it <= g->n; it++) {
        double q[3] = {p[0] + s * dir[0], p[1] + s * dir[1], p[2] + s * dir[2]};
        size_t c = cell_of(g, q);
        if (c == SIZE_MAX) return s;
        double next = s;
        for (size_t i = g->start[c]; i < g->start[c + 1]; i++) {
            const double *b = g->xyzr + 4 * (size_t)g->item[i];
            if (!(dist3(q, b) < b[3])) continue;
            double d[3] = {b[0] - p[0], b[1] - p[1], b[2] - p[2]};
            double h = d[0] * dir[0] + d[1] * dir[1] + d[2] * dir[2];
            double c2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - b[3] * b[3];
            double exit = h + sqrt(fmax(h * h - c2, 0));
            if (exit > next) next = exit;
        }
        if (!(next > s + slack)) return s + slack;
        s = next;
    }
    return HUGE_VAL; /* not reached (see above); no bound rather than a wrong one */
}
