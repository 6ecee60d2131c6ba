/* Our side of the closest-point evaluation (bench/closest_eval.h).
 *   eval_closest prepare MESH PREFIX N   writes PREFIX.mesh and N queries of each kind:
 *       random  uniform in the bounding box grown by 10 % of its diagonal, random order
 *       near    a vertex (random) plus an offset up to 1 % of the diagonal, random order
 *       path    a random walk of N steps of 0.05 % of the diagonal through the box, reflected
 *               at its faces: each query close to the last, the coherent case of §3.3 / §5.1
 *   eval_closest run PREFIX KIND [REPS] [collapse|collapse-static]   times the hierarchy's build and
 *       fl_sweep_closest (exact answers) on the queries; prints RESULT lines, writes
 *       PREFIX.KIND.ours.d; with "collapse" the edge-collapse hierarchy (fl_sweep_collapse_*)
 *       instead, writing PREFIX.KIND.collapse.d and the hierarchy's bytes; with
 *       "collapse-static" the same hierarchy with every query from its start level (the cursor is
 *       reset before each: no §5.1 coherence), writing PREFIX.KIND.collapse-static.d
 *   eval_closest compare A.d B.d          prints the largest |difference| of two distance files */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <string.h>

#include "closest_eval.h"
#include "flintstone.h"

static uint64_t rng = 0x853c49e6748fea9bull;
static double uniform(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) * 0x1p-53;
}

static int write_queries(const char *prefix, const char *kind, const double *q, size_t n)
{
    char path[1024];
    snprintf(path, sizeof path, "%s.%s.q", prefix, kind);
    FILE *f = fopen(path, "wb");
    if (!f) return 1;
    fwrite(q, 3 * sizeof(double), n, f);
    return fclose(f) != 0;
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
    FILE *f = fopen(path, "wb");
    uint64_t v = m.vertex_count, t = m.triangle_count;
    fwrite(&v, 8, 1, f);
    fwrite(&t, 8, 1, f);
    fwrite(m.xyz, sizeof(double), 3 * v, f);
    fwrite(m.tri, sizeof(uint32_t), 3 * t, f);
    fclose(f);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < v; i++)
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], m.xyz[3 * i + k]);
            hi[k] = fmax(hi[k], m.xyz[3 * i + k]);
        }
    double diag = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                       (hi[2] - lo[2]) * (hi[2] - lo[2]));
    double *q = malloc(3 * n * sizeof *q);
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            q[3 * i + k] = lo[k] - 0.1 * diag + uniform() * (hi[k] - lo[k] + 0.2 * diag);
    int rc = write_queries(prefix, "random", q, n);
    for (size_t i = 0; i < n; i++) {
        size_t vi = (size_t)(uniform() * (double)v);
        for (int k = 0; k < 3; k++) q[3 * i + k] = m.xyz[3 * vi + k] + (uniform() - 0.5) * 0.02 * diag;
    }
    rc |= write_queries(prefix, "near", q, n);
    double p[3], dir[3];
    for (int k = 0; k < 3; k++) p[k] = 0.5 * (lo[k] + hi[k]);
    for (size_t i = 0; i < n; i++) {
        double len = 0;
        for (int k = 0; k < 3; k++) {
            dir[k] = uniform() - 0.5;
            len += dir[k] * dir[k];
        }
        len = sqrt(len);
        for (int k = 0; k < 3; k++) {
            p[k] += dir[k] / len * 5e-4 * diag;
            if (p[k] < lo[k] || p[k] > hi[k]) p[k] -= 2 * dir[k] / len * 5e-4 * diag;
            q[3 * i + k] = p[k];
        }
    }
    rc |= write_queries(prefix, "path", q, n);
    free(q);
    fl_mesh_free(&m);
    printf("PREPARED vertices=%llu triangles=%llu diagonal=%g queries=%zu\n",
           (unsigned long long)v, (unsigned long long)t, diag, n);
    return rc;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The queries through one cursor reset before each (every query from the start level). */
static fl_status collapse_static(const fl_sweep_collapse *h, const double *q, size_t n,
                                 fl_closest *r, fl_error *err)
{
    fl_sweep_collapse_cursor *c;
    fl_status st = fl_sweep_collapse_cursor_new(h, &c, err);
    for (size_t i = 0; i < n && st == FL_OK; i++) {
        fl_sweep_collapse_cursor_reset(c);
        st = fl_sweep_collapse_cursor_closest(c, q + 3 * i, 0, r + i, err);
    }
    fl_sweep_collapse_cursor_free(c);
    return st;
}

/* One build + query run of the edge-collapse hierarchy (mode 1: one coherent cursor, the
 * library's batch call; mode 2: every query from the start level); *bytes gets its size. */
