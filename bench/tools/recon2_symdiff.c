/* One scorer for the area of every method's result in the 2D boundary-construction evaluation
 * (docs/reconstruct2d.md, bench/recon2_eval.h): reads the rings again (same cases, same shuffle)
 * and the <method>.edges files the evaluation programs wrote, turns each method's boundary edges
 * into a region and prints, per method, the symmetric-difference area between that region and
 * the true ring, relative to the ring's area: |A xor B| / |A|.
 *   recon2_symdiff RINGS.xy MIN_POINTS METHOD.edges...
 * The overlay is GEOS's (GEOSSymDifference, GEOSArea): an independent method, and the same code
 * for every method, ours included. The region of a method's edges:
 *   - edges forming one cycle (every touched point of degree 2, connected): the polygon of that
 *     cycle; when GEOS finds it invalid (self-intersecting), GEOSMakeValid repairs it and the case
 *     is counted in made_valid;
 *   - any other edge set (several components, pinched vertices: CGAL's alpha shape): the
 *     linework noded by GEOSUnaryUnion and closed into an area by GEOSBuildArea (rings inside
 *     rings become holes); counted in linework;
 *   - no edges: the empty region (relative difference 1); counted in empty.
 * The true ring is checked the same way (truth_made_valid). Prints per method:
 *   SYMDIFF method=<file name without .edges> cases=<n> median=<median> mean=<mean>
 *           filled_median=<median with the region's holes filled>
 *           area_ratio_median=<median of |B| / |A|> cycles=<k> made_valid=<k> linework=<k>
 *           empty=<k> failed=<k> truth_made_valid=<k>
 * (failed: GEOS gave no result; such a case is scored 1, as if nothing matched.) */
#define _POSIX_C_SOURCE 200809L
#include <geos_c.h>
#include <stdarg.h>

#include "../recon2_eval.h"

static void on_geos_notice(const char *fmt, ...)
{
    (void)fmt; /* isValid's "Self-intersection at ..." notices: counted, not printed */
}

