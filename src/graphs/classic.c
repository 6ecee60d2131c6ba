/* The classical graphs of thesis §2.2, built from the γ-graph where it unifies them (§3.2:
 * convex hull = γ(-1,1), Delaunay = γ([-1,1],[0,1]), β_c(b) = γ(b,b)) and otherwise filtered
 * from its Delaunay edges, which contain them all (NNG ⊆ EMST ⊆ RNG ⊆ GG ⊆ DT, §2.2.2-2.2.9).
 * Distance decisions use the exact signs of gamma_pred.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "graphs/gamma_internal.h"

typedef struct classic_ctx {
    const double *coords;
    size_t n;
    int dim;
    graph_grid grid;
    fl_vec local;
} classic_ctx;

static const double *cpt(const classic_ctx *c, uint32_t i)
{
    return c->coords + (size_t)i * c->dim;
}

static fl_status gamma_of(const classic_ctx *c, int range, double c0, double c1, double c2,
                          double c3, int want_params, fl_graph *out, fl_error *err)
{
    fl_gamma_params p = {range, {c0, c1, c2, c3}};
    fl_graph_options o = {FL_GAMMA_AUTO, want_params, NULL, NULL};
    return fl_gamma_graph(c->coords, c->n, c->dim, &p, &o, out, err);
}

/* The edges of a γ-Delaunay graph (its simplices' sides), sorted, without repeats. */
static fl_status delaunay_edges(const classic_ctx *c, fl_graph *edges, fl_error *err)
{
    fl_graph dt;
    fl_status st = gamma_of(c, 1, -1, 1, 0, 1, 0, &dt, err);
    if (st != FL_OK || c->dim == 2) {
        *edges = dt;
        return st;
    }
    graph_builder b;
    graph_builder_init(&b, c->dim, 2, c->n);
    for (size_t t = 0; t < dt.simplex_count; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t e[2] = {dt.simplices[3 * t + k], dt.simplices[3 * t + (k + 1) % 3]};
            if (graph_builder_add(&b, e, 0, 0)) {
                graph_builder_free(&b);
                fl_graph_free(&dt);
                return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
            }
        }
    fl_graph_free(&dt);
    return graph_builder_finish(&b, 0, edges, err);
}

/* Is any point p != a, b with test(p) < 0 among the grid cells of the box [lo, hi]? */
typedef int (*point_test)(const classic_ctx *c, const double *a, const double *b, const double *p,
                          double param);

static int any_point(classic_ctx *c, uint32_t ia, uint32_t ib, const double *lo, const double *hi,
                     point_test test, double param, int *found)
{
    c->local.count = 0;
    if (graph_grid_box(&c->grid, lo, hi, &c->local)) return -1;
    const uint32_t *l = c->local.data;
    *found = 0;
    for (size_t i = 0; i < c->local.count && !*found; i++)
        if (l[i] != ia && l[i] != ib && test(c, cpt(c, ia), cpt(c, ib), cpt(c, l[i]), param))
            *found = 1;
    return 0;
}

/* Gabriel neighbourhood (Def. 2.9): strictly inside the ball with diameter ab. */
static int in_gabriel(const classic_ctx *c, const double *a, const double *b, const double *p,
                      double unused)
{
    (void)unused;
    return gamma_diametral_sign(a, b, p, c->dim) < 0;
}

/* Lune of β_l(b), b in [0,1) (Def. 2.16): strictly inside both balls of radius k|ab| centred at
 * a + k(b-a) and b + k(a-b), k = 1/(2(1-b)); p is inside the first iff
 * |p-a|^2 - 2k (p-a).(b-a) < 0. b = 1/2 is the relative neighbourhood (Def. 2.8). */
static int in_lune_ball(const double *a, const double *b, const double *p, double k, int dim)
{
    const double coef[2] = {1, -2 * k}, *x[2] = {p, p}, *y[2] = {a, a}, *u[2] = {p, b},
                 *w[2] = {a, a};
    return gamma_exact_sum_sign(2, coef, x, y, u, w, dim) < 0;
}

static int in_lune(const classic_ctx *c, const double *a, const double *b, const double *p,
                   double k)
{
    return in_lune_ball(a, b, p, k, c->dim) && in_lune_ball(b, a, p, k, c->dim);
}

