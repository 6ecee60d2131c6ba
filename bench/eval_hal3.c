/* Our side of the 3D flintstone benchmark (bench/workloads/hal3.sh, docs/hal.md "3D"). Files in
 * the format of bench/closest_eval.h (PREFIX.mesh, PREFIX.KIND.q), shared with the CGAL peer
 * bench/peers/hal3_cgal.cpp.
 *   eval_hal3 prepare MESH PREFIX N    PREFIX.mesh, N queries uniform in the bounding box
 *       (PREFIX.random.q), and two moved copies for the intersection test: PREFIX-near.mesh
 *       (rotated by 0.2 rad about z through the box centre and shifted by 10 % of the x extent:
 *       the surfaces cross) and PREFIX-far.mesh (rotated, shifted by 102 % of the x extent)
 *   eval_hal3 inside PREFIX [REPS]     times fl_hal3_build (once) and fl_hal3_contains on the
 *       queries (median of REPS); writes PREFIX.random.ours.a (one byte a query: 0 outside,
 *       1 inside, 2 on the surface)
 *   eval_hal3 brute PREFIX N A.a...    brute force (every triangle, +z ray, exact) on the first
 *       N queries; prints the number of disagreements with each answer file
 *   eval_hal3 compare A.a B.a          prints how many answers differ
 *   eval_hal3 intersect PREFIX OTHER [REPS]  builds both trees, times fl_hal3_intersect with
 *       first_only (the do_intersect question) and the full pair list
 *   eval_hal3 closed PREFIX            every level and adaptive approximation checked closed,
 *       oriented and manifold (fl_mesh_check); one CLOSED line */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <string.h>

#include "closest_eval.h"
#include "flintstone.h"
#include "hal/hal3_oracle.h"

static uint64_t rng = 0x853c49e6748fea9bull;
static double uniform(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) * 0x1p-53;
}

static int write_file(const char *path, const void *data, size_t size, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (!f) return 1;
    int bad = fwrite(data, size, n, f) != n;
    return (fclose(f) != 0) | bad;
}

static int write_mesh(const char *path, const fl_mesh *m)
{
    FILE *f = fopen(path, "wb");
    if (!f) return 1;
    uint64_t v = m->vertex_count, t = m->triangle_count;
    fwrite(&v, 8, 1, f);
    fwrite(&t, 8, 1, f);
    fwrite(m->xyz, sizeof(double), 3 * v, f);
    fwrite(m->tri, sizeof(uint32_t), 3 * t, f);
    return fclose(f) != 0;
}

/* The copy rotated by `angle` about the z axis through c and shifted by dx along x. */
static int write_moved(const char *prefix, const char *name, const fl_mesh *m, const double *c,
                       double angle, double dx)
{
    fl_mesh w = *m;
    w.xyz = malloc(3 * m->vertex_count * sizeof(double));
    if (!w.xyz) return 1;
    double cs = cos(angle), sn = sin(angle);
    for (size_t i = 0; i < m->vertex_count; i++) {
        const double *p = m->xyz + 3 * i;
        double x = p[0] - c[0], y = p[1] - c[1];
        w.xyz[3 * i] = c[0] + cs * x - sn * y + dx;
        w.xyz[3 * i + 1] = c[1] + sn * x + cs * y;
        w.xyz[3 * i + 2] = p[2];
    }
    char path[1024];
    snprintf(path, sizeof path, "%s-%s.mesh", prefix, name);
    int rc = write_mesh(path, &w);
    free(w.xyz);
    return rc;
}

static int prepare(const char *mesh_path, const char *prefix, size_t n)
{
    fl_mesh m;
    fl_error err;
    if (fl_read_mesh(mesh_path, &m, &err)) {
        fprintf(stderr, "%s: %s\n", mesh_path, err.message);
        return 1;
    }
    char path[1024];
    snprintf(path, sizeof path, "%s.mesh", prefix);
    int rc = write_mesh(path, &m);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < m.vertex_count; i++)
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], m.xyz[3 * i + k]);
            hi[k] = fmax(hi[k], m.xyz[3 * i + k]);
        }
    double *q = malloc(3 * n * sizeof *q + 1);
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) q[3 * i + k] = lo[k] + uniform() * (hi[k] - lo[k]);
    snprintf(path, sizeof path, "%s.random.q", prefix);
    rc |= write_file(path, q, 3 * sizeof(double), n);
    free(q);
    double c[3] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
    rc |= write_moved(prefix, "near", &m, c, 0.2, 0.1 * (hi[0] - lo[0]));
    rc |= write_moved(prefix, "far", &m, c, 0.2, 1.02 * (hi[0] - lo[0]));
    printf("PREPARED vertices=%zu triangles=%zu queries=%zu\n", m.vertex_count, m.triangle_count,
           n);
    fl_mesh_free(&m);
    return rc;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int build(const char *prefix, fl_mesh *m, fl_hal3 *hal, double *seconds)
{
    ce_mesh cm;
    if (ce_read_mesh(prefix, &cm)) {
        fprintf(stderr, "cannot read %s.mesh\n", prefix);
        return 1;
    }
    *m = (fl_mesh){cm.v, cm.xyz, cm.t, cm.tri};
    fl_error err;
    double t0 = ce_now();
    if (fl_hal3_build(m, NULL, hal, &err)) {
        fprintf(stderr, "%s: %s\n", prefix, err.message);
        return 1;
    }
    *seconds = ce_now() - t0;
    return 0;
}

