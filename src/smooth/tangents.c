/* Step 2's boundary tangents at the vertices (thesis §9.6, step 2), spread where the star
 * projects onto a nearly degenerate corner.
 *
 * Step 2 puts the edge point next to vertex V at V + tension * (the edge projected on the
 * tangent plane). The micro patches at V (three-split and six-split alike) inherit the corner
 * between two consecutive projected edges (halved by the point W or N towards the split
 * point). Where that corner is tiny — a needle triangle (CGAL's mpi_triang.off: 2.8e-5 degrees
 * at vertex 6) or a triangle seen edge-on from the vertex normal (double-torus-example.off:
 * projected sine 2.7e-7 at vertex 1) — the patch normal at V is the cross product of nearly
 * parallel spokes, and rounding the stored control points (eps |coordinates|) tilts it by
 * eps |p| / (|spoke| sin corner): 4e-9 rad there, above the 1e-7 degree G1 threshold.
 *
 * G1 does not need the projected edges. Any tangent directions in the tangent plane keep the
 * construction valid (eq. 9.3a holds by construction at every vertex: d, l, r lie in the plane)
 * as long as the orientation condition holds, i.e. the directions keep the star's cyclic
 * order with every gap in (0, pi). So at a vertex whose smallest gap is below min_gap the
 * angles are blended towards equal spacing, gap' = (1 - alpha) gap + alpha 2 pi / k with the
 * least alpha that lifts every gap to min_gap: the order is kept, every gap stays in (0, pi)
 * (a convex combination of values in (0, pi)), and the directions move by at most about
 * alpha * pi (alpha ~ 1e-3 on the meshes above). Lengths stay those of the projected edges.
 * A gap within min_gap of pi is as bad (the spoke W - V = (E - V + E' - V) / 3 towards the
 * split point, of two nearly opposite vectors, splits it into micro corners), so gaps above
 * pi - min_gap are pulled below it the same way.
 *
 * Round 10 (issue #11): the micro corners, not only the macro gaps. The spoke towards the split
 * point has the direction of t_i + t_i+1, so a tangent much shorter than its neighbour gives a
 * micro corner of about (short / long) * gap: an edge seen nearly end-on from the normal
 * (double-torus-example.off: a projected length of 6.5e-6 beside 0.25) made micro corners of
 * 1.8e-5 rad and normal errors of 5.4e-10. So where a micro corner's sine is below min_micro
 * the lengths are blended towards their mean as well (and the gaps further towards equal),
 * by the least amount that lifts every micro corner to min_micro. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "smooth/smooth_internal.h"

/* 1e-3 rad (0.057 degrees): the tilt bound above is then ~1e-12 rad for |p| / |spoke| ~ 10. */
static const double min_gap = 1e-3;

/* Round 10 (issue #11, normals to 1e-12): the smallest sine of a micro corner at a vertex.
 * The patch normal there is the cross product of the corner's two spokes, evaluated in double:
 * its rounding alone is a few eps / sine (2e-13 at 1e-3), and a control point off the tangent
 * plane by delta tilts it by delta / (|spoke| sine) (snap.c keeps delta ~1e-3 ulp). */
static const double min_micro = 1e-3;

enum { SPREAD_STAR = 256 }; /* larger stars keep their projected edges */

/* The half-edge after h around its start vertex, counter-clockwise seen from outside. */
static uint32_t next_around(const uint32_t *opp, uint32_t h)
{
    return opp[3 * (h / 3) + (h + 2) % 3];
}

static void project(const fl_mesh *m, const double *normals, uint32_t h, double *out)
{
    uint32_t a = m->tri[h], b = m->tri[3 * (h / 3) + (h + 1) % 3];
    const double *n = normals + 3 * a;
    double d[3];
    g1_sub(m->xyz + 3 * b, m->xyz + 3 * a, d);
    double s = g1_dot(d, n);
    for (int k = 0; k < 3; k++)
        out[k] = d[k] - s * n[k];
}

