/* The control points next to a vertex corner, moved by a few units in the last place so that
 * they lie in the vertex's tangent plane far more exactly than one rounding (issue #11:
 * normals interpolated to 1e-12, measured).
 *
 * Every scheme puts the two control points next to a patch corner at vertex V into the tangent
 * plane (V, n) by construction (§9.6 step 2; the spoke points W, N are combinations of such
 * points), but only up to the rounding of the stored doubles, delta ~ eps |P|. The patch
 * normal at V is the cross product of the two spokes P - V, so delta tilts it by
 * delta / (|P - V| sin(corner)): 1.7e-10 on double-torus-example.off, where a spoke was 1.1e-6
 * long, and 3e-11 on mpi_triang.off (spokes of 2e-3 at |P| = 6). Among the doubles within
 * 1024 units in the last place of P's largest coordinate in the two coordinates where n is
 * smallest (stepped so their (2R + 1)^2 combinations spread the residual evenly; a second pass
 * of single ulps where that fails), the third coordinate is solved for the plane and rounded;
 * the first candidate whose residual (P - V) . n, evaluated in long double, is below eps / 8
 * of |P - V| is kept (else the smallest found, typically ~1/300 of an ulp), which takes the
 * tilt below 3e-13 on those meshes. The move is at most 1024 ulps of |P| and 2^-40 |P - V|
 * (the G1 conditions see it relative to the spoke: with 1024 ulps alone elk.off's jump grew
 * from 2e-8 to 8e-8 degrees at a spoke of 1.9e-4 at |P| = 69), and it depends only on (P, V, n): a control point shared by two patches (the
 * boundary point of an edge, the spoke point of two micro patches) moves the same way in both,
 * so shared points stay bit-identical. */
#include <math.h>
#include <string.h>

#include "smooth/smooth_internal.h"

enum { SNAP_R = 6, SNAP_R2 = 16, SNAP_MAX_ULPS = 1024 };

/* (p - v) . n in long double: the differences are exact unless p and v are far apart, the
 * products carry 64-bit mantissas. */
static long double plane_residual(const double *p, const double *v, const double *n)
{
    long double s = 0;
    for (int d = 0; d < 3; d++)
        s += ((long double)p[d] - (long double)v[d]) * (long double)n[d];
    return s;
}

static double ulp_of(double x)
{
    x = fabs(x);
    return nextafter(x, INFINITY) - x;
}

/* The step for a coordinate with normal component nx so that one step moves the residual by
 * about `span` (rounded up to whole ulps of x when up, else to the nearest): at least one ulp
 * of x, at most `cap` (an absolute bound on the move). */
static double step_for(double x, double nx, double span, double cap, int up)
{
    double st = span / fabs(nx), u = ulp_of(x);
    if (!(st > u)) return u;
    return st < cap ? u * (up ? ceil(st / u) : nearbyint(st / u)) : cap;
}

/* The grid p_a + i ka, p_b + j kb (|i| <= ra, |j| <= rb, both <= SNAP_R2), p_c solved in long
 * double and rounded to the nearest double (its neighbours are a whole step of the residual
 * further); keeps in out the candidate of least residual below *best (updated), stopping once
 * it is <= enough. */
static void search(const double *p, const double *v, const double *n, const int *axes,
                   const double *step, const int *range, double enough, long double *best,
                   double *out)
{
    int a = axes[0], b = axes[1], c = axes[2], r0 = range[0], r1 = range[1];
    long double ra[2 * SNAP_R2 + 1], rb[2 * SNAP_R2 + 1], inv = 1.0L / n[c];
    for (int k = -r0; k <= r0; k++) /* the residual's parts from p_a and p_b */
        ra[k + r0] = ((long double)(p[a] + k * step[0]) - v[a]) * n[a];
    for (int k = -r1; k <= r1; k++)
        rb[k + r1] = ((long double)(p[b] + k * step[1]) - v[b]) * n[b];
    for (int i = 0; i <= 2 * r0 && *best > (long double)enough; i++)
        for (int j = 0; j <= 2 * r1; j++) {
            long double part = ra[i] + rb[j];
            double cand = (double)((long double)v[c] - part * inv);
            long double res = fabsl(part + ((long double)cand - v[c]) * n[c]);
            if (res < *best) { /* NaN is never smaller: it cannot be chosen */
                *best = res;
                out[a] = p[a] + (i - r0) * step[0];
                out[b] = p[b] + (j - r1) * step[1];
                out[c] = cand;
            }
        }
}