/* The open infinite strip between the hyperplanes through a and b normal to ab (β_l(1)). */
static int in_strip(const classic_ctx *c, const double *a, const double *b, const double *p,
                    double unused)
{
    (void)unused;
    const double one = 1, *x1[1] = {p}, *y1[1] = {a}, *u1[1] = {b}, *w1[1] = {a};
    const double *x2[1] = {p}, *y2[1] = {b}, *u2[1] = {a}, *w2[1] = {b};
    return gamma_exact_sum_sign(1, &one, x1, y1, u1, w1, c->dim) > 0 &&
           gamma_exact_sum_sign(1, &one, x2, y2, u2, w2, c->dim) > 0;
}

/* Keeps the edges of `cand` whose neighbourhood (test) holds no point. The neighbourhood lies
 * in the ball around the midpoint of radius reach*|ab| (reach < 0: unbounded). */
static fl_status filter_edges(classic_ctx *c, const fl_graph *cand, point_test test, double param,
                              double reach, fl_graph *out, fl_error *err)
{
    graph_builder b;
    graph_builder_init(&b, c->dim, 2, c->n);
    double lo[3], hi[3];
    for (size_t e = 0; e < cand->simplex_count; e++) {
        uint32_t ia = cand->simplices[2 * e], ib = cand->simplices[2 * e + 1];
        const double *a = cpt(c, ia), *bb = cpt(c, ib);
        double len = 0;
        for (int k = 0; k < c->dim; k++)
            len += (bb[k] - a[k]) * (bb[k] - a[k]);
        len = sqrt(len);
        for (int k = 0; k < c->dim; k++) {
            double m = 0.5 * (a[k] + bb[k]), r = reach < 0 ? INFINITY : reach * len * 1.000001;
            lo[k] = m - r - 1e-300;
            hi[k] = m + r + 1e-300;
        }
        int found;
        if (any_point(c, ia, ib, lo, hi, test, param, &found) ||
            (!found && graph_builder_add(&b, cand->simplices + 2 * e, 0, 0))) {
            graph_builder_free(&b);
            return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
        }
    }
    return graph_builder_finish(&b, 0, out, err);
}

/* Kruskal on the Delaunay edges in exact length order (ties by indices): the EMST. */
typedef struct edge_order {
    const classic_ctx *c;
    const uint32_t *e;
} edge_order;

static int compare_edges(const edge_order *o, uint32_t i, uint32_t j)
{
    const uint32_t *a = o->e + 2 * (size_t)i, *b = o->e + 2 * (size_t)j;
    int s = gamma_compare_dist(cpt(o->c, a[0]), cpt(o->c, a[1]), cpt(o->c, b[0]), cpt(o->c, b[1]),
                               o->c->dim);
    if (s) return s;
    if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
    return a[1] < b[1] ? -1 : a[1] > b[1];
}

/* Merge sort of edge indices with the exact comparison (qsort has no context argument). */
static void sort_edges(const edge_order *o, uint32_t *idx, uint32_t *tmp, size_t n)
{
    if (n < 2) return;
    size_t h = n / 2;
    sort_edges(o, idx, tmp, h);
    sort_edges(o, idx + h, tmp, n - h);
    size_t i = 0, j = h, k = 0;
    while (i < h || j < n)
        tmp[k++] =
            (j >= n || (i < h && compare_edges(o, idx[i], idx[j]) <= 0)) ? idx[i++] : idx[j++];
    memcpy(idx, tmp, n * sizeof *idx);
}