/* The sine of the smaller of the two micro corners a patch gets at V inside the corner
 * between tangents of lengths a and b at angle g: the spoke towards the split point (W - V in
 * the three-split, N - V in the six-split, both (E - V + E' - V) / 3) has the direction of the
 * sum of the two tangents, so the corners are b sin g / |sum| and a sin g / |sum|. 0 for a
 * zero spoke, NaN for NaN input. */
static double micro_sine(double a, double b, double g)
{
    double s = sqrt(a * a + b * b + 2 * a * b * cos(g));
    if (s == 0) return 0;
    return fmin(a, b) * sin(g) / s;
}

/* Every micro corner of a star with gaps g[0..k) (gap i between tangents i and i + 1) and
 * tangent lengths len[0..k) has a sine of at least min_micro (NaN fails). */
static int micro_corners_ok(size_t k, const double *g, const double *len)
{
    for (size_t i = 0; i < k; i++)
        if (!(micro_sine(len[i], len[(i + 1) % k], g[i]) >= min_micro)) return 0;
    return 1;
}

/* out[i] = (1 - alpha) gap[i] + alpha even: a convex combination keeps the cyclic order. */
static void blend_gaps(size_t k, const double *gap, double even, double alpha, double *out)
{
    for (size_t i = 0; i < k; i++)
        out[i] = (1 - alpha) * gap[i] + alpha * even;
}

/* Spreads the star of vertex v whose half-edges are ring[0..k) in counter-clockwise order;
 * returns 1 if it changed tan. Stars that do not wind once around n (the orientation condition
 * failed, a NaN) are left alone. */
