/* Certified Hausdorff distance between the boundary of a union of balls U and a triangle mesh M
 * (issue #12: ∂∪B_perp against ∂O; method and proof in docs/skin.md, "Certified Hausdorff
 * distance of the union").
 *
 * Both directed distances are suprema of 1-Lipschitz functions over compact sets, bounded by
 * branch and bound on covers of those sets by small pieces P with a centre p and a radius
 * delta (every point of P within delta of p):   sup over P of h  <=  h_upper(p) + delta.
 *  - ∂U -> M, h = d(., M): ∂U is contained in the union of the spheres S_i, so pieces are
 *    patches of each sphere under the gnomonic (cube-map) parametrisation: on face w = (u, v, 1)
 *    of the cube, x = c + r w/|w|. The map w -> w/|w| has derivative norm 1/|w| <= 1 there, so
 *    a (u, v) square of side h lies within r h/sqrt(2) of the image of its centre. A patch
 *    inside another ball's open interior (with margin delta) has no point on ∂U and is dropped;
 *    the others are kept (kept points off ∂U can only raise the bound). d(p, M) comes from the
 *    Meshsweeper hierarchy as an interval. Lower bound: d(p, M) at patch centres on ∂U.
 *  - M -> ∂U, h = d(., ∂U): pieces are 4-split subtriangles, centre the centroid g, delta the
 *    largest distance from g to a corner (a triangle is convex). Outside U, d(g, ∂U) =
 *    min_i |g - c_i| - r_i exactly; inside, it lies between max_i r_i - |g - c_i| and the
 *    parameter where the ray along the triangle's normal leaves U (that exit point is on ∂U).
 * Levels are processed breadth first so the lower bound L found on coarse pieces prunes the
 * finer ones: a piece whose upper bound is <= L cannot raise the supremum; a piece within the
 * precision of L (or smaller than it) is a leaf whose upper bound counts. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "skin/skin_hausdorff.h"

/* A piece: a sphere patch (ball, face, u0, v0, h) or a subtriangle (tri, p[3][3]). */
typedef struct patch {
    uint32_t ball, face;
    double u0, v0, h;
} patch;

typedef struct piece {
    uint32_t tri;
    double p[3][3];
} piece;

typedef struct bnb {
    const skin_ball_grid *g;
    const fl_mesh *mesh;
    fl_sweep_cursor *cursor;
    double precision, tol, slack;
    size_t pieces, max_pieces;
    double lower, upper;
    fl_progress_fn progress;
    void *progress_user;
} bnb;

static double dist3(const double *a, const double *b)
{
    double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
    return sqrt(d0 * d0 + d1 * d1 + d2 * d2);
}

static fl_status count_piece(bnb *s, fl_error *err)
{
    if (++s->pieces > s->max_pieces)
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                       "skin: the union's Hausdorff bound needs more than %zu pieces at "
                       "precision %g; ask for a coarser precision",
                       s->max_pieces, s->precision);
    return FL_OK;
}

/* The point of patch (ball b, face f) at (u, v). */
static void patch_point(const skin_ball_grid *g, uint32_t b, uint32_t f, double u, double v,
                        double x[3])
{
    const double *c = g->xyzr + 4 * (size_t)b;
    int a = (int)(f / 2);
    double w[3];
    w[a] = f % 2 ? -1 : 1;
    w[(a + 1) % 3] = u;
    w[(a + 2) % 3] = v;
    double n = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    for (int k = 0; k < 3; k++) x[k] = c[k] + c[3] * w[k] / n;
}

/* Evaluates one sphere patch; returns its upper bound, or -1 when it has no point on ∂U. */
static fl_status eval_patch(bnb *s, const patch *q, double *upper, fl_error *err)
{
    fl_status st = count_piece(s, err);
    if (st != FL_OK) return st;
    double r = s->g->xyzr[4 * (size_t)q->ball + 3], delta = r * q->h / sqrt(2.0);
    double x[3];
    patch_point(s->g, q->ball, q->face, q->u0 + q->h / 2, q->v0 + q->h / 2, x);
    *upper = -1;
    if (skin_ball_grid_buried(s->g, x, delta, s->slack, q->ball)) return FL_OK;
    fl_closest c;
    st = fl_sweep_cursor_closest(s->cursor, x, s->tol, &c, err);
    if (st != FL_OK) return st;
    if (skin_ball_grid_exposed(s->g, x, q->ball)) s->lower = fmax(s->lower, c.lower);
    *upper = c.upper + delta + s->slack;
    return FL_OK;
}

/* The refine-or-keep rule shared by both directions: 1 to split the piece, 0 when done with
 * it (its upper bound is then folded into s->upper unless L already dominates it). */
static int refine(bnb *s, double upper, double delta)
{
    if (upper < 0 || upper <= s->lower) return 0;
    if (upper <= s->lower + s->precision || delta <= s->precision / 4) {
        s->upper = fmax(s->upper, upper);
        return 0;
    }
    return 1;
}