static int run_collapse_once(const fl_mesh *m, const double *q, size_t n, fl_closest *r,
                             int mode, double *build, double *query, size_t *bytes)
{
    fl_error err;
    fl_sweep_collapse *h;
    double t0 = ce_now();
    if (fl_sweep_collapse_build(m, NULL, &h, &err)) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    *build = ce_now() - t0;
    t0 = ce_now();
    if ((mode == 2 ? collapse_static(h, q, n, r, &err)
                   : fl_sweep_collapse_closest(h, q, n, 0, r, &err)) != FL_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    *query = ce_now() - t0;
    fl_sweep_collapse_info info;
    fl_sweep_collapse_info_get(h, &info, &err);
    *bytes = info.bytes + info.cursor_bytes;
    fl_sweep_collapse_free(h);
    return 0;
}

static int run(const char *prefix, const char *kind, int reps, int collapse)
{
    ce_mesh cm;
    size_t n = 0;
    double *q = ce_read_queries(prefix, kind, &n);
    if (ce_read_mesh(prefix, &cm) || !q) {
        fprintf(stderr, "cannot read %s inputs\n", prefix);
        return 1;
    }
    fl_mesh m = {cm.v, cm.xyz, cm.t, cm.tri};
    fl_error err;
    fl_closest *r = malloc(n * sizeof *r);
    double *build = malloc(reps * sizeof *build), *query = malloc(reps * sizeof *query);
    size_t bytes = 0;
    for (int k = 0; k < reps && collapse; k++)
        if (run_collapse_once(&m, q, n, r, collapse, build + k, query + k, &bytes)) return 1;
    for (int k = 0; k < reps && !collapse; k++) {
        fl_sweep *sw;
        double t0 = ce_now();
        if (fl_sweep_build(&m, NULL, &sw, &err)) {
            fprintf(stderr, "%s\n", err.message);
            return 1;
        }
        build[k] = ce_now() - t0;
        t0 = ce_now();
        if (fl_sweep_closest(sw, q, n, 0, r, &err)) {
            fprintf(stderr, "%s\n", err.message);
            return 1;
        }
        query[k] = ce_now() - t0;
        fl_sweep_free(sw);
    }
    qsort(build, reps, sizeof *build, cmp_double);
    qsort(query, reps, sizeof *query, cmp_double);
    double *d = malloc(n * sizeof *d);
    size_t reused = 0;
    for (size_t i = 0; i < n; i++) {
        d[i] = r[i].distance;
        reused += r[i].reused;
    }
    const char *tag[] = {"ours", "collapse", "collapse-static"};
    ce_write_distances(prefix, kind, tag[collapse], d, n);
    printf("RESULT method=flintstone%s kind=%s queries=%zu build_s=%.6f query_s=%.6f reused=%zu "
           "bytes_per_triangle=%.1f\n",
           collapse == 2 ? "_collapse_static" : collapse ? "_collapse" : "", kind, n,
           build[reps / 2], query[reps / 2], reused,
           (double)bytes / (double)m.triangle_count);
    free(d);
    free(r);
    free(q);
    free(build);
    free(query);
    free(cm.xyz);
    free(cm.tri);
    return 0;
}

static int compare(const char *a, const char *b)
{
    FILE *fa = fopen(a, "rb"), *fb = fopen(b, "rb");
    if (!fa || !fb) return 1;
    double x, y, worst = 0, scale = 0;
    size_t n = 0;
    while (fread(&x, sizeof x, 1, fa) == 1 && fread(&y, sizeof y, 1, fb) == 1) {
        worst = fmax(worst, fabs(x - y));
        scale = fmax(scale, fabs(x));
        n++;
    }
    fclose(fa);
    fclose(fb);
    printf("COMPARE n=%zu max_abs_diff=%.3e max_distance=%.6g\n", n, worst, scale);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc >= 5 && strcmp(argv[1], "prepare") == 0)
        return prepare(argv[2], argv[3], (size_t)atol(argv[4]));
    if (argc >= 4 && strcmp(argv[1], "run") == 0)
        return run(argv[2], argv[3], argc > 4 ? atoi(argv[4]) : 3,
                   argc <= 5                                    ? 0
                   : strcmp(argv[5], "collapse") == 0        ? 1
                   : strcmp(argv[5], "collapse-static") == 0 ? 2
                                                             : 0);
    if (argc >= 4 && strcmp(argv[1], "compare") == 0) return compare(argv[2], argv[3]);
    fprintf(stderr, "usage: eval_closest prepare MESH PREFIX N | "
                    "run PREFIX KIND [REPS] [collapse|collapse-static] | compare A.d B.d\n");
    return 2;
}
