/* GEOS peer of the 2D boundary-construction evaluation (bench/recon2_eval.h): GEOSConcaveHull
 * of the points as a MultiPoint, without holes, at edge-length ratio 0 (the most concave hull
 * GEOS makes) and 0.1. The hull's shell is mapped back to the input points by coordinates (GEOS
 * keeps them exactly) and scored like ours. Timed: making the MultiPoint and the hull.
 *   geos_concave RINGS.xy [MIN_POINTS [EDGES_DIR|- [RATIO]]]   (EDGES_DIR: bench/recon2_eval.h)
 * RATIO: only that length ratio (the closed-curve workload runs 0 alone: 1e5 points take GEOS
 * tens of seconds). */
#define _POSIX_C_SOURCE 200809L
#include <geos_c.h>
#include <stdarg.h>
#include <time.h>

#include "../recon2_eval.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void on_geos_message(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

/* Index of the point with coordinates (x, y), by binary search in the sorted order. */
static long lookup(const double *sorted_xyi, size_t n, double x, double y)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        const double *p = sorted_xyi + 3 * mid;
        if (p[0] < x || (p[0] == x && p[1] < y))
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo < n && sorted_xyi[3 * lo] == x && sorted_xyi[3 * lo + 1] == y)
        return (long)sorted_xyi[3 * lo + 2];
    return -1;
}

static int run(const r2_set *s, double ratio, const char *name, const char *dir)
{
    r2_score sc = {0};
    FILE *out = r2_edges_open(dir, name);
    for (size_t k = 0; k < s->count; k++) {
        const r2_case *c = &s->cases[k];
        double t0 = now();
        GEOSGeometry **pts = malloc(c->n * sizeof *pts);
        for (size_t i = 0; i < c->n; i++)
            pts[i] = GEOSGeom_createPointFromXY(c->xy[2 * i], c->xy[2 * i + 1]);
        GEOSGeometry *mp = GEOSGeom_createCollection(GEOS_MULTIPOINT, pts, (unsigned)c->n);
        free(pts);
        GEOSGeometry *hull = GEOSConcaveHull(mp, ratio, 0);
        sc.seconds += now() - t0;
        uint32_t *edges = NULL;
        size_t m = 0;
        if (hull && GEOSGeomTypeId(hull) == GEOS_POLYGON) {
            const GEOSCoordSequence *seq = GEOSGeom_getCoordSeq(GEOSGetExteriorRing(hull));
            unsigned len = 0;
            GEOSCoordSeq_getSize(seq, &len);
            double *sorted = malloc(c->n * 3 * sizeof *sorted);
            for (size_t i = 0; i < c->n; i++) {
                sorted[3 * i] = c->xy[2 * i];
                sorted[3 * i + 1] = c->xy[2 * i + 1];
                sorted[3 * i + 2] = (double)i;
            }
            qsort(sorted, c->n, 3 * sizeof *sorted, r2_cmp_xy);
            edges = malloc(2 * (size_t)len * sizeof *edges);
            long prev = -1;
            for (unsigned i = 0; i < len; i++) {
                double x, y;
                GEOSCoordSeq_getXY(seq, i, &x, &y);
                long id = lookup(sorted, c->n, x, y);
                if (id >= 0 && prev >= 0 && id != prev) {
                    edges[2 * m] = (uint32_t)prev;
                    edges[2 * m + 1] = (uint32_t)id;
                    m++;
                }
                prev = id;
            }
            free(sorted);
        }
        r2_score_case(&sc, c, edges, m);
        r2_edges_write(out, k, edges, m);
        free(edges);
        if (hull) GEOSGeom_destroy(hull);
        GEOSGeom_destroy(mp);
    }
    if (out) fclose(out);
    r2_print(&sc, name);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: geos_concave RINGS.xy [MIN_POINTS [EDGES_DIR|- [RATIO]]]\n");
        return 2;
    }
    r2_set s;
    if (r2_load(argv[1], argc > 2 ? (size_t)atol(argv[2]) : 20, &s)) return 1;
    initGEOS(on_geos_message, on_geos_message);
    const char *dir = argc > 3 ? argv[3] : NULL;
    int rc;
    if (argc > 4) {
        char name[64];
        snprintf(name, sizeof name, "geos-concave-hull-%s", argv[4]);
        rc = run(&s, atof(argv[4]), name, dir);
    } else {
        rc = run(&s, 0.0, "geos-concave-hull-0", dir) || run(&s, 0.1, "geos-concave-hull-0.1", dir);
    }
    finishGEOS();
    r2_free(&s);
    return rc;
}