static fl_status run_patches(bnb *s, fl_vec *cur, fl_vec *next, fl_error *err)
{
    fl_status st = FL_OK;
    double *ub = NULL;
    for (int level = 0; cur->count > 0 && st == FL_OK; level++) {
        if (fl_progress(s->progress, s->progress_user, "union hausdorff", 0.05 * level))
            return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
        free(ub);
        ub = fl_alloc_array(cur->count, sizeof(double));
        if (!ub) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (patches)");
        const patch *pc = cur->data;
        for (size_t i = 0; i < cur->count && st == FL_OK; i++) st = eval_patch(s, pc + i, ub + i, err);
        next->count = 0;
        for (size_t i = 0; i < cur->count && st == FL_OK; i++) {
            double r = s->g->xyzr[4 * (size_t)pc[i].ball + 3];
            if (!refine(s, ub[i], r * pc[i].h / sqrt(2.0))) continue;
            double h = pc[i].h / 2;
            for (int k = 0; k < 4 && st == FL_OK; k++) {
                patch c = {pc[i].ball, pc[i].face, pc[i].u0 + (k & 1) * h, pc[i].v0 + (k >> 1) * h,
                           h};
                if (fl_vec_push(next, &c, 1))
                    st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (patches)");
            }
        }
        fl_vec t = *cur;
        *cur = *next;
        *next = t;
    }
    free(ub);
    return st;
}

/* sup over ∂U of d(., M). */
static fl_status from_union(bnb *s, fl_error *err)
{
    fl_vec cur, next;
    fl_vec_init(&cur, sizeof(patch));
    fl_vec_init(&next, sizeof(patch));
    fl_status st = FL_OK;
    for (size_t b = 0; b < s->g->n && st == FL_OK; b++)
        for (uint32_t f = 0; f < 6 && st == FL_OK; f++)
            for (int k = 0; k < 4 && st == FL_OK; k++) {
                patch q = {(uint32_t)b, f, -1 + (k & 1), -1 + (k >> 1), 1};
                if (fl_vec_push(&cur, &q, 1))
                    st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (patches)");
            }
    if (st == FL_OK) st = run_patches(s, &cur, &next, err);
    fl_vec_free(&cur);
    fl_vec_free(&next);
    return st;
}

/* Upper bound of d(., ∂U) over a subtriangle (lower bound folded into s->lower). */
static fl_status eval_piece(bnb *s, const piece *q, double *upper, double *delta, fl_error *err)
{
    fl_status st = count_piece(s, err);
    if (st != FL_OK) return st;
    double g[3];
    for (int k = 0; k < 3; k++) g[k] = (q->p[0][k] + q->p[1][k] + q->p[2][k]) / 3;
    *delta = fmax(fmax(dist3(g, q->p[0]), dist3(g, q->p[1])), dist3(g, q->p[2]));
    double f = skin_ball_grid_signed(s->g, g), hu;
    if (f >= 0) {
        s->lower = fmax(s->lower, f);
        hu = f;
    } else {
        s->lower = fmax(s->lower, -f);
        /* the normal of the input triangle: any direction gives an upper bound, the normal
         * a close one where ∂U runs parallel to the surface */
        const uint32_t *t = s->mesh->tri + 3 * (size_t)q->tri;
        const double *a = s->mesh->xyz + 3 * (size_t)t[0], *b = s->mesh->xyz + 3 * (size_t)t[1],
                     *c = s->mesh->xyz + 3 * (size_t)t[2];
        double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                       e1[0] * e2[1] - e1[1] * e2[0]};
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (!(len > 0)) {
            n[0] = n[1] = 0;
            n[2] = len = 1;
        }
        for (int k = 0; k < 3; k++) n[k] /= len;
        hu = skin_ball_grid_ray_exit(s->g, g, n, s->slack);
    }
    *upper = hu + *delta + s->slack;
    return FL_OK;
}

static fl_status run_pieces(bnb *s, fl_vec *cur, fl_vec *next, fl_error *err)
{
    fl_status st = FL_OK;
    double *ub = NULL, *dl = NULL;
    for (int level = 0; cur->count > 0 && st == FL_OK; level++) {
        if (fl_progress(s->progress, s->progress_user, "union hausdorff", 0.5 + 0.05 * level))
            return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
        free(ub);
        free(dl);
        ub = fl_alloc_array(cur->count, sizeof(double));
        dl = fl_alloc_array(cur->count, sizeof(double));
        if (!ub || !dl) {
            st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (pieces)");
            break;
        }
        const piece *pc = cur->data;
        for (size_t i = 0; i < cur->count && st == FL_OK; i++)
            st = eval_piece(s, pc + i, ub + i, dl + i, err);
        next->count = 0;
        for (size_t i = 0; i < cur->count && st == FL_OK; i++) {
            if (!refine(s, ub[i], dl[i])) continue;
            double m[3][3];
            for (int j = 0; j < 3; j++)
                for (int k = 0; k < 3; k++) m[j][k] = 0.5 * (pc[i].p[j][k] + pc[i].p[(j + 1) % 3][k]);
            const double *kids[4][3] = {{pc[i].p[0], m[0], m[2]}, {m[0], pc[i].p[1], m[1]},
                                        {m[2], m[1], pc[i].p[2]}, {m[0], m[1], m[2]}};
            for (int q = 0; q < 4 && st == FL_OK; q++) {
                piece c;
                c.tri = pc[i].tri;
                for (int j = 0; j < 3; j++) memcpy(c.p[j], kids[q][j], sizeof c.p[j]);
                if (fl_vec_push(next, &c, 1))
                    st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (pieces)");
            }
        }
        fl_vec t = *cur;
        *cur = *next;
        *next = t;
    }
    free(ub);
    free(dl);
    return st;
}