static int spread_star(const fl_mesh *m, const double *n, const uint32_t *ring, size_t k,
                       double *tan)
{
    double u[3] = {1, 0, 0}, w[3], phi[SPREAD_STAR], gap[SPREAD_STAR];
    if (fabs(n[0]) > 0.6) u[0] = 0, u[1] = 1;
    double s = g1_dot(u, n);
    for (int d = 0; d < 3; d++)
        u[d] -= s * n[d];
    if (!(g1_normalize(u) > 0)) return 0;
    g1_cross(n, u, w);
    for (size_t i = 0; i < k; i++) {
        const double *t = tan + 3 * (size_t)ring[i];
        phi[i] = atan2(g1_dot(t, w), g1_dot(t, u));
    }
    const double two_pi = 6.283185307179586;
    double sum = 0, smallest = INFINITY, even = two_pi / (double)k;
    for (size_t i = 0; i < k; i++) { /* signed, in (-pi, pi]: < 0 where a triangle projects
                                        * clockwise (no valid normal, normals.c) */
        double g = phi[(i + 1) % k] - phi[i];
        if (g > 3.14159265358979) g -= two_pi;
        if (g <= -3.14159265358979) g += two_pi;
        gap[i] = g;
        sum += g;
        smallest = fmin(smallest, g);
    }
    const double pi = 3.14159265358979, max_gap = pi - min_gap;
    if (k < 3 || !isfinite(sum)) return 0;
    double largest = 0, base[SPREAD_STAR], mean = 0, blend[SPREAD_STAR];
    for (size_t i = 0; i < k; i++)
        largest = fmax(largest, gap[i]);
    /* A star that does not wind once around n with gaps below pi (only where no valid normal
     * exists: normals.c) gets equally spaced tangents in its cyclic order (alpha = 1), with
     * the 3-D edge lengths: the projection may be a point (an edge along n). */
    int winds = fabs(sum - two_pi) < 1e-9 && largest < pi;
    for (size_t i = 0; i < k; i++) {
        double e[3];
        uint32_t h = ring[i];
        g1_sub(m->xyz + 3 * m->tri[3 * (h / 3) + (h + 1) % 3], m->xyz + 3 * m->tri[h], e);
        base[i] = winds ? g1_length(tan + 3 * (size_t)h) : g1_length(e);
        mean += base[i] / (double)k;
    }
    int gaps_ok = smallest >= min_gap && largest <= max_gap;
    if (gaps_ok && (!winds || micro_corners_ok(k, gap, base))) return 0;
    /* gap' in [min_gap, pi - min_gap]: a gap near pi splits into two micro corners through
     * the spoke W - V = (E - V + E' - V) / 3 of nearly opposite vectors, which is as
     * degenerate (case 1 of tests/smooth/test_g1_degenerate_corner.c: vertex c of a needle). */
    double alpha = winds ? 0 : 1;
    for (size_t i = 0; winds && i < k; i++) {
        if (gap[i] < min_gap) alpha = fmax(alpha, (min_gap - gap[i]) / (even - gap[i]));
        if (gap[i] > max_gap) alpha = fmax(alpha, (gap[i] - max_gap) / (gap[i] - even));
    }
    if (!(alpha >= 0 && alpha <= 1)) return 0;
    /* Then the micro corners (round 10): the least s in [0, 1] for which the gaps blended by
     * alpha + s (1 - alpha) and the lengths blended by s towards their mean give every micro
     * corner a sine of at least min_micro. s = 1 (equal gaps and lengths: micro corners of
     * pi / k) always does; bisection, 40 steps. */
    double sb = 0;
    blend_gaps(k, gap, even, alpha, blend);
    if (!micro_corners_ok(k, blend, base)) {
        double lo = 0, hi = 1, len[SPREAD_STAR];
        for (int it = 0; it < 40; it++) {
            double mid = (lo + hi) / 2;
            blend_gaps(k, gap, even, alpha + mid * (1 - alpha), blend);
            for (size_t i = 0; i < k; i++)
                len[i] = (1 - mid) * base[i] + mid * mean;
            if (micro_corners_ok(k, blend, len))
                hi = mid;
            else
                lo = mid;
        }
        sb = hi;
        blend_gaps(k, gap, even, alpha + sb * (1 - alpha), blend);
    }
    double at = 0, orig = 0, shift = 0, *psi = gap; /* new angles, relative to phi[0] */
    for (size_t i = 0; i < k; i++) { /* no net rotation: mean change of angle 0 */
        double g = gap[i];
        psi[i] = at;
        shift += (at - orig) / (double)k;
        at += blend[i];
        orig += g;
    }
    for (size_t i = 0; i < k; i++) {
        double *t = tan + 3 * (size_t)ring[i], len = (1 - sb) * base[i] + sb * mean;
        double a = phi[0] + psi[i] - shift, c = cos(a), sn = sin(a);
        for (int d = 0; d < 3; d++)
            t[d] = len * (c * u[d] + sn * w[d]);
    }
    return 1;
}

fl_status g1_edge_tangents(const fl_mesh *m, const double *normals, const uint32_t *opp,
                           int spread_corners, double *tan, size_t *spread, fl_error *err)
{
    size_t nh = 3 * m->triangle_count;
    unsigned char *seen = fl_calloc_array(m->vertex_count ? m->vertex_count : 1, 1);
    if (!seen) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    for (size_t h = 0; h < nh; h++)
        project(m, normals, (uint32_t)h, tan + 3 * h);
    *spread = 0;
    if (!spread_corners) { /* PN triangles (FL_G1_MACRO): the projected edges of Vlachos */
        free(seen);
        return FL_OK;
    }
    uint32_t ring[SPREAD_STAR];
    for (size_t h0 = 0; h0 < nh; h0++) {
        uint32_t v = m->tri[h0];
        if (seen[v]) continue;
        seen[v] = 1;
        size_t k = 0;
        uint32_t h = (uint32_t)h0;
        do {
            ring[k++] = h;
            h = next_around(opp, h);
        } while (h != h0 && k < SPREAD_STAR);
        if (h != h0) continue; /* a star too large to spread */
        *spread += (size_t)spread_star(m, normals + 3 * v, ring, k, tan);
    }
    free(seen);
    return FL_OK;
}
