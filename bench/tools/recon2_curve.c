/* Closed-curve samples for the 2D boundary-construction speed workload
 * (bench/workloads/reconstruct2_curve.sh): N points on the five-lobed curve
 * r(t) = 1 + 0.3 sin(5t), uniform in arc length, each moved along the radius by a uniform jitter
 * of at most 1% of the spacing. Written in curve order as one ring of a .xy file (the format of
 * countries-50m.xy); bench/recon2_eval.h shuffles the points when it loads them, and the curve
 * order is the truth the result is scored against.
 *   recon2_curve N OUT.xy [SEED] */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

static double speed(double t) /* |dP/dt| = sqrt(r^2 + r'^2) */
{
    double r = 1 + 0.3 * sin(5 * t), dr = 1.5 * cos(5 * t);
    return sqrt(r * r + dr * dr);
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: recon2_curve N OUT.xy [SEED]\n");
        return 2;
    }
    long n = atol(argv[1]);
    if (n < 3 || n > 100000000) {
        fprintf(stderr, "N must be in [3, 1e8]\n");
        return 2;
    }
    uint64_t seed = argc > 3 ? (uint64_t)strtoull(argv[3], NULL, 10) : 0;
    seed = seed * 0x9e3779b97f4a7c15ull + 0x2545f4914f6cdd1dull;
    /* Arc length table s(t) on m steps (Simpson on each step), inverted by interpolation. */
    size_t m = (size_t)n * 8 < (1u << 16) ? (1u << 16) : (size_t)n * 8;
    double *s = malloc((m + 1) * sizeof *s), h = 2 * 3.14159265358979323846 / (double)m;
    s[0] = 0;
    for (size_t i = 0; i < m; i++) {
        double t = (double)i * h;
        s[i + 1] = s[i] + h / 6 * (speed(t) + 4 * speed(t + h / 2) + speed(t + h));
    }
    double len = s[m], spacing = len / (double)n;
    FILE *f = fopen(argv[2], "w");
    if (!f) {
        fprintf(stderr, "cannot write %s\n", argv[2]);
        free(s);
        return 1;
    }
    fprintf(f, "# r(t) = 1 + 0.3 sin(5t), %ld points uniform in arc length (length %.9g), "
               "radial jitter <= %.3g\n", n, len, 0.01 * spacing);
    size_t i = 0;
    for (long j = 0; j < n; j++) {
        double target = (double)j * spacing;
        while (i + 1 < m && s[i + 1] <= target) i++;
        double t = ((double)i + (target - s[i]) / (s[i + 1] - s[i])) * h;
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        double u = (double)(seed >> 11) / 9007199254740992.0; /* [0, 1) */
        double r = 1 + 0.3 * sin(5 * t) + (2 * u - 1) * 0.01 * spacing;
        fprintf(f, "%.17g %.17g\n", r * cos(t), r * sin(t));
    }
    fclose(f);
    free(s);
    return 0;
}
