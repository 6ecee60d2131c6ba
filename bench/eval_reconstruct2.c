/* Our side of the 2D boundary-construction evaluation (bench/recon2_eval.h): constriction with
 * each of its three criteria, the convex hull as the baseline every method starts from, and
 * the Delaunay triangulation alone (its time is what constriction is compared to: the issue's
 * target is constriction <= 1.5x our own DT).
 *   eval_reconstruct2 RINGS.xy [MIN_POINTS [EDGES_DIR|- [all|gamma]]]
 * EDGES_DIR receives <method>.edges for bench/tools/recon2_symdiff; "gamma" runs only the
 * default criterion (the closed-curve timing of bench/workloads/reconstruct2_curve.sh).
 * Our RESULT lines also carry simple=<fraction of results that fl_polygon_check finds simple>
 * (exact predicates; a check on top of fl_reconstruct2's own guarantee). */
#define _POSIX_C_SOURCE 200809L
#include <time.h>

#include "flintstone.h"
#include "recon2_eval.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Boundary cycle -> undirected edges. */
static uint32_t *cycle_edges(const uint32_t *cycle, size_t m)
{
    uint32_t *e = malloc(2 * m * sizeof *e);
    for (size_t i = 0; i < m; i++) {
        e[2 * i] = cycle[i];
        e[2 * i + 1] = cycle[(i + 1) % m];
    }
    return e;
}

/* 1 when the cycle through c's points is a simple polygon (exact check). */
static int cycle_simple(const r2_case *c, const uint32_t *cycle, size_t m)
{
    double *xy = malloc(2 * m * sizeof *xy);
    for (size_t i = 0; i < m; i++) {
        xy[2 * i] = c->xy[2 * cycle[i]];
        xy[2 * i + 1] = c->xy[2 * cycle[i] + 1];
    }
    size_t rings[2] = {0, m}, polys[2] = {0, 1};
    fl_polygon p = {m, xy, 1, rings, 1, polys};
    fl_polygon_report rep;
    fl_error err;
    int simple = 0;
    if (fl_polygon_check(&p, &rep, &err) == FL_OK) {
        simple = rep.simple;
        fl_polygon_report_free(&rep);
    }
    free(xy);
    return simple;
}

static void print_simple(const char *method, const r2_score *sc, size_t simple)
{
    r2_print(sc, method);
    printf("SIMPLE method=%s cases=%zu simple=%.4f\n", method, sc->cases,
           sc->cases ? (double)simple / (double)sc->cases : 0);
}

static int run_delaunay(const r2_set *s, const char *dir)
{
    r2_score dt = {0}, hull = {0};
    size_t simple = 0;
    FILE *out = r2_edges_open(dir, "convex-hull");
    for (size_t k = 0; k < s->count; k++) {
        const r2_case *c = &s->cases[k];
        fl_dt2 d;
        fl_error err;
        double t0 = now();
        if (fl_dt2_build(c->xy, c->n, NULL, &d, &err)) {
            fprintf(stderr, "case %zu: %s\n", k, err.message);
            if (out) fclose(out);
            return 1;
        }
        dt.seconds += now() - t0;
        uint32_t *e = cycle_edges(d.hull, d.hull_count);
        r2_score_case(&hull, c, e, d.hull_count);
        r2_edges_write(out, k, e, d.hull_count);
        simple += cycle_simple(c, d.hull, d.hull_count);
        free(e);
        fl_dt2_free(&d);
    }
    if (out) fclose(out);
    dt.cases = hull.cases;
    hull.seconds = dt.seconds;
    print_simple("convex-hull", &hull, simple);
    printf("RESULT method=flintstone-delaunay cases=%zu seconds=%.6f\n", dt.cases, dt.seconds);
    return 0;
}

static int run_constriction(const r2_set *s, fl_reconstruct2_criterion crit, const char *name,
                            const char *dir)
{
    r2_score sc = {0};
    size_t simple = 0;
    fl_reconstruct2_options opt = {0};
    opt.criterion = crit;
    FILE *out = r2_edges_open(dir, name);
    for (size_t k = 0; k < s->count; k++) {
        const r2_case *c = &s->cases[k];
        fl_reconstruction2 rec;
        fl_error err;
        double t0 = now();
        if (fl_reconstruct2(c->xy, c->n, &opt, &rec, &err)) {
            fprintf(stderr, "case %zu (%s): %s\n", k, name, err.message);
            if (out) fclose(out);
            return 1;
        }
        sc.seconds += now() - t0;
        uint32_t *e = cycle_edges(rec.boundary, rec.boundary_count);
        r2_score_case(&sc, c, e, rec.boundary_count);
        r2_edges_write(out, k, e, rec.boundary_count);
        simple += cycle_simple(c, rec.boundary, rec.boundary_count);
        free(e);
        fl_reconstruction2_free(&rec);
    }
    if (out) fclose(out);
    print_simple(name, &sc, simple);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr,
                "usage: eval_reconstruct2 RINGS.xy [MIN_POINTS [EDGES_DIR|- [all|gamma]]]\n");
        return 2;
    }
    const char *dir = argc > 3 ? argv[3] : NULL;
    int all = !(argc > 4 && strcmp(argv[4], "gamma") == 0);
    r2_set s;
    if (r2_load(argv[1], argc > 2 ? (size_t)atol(argv[2]) : 20, &s)) return 1;
    int rc = run_delaunay(&s, dir) ||
             run_constriction(&s, FL_RECONSTRUCT2_GAMMA, "constriction-gamma", dir) ||
             (all && run_constriction(&s, FL_RECONSTRUCT2_AREA_CHANGE,
                                      "constriction-area-change", dir)) ||
             (all && run_constriction(&s, FL_RECONSTRUCT2_VORONOI_SKELETON,
                                      "constriction-voronoi-skeleton", dir));
    r2_free(&s);
    return rc;
}
