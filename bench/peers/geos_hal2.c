/* GEOS peer of the 2D flintstone evaluation (bench/hal2_eval.h), on the same rings and queries
 * as bench/eval_hal2.c: Douglas-Peucker simplification (GEOSSimplify) at the same tolerances,
 * point inclusion through a prepared polygon (GEOSPreparedContains; the point geometry is made
 * per query, as the 3.11 C API requires), and boundary-intersection detection (GEOSIntersects
 * on the rings as LinearRings, plain and prepared).
 *   geos_hal2 RINGS.xy ANSWERS_PREFIX [RINGS=20] [QUERIES=1000000] [PAIR_RINGS=300] */
#define _POSIX_C_SOURCE 200809L
#include <geos_c.h>
#include <stdarg.h>
#include <time.h>

#include "../hal2_eval.h"

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

static GEOSGeometry *ring_geometry(const h2_ring *r)
{
    GEOSCoordSequence *seq = GEOSCoordSeq_create((unsigned)r->n + 1, 2);
    for (size_t i = 0; i <= r->n; i++)
        GEOSCoordSeq_setXY(seq, (unsigned)i, r->xy[2 * (i % r->n)], r->xy[2 * (i % r->n) + 1]);
    return GEOSGeom_createLinearRing(seq);
}

static void approximation(const h2_set *s, size_t k)
{
    for (size_t f = 0; f < H2_FRACTIONS; f++) {
        size_t vertices = 0;
        double measured = 0, t = 0;
        for (size_t i = 0; i < k; i++) {
            const h2_ring *r = &s->rings[i];
            double d = h2_diagonal(r);
            GEOSGeometry *ring = ring_geometry(r);
            double t0 = now();
            GEOSGeometry *simple = GEOSSimplify(ring, h2_fractions[f] * d);
            t += now() - t0;
            const GEOSCoordSequence *seq = GEOSGeom_getCoordSeq(simple);
            unsigned len = 0;
            if (seq) GEOSCoordSeq_getSize(seq, &len);
            size_t m = len > 1 ? len - 1 : len; /* the closing repeat */
            double *xy = malloc((2 * m + 2) * sizeof *xy);
            for (unsigned j = 0; j < m; j++) GEOSCoordSeq_getXY(seq, j, &xy[2 * j], &xy[2 * j + 1]);
            vertices += m;
            if (m) measured = fmax(measured, h2_error(r, xy, m) / d);
            free(xy);
            GEOSGeom_destroy(simple);
            GEOSGeom_destroy(ring);
        }
        printf("APPROX method=geos-douglas-peucker fraction=%g vertices=%zu measured=%.3e "
               "seconds=%.6f\n",
               h2_fractions[f], vertices, measured, t);
    }
}

static void inclusion(const h2_set *s, size_t k, size_t total, const char *prefix)
{
    size_t m = total / k, inside = 0;
    double t = 0, tprep = 0;
    char path[1024];
    snprintf(path, sizeof path, "%s.inside", prefix);
    FILE *out = fopen(path, "wb");
    uint8_t *ans = malloc(m);
    for (size_t i = 0; i < k; i++) {
        GEOSGeometry *poly = GEOSGeom_createPolygon(ring_geometry(&s->rings[i]), NULL, 0);
        double *q = h2_queries(&s->rings[i], i, m);
        double t0 = now();
        const GEOSPreparedGeometry *prep = GEOSPrepare(poly);
        tprep += now() - t0;
        t0 = now();
        for (size_t j = 0; j < m; j++) {
            GEOSGeometry *pt = GEOSGeom_createPointFromXY(q[2 * j], q[2 * j + 1]);
            ans[j] = GEOSPreparedContains(prep, pt) == 1;
            GEOSGeom_destroy(pt);
        }
        t += now() - t0;
        for (size_t j = 0; j < m; j++) inside += ans[j];
        fwrite(ans, 1, m, out);
        GEOSPreparedGeom_destroy(prep);
        GEOSGeom_destroy(poly);
        free(q);
    }
    fclose(out);
    free(ans);
    printf("INSIDE method=geos-prepared-contains queries=%zu seconds=%.6f prepare_seconds=%.6f "
           "inside=%zu\n",
           m * k, t, tprep, inside);
}

static void intersection(const h2_set *s, size_t k, const char *prefix)
{
    uint32_t *p;
    size_t n = h2_pairs(s, k, &p), meeting = 0, meeting_prep = 0;
    GEOSGeometry **g = malloc(k * sizeof *g);
    for (size_t i = 0; i < k; i++) g[i] = ring_geometry(&s->rings[i]);
    uint8_t *ans = malloc(n + 1);
    double t0 = now();
    for (size_t i = 0; i < n; i++) {
        ans[i] = GEOSIntersects(g[p[2 * i]], g[p[2 * i + 1]]) == 1;
        meeting += ans[i];
    }
    double t = now() - t0;
    const GEOSPreparedGeometry **prep = malloc(k * sizeof *prep);
    t0 = now();
    for (size_t i = 0; i < k; i++) prep[i] = GEOSPrepare(g[i]);
    for (size_t i = 0; i < n; i++) meeting_prep += GEOSPreparedIntersects(prep[p[2 * i]], g[p[2 * i + 1]]) == 1;
    double tp = now() - t0;
    char path[1024];
    snprintf(path, sizeof path, "%s.pairs", prefix);
    FILE *out = fopen(path, "wb");
    fwrite(ans, 1, n, out);
    fclose(out);
    for (size_t i = 0; i < k; i++) {
        GEOSPreparedGeom_destroy(prep[i]);
        GEOSGeom_destroy(g[i]);
    }
    free(prep);
    free(g);
    free(ans);
    free(p);
    printf("INTERSECT method=geos-intersects pairs=%zu meeting=%zu seconds=%.6f\n", n, meeting, t);
    printf("INTERSECT method=geos-prepared-intersects pairs=%zu meeting=%zu seconds=%.6f "
           "(preparing included)\n",
           n, meeting_prep, tp);
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: geos_hal2 RINGS.xy ANSWERS_PREFIX [RINGS] [QUERIES] [PAIR_RINGS]\n");
        return 2;
    }
    size_t k = argc > 3 ? (size_t)atol(argv[3]) : 20;
    size_t queries = argc > 4 ? (size_t)atol(argv[4]) : 1000000;
    size_t kp = argc > 5 ? (size_t)atol(argv[5]) : 300;
    h2_set s;
    if (h2_load(argv[1], k > kp ? k : kp, &s)) return 1;
    if (k > s.count) k = s.count;
    if (kp > s.count) kp = s.count;
    initGEOS(on_geos_message, on_geos_message);
    approximation(&s, k);
    inclusion(&s, k, queries, argv[2]);
    intersection(&s, kp, argv[2]);
    finishGEOS();
    h2_free(&s);
    return 0;
}