static int inside(const char *prefix, int reps)
{
    size_t n = 0;
    double *q = ce_read_queries(prefix, "random", &n);
    fl_mesh m;
    fl_hal3 hal;
    double build_s;
    if (!q || build(prefix, &m, &hal, &build_s)) return 1;
    uint8_t *w = malloc(n + 1);
    double *t = malloc(reps * sizeof *t);
    fl_error err;
    for (int k = 0; k < reps; k++) {
        double t0 = ce_now();
        if (fl_hal3_contains(&hal, q, n, w, &err)) {
            fprintf(stderr, "%s\n", err.message);
            return 1;
        }
        t[k] = ce_now() - t0;
    }
    qsort(t, reps, sizeof *t, cmp_double);
    size_t count[3] = {0, 0, 0};
    for (size_t i = 0; i < n; i++) count[w[i]]++;
    char path[1024];
    snprintf(path, sizeof path, "%s.random.ours.a", prefix);
    int rc = write_file(path, w, 1, n);
    printf("RESULT method=flintstone queries=%zu build_s=%.6f query_s=%.6f nodes=%zu depth=%u "
           "inside=%zu boundary=%zu\n",
           n, build_s, t[reps / 2], hal.node_count, hal.depth, count[1], count[2]);
    fl_hal3_free(&hal);
    free(m.xyz);
    free(m.tri);
    free(w);
    free(t);
    free(q);
    return rc;
}

/* ---- brute force: the +z ray of tests/hal/hal3_oracle.h, every triangle ---- */

static uint8_t brute_inside(const fl_mesh *m, const double *x)
{
    return hal3_oracle_inside(m, x);
}

static uint8_t *read_answers(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    *n = (size_t)ftell(f);
    fseek(f, 0, SEEK_SET);
    uint8_t *a = malloc(*n + 1);
    if (fread(a, 1, *n, f) != *n) {
        free(a);
        a = NULL;
    }
    fclose(f);
    return a;
}

static int brute(const char *prefix, size_t nb, int nfiles, char **files)
{
    size_t n = 0;
    double *q = ce_read_queries(prefix, "random", &n);
    ce_mesh cm;
    if (!q || ce_read_mesh(prefix, &cm)) return 1;
    fl_mesh m = {cm.v, cm.xyz, cm.t, cm.tri};
    if (nb > n) nb = n;
    uint8_t *b = malloc(nb + 1);
    double t0 = ce_now();
    for (size_t i = 0; i < nb; i++) b[i] = brute_inside(&m, q + 3 * i);
    double sec = ce_now() - t0;
    printf("BRUTE queries=%zu seconds=%.3f", nb, sec);
    for (int f = 0; f < nfiles; f++) {
        size_t na = 0, diff = 0;
        uint8_t *a = read_answers(files[f], &na);
        if (!a || na < nb) return 1;
        for (size_t i = 0; i < nb; i++) diff += a[i] != b[i];
        printf(" diff%d=%zu", f, diff);
        free(a);
    }
    printf("\n");
    free(b);
    free(q);
    free(cm.xyz);
    free(cm.tri);
    return 0;
}

static int compare(const char *pa, const char *pb)
{
    size_t na = 0, nb = 0, diff = 0;
    uint8_t *a = read_answers(pa, &na), *b = read_answers(pb, &nb);
    if (!a || !b || na != nb) return 1;
    for (size_t i = 0; i < na; i++) diff += a[i] != b[i];
    printf("COMPARE n=%zu differ=%zu\n", na, diff);
    free(a);
    free(b);
    return 0;
}