static fl_status emst(const classic_ctx *c, const fl_graph *cand, fl_graph *out, fl_error *err)
{
    size_t m = cand->simplex_count;
    uint32_t *idx = fl_alloc_array(m, sizeof *idx), *tmp = fl_alloc_array(m, sizeof *tmp);
    uint32_t *root = fl_alloc_array(c->n, sizeof *root);
    graph_builder b;
    graph_builder_init(&b, c->dim, 2, c->n);
    int oom = !idx || !tmp || !root;
    if (!oom) {
        for (size_t i = 0; i < m; i++)
            idx[i] = (uint32_t)i;
        for (size_t i = 0; i < c->n; i++)
            root[i] = (uint32_t)i;
        edge_order o = {c, cand->simplices};
        sort_edges(&o, idx, tmp, m);
        for (size_t i = 0; i < m && !oom; i++) {
            const uint32_t *e = cand->simplices + 2 * (size_t)idx[i];
            uint32_t ra = fl_uf_find(root, e[0]), rb = fl_uf_find(root, e[1]);
            if (ra == rb) continue;
            root[ra] = rb;
            oom = graph_builder_add(&b, e, 0, 0) != 0;
        }
    }
    free(idx);
    free(tmp);
    free(root);
    if (oom) {
        graph_builder_free(&b);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    return graph_builder_finish(&b, 0, out, err);
}

/* Each point joined to its nearest point (ties: lowest index); nearest neighbours are Gabriel
 * neighbours, hence among the Delaunay edges. */
static fl_status nng(const classic_ctx *c, const fl_graph *cand, fl_graph *out, fl_error *err)
{
    uint32_t *best = fl_alloc_array(c->n, sizeof *best);
    if (!best) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    for (size_t i = 0; i < c->n; i++)
        best[i] = UINT32_MAX;
    for (size_t e = 0; e < cand->simplex_count; e++)
        for (int s = 0; s < 2; s++) {
            uint32_t i = cand->simplices[2 * e + s], j = cand->simplices[2 * e + 1 - s];
            if (best[i] == UINT32_MAX) {
                best[i] = j;
                continue;
            }
            int cmp = gamma_compare_dist(cpt(c, i), cpt(c, j), cpt(c, i), cpt(c, best[i]), c->dim);
            if (cmp < 0 || (cmp == 0 && j < best[i])) best[i] = j;
        }
    graph_builder b;
    graph_builder_init(&b, c->dim, 2, c->n);
    int oom = 0;
    for (size_t i = 0; i < c->n && !oom; i++) {
        uint32_t e[2] = {(uint32_t)i, best[i]};
        if (best[i] != UINT32_MAX) oom = graph_builder_add(&b, e, 0, 0) != 0;
    }
    free(best);
    if (oom) {
        graph_builder_free(&b);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    return graph_builder_finish(&b, 0, out, err);
}

/* α(a) shape, a < 0 (Def. 2.14): simplices touched by an empty ball of radius 1/|a|. The empty
 * balls touching a simplex are B(t), t between its witnesses' offsets, so a radius rho is
 * available iff its |c| = 1 - r/rho lies in [0, c1'] when the extreme balls are on opposite
 * sides (c0' >= 0), or in [-c0', c1'] when on the same side. */
static fl_status alpha_negative(const classic_ctx *c, double a, fl_graph *out, fl_error *err)
{
    fl_graph dt;
    fl_status st = gamma_of(c, 1, -1, 1, 0, 1, 1, &dt, err);
    if (st != FL_OK) return st;
    graph_builder b;
    graph_builder_init(&b, c->dim, c->dim, c->n);
    int oom = 0;
    for (size_t i = 0; i < dt.simplex_count && !oom; i++) {
        const uint32_t *s = dt.simplices + i * (size_t)c->dim;
        gamma_frame f;
        if (!gamma_frame_init(&f, c->coords, c->dim, s)) continue;
        double m = 1 - f.r * fabs(a), c0 = dt.params[2 * i], c1 = dt.params[2 * i + 1];
        int ok = m >= 0 && m <= c1 && (c0 >= 0 || m >= -c0);
        if (ok) oom = graph_builder_add(&b, s, 0, 0) != 0;
    }
    fl_graph_free(&dt);
    if (oom) {
        graph_builder_free(&b);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    return graph_builder_finish(&b, 0, out, err);
}

/* Does a ball of radius rho touching simplex s contain every point (closed)? Points on the +
 * side need t >= tau(p), on the - side t <= tau(p), on H inside the smallest ball. */
static int alpha_enclosing(const classic_ctx *c, const uint32_t *s, double rho)
{
    gamma_frame f;
    if (!gamma_frame_init(&f, c->coords, c->dim, s) || rho < f.r) return 0;
    double lo = -INFINITY, hi = INFINITY, t = sqrt(rho * rho - f.r * f.r);
    for (size_t i = 0; i < c->n; i++) {
        int vertex = 0;
        for (int k = 0; k < c->dim; k++)
            vertex |= s[k] == i;
        if (vertex) continue;
        const double *p = cpt(c, (uint32_t)i);
        int side = gamma_frame_side(&f, p);
        if (side == 0) {
            double d2 = 0;
            for (int k = 0; k < c->dim; k++)
                d2 += (p[k] - f.center[k]) * (p[k] - f.center[k]);
            if (d2 > f.r * f.r) return 0;
            continue;
        }
        double tau = gamma_frame_offset(&f, p, side);
        if (side > 0) lo = fmax(lo, tau);
        if (side < 0) hi = fmin(hi, tau);
    }
    return (lo <= t && t <= hi) || (lo <= -t && -t <= hi);
}

/* α(a) shape, a > 0: simplices on a ball of radius 1/a containing all points. Its vertices are
 * extreme, so only convex-hull vertices are combined: O(h^k N) for h hull vertices. */
static fl_status alpha_positive(const classic_ctx *c, double a, fl_graph *out, fl_error *err)
{
    fl_graph ch;
    fl_status st = gamma_of(c, 0, -1, 1, 0, 0, 0, &ch, err);
    if (st != FL_OK) return st;
    char *on_hull = fl_calloc_array(c->n, 1);
    uint32_t *h = fl_alloc_array(c->n, sizeof *h);
    size_t nh = 0;
    graph_builder b;
    graph_builder_init(&b, c->dim, c->dim, c->n);
    int oom = !on_hull || !h;
    for (size_t i = 0; !oom && i < ch.simplex_count * (size_t)c->dim; i++)
        on_hull[ch.simplices[i]] = 1;
    for (size_t i = 0; !oom && i < c->n; i++)
        if (on_hull[i]) h[nh++] = (uint32_t)i;
    for (size_t i = 0; !oom && i < nh; i++)
        for (size_t j = i + 1; !oom && j < nh; j++)
            for (size_t k = c->dim == 3 ? j + 1 : 0; !oom && (c->dim == 2 || k < nh); k++) {
                uint32_t s[3] = {h[i], h[j], c->dim == 3 ? h[k] : 0};
                if (alpha_enclosing(c, s, 1 / a)) oom = graph_builder_add(&b, s, 0, 0) != 0;
                if (c->dim == 2) break;
            }
    free(on_hull);
    free(h);
    fl_graph_free(&ch);
    if (oom) {
        graph_builder_free(&b);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    return graph_builder_finish(&b, 0, out, err);
}

static fl_status beta_lune(classic_ctx *c, double beta, fl_graph *out, fl_error *err)
{
    if (beta < 0) return gamma_of(c, 0, beta, beta, 0, 0, 0, out, err); /* = β_c(b), §2.2.11 */
    fl_graph gg; /* N_βl(b) ⊇ the Gabriel disc for b >= 0, so β_l(b) ⊆ GG */
    fl_status st = gamma_of(c, 0, 0, 0, 0, 0, 0, &gg, err);
    if (st != FL_OK) return st;
    if (beta >= 1) {
        st = filter_edges(c, &gg, in_strip, 0, -1, out, err);
    } else {
        double k = 1 / (2 * (1 - beta));
        st = filter_edges(c, &gg, in_lune, k, 2 * k, out, err);
    }
    fl_graph_free(&gg);
    return st;
}

static fl_status edge_graph(classic_ctx *c, fl_graph_kind kind, fl_graph *out, fl_error *err)
{
    fl_graph dt;
    fl_status st = delaunay_edges(c, &dt, err);
    if (st != FL_OK) return st;
    if (kind == FL_GRAPH_GABRIEL) st = filter_edges(c, &dt, in_gabriel, 0, 0.5, out, err);
    if (kind == FL_GRAPH_RNG) st = filter_edges(c, &dt, in_lune, 1.0, 2.0, out, err);
    if (kind == FL_GRAPH_EMST) st = emst(c, &dt, out, err);
    if (kind == FL_GRAPH_NNG) st = nng(c, &dt, out, err);
    fl_graph_free(&dt);
    return st;
}

static fl_status classic_dispatch(classic_ctx *c, fl_graph_kind kind, double param, fl_graph *out,
                                  fl_error *err)
{
    int planar_only = kind == FL_GRAPH_BETA_CIRCLE || kind == FL_GRAPH_BETA_LUNE;
    if (planar_only && c->dim != 2)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "β-skeletons are defined for 2D points only (thesis §2.2.11)");
    if (planar_only && !(param >= -1 && param <= 1))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "β must be in [-1,1], got %g", param);
    switch (kind) {
    case FL_GRAPH_CONVEX_HULL:
        return gamma_of(c, 0, -1, 1, 0, 0, 0, out, err);
    case FL_GRAPH_DELAUNAY:
        return gamma_of(c, 1, -1, 1, 0, 1, 0, out, err);
    case FL_GRAPH_BETA_CIRCLE:
        return gamma_of(c, 0, param, param, 0, 0, 0, out, err);
    case FL_GRAPH_BETA_LUNE:
        return beta_lune(c, param, out, err);
    case FL_GRAPH_ALPHA_SHAPE:
        if (!isfinite(param))
            return fl_fail(err, FL_ERR_USAGE, NULL, -1, "α must be a finite number");
        if (param == 0) return gamma_of(c, 0, -1, 1, 0, 0, 0, out, err);
        return param < 0 ? alpha_negative(c, param, out, err) : alpha_positive(c, param, out, err);
    case FL_GRAPH_GABRIEL:
    case FL_GRAPH_RNG:
    case FL_GRAPH_EMST:
    case FL_GRAPH_NNG:
        return edge_graph(c, kind, out, err);
    }
    return fl_fail(err, FL_ERR_USAGE, NULL, -1, "unknown graph kind %d", (int)kind);
}

fl_status fl_classic_graph(const double *coords, size_t n, int dim, fl_graph_kind kind,
                           double param, fl_graph *out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "out is NULL");
    memset(out, 0, sizeof *out);
    fl_status st = graph_check_points(coords, n, dim, err);
    if (st != FL_OK) return st;
    classic_ctx c = {coords, n, dim, {0}, {0}};
    fl_vec_init(&c.local, sizeof(uint32_t));
    st = graph_grid_build(&c.grid, coords, n, dim, err);
    if (st == FL_OK) st = classic_dispatch(&c, kind, param, out, err);
    graph_grid_free(&c.grid);
    fl_vec_free(&c.local);
    return st;
}

fl_status fl_graph_kind_parse(const char *text, fl_graph_kind *kind, double *param, fl_error *err)
{
    static const struct {
        const char *name;
        fl_graph_kind kind;
        int needs_param;
    } names[] = {{"ch", FL_GRAPH_CONVEX_HULL, 0},
                 {"dt", FL_GRAPH_DELAUNAY, 0},
                 {"gabriel", FL_GRAPH_GABRIEL, 0},
                 {"rng", FL_GRAPH_RNG, 0},
                 {"emst", FL_GRAPH_EMST, 0},
                 {"nng", FL_GRAPH_NNG, 0},
                 {"beta-circle", FL_GRAPH_BETA_CIRCLE, 1},
                 {"beta-lune", FL_GRAPH_BETA_LUNE, 1},
                 {"alpha", FL_GRAPH_ALPHA_SHAPE, 1}};
    if (!text || !kind || !param) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "nothing to parse");
    const char *colon = strchr(text, ':');
    size_t len = colon ? (size_t)(colon - text) : strlen(text);
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        if (strlen(names[i].name) != len || strncmp(names[i].name, text, len) != 0) continue;
        *kind = names[i].kind;
        *param = 0;
        if (names[i].needs_param != (colon != NULL))
            return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                           names[i].needs_param ? "graph kind %s needs a parameter, e.g. %s:0.5"
                                                : "graph kind %s takes no parameter (got \"%s\")",
                           names[i].name, names[i].needs_param ? names[i].name : text);
        if (colon) {
            char *end;
            *param = strtod(colon + 1, &end);
            if (end == colon + 1 || *end != '\0' || !isfinite(*param))
                return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                               "graph kind \"%s\": \"%s\" is not a number", text, colon + 1);
        }
        return FL_OK;
    }
    return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                   "unknown graph kind \"%s\"; expected ch, dt, gabriel, rng, emst, nng, "
                   "beta-circle:B, beta-lune:B or alpha:A",
                   text);
}