/* sup over M of d(., ∂U). */
static fl_status from_mesh(bnb *s, fl_error *err)
{
    fl_vec cur, next;
    fl_vec_init(&cur, sizeof(piece));
    fl_vec_init(&next, sizeof(piece));
    fl_status st = FL_OK;
    for (size_t t = 0; t < s->mesh->triangle_count && st == FL_OK; t++) {
        piece q;
        q.tri = (uint32_t)t;
        for (int j = 0; j < 3; j++)
            memcpy(q.p[j], s->mesh->xyz + 3 * (size_t)s->mesh->tri[3 * t + j], sizeof q.p[j]);
        if (fl_vec_push(&cur, &q, 1))
            st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory (pieces)");
    }
    if (st == FL_OK) st = run_pieces(s, &cur, &next, err);
    fl_vec_free(&cur);
    fl_vec_free(&next);
    return st;
}

static void mesh_box(const fl_mesh *m, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = HUGE_VAL;
        hi[k] = -HUGE_VAL;
    }
    for (size_t v = 0; v < m->vertex_count; v++)
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], m->xyz[3 * v + k]);
            hi[k] = fmax(hi[k], m->xyz[3 * v + k]);
        }
}

fl_status fl_skin_union_hausdorff(const fl_balls *balls, const fl_mesh *mesh,
                                  const fl_skin_union_hausdorff_options *opt,
                                  fl_skin_union_hausdorff_result *out, fl_error *err)
{
    if (out) memset(out, 0, sizeof *out);
    if (!balls || !mesh || !out || (balls->count && !balls->xyzw))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "skin: NULL argument");
    fl_skin_union_hausdorff_options o = {0};
    if (opt) o = *opt;
    if (!(o.precision >= 0) || !isfinite(o.precision))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "skin: precision must be finite and >= 0");
    fl_sweep *sw = NULL;
    fl_status st = fl_sweep_build(mesh, NULL, &sw, err); /* validates the mesh */
    if (st != FL_OK) return st;
    double lo[3], hi[3];
    mesh_box(mesh, lo, hi);
    double diag = dist3(lo, hi);
    bnb s;
    memset(&s, 0, sizeof s);
    skin_ball_grid g;
    st = skin_ball_grid_build(balls, lo, hi, &g, err);
    if (st != FL_OK) {
        fl_sweep_free(sw);
        return st;
    }
    s.g = &g;
    s.mesh = mesh;
    s.precision = o.precision > 0 ? o.precision : 1e-3 * diag;
    if (!(s.precision > 0)) s.precision = 1e-3 * g.rmax;
    s.tol = s.precision / 8;
    /* rounding of the few operations behind each distance, on the scale of the input */
    double scale = fmax(fmax(fabs(lo[0]), fabs(hi[0])), fmax(fmax(fabs(lo[1]), fabs(hi[1])),
                                                               fmax(fabs(lo[2]), fabs(hi[2]))));
    s.slack = 1e-12 * (scale + diag + g.rmax);
    s.max_pieces = o.max_pieces ? o.max_pieces : 50000000;
    s.progress = o.progress;
    s.progress_user = o.progress_user;
    st = fl_sweep_cursor_new(sw, &s.cursor, err);
    if (st == FL_OK) st = from_union(&s, err);
    if (st == FL_OK) {
        out->from_union[0] = s.lower;
        out->from_union[1] = fmax(s.upper, s.lower);
        s.lower = s.upper = 0;
        st = from_mesh(&s, err);
    }
    if (st == FL_OK) {
        out->from_mesh[0] = s.lower;
        out->from_mesh[1] = fmax(s.upper, s.lower);
        out->hausdorff[0] = fmax(out->from_union[0], out->from_mesh[0]);
        out->hausdorff[1] = fmax(out->from_union[1], out->from_mesh[1]);
        out->pieces = s.pieces;
    } else {
        memset(out, 0, sizeof *out);
    }
    fl_sweep_cursor_free(s.cursor);
    fl_sweep_free(sw);
    skin_ball_grid_free(&g);
    return st;
}
