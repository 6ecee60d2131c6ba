/* 3D boundary construction at scale (docs/reconstruct3d.md, "Speed at 1e5 and 1e6 points";
 * issue 6's target: the whole reconstruction <= 3x our own 3D Delaunay time):
 *
 *   recon3_scale N SEED [OUT.xyz]
 *
 * samples N points on a smooth closed genus-0 surface (a radially perturbed sphere,
 * r(d) = 1 + 0.2 d_x d_y + 0.15 sin(3 d_z) for a uniform direction d: star-shaped, curvature
 * varying by about 3x, sampling density by about 1.5x), times fl_dt3_build and fl_reconstruct3
 * (γ-indicator; its Delaunay build included) on the same points in the same process, alternately,
 * three rounds each, and prints one line
 *
 *   RESULT n=N dt=SECONDS rec=SECONDS ratio=R on_boundary=B/U closed=.. manifold=.. genus=..
 *          flips=F augmented_c0=C
 *
 * (plus dt_cpu, rec_cpu, cpu_ratio: the same in process CPU time, steadier on a loaded machine)
 * with median wall-clock seconds and the reconstruction checked by fl_mesh_check (no
 * self-intersection search: O(T log T) it would dominate). OUT.xyz, when given, receives the
 * points (%.17g) so that a peer can reconstruct exactly the same input. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "flintstone.h"

static double clock_s(clockid_t id)
{
    struct timespec t;
    clock_gettime(id, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double now(void)
{
    return clock_s(CLOCK_MONOTONIC);
}

static double cpu(void)
{
    return clock_s(CLOCK_PROCESS_CPUTIME_ID);
}

static uint64_t splitmix64(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static double uniform(uint64_t *s)
{
    return (double)(splitmix64(s) >> 11) / 9007199254740992.0;
}

/* A uniform direction (Marsaglia) scaled to the surface r(d). */
static void sample(uint64_t *s, double *p)
{
    double a, b, q;
    do {
        a = 2 * uniform(s) - 1, b = 2 * uniform(s) - 1, q = a * a + b * b;
    } while (q >= 1 || q == 0);
    double f = 2 * sqrt(1 - q), d[3] = {a * f, b * f, 1 - 2 * q};
    double r = 1 + 0.2 * d[0] * d[1] + 0.15 * sin(3 * d[2]);
    for (int k = 0; k < 3; k++) p[k] = r * d[k];
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    if (argc < 3 || argc > 4) {
        fprintf(stderr, "usage: recon3_scale N SEED [OUT.xyz]\n");
        return 2;
    }
    size_t n = (size_t)strtod(argv[1], NULL);
    uint64_t seed = (uint64_t)strtoull(argv[2], NULL, 10);
    double *xyz = n ? malloc(3 * n * sizeof *xyz) : NULL;
    if (!xyz) return fprintf(stderr, "recon3_scale: bad N or no memory\n"), 3;
    for (size_t i = 0; i < n; i++) sample(&seed, xyz + 3 * i);
    if (argc == 4) {
        FILE *f = fopen(argv[3], "w");
        if (!f) return fprintf(stderr, "recon3_scale: cannot write %s\n", argv[3]), 3;
        for (size_t i = 0; i < n; i++)
            fprintf(f, "%.17g %.17g %.17g\n", xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
        if (fclose(f) != 0) return fprintf(stderr, "recon3_scale: write failed\n"), 3;
    }
    double dt_s[3], rec_s[3], dt_c[3], rec_c[3];
    fl_reconstruction3 rec = {0};
    fl_error err;
    for (int round = 0; round < 3; round++) {
        fl_dt3 dt;
        double t0 = now(), c0 = cpu();
        if (fl_dt3_build(xyz, n, NULL, &dt, &err) != FL_OK)
            return fprintf(stderr, "fl_dt3_build: %s\n", err.message), 1;
        dt_s[round] = now() - t0;
        dt_c[round] = cpu() - c0;
        fl_dt3_free(&dt);
        fl_reconstruction3_free(&rec);
        t0 = now(), c0 = cpu();
        if (fl_reconstruct3(xyz, n, NULL, &rec, &err) != FL_OK)
            return fprintf(stderr, "fl_reconstruct3: %s\n", err.message), 1;
        rec_s[round] = now() - t0;
        rec_c[round] = cpu() - c0;
    }
    qsort(dt_s, 3, sizeof *dt_s, cmp_double);
    qsort(rec_s, 3, sizeof *rec_s, cmp_double);
    qsort(dt_c, 3, sizeof *dt_c, cmp_double);
    qsort(rec_c, 3, sizeof *rec_c, cmp_double);
    fl_mesh m = {.vertex_count = n, .xyz = xyz, .triangle_count = rec.triangle_count,
                 .tri = rec.tri};
    fl_mesh_check_options o = {.skip_self_intersections = 1};
    fl_mesh_report r;
    if (fl_mesh_check(&m, &o, &r, &err) != FL_OK)
        return fprintf(stderr, "fl_mesh_check: %s\n", err.message), 1;
    printf("RESULT n=%zu dt=%.3f rec=%.3f ratio=%.2f dt_cpu=%.3f rec_cpu=%.3f cpu_ratio=%.2f "
           "on_boundary=%zu/%zu closed=%d manifold=%d genus=%lld flips=%zu augmented_c0=%g\n",
           n, dt_s[1], rec_s[1], rec_s[1] / dt_s[1], dt_c[1], rec_c[1], rec_c[1] / dt_c[1],
           rec.boundary_vertex_count, rec.unique_count,
           r.closed, r.manifold, r.genus, rec.flip_count, rec.augmented_c0);
    fl_mesh_report_free(&r);
    fl_reconstruction3_free(&rec);
    free(xyz);
    return 0;
}