static int intersect(const char *prefix, const char *other, int reps)
{
    fl_mesh ma, mb;
    fl_hal3 a, b;
    double ba, bb;
    char path[1024];
    snprintf(path, sizeof path, "%s-%s", prefix, other);
    if (build(prefix, &ma, &a, &ba) || build(path, &mb, &b, &bb)) return 1;
    double *t = malloc(reps * sizeof *t), *ta = malloc(reps * sizeof *ta);
    fl_error err;
    fl_hal3_pairs first, all;
    for (int k = 0; k < reps; k++) {
        /* The do_intersect question can take well under a microsecond (disjoint boxes): the
         * calls are repeated for at least 1 ms and the time per call is reported. */
        double t0 = ce_now(), el;
        size_t calls = 0;
        do {
            if (calls) fl_hal3_pairs_free(&first);
            if (fl_hal3_intersect(&a, &b, 1, &first, &err)) return 1;
            calls++;
        } while ((el = ce_now() - t0) < 1e-3);
        t[k] = el / (double)calls;
        t0 = ce_now();
        if (fl_hal3_intersect(&a, &b, 0, &all, &err)) return 1;
        ta[k] = ce_now() - t0;
        if (k + 1 < reps) {
            fl_hal3_pairs_free(&first);
            fl_hal3_pairs_free(&all);
        }
    }
    qsort(t, reps, sizeof *t, cmp_double);
    qsort(ta, reps, sizeof *ta, cmp_double);
    printf("RESULT method=flintstone intersect=%d pairs=%zu build_s=%.6f query_s=%.9f "
           "all_pairs_s=%.6f\n",
           first.count > 0, all.count, ba + bb, t[reps / 2], ta[reps / 2]);
    fl_hal3_pairs_free(&first);
    fl_hal3_pairs_free(&all);
    fl_hal3_free(&a);
    fl_hal3_free(&b);
    free(ma.xyz);
    free(ma.tri);
    free(mb.xyz);
    free(mb.tri);
    free(t);
    free(ta);
    return 0;
}

/* Whether ap is a closed, oriented, manifold mesh (fl_mesh_check without the self-intersection
 * search); *bad receives its boundary + non-manifold + misoriented edges. */
static int is_closed(const fl_mesh *ap, size_t *bad)
{
    fl_mesh_check_options o = {.skip_self_intersections = 1};
    fl_mesh_report r;
    fl_error err;
    if (fl_mesh_check(ap, &o, &r, &err)) return 0;
    *bad = r.boundary_edges + r.nonmanifold_edges + r.misoriented_edges;
    int ok = r.closed && r.oriented && r.manifold && *bad == 0;
    fl_mesh_report_free(&r);
    return ok;
}

/* Crack-freeness on a real mesh (docs/hal.md "Approximations are closed"): every level
 * 0..depth and the adaptive approximations at R/2 .. R/64 (R = level-0 ball radius) checked
 * with fl_mesh_check. Prints one CLOSED line. */
static int closed(const char *prefix)
{
    fl_mesh m;
    fl_hal3 hal;
    double build_s;
    if (build(prefix, &m, &hal, &build_s)) return 1;
    size_t levels = 0, levels_ok = 0, bounds = 0, bounds_ok = 0, worst = 0, bad = 0;
    int exact = 0;
    fl_error err;
    for (uint32_t l = 0; l <= hal.depth; l++) {
        fl_mesh ap;
        if (fl_hal3_approximate_level(&hal, l, &ap, NULL, &err)) return 1;
        levels++;
        levels_ok += (size_t)is_closed(&ap, &bad);
        worst = bad > worst ? bad : worst;
        if (l == hal.depth) exact = ap.triangle_count == m.triangle_count;
        fl_mesh_free(&ap);
    }
    double R = sqrt(hal.ball[3]);
    for (int k = 1; k <= 6; k++) {
        fl_mesh ap;
        double e = 0;
        if (fl_hal3_approximate_error(&hal, R / (1 << k), &ap, &e, NULL, &err)) return 1;
        bounds++;
        bounds_ok += (size_t)(is_closed(&ap, &bad) && e <= R / (1 << k));
        worst = bad > worst ? bad : worst;
        fl_mesh_free(&ap);
    }
    printf("CLOSED levels=%zu levels_closed=%zu bounds=%zu bounds_closed=%zu worst_bad_edges=%zu "
           "finest_is_input=%d\n",
           levels, levels_ok, bounds, bounds_ok, worst, exact);
    fl_hal3_free(&hal);
    free(m.xyz);
    free(m.tri);
    return 0;
}

int main(int argc, char **argv)
{
    (void)ce_write_distances; /* closest_eval.h's, not needed here */
    if (argc >= 5 && strcmp(argv[1], "prepare") == 0)
        return prepare(argv[2], argv[3], (size_t)atol(argv[4]));
    if (argc >= 3 && strcmp(argv[1], "inside") == 0)
        return inside(argv[2], argc > 3 ? atoi(argv[3]) : 3);
    if (argc >= 5 && strcmp(argv[1], "brute") == 0)
        return brute(argv[2], (size_t)atol(argv[3]), argc - 4, argv + 4);
    if (argc >= 4 && strcmp(argv[1], "compare") == 0) return compare(argv[2], argv[3]);
    if (argc >= 3 && strcmp(argv[1], "closed") == 0) return closed(argv[2]);
    if (argc >= 4 && strcmp(argv[1], "intersect") == 0)
        return intersect(argv[2], argv[3], argc > 4 ? atoi(argv[4]) : 3);
    fprintf(stderr, "usage: eval_hal3 prepare MESH PREFIX N | inside PREFIX [REPS] | "
                    "brute PREFIX N A.a... | compare A.a B.a | intersect PREFIX OTHER [REPS] | "
                    "closed PREFIX\n");
    return 2;
}
