/* Vertex normal estimation (thesis §9.4) and the repair of normals that violate the G1
 * orientation condition (§9.6, last paragraphs). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "smooth/smooth_internal.h"

fl_status fl_g1_vertex_normals(const fl_mesh *mesh, int weighting, double *normals, fl_error *err)
{
    if (!mesh || !normals || weighting < 0 || weighting > FL_G1_WEIGHT_INVERSE)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "NULL argument or bad weighting");
    memset(normals, 0, mesh->vertex_count * 3 * sizeof(double));
    for (size_t t = 0; t < mesh->triangle_count; t++) {
        const uint32_t *v = mesh->tri + 3 * t;
        for (int k = 0; k < 3; k++)
            if (v[k] >= mesh->vertex_count)
                return fl_fail(err, FL_ERR_INPUT, NULL, -1, "triangle %zu: index out of range", t);
        double e1[3], e2[3], c[3];
        g1_sub(mesh->xyz + 3 * v[1], mesh->xyz + 3 * v[0], e1);
        g1_sub(mesh->xyz + 3 * v[2], mesh->xyz + 3 * v[0], e2);
        g1_cross(e1, e2, c); /* |c| = twice the area (method 1 weights by area) */
        double twice_area = g1_length(c), w = 1; /* |c|^2 underflowed at 1e-150 (fuzz_smooth) */
        if (twice_area == 0) continue; /* no direction to contribute */
        if (weighting == FL_G1_WEIGHT_UNIFORM) w = 1 / twice_area;
        if (weighting == FL_G1_WEIGHT_INVERSE) w = 2 / (twice_area * twice_area);
        for (int k = 0; k < 3; k++)
            for (int d = 0; d < 3; d++)
                normals[3 * v[k] + d] += w * c[d];
    }
    for (size_t i = 0; i < mesh->vertex_count; i++) {
        double *n = normals + 3 * i;
        if (!(g1_normalize(n) > 0) || !isfinite(n[0] + n[1] + n[2]))
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "vertex %zu has no normal (unused, or its triangles cancel out)", i);
    }
    return FL_OK;
}

/* The orientation condition at vertex v: eq. 9.3a at v reads d + f l + g r = 0 with d the
 * projected edge and l, r the cross-boundary vectors of the two patches; f and g have the
 * signs that make the surface G1 (not just tangent-plane continuous) exactly when the two
 * neighbouring triangles project onto opposite sides of the projected edge. Around v that is:
 * every incident triangle (v, a, b) projects counter-clockwise on the tangent plane, i.e.
 * the point v + h n lies above it. Decided exactly on the rounded point v + h n. */
static int star_ok(const fl_mesh *m, uint32_t v, const uint32_t *star, size_t n_star,
                   const double *n, double h)
{
    const double *p = m->xyz + 3 * v;
    double q[3] = {p[0] + h * n[0], p[1] + h * n[1], p[2] + h * n[2]};
    for (size_t s = 0; s < n_star; s++) {
        const uint32_t *t = m->tri + 3 * (star[s] / 3);
        int k = (int)(star[s] % 3);
        const double *a = m->xyz + 3 * t[(k + 1) % 3], *b = m->xyz + 3 * t[(k + 2) % 3];
        if (fl_orient3d(p, a, b, q) >= 0) return 0; /* q not strictly above (v, a, b) */
        /* The exact sign is on the rounded q; a triangle seen almost edge-on also projects
         * onto (nearly) a segment, which makes eq. 9.3a degenerate, so ask for a margin:
         * the normal at least 1e-6 radians off the triangle's plane. */
        double ea[3], eb[3], c[3];
        g1_sub(a, p, ea);
        g1_sub(b, p, eb);
        g1_cross(ea, eb, c);
        if (!(g1_dot(c, n) > 1e-6 * sqrt(g1_dot(c, c)))) return 0;
    }
    return 1;
}

/* Unit normal of the triangle of half-edge he; 0 when it has none. */
static int triangle_unit_normal(const fl_mesh *m, uint32_t he, double *u)
{
    const uint32_t *t = m->tri + 3 * (he / 3);
    double e1[3], e2[3];
    g1_sub(m->xyz + 3 * t[1], m->xyz + 3 * t[0], e1);
    g1_sub(m->xyz + 3 * t[2], m->xyz + 3 * t[0], e2);
    g1_cross(e1, e2, u);
    return g1_normalize(u) > 0;
}

enum { MAXIMIN_STAR = 48 }; /* O(k^4) below; larger stars keep the perceptron's answer */

static double min_cos(const double (*u)[3], size_t k, const double *n)
{
    double worst = INFINITY;
    for (size_t i = 0; i < k; i++)
        worst = fmin(worst, g1_dot(u[i], n));
    return worst;
}

static void consider(const double (*u)[3], size_t k, double *c, double *best, double *score)
{
    if (!(g1_normalize(c) > 0)) return;
    for (int sign = 0; sign < 2; sign++) {
        double s = min_cos(u, k, c);
        if (s > *score) {
            *score = s;
            memcpy(best, c, 3 * sizeof(double));
        }
        for (int d = 0; d < 3; d++)
            c[d] = -c[d];
    }
}

/* The unit direction whose smallest cosine to the star's triangle normals is largest (the
 * centre of the smallest spherical cap holding them). The optimum has equal cosines to one,
 * two or three of the normals, so every such candidate is tried. Returns that cosine: a normal
 * satisfying the orientation condition exists iff it is > 0 (Gordan's alternative). */
