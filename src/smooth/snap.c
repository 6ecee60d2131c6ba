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
 * 1024 units in the last place of P in the two coordinates where n is smallest (stepped so
 * their (2R + 1)^2 combinations spread the residual evenly), the third coordinate is solved
 * for the plane and rounded; the candidate with the smallest residual (P - V) . n, evaluated
 * in long double, is kept: about 1/338 of an ulp at R = 6, which takes the tilt below 1e-13 on
 * those meshes. The move is at most 1e-13 relative, far below any tolerance of the G1
 * conditions, and it depends only on (P, V, n): a control point shared by two patches (the
 * boundary point of an edge, the spoke point of two micro patches) moves the same way in both,
 * so shared points stay bit-identical. */
#include <math.h>
#include <string.h>

#include "smooth/smooth_internal.h"

enum { SNAP_R = 6, SNAP_MAX_ULPS = 1024 };

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

/* How many ulps of x one step moves so that the residual moves by about `span` (n_x the
 * normal's component): at least 1, at most SNAP_MAX_ULPS / SNAP_R so no point moves more than
 * SNAP_MAX_ULPS ulps (1e-13 relative: far below any G1 tolerance). */
static double step_ulps(double x, double nx, double span)
{
    double per = ulp_of(x) * fabs(nx), k = floor(span / per);
    if (!(k >= 1)) return 1;
    return k > SNAP_MAX_ULPS / SNAP_R ? SNAP_MAX_ULPS / SNAP_R : k;
}

/* Moves p by at most SNAP_MAX_ULPS ulps a coordinate to a double near the plane through v with
 * normal n. The residual changes in steps of g = ulp(p_c) |n_c| when p_c (n's largest
 * component) is re-rounded; the two other coordinates are stepped so that their (2R + 1)^2
 * combinations shift it by multiples of about g / (2R + 1)^2 (where n is not too close to an
 * axis), and for each the best rounding of p_c is taken: a residual near g / 338. Returns
 * without change for non-finite input or a zero normal. */
static void snap_point(double *p, const double *v, const double *n)
{
    long double best = fabsl(plane_residual(p, v, n));
    if (!isfinite((double)best)) return;
    int c = 0;
    for (int d = 1; d < 3; d++)
        if (fabs(n[d]) > fabs(n[c])) c = d;
    if (!(fabs(n[c]) > 0)) return;
    int a = (c + 1) % 3, b = (c + 2) % 3;
    double g = ulp_of(p[c]) * fabs(n[c]), w = 2 * SNAP_R + 1;
    if (best <= (long double)g / 1024) return; /* good enough: leave it bit for bit */
    double ka = step_ulps(p[a], n[a], g / w) * ulp_of(p[a]);
    double kb = step_ulps(p[b], n[b], g / (w * w)) * ulp_of(p[b]);
    double pa[2 * SNAP_R + 1], pb[2 * SNAP_R + 1], out[3];
    for (int k = -SNAP_R; k <= SNAP_R; k++) {
        pa[k + SNAP_R] = p[a] + k * ka;
        pb[k + SNAP_R] = p[b] + k * kb;
    }
    memcpy(out, p, sizeof out);
    for (int i = 0; i < 2 * SNAP_R + 1 && best > (long double)g / 1024; i++)
        for (int j = 0; j < 2 * SNAP_R + 1; j++) {
            long double part = ((long double)pa[i] - v[a]) * n[a] +
                               ((long double)pb[j] - v[b]) * n[b];
            double ideal = (double)((long double)v[c] - part / n[c]);
            double cand[3] = {nextafter(ideal, -INFINITY), ideal, nextafter(ideal, INFINITY)};
            for (int q = 0; q < 3; q++) {
                long double r = fabsl(part + ((long double)cand[q] - v[c]) * n[c]);
                if (r < best) { /* NaN is never smaller: it cannot be chosen */
                    best = r;
                    out[a] = pa[i];
                    out[b] = pb[j];
                    out[c] = cand[q];
                }
            }
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
