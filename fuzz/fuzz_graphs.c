/* Fuzzes fl_gamma_graph and fl_classic_graph on up to 10 decoded points in 2D or 3D. The γ-graph
 * is computed twice, by the default (Delaunay / output-sensitive) method and by the brute force
 * of Theorem 3.1, and the two simplex sets must be equal: a differential oracle. Classic graphs
 * only need to succeed or fail cleanly. */
#include "fuzz_common.h"

static int g_k;
static int cmp_k(const void *a, const void *b)
{
    const uint32_t *x = a, *y = b;
    for (int i = 0; i < g_k; i++)
        if (x[i] != y[i]) return x[i] < y[i] ? -1 : 1;
    return 0;
}

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return x < y ? -1 : x > y;
}

/* Sorts indices inside every simplex, then the simplices. */
static void canonical(fl_graph *g)
{
    int k = g->simplex_size;
    for (size_t s = 0; s < g->simplex_count; s++)
        qsort(g->simplices + (size_t)k * s, (size_t)k, sizeof(uint32_t), cmp_u32);
    g_k = k;
    qsort(g->simplices, g->simplex_count, (size_t)k * sizeof(uint32_t), cmp_k);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    uint8_t head = fz_byte(&in);
    int dim = (head & 1) ? 3 : 2;
    size_t n = fz_byte(&in) % 11;
    fl_error err;
    memset(&err, 0, sizeof err);
    if (head & 2) { /* classic graph */
        fl_graph_kind kind = (fl_graph_kind)(fz_byte(&in) % 9);
        double param = ((int)fz_byte(&in) % 21 - 10) / 10.0;
        double c[10 * 3];
        int bad = fz_coords(&in, c, n * (size_t)dim);
        fl_graph g;
        fl_status st = fl_classic_graph(c, n, dim, kind, param, &g, &err);
        fz_check_status(st, &err, "fl_classic_graph");
        if (st == FL_OK) {
            FZ_ASSERT(!bad, "NaN/Inf accepted");
            for (size_t i = 0; i < g.simplex_count * (size_t)g.simplex_size; i++)
                FZ_ASSERT(g.simplices[i] < n, "index out of range");
            fl_graph_free(&g);
        } else if (bad) {
            FZ_ASSERT(st == FL_ERR_INPUT || st == FL_ERR_USAGE, "NaN gave %d", (int)st);
        }
        return 0;
    }
    fl_gamma_params par;
    memset(&par, 0, sizeof par);
    par.range = fz_byte(&in) & 1;
    for (int i = 0; i < 4; i++) par.c[i] = ((int)fz_byte(&in) % 21 - 10) / 10.0;
    /* Mostly valid parameters (an invalid one is a clean FL_ERR_USAGE, covered by few inputs). */
    if (!(head & 4)) {
        double t;
        if (par.range == 0 && fabs(par.c[0]) > fabs(par.c[1]))
            t = par.c[0], par.c[0] = par.c[1], par.c[1] = t;
        if (par.range != 0 && par.c[0] > par.c[1]) t = par.c[0], par.c[0] = par.c[1], par.c[1] = t;
        if (par.range != 0 && par.c[2] > par.c[3]) t = par.c[2], par.c[2] = par.c[3], par.c[3] = t;
    }
    double c[10 * 3];
    int bad = fz_coords(&in, c, n * (size_t)dim);
    fl_graph_options opt = {0};
    fl_graph fast, brute;
    fl_status st = fl_gamma_graph(c, n, dim, &par, &opt, &fast, &err);
    fz_check_status(st, &err, "fl_gamma_graph");
    if (st != FL_OK) {
        if (bad) FZ_ASSERT(st == FL_ERR_INPUT || st == FL_ERR_USAGE, "NaN gave %d", (int)st);
        return 0;
    }
    FZ_ASSERT(!bad, "NaN/Inf accepted");
    /* The neighbourhood sizes c0', c1' are floating point, so the two methods may round a
     * borderline simplex differently on badly scaled input (found by this target: an edge of
     * length 1e30 next to unit spacing). Compare only well-scaled point sets. */
    for (size_t i = 0; i < n * (size_t)dim; i++)
        if (fabs(c[i]) > 1e6 || (c[i] != 0 && fabs(c[i]) < 1e-6)) {
            fl_graph_free(&fast);
            return 0;
        }
    opt.method = FL_GAMMA_BRUTE_FORCE;
    fl_error err2;
    st = fl_gamma_graph(c, n, dim, &par, &opt, &brute, &err2);
    FZ_ASSERT(st == FL_OK, "brute force failed where default succeeded: %s", err2.message);
    canonical(&fast);
    canonical(&brute);
    FZ_ASSERT(fast.simplex_size == brute.simplex_size, "simplex sizes differ");
    FZ_ASSERT(fast.simplex_count == brute.simplex_count, "default %zu simplices, brute %zu",
              fast.simplex_count, brute.simplex_count);
    FZ_ASSERT(memcmp(fast.simplices, brute.simplices,
                     fast.simplex_count * (size_t)fast.simplex_size * sizeof(uint32_t)) == 0,
              "simplex sets differ");
    fl_graph_free(&fast);
    fl_graph_free(&brute);
    return 0;
}
