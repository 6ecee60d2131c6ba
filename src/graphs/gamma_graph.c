/* The γ-neighbourhood graph (thesis §3.2-3.5): parameter handling, the Theorem 3.1 brute force
 * and the choice of construction. */
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "graphs/gamma_internal.h"

static fl_status cancelled(fl_error *err)
{
    return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
}

static fl_status add_if_accepted(const double *coords, size_t n, int dim, const fl_gamma_params *p,
                                 gamma_part part, const uint32_t *s, graph_builder *b,
                                 fl_error *err)
{
    gamma_value v;
    if (!gamma_simplex_value_all(coords, n, dim, s, &v) || !gamma_params_accept(p, &v))
        return FL_OK;
    if ((part == GAMMA_DELAUNAY_PART && !v.delaunay) ||
        (part == GAMMA_NON_DELAUNAY_PART && v.delaunay))
        return FL_OK;
    if (graph_builder_add(b, s, v.c0, v.c1))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory collecting simplices");
    return FL_OK;
}

fl_status gamma_brute_force(const double *coords, size_t n, int dim, const fl_gamma_params *p,
                            gamma_part part, const fl_graph_options *opt, graph_builder *b,
                            fl_error *err)
{
    fl_progress_fn progress = opt ? opt->progress : NULL;
    void *user = opt ? opt->progress_user : NULL;
    uint32_t s[3] = {0, 0, 0};
    for (size_t i = 0; i < n; i++) {
        if (fl_progress(progress, user, "gamma brute force", (double)i / (double)n))
            return cancelled(err);
        s[0] = (uint32_t)i;
        for (size_t j = i + 1; j < n; j++) {
            s[1] = (uint32_t)j;
            fl_status st = FL_OK;
            if (dim == 2) st = add_if_accepted(coords, n, dim, p, part, s, b, err);
            for (size_t k = j + 1; dim == 3 && k < n && st == FL_OK; k++) {
                s[2] = (uint32_t)k;
                st = add_if_accepted(coords, n, dim, p, part, s, b, err);
            }
            if (st != FL_OK) return st;
        }
    }
    return FL_OK;
}

/* The smallest c1' the parameters can accept: c1' >= c2 (Def. 3.3), c1' >= c1 (Lemmas 3.1 and
 * 3.2: the second term of 3.2 needs c1' >= |c0| >= 0). */
static double c1_floor(const fl_gamma_params *p)
{
    return p->range ? p->c[2] : p->c[1];
}

/* Can a simplex with an empty ball (c1' >= 0) be accepted? */
static int accepts_delaunay(const fl_gamma_params *p)
{
    return !p->range || p->c[3] >= 0;
}

/* The simplices with an empty ball: a subset of the Delaunay triangulation's (Thm. 3.2). */
static fl_status delaunay_part(const double *coords, size_t n, int dim, const fl_gamma_params *p,
                               const fl_graph_options *opt, graph_builder *b, fl_error *err)
{
    return gamma_delaunay_part(coords, n, dim, p, opt, b, err);
}

/* The simplices without an empty ball (c1' < 0). */
static fl_status non_delaunay_part(const double *coords, size_t n, int dim,
                                   const fl_gamma_params *p, const fl_graph_options *opt,
                                   graph_builder *b, fl_error *err)
{
    double kappa = -c1_floor(p);
    if (dim == 2 && kappa < 1) return gamma_lens_edges(coords, n, p, kappa, opt, b, err);
    if (dim == 3 && kappa < 1) return gamma_lens_triangles(coords, n, p, kappa, opt, b, err);
    return gamma_brute_force(coords, n, dim, p, GAMMA_NON_DELAUNAY_PART, opt, b, err);
}

static fl_status gamma_graph_run(const double *coords, size_t n, int dim,
                                 const fl_gamma_params *params, const fl_graph_options *opt,
                                 fl_graph *out, fl_error *err);

/* γ-graphs are invariant under scaling (Def. 3.1 measures every ball against the simplex's own
 * radius), but the neighbourhood sizes c0', c1' are computed in floating point, where squared
 * lengths under/overflow at coordinates near 1e-300 / 1e+300 (found by tests/degenerate: the
 * default method and the brute force disagreed on a 4x4 grid at 1e-300). Returns a copy scaled
 * by a power of two that brings max |x| into [1, 2), or NULL when no scaling is needed or the
 * scaling would not be exact (a coordinate would become subnormal). */
