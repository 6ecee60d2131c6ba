/* Our side of the 2D boundary-construction evaluation (bench/recon2_eval.h): constriction with
 * each of its three criteria, the convex hull as the baseline every method starts from, and
 * the Delaunay triangulation alone (its time is what constriction is compared to: the issue's
 * target is constriction <= 1.5x our own DT).
 *   eval_reconstruct2 RINGS.xy [MIN_POINTS] */
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

static int run_delaunay(const r2_set *s)
{
    r2_score dt = {0}, hull = {0};
    for (size_t k = 0; k < s->count; k++) {
        const r2_case *c = &s->cases[k];
        fl_dt2 d;
        fl_error err;
        double t0 = now();
        if (fl_dt2_build(c->xy, c->n, NULL, &d, &err)) {
            fprintf(stderr, "case %zu: %s\n", k, err.message);
            return 1;
        }
        dt.seconds += now() - t0;
        uint32_t *e = cycle_edges(d.hull, d.hull_count);
        r2_score_case(&hull, c, e, d.hull_count);
        free(e);
        fl_dt2_free(&d);
    }
    dt.cases = hull.cases;
    hull.seconds = dt.seconds;
    r2_print(&hull, "convex-hull");
    printf("RESULT method=flintstone-delaunay cases=%zu seconds=%.6f\n", dt.cases, dt.seconds);
    return 0;
}

static int run_constriction(const r2_set *s, fl_reconstruct2_criterion crit, const char *name)
{
    r2_score sc = {0};
    fl_reconstruct2_options opt = {0};
    opt.criterion = crit;
    for (size_t k = 0; k < s->count; k++) {
        const r2_case *c = &s->cases[k];
        fl_reconstruction2 rec;
        fl_error err;
        double t0 = now();
        if (fl_reconstruct2(c->xy, c->n, &opt, &rec, &err)) {
            fprintf(stderr, "case %zu (%s): %s\n", k, name, err.message);
            return 1;
        }
        sc.seconds += now() - t0;
        uint32_t *e = cycle_edges(rec.boundary, rec.boundary_count);
        r2_score_case(&sc, c, e, rec.boundary_count);
        free(e);
        fl_reconstruction2_free(&rec);
    }
    r2_print(&sc, name);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: eval_reconstruct2 RINGS.xy [MIN_POINTS]\n");
        return 2;
    }
    r2_set s;
    if (r2_load(argv[1], argc > 2 ? (size_t)atol(argv[2]) : 20, &s)) return 1;
    int rc = run_delaunay(&s) || run_constriction(&s, FL_RECONSTRUCT2_GAMMA, "constriction-gamma") ||
             run_constriction(&s, FL_RECONSTRUCT2_AREA_CHANGE, "constriction-area-change") ||
             run_constriction(&s, FL_RECONSTRUCT2_VORONOI_SKELETON, "constriction-voronoi-skeleton");
    r2_free(&s);
    return rc;
}