static void on_geos_message(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

typedef struct counts {
    size_t cycles, made_valid, linework, empty, failed, truth_made_valid;
} counts;

/* Polygon through the points of c in the order `order` (m points); repaired when invalid. */
static GEOSGeometry *ring_polygon(const r2_case *c, const uint32_t *order, size_t m, size_t *fixed)
{
    GEOSCoordSequence *seq = GEOSCoordSeq_create((unsigned)m + 1, 2);
    for (size_t i = 0; i <= m; i++) {
        uint32_t p = order[i % m];
        GEOSCoordSeq_setXY(seq, (unsigned)i, c->xy[2 * p], c->xy[2 * p + 1]);
    }
    GEOSGeometry *g = GEOSGeom_createPolygon(GEOSGeom_createLinearRing(seq), NULL, 0);
    if (GEOSisValid(g) != 1) {
        GEOSGeometry *v = GEOSMakeValid(g);
        GEOSGeom_destroy(g);
        g = v;
        (*fixed)++;
    }
    return g;
}

/* The cycle order of the m edges when they form one cycle, else NULL. */
static uint32_t *edge_cycle(size_t n, const uint32_t *e, size_t m)
{
    if (m < 3) return NULL;
    uint32_t *adj = malloc(2 * n * sizeof *adj);
    unsigned char *deg = calloc(n, 1);
    int ok = 1;
    for (size_t i = 0; i < m && ok; i++)
        for (int s = 0; s < 2 && ok; s++) {
            uint32_t a = e[2 * i + s], b = e[2 * i + 1 - s];
            if (a == b || deg[a] == 2) ok = 0;
            else adj[2 * a + deg[a]++] = b;
        }
    uint32_t *order = NULL;
    if (ok) {
        order = malloc(m * sizeof *order);
        uint32_t prev = e[0], cur = e[1];
        order[0] = e[0];
        size_t k = 1;
        while (cur != e[0] && k < m) {
            order[k++] = cur;
            uint32_t next = adj[2 * cur] == prev ? adj[2 * cur + 1] : adj[2 * cur];
            prev = cur;
            cur = next;
        }
        if (cur != e[0] || k != m) { /* more than one component */
            free(order);
            order = NULL;
        }
    }
    free(adj);
    free(deg);
    return order;
}

/* The noded linework of the edges closed into an area (holes where rings nest). */
static GEOSGeometry *linework_area(const r2_case *c, const uint32_t *e, size_t m)
{
    GEOSGeometry **lines = malloc(m * sizeof *lines);
    for (size_t i = 0; i < m; i++) {
        GEOSCoordSequence *seq = GEOSCoordSeq_create(2, 2);
        for (unsigned s = 0; s < 2; s++)
            GEOSCoordSeq_setXY(seq, s, c->xy[2 * e[2 * i + s]], c->xy[2 * e[2 * i + s] + 1]);
        lines[i] = GEOSGeom_createLineString(seq);
    }
    GEOSGeometry *ml = GEOSGeom_createCollection(GEOS_MULTILINESTRING, lines, (unsigned)m);
    free(lines);
    GEOSGeometry *noded = GEOSUnaryUnion(ml);
    GEOSGeom_destroy(ml);
    if (!noded) return NULL;
    GEOSGeometry *area = GEOSBuildArea(noded);
    GEOSGeom_destroy(noded);
    return area;
}

/* The region without its holes: the union of the outer rings of its polygons (what a user who
 * keeps only the outer boundary gets; matters for CGAL's alpha shapes, whose region has holes
 * where the interior triangles are larger than alpha). NULL when it has no polygon. */
static GEOSGeometry *fill_holes(const GEOSGeometry *g)
{
    int parts = GEOSGetNumGeometries(g);
    GEOSGeometry **shells = malloc((parts > 0 ? (size_t)parts : 1) * sizeof *shells);
    unsigned k = 0;
    for (int i = 0; i < parts; i++) {
        const GEOSGeometry *p = GEOSGetGeometryN(g, i);
        if (GEOSGeomTypeId(p) != GEOS_POLYGON || GEOSisEmpty(p)) continue;
        GEOSGeometry *ring = GEOSGeom_clone(GEOSGetExteriorRing(p));
        shells[k++] = GEOSGeom_createPolygon(ring, NULL, 0);
    }
    GEOSGeometry *u = NULL;
    if (k) {
        GEOSGeometry *mp = GEOSGeom_createCollection(GEOS_MULTIPOLYGON, shells, k);
        u = GEOSUnaryUnion(mp);
        GEOSGeom_destroy(mp);
    }
    free(shells);
    return u;
}

/* |t xor r| / |t|, or 1 when GEOS fails (counted). */
static double rel_symdiff(const GEOSGeometry *t, double at, const GEOSGeometry *r, counts *k)
{
    double d = 0;
    GEOSGeometry *x = r ? GEOSSymDifference(t, r) : NULL;
    int ok = x && GEOSArea(x, &d) == 1 && at > 0;
    if (x) GEOSGeom_destroy(x);
    if (!ok) k->failed++;
    return ok ? d / at : 1;
}

/* Scores one case: out[0] = relative symmetric difference, out[1] = the same with the region's
 * holes filled, out[2] = |region| / |ring|. */
static void score(const r2_case *c, const uint32_t *e, size_t m, counts *k, double out[3])
{
    uint32_t *truth_order = malloc(c->n * sizeof *truth_order);
    for (size_t i = 0; i < c->n; i++) truth_order[c->truth[i]] = (uint32_t)i;
    GEOSGeometry *t = ring_polygon(c, truth_order, c->n, &k->truth_made_valid);
    free(truth_order);
    double at = 0, ar = 0;
    GEOSArea(t, &at);
    GEOSGeometry *r = NULL;
    uint32_t *order = edge_cycle(c->n, e, m);
    if (m == 0) {
        k->empty++;
    } else if (order) {
        k->cycles++;
        r = ring_polygon(c, order, m, &k->made_valid);
    } else {
        k->linework++;
        r = linework_area(c, e, m);
    }
    free(order);
    out[0] = out[1] = 1;
    out[2] = 0;
    if (r) {
        if (GEOSArea(r, &ar) == 1 && at > 0) out[2] = ar / at;
        out[0] = rel_symdiff(t, at, r, k);
        GEOSGeometry *filled = fill_holes(r);
        out[1] = filled ? rel_symdiff(t, at, filled, k) : out[0];
        if (filled) GEOSGeom_destroy(filled);
        GEOSGeom_destroy(r);
    } else if (m) {
        k->failed++;
    }
    GEOSGeom_destroy(t);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(const double *sorted, size_t n)
{
    return n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
}

static int score_file(const r2_set *s, const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        fprintf(stderr, "cannot open %s\n", path);
        return 1;
    }
    size_t cap = s->count ? s->count : 1;
    double *rel = malloc(cap * sizeof *rel), *ratio = malloc(cap * sizeof *ratio), sum = 0;
    double *filled = malloc(cap * sizeof *filled);
    counts k = {0};
    size_t done = 0;
    int rc = 0;
    for (; done < s->count; done++) {
        const r2_case *c = &s->cases[done];
        size_t id, m;
        if (fscanf(f, " case %zu %zu", &id, &m) != 2 || id != done || m > 4 * c->n + 16) {
            fprintf(stderr, "%s: bad header for case %zu\n", path, done);
            rc = 1;
            break;
        }
        uint32_t *e = malloc((2 * m + 1) * sizeof *e);
        for (size_t i = 0; i < 2 * m && !rc; i++)
            if (fscanf(f, "%u", &e[i]) != 1 || e[i] >= c->n) rc = 1;
        if (rc) {
            fprintf(stderr, "%s: bad edge in case %zu\n", path, done);
            free(e);
            break;
        }
        double o[3];
        score(c, e, m, &k, o);
        rel[done] = o[0];
        filled[done] = o[1];
        ratio[done] = o[2];
        sum += rel[done];
        free(e);
    }
    fclose(f);
    if (!rc) {
        qsort(rel, done, sizeof *rel, cmp_double);
        qsort(ratio, done, sizeof *ratio, cmp_double);
        qsort(filled, done, sizeof *filled, cmp_double);
        double med = median(rel, done);
        const char *base = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
        int len = (int)(strstr(base, ".edges") ? (size_t)(strstr(base, ".edges") - base)
                                                : strlen(base));
        printf("SYMDIFF method=%.*s cases=%zu median=%.6f mean=%.6f filled_median=%.6f "
               "area_ratio_median=%.4f cycles=%zu made_valid=%zu linework=%zu empty=%zu "
               "failed=%zu truth_made_valid=%zu\n",
               len, base, done, med, sum / (double)done, median(filled, done),
               median(ratio, done), k.cycles,
               k.made_valid, k.linework, k.empty, k.failed, k.truth_made_valid);
    }
    free(rel);
    free(ratio);
    free(filled);
    return rc;
}

int main(int argc, char **argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: recon2_symdiff RINGS.xy MIN_POINTS METHOD.edges...\n");
        return 2;
    }
    r2_set s;
    if (r2_load(argv[1], (size_t)atol(argv[2]), &s)) return 1;
    if (s.count == 0) {
        fprintf(stderr, "no rings\n");
        r2_free(&s);
        return 1;
    }
    initGEOS(on_geos_notice, on_geos_message);
    int rc = 0;
    for (int i = 3; i < argc; i++) rc |= score_file(&s, argv[i]);
    finishGEOS();
    r2_free(&s);
    return rc;
}