static double *rescaled_copy(const double *coords, size_t n, int dim)
{
    double max = 0, min = INFINITY;
    for (size_t i = 0; i < n * (size_t)dim; i++) {
        double a = fabs(coords[i]);
        if (a > max) max = a;
        if (a > 0 && a < min) min = a;
    }
    if (max == 0) return NULL;
    int k = -ilogb(max);
    if (k > -64 && k < 64) return NULL; /* moderate scale: nothing to gain */
    if (k < 0 && ldexp(min, k) < DBL_MIN) return NULL; /* scaling down must stay exact */
    double *c = fl_alloc_array(n * (size_t)dim, sizeof *c);
    if (!c) return NULL; /* fall back to the unscaled input */
    for (size_t i = 0; i < n * (size_t)dim; i++) c[i] = ldexp(coords[i], k);
    return c;
}

fl_status fl_gamma_graph(const double *coords, size_t n, int dim, const fl_gamma_params *params,
                         const fl_graph_options *opt, fl_graph *out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "out is NULL");
    memset(out, 0, sizeof *out);
    fl_status st = graph_check_points(coords, n, dim, err);
    if (st == FL_OK) st = gamma_check_params(params, err);
    if (st != FL_OK) return st;
    double *scaled = rescaled_copy(coords, n, dim);
    st = gamma_graph_run(scaled ? scaled : coords, n, dim, params, opt, out, err);
    free(scaled);
    return st;
}

static fl_status gamma_graph_run(const double *coords, size_t n, int dim,
                                 const fl_gamma_params *params, const fl_graph_options *opt,
                                 fl_graph *out, fl_error *err)
{
    fl_status st = FL_OK;
    graph_builder b;
    graph_builder_init(&b, dim, dim, n);
    if (opt && opt->method == FL_GAMMA_BRUTE_FORCE) {
        st = gamma_brute_force(coords, n, dim, params, GAMMA_ALL, opt, &b, err);
    } else {
        if (accepts_delaunay(params)) st = delaunay_part(coords, n, dim, params, opt, &b, err);
        if (st == FL_OK && c1_floor(params) < 0)
            st = non_delaunay_part(coords, n, dim, params, opt, &b, err);
    }
    if (st != FL_OK) {
        graph_builder_free(&b);
        return st;
    }
    return graph_builder_finish(&b, opt && opt->want_params, out, err);
}

int fl_gamma_simplex_params(const double *coords, size_t n, int dim, const uint32_t *simplex,
                            double *c0, double *c1)
{
    if (!coords || !simplex || (dim != 2 && dim != 3) || !c0 || !c1) return -1;
    for (int i = 0; i < dim; i++) {
        if (simplex[i] >= n) return -1;
        for (int j = 0; j < i; j++)
            if (simplex[i] == simplex[j]) return -1;
    }
    gamma_value v;
    if (!gamma_simplex_value_all(coords, n, dim, simplex, &v)) return 0;
    *c0 = v.c0;
    *c1 = v.c1;
    return 1;
}

fl_status fl_gamma_params_parse(const char *text, fl_gamma_params *params, fl_error *err)
{
    if (!text || !params) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "nothing to parse");
    memset(params, 0, sizeof *params);
    const char *s = text;
    int count = 0;
    while (count < 4) {
        char *end;
        errno = 0;
        double v = strtod(s, &end);
        if (end == s || errno)
            return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                           "γ parameters \"%s\": expected numbers separated by commas", text);
        params->c[count++] = v;
        if (*end == '\0') break;
        if (*end != ',' || count == 4)
            return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                           "γ parameters \"%s\": expected c0,c1 or c0,c1,c2,c3", text);
        s = end + 1;
    }
    if (count != 2 && count != 4)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "γ parameters \"%s\": expected 2 (c0,c1) or 4 (c0,c1,c2,c3) numbers, got %d",
                       text, count);
    params->range = count == 4;
    return gamma_check_params(params, err);
}