static double maximin_normal(const fl_mesh *m, const uint32_t *star, size_t k, double *best)
{
    double u[MAXIMIN_STAR][3], score = -INFINITY, c[3], a[3], b[3];
    size_t n = 0;
    for (size_t s = 0; s < k; s++)
        n += (size_t)triangle_unit_normal(m, star[s], u[n]);
    for (size_t i = 0; i < n; i++) {
        memcpy(c, u[i], sizeof c);
        consider((const double (*)[3])u, n, c, best, &score);
        for (size_t j = i + 1; j < n; j++) {
            for (int d = 0; d < 3; d++)
                c[d] = u[i][d] + u[j][d];
            consider((const double (*)[3])u, n, c, best, &score);
            for (size_t l = j + 1; l < n; l++) {
                g1_sub(u[i], u[j], a);
                g1_sub(u[i], u[l], b);
                g1_cross(a, b, c);
                consider((const double (*)[3])u, n, c, best, &score);
            }
        }
    }
    return score;
}

/* Finds a normal with positive component along every incident triangle normal, starting from
 * the estimate: each round pushes n towards the unit normal of the worst triangle until that
 * triangle sees n at a small positive angle (a perceptron on the cone of feasible normals).
 * The perceptron aims at 0.05 (2.9 degrees) and cycles when the feasible cone is narrower:
 * on CGAL's hand.off three vertices (1143, 1151, 1185) have cones of 0.90-1.07 degrees. Then
 * the widest direction n* (maximin_normal) is taken and moved back towards the estimate, on
 * the chord between them, half-way from where the condition starts to hold (bisection; the
 * feasible set is convex) to n*: close to the estimate, with a margin. */
static int repair_one(const fl_mesh *m, uint32_t v, const uint32_t *star, size_t n_star, double *n,
                      double h)
{
    double n0[3], wide[3];
    memcpy(n0, n, sizeof n0);
    for (int round = 0; round < 200; round++) {
        if (star_ok(m, v, star, n_star, n, h)) return 1;
        double worst = INFINITY, u_worst[3] = {0, 0, 0};
        for (size_t s = 0; s < n_star; s++) {
            double u[3];
            if (!triangle_unit_normal(m, star[s], u)) continue;
            double c = g1_dot(u, n);
            if (c < worst) {
                worst = c;
                memcpy(u_worst, u, sizeof u);
            }
        }
        double push = 0.05 - worst;
        for (int d = 0; d < 3; d++)
            n[d] += push * u_worst[d];
        if (!(g1_normalize(n) > 0)) return 0;
    }
    if (star_ok(m, v, star, n_star, n, h)) return 1;
    if (n_star > MAXIMIN_STAR) return 0;
    double score = maximin_normal(m, star, n_star, wide);
    if (!(score > 0) || !star_ok(m, v, star, n_star, wide, h)) {
        /* No valid normal (CGAL's elk.off, corner_poly.off): the widest direction is the least
         * bad one; tangents.c then spreads the boundary tangents into a star that winds once
         * (docs/smooth.md, "Vertices without a valid normal"). */
        if (score > -1 && isfinite(score)) memcpy(n, wide, sizeof wide);
        return 0;
    }
    double lo = 0, hi = 1, c[3];
    for (int it = 0; it < 40; it++) {
        double t = (lo + hi) / 2;
        for (int d = 0; d < 3; d++)
            c[d] = (1 - t) * n0[d] + t * wide[d];
        if (g1_normalize(c) > 0 && star_ok(m, v, star, n_star, c, h))
            hi = t;
        else
            lo = t;
    }
    double t = (hi + 1) / 2;
    for (int d = 0; d < 3; d++)
        c[d] = (1 - t) * n0[d] + t * wide[d];
    int mid_ok = g1_normalize(c) > 0 && star_ok(m, v, star, n_star, c, h);
    memcpy(n, mid_ok ? c : wide, sizeof c);
    return 1;
}

fl_status g1_repair_normals(const fl_mesh *m, double *normals, size_t *repairs, size_t *failures,
                            fl_error *err)
{
    size_t nv = m->vertex_count, nh = 3 * m->triangle_count;
    size_t *start = fl_calloc_array(nv + 1, sizeof *start);
    uint32_t *star = fl_alloc_array(nh ? nh : 1, sizeof *star);
    double *h = fl_calloc_array(nv ? nv : 1, sizeof *h);
    if (!start || !star || !h) {
        free(start);
        free(star);
        free(h);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    for (size_t i = 0; i < nh; i++)
        start[m->tri[i] + 1]++;
    for (size_t v = 0; v < nv; v++)
        start[v + 1] += start[v];
    for (size_t i = 0; i < nh; i++) {
        uint32_t v = m->tri[i];
        const double *a = m->xyz + 3 * v, *b = m->xyz + 3 * m->tri[3 * (i / 3) + (i + 1) % 3];
        double d[3];
        g1_sub(b, a, d);
        h[v] = fmax(h[v], sqrt(g1_dot(d, d))); /* lifts v + h n clear of rounding */
        star[start[v]++] = (uint32_t)i;
    }
    for (size_t v = nv; v > 0; v--)
        start[v] = start[v - 1];
    start[0] = 0;
    *repairs = *failures = 0;
    for (uint32_t v = 0; v < nv; v++) {
        size_t n_star = start[v + 1] - start[v];
        if (!n_star || star_ok(m, v, star + start[v], n_star, normals + 3 * v, h[v])) continue;
        (*repairs)++;
        if (!repair_one(m, v, star + start[v], n_star, normals + 3 * v, h[v])) (*failures)++;
    }
    free(start);
    free(star);
    free(h);
    return FL_OK;
}
