/* Writes the inputs of the Delaunay benchmarks, the same points in the format of every program:
 *
 *   gen_points uniform2 N SEED PREFIX   N uniform random points in the unit square
 *   gen_points uniform3 N SEED PREFIX   N uniform random points in the unit cube
 *   gen_points sphere   N SEED PREFIX   N uniform random points on the unit sphere's surface
 *   gen_points weighted N SEED PREFIX   N uniform points in the unit cube, each with a random
 *                                       weight (squared radius) in [0, s^2), s = N^(-1/3) the
 *                                       mean spacing, so that some balls are hidden
 *   gen_points convert  IN PREFIX       the first 3 numbers of every line of a text point file
 *                                       (.xyz with or without normals; '#' lines and blank lines
 *                                       skipped)
 *
 * and writes
 *   PREFIX.bin   raw native doubles, 2, 3 or 4 (x y z w) per point: what bench/ours_delaunay and
 *                bench/peers/cgal_*.cpp read, outside the timing, so both sides triangulate
 *                bit-identical coordinates and no text parsing is measured
 *   PREFIX.qh    qhull's input ("dim", "n", then the coordinates; %.17g, so exact)
 *   PREFIX.node  TetGen's input (3D only; weighted: the weight is the one point attribute)
 *
 * The random generator is splitmix64 with the given seed: the inputs are the same on every
 * machine. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

static uint64_t splitmix64(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* Uniform in [0, 1) with 53 random bits. */
static double uniform(uint64_t *state)
{
    return (double)(splitmix64(state) >> 11) * 0x1p-53;
}

/* A direction uniform on the sphere: z uniform in [-1, 1] and an angle uniform (Archimedes). */
static void on_sphere(uint64_t *state, double *p)
{
    double z = 2 * uniform(state) - 1, phi = 2 * PI * uniform(state);
    double r = sqrt(1 - z * z);
    p[0] = r * cos(phi);
    p[1] = r * sin(phi);
    p[2] = z;
}

static int generate(const char *kind, size_t n, uint64_t seed, double **out, int *dim)
{
    int d = !strcmp(kind, "uniform2") ? 2 : !strcmp(kind, "weighted") ? 4 : 3;
    if (strcmp(kind, "uniform2") && strcmp(kind, "uniform3") && strcmp(kind, "sphere") &&
        strcmp(kind, "weighted")) {
        fprintf(stderr, "gen_points: unknown kind %s\n", kind);
        return 1;
    }
    double *c = malloc(n * (size_t)d * sizeof *c);
    if (!c) return 1;
    uint64_t state = seed;
    double spacing = pow((double)n, -1.0 / 3);
    for (size_t i = 0; i < n; i++) {
        double *p = c + i * (size_t)d;
        if (!strcmp(kind, "sphere")) {
            on_sphere(&state, p);
            continue;
        }
        for (int k = 0; k < (d == 4 ? 3 : d); k++)
            p[k] = uniform(&state);
        if (d == 4) p[3] = uniform(&state) * spacing * spacing;
    }
    *out = c;
    *dim = d;
    return 0;
}

/* Reads the first three numbers of every line of a text file. */
static int convert(const char *path, double **out, size_t *n)
{
    FILE *fp = fopen(path, "r");
    if (!fp) {
        fprintf(stderr, "gen_points: cannot open %s\n", path);
        return 1;
    }
    size_t cap = 1024, count = 0;
    double *c = malloc(cap * 3 * sizeof *c);
    char line[4096];
    while (c && fgets(line, sizeof line, fp)) {
        double p[3];
        if (line[0] == '#' || sscanf(line, "%lf %lf %lf", &p[0], &p[1], &p[2]) != 3) continue;
        if (count == cap) {
            double *bigger = realloc(c, (cap *= 2) * 3 * sizeof *c);
            if (!bigger) free(c);
            c = bigger;
            if (!c) break;
        }
        memcpy(c + 3 * count++, p, sizeof p);
    }
    fclose(fp);
    *out = c;
    *n = count;
    return c ? 0 : 1;
}

static FILE *open_out(const char *prefix, const char *ext)
{
    char path[4096];
    snprintf(path, sizeof path, "%s%s", prefix, ext);
    FILE *fp = fopen(path, "wb");
    if (!fp) fprintf(stderr, "gen_points: cannot write %s\n", path);
    return fp;
}

static int write_all(const char *prefix, const double *c, size_t n, int dim)
{
    FILE *fp = open_out(prefix, ".bin");
    if (!fp) return 1;
    int failed = fwrite(c, sizeof *c * (size_t)dim, n, fp) != n;
    failed |= fclose(fp) != 0;
    int geo = dim == 4 ? 3 : dim; /* qhull gets the centres only */
    if (!(fp = open_out(prefix, ".qh"))) return 1;
    fprintf(fp, "%d\n%zu\n", geo, n);
    for (size_t i = 0; i < n; i++) {
        for (int k = 0; k < geo; k++)
            fprintf(fp, k ? " %.17g" : "%.17g", c[i * (size_t)dim + (size_t)k]);
        fputc('\n', fp);
    }
    failed |= fclose(fp) != 0;
    if (geo == 3) {
        if (!(fp = open_out(prefix, ".node"))) return 1;
        fprintf(fp, "%zu 3 %d 0\n", n, dim == 4);
        for (size_t i = 0; i < n; i++) {
            const double *p = c + i * (size_t)dim;
            fprintf(fp, "%zu %.17g %.17g %.17g", i + 1, p[0], p[1], p[2]);
            if (dim == 4) fprintf(fp, " %.17g", p[3]);
            fputc('\n', fp);
        }
        failed |= fclose(fp) != 0;
    }
    return failed;
}

int main(int argc, char **argv)
{
    double *c = NULL;
    size_t n = 0;
    int dim = 3;
    const char *prefix;
    if (argc == 4 && !strcmp(argv[1], "convert")) {
        prefix = argv[3];
        if (convert(argv[2], &c, &n)) return 1;
    } else if (argc == 5) {
        n = strtoul(argv[2], NULL, 10);
        prefix = argv[4];
        if (n < 4 || generate(argv[1], n, strtoull(argv[3], NULL, 10), &c, &dim)) return 1;
    } else {
        fprintf(stderr, "usage: gen_points uniform2|uniform3|sphere|weighted N SEED PREFIX\n"
                        "       gen_points convert IN.xyz PREFIX\n");
        return 2;
    }
    int failed = write_all(prefix, c, n, dim);
    free(c);
    return failed;
}