/* How many steps of size st stay within cap (at most r). */
static int steps_within(double st, double cap, int r)
{
    double k = floor(cap / st);
    return k >= r ? r : k >= 1 ? (int)k : 0;
}

/* Moves p by at most SNAP_MAX_ULPS ulps of its largest coordinate and at most 2^-40 |p - v|
 * (so the G1 conditions, which see the move relative to the spoke p - v, move by ~1e-12) to a
 * double near the plane through v with normal n. The residual changes in steps of
 * g = ulp(p_c) |n_c| when p_c (n's largest component) is re-rounded; the two other
 * coordinates are stepped so that their (2R + 1)^2 combinations shift it by multiples of about
 * g / (2R + 1)^2 (unless n is within ~5e-4 of an axis or the cap binds), and for each the best
 * rounding of p_c is taken. Returns without change for non-finite input or a zero normal. */
static void snap_point(double *p, const double *v, const double *n)
{
    long double best = fabsl(plane_residual(p, v, n));
    if (!isfinite((double)best)) return;
    int c = 0;
    for (int d = 1; d < 3; d++)
        if (fabs(n[d]) > fabs(n[c])) c = d;
    if (!(fabs(n[c]) > 0)) return;
    int a = (c + 1) % 3, b = (c + 2) % 3;
    if (fabs(n[b]) > fabs(n[a])) a = b, b = (c + 1) % 3; /* a: the coarse steps */
    double g = ulp_of(p[c]) * fabs(n[c]), w = 2 * SNAP_R + 1, pv[3];
    g1_sub(p, v, pv);
    double spoke = g1_length(pv);
    /* good enough: the tilt residual / |p - v| an eighth of eps (below the evaluation's own
     * rounding), or 1/4096 of g (no further); then the point is left bit for bit */
    double enough = fmax(ldexp(spoke, -56), g / 4096);
    if (best <= (long double)enough) return;
    double u = ulp_of(fmax(fabs(p[0]), fmax(fabs(p[1]), fabs(p[2]))));
    double cap = fmin(u * SNAP_MAX_ULPS, fmax(ldexp(spoke, -32), u * SNAP_R2));
    /* the coarse steps cover g, the fine ones one coarse step */
    double ka = step_for(p[a], n[a], g / w, cap / SNAP_R, 1);
    double kb = step_for(p[b], n[b], ka * fabs(n[a]) / w, cap / SNAP_R, 0);
    double out[3], step[2] = {ka, kb};
    int axes[3] = {a, b, c};
    int range[2] = {steps_within(ka, cap, SNAP_R), steps_within(kb, cap, SNAP_R)};
    memcpy(out, p, sizeof out);
    search(p, v, n, axes, step, range, enough, &best, out);
    /* where the ulps of p_a, p_b move the residual by nearly whole multiples of g (ulp ratios
     * of 8 or 16 times a ratio of normal components near an integer) the grid cannot spread
     * it: then every combination of single ulps in a wider box */
    if (best > 4 * (long double)enough) {
        step[0] = ulp_of(p[a]);
        step[1] = ulp_of(p[b]);
        range[0] = steps_within(step[0], cap, SNAP_R2);
        range[1] = steps_within(step[1], cap, SNAP_R2);
        search(p, v, n, axes, step, range, enough, &best, out);
    }
    memcpy(p, out, sizeof out);
}

void g1_snap_corner_points(fl_g1_surface *s)
{
    /* the two control points next to corner c (b300: b210, b201; b030: b120, b021; b003:
     * b102, b012), as g1_ix(i, j) */
    static const int next[3][2][2] = {{{2, 1}, {2, 0}}, {{1, 2}, {0, 2}}, {{1, 0}, {0, 1}}};
    static const int corner[3][2] = {{3, 0}, {0, 3}, {0, 0}};
    for (size_t p = 0; p < s->patch_count; p++)
        for (int c = 0; c < 3; c++) {
            uint32_t v = s->corner[3 * p + c];
            if (v >= s->vertex_count) continue;
            double *ctrl = s->ctrl + 30 * p;
            const double *at = ctrl + 3 * g1_ix(corner[c][0], corner[c][1]);
            for (int k = 0; k < 2; k++)
                snap_point(ctrl + 3 * g1_ix(next[c][k][0], next[c][k][1]), at,
                           s->normal + 3 * (size_t)v);
        }
}
