/* Peak memory of one capability on n generated points, for docs/reliability.md:
 *   rss_probe dt2|dt3|rec2|rec3|rec3s|sweep N
 * Generates the input in memory (uniform square / cube; for rec2 the closed curve
 * r(t) = 1 + 0.3 sin 5t of bench/tools/recon2_curve.c at random t; a torus surface for rec3, which
 * constriction must close into a sphere and which therefore locks and flips a lot; for rec3s the
 * genus-0 perturbed sphere of bench/recon3_scale.c, the "closed surface" case; a height-field
 * grid mesh of about 2N triangles for sweep), records the peak RSS (getrusage ru_maxrss), runs
 * the build, and prints the peak again: the difference is the build's own peak (working memory
 * plus its output), reported per input point (per triangle for sweep). Built and run by
 * scripts/measure-rss.sh; one capability a process so peaks do not mix. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "flintstone.h"

static long peak_kb(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_maxrss;
}

static double rnd(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / 9007199254740992.0;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(int argc, char **argv)
{
    if (argc != 3) return fprintf(stderr, "usage: rss_probe dt2|dt3|rec2|rec3|rec3s|sweep N\n"), 1;
    const char *kind = argv[1];
    size_t n = (size_t)strtod(argv[2], NULL), units = n;
    unsigned long long seed = 42;
    double *c = malloc(3 * n * sizeof *c);
    uint32_t *tri = NULL;
    if (!c) return fprintf(stderr, "no memory for the input\n"), 3;
    if (strcmp(kind, "rec3") == 0) {
        for (size_t i = 0; i < n; i++) { /* torus R = 2, r = 1: a genus-1 surface sample */
            double u = 6.283185307179586 * rnd(&seed), v = 6.283185307179586 * rnd(&seed);
            c[3 * i] = (2 + cos(v)) * cos(u), c[3 * i + 1] = (2 + cos(v)) * sin(u);
            c[3 * i + 2] = sin(v);
        }
    } else if (strcmp(kind, "rec2") == 0) { /* stored as x, y, 0 and packed below */
        for (size_t i = 0; i < n; i++) {
            double t = 6.283185307179586 * rnd(&seed);
            double r = 1 + 0.3 * sin(5 * t) + 1e-9 * (rnd(&seed) - 0.5);
            c[3 * i] = r * cos(t), c[3 * i + 1] = r * sin(t), c[3 * i + 2] = 0;
        }
    } else if (strcmp(kind, "rec3s") == 0) {
        for (size_t i = 0; i < n; i++) { /* r(d) = 1 + 0.2 dx dy + 0.15 sin(3 dz), d uniform */
            double a, b, q;
            do {
                a = 2 * rnd(&seed) - 1, b = 2 * rnd(&seed) - 1, q = a * a + b * b;
            } while (q >= 1 || q == 0);
            double f = 2 * sqrt(1 - q), d[3] = {a * f, b * f, 1 - 2 * q};
            double r = 1 + 0.2 * d[0] * d[1] + 0.15 * sin(3 * d[2]);
            for (int k = 0; k < 3; k++) c[3 * i + k] = r * d[k];
        }
    } else if (strcmp(kind, "sweep") == 0) {
        size_t k = (size_t)sqrt((double)n);
        n = k * k;
        for (size_t i = 0; i < k; i++)
            for (size_t j = 0; j < k; j++) {
                double *p = c + 3 * (i * k + j);
                p[0] = (double)i, p[1] = (double)j;
                p[2] = sin(0.1 * (double)i) * cos(0.07 * (double)j);
            }
        units = 2 * (k - 1) * (k - 1);
        tri = malloc(3 * units * sizeof *tri);
        if (!tri) return fprintf(stderr, "no memory for the mesh\n"), 3;
        size_t t = 0;
        for (size_t i = 0; i + 1 < k; i++)
            for (size_t j = 0; j + 1 < k; j++) {
                uint32_t a = (uint32_t)(i * k + j), b = a + 1, d = a + (uint32_t)k, e = d + 1;
                uint32_t q[6] = {a, d, b, b, d, e};
                memcpy(tri + 3 * t, q, sizeof q);
                t += 2;
            }
    } else {
        for (size_t i = 0; i < 3 * n; i++) c[i] = rnd(&seed);
    }
    long before = peak_kb();
    double t0 = now();
    fl_error err;
    fl_status st;
    if (strcmp(kind, "dt2") == 0) {
        for (size_t i = 0; i < n; i++) c[2 * i] = c[3 * i], c[2 * i + 1] = c[3 * i + 1];
        fl_dt2 dt;
        st = fl_dt2_build(c, n, NULL, &dt, &err);
        if (!st) units = n, fl_dt2_free(&dt);
    } else if (strcmp(kind, "rec2") == 0) {
        for (size_t i = 0; i < n; i++) c[2 * i] = c[3 * i], c[2 * i + 1] = c[3 * i + 1];
        fl_reconstruction2 rec;
        st = fl_reconstruct2(c, n, NULL, &rec, &err);
        if (!st) fl_reconstruction2_free(&rec);
    } else if (strcmp(kind, "dt3") == 0) {
        fl_dt3 dt;
        st = fl_dt3_build(c, n, NULL, &dt, &err);
        if (!st) fl_dt3_free(&dt);
    } else if (strcmp(kind, "rec3") == 0 || strcmp(kind, "rec3s") == 0) {
        fl_reconstruction3 rec;
        st = fl_reconstruct3(c, n, NULL, &rec, &err);
        if (!st) fl_reconstruction3_free(&rec);
    } else if (strcmp(kind, "sweep") == 0) {
        fl_mesh m = {n, c, units, tri};
        fl_sweep *s;
        st = fl_sweep_build(&m, NULL, &s, &err);
        if (!st) fl_sweep_free(s);
    } else {
        return fprintf(stderr, "unknown kind %s\n", kind), 1;
    }
    double secs = now() - t0;
    long after = peak_kb();
    if (st) return fprintf(stderr, "%s failed: %s\n", kind, err.message), 3;
    printf("%s n=%zu units=%zu input_kb=%ld peak_kb=%ld build_kb=%ld bytes_per_unit=%.0f "
           "seconds=%.2f\n", kind, n, units, before, after, after - before,
           1024.0 * (double)(after - before) / (double)units, secs);
    free(c);
    free(tri);
    return 0;
}
