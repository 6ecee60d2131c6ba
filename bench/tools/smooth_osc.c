/* Oscillation of the G1 schemes (docs/smooth.md, "Oscillation"): for a mesh and a scheme,
 * the max normal jump across patch edges, folds, max deviation from the mesh (all from
 * fl_g1_surface_measure) and the control-point displacement: the distance of every control
 * point from the matching control point of the PN patch (the macro patch of steps 1-3)
 * restricted to the same micro domain (by blossoming), max and mean, in mean edge lengths.
 * Built and run by bench/workloads/smooth.sh:
 *   smooth_osc MESH three-split|six-split|pn|auto [SAMPLES]
 * prints one line "RESULT key=value ...". CPU seconds are the build alone. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "flintstone.h"

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Index of b_ijk (k = n - i - j) in a degree-n net in fl_g1_surface order. */
static int idx(int n, int i, int j)
{
    return (n - i) * (n - i + 1) / 2 + (n - i - j);
}

static int ix(int i, int j)
{
    return idx(3, i, j);
}

/* Blossom of a cubic Bézier triangle at the barycentric arguments u[0], u[1], u[2]: de
 * Casteljau with a different argument at each level. */
static void blossom(const double *ctrl, const double u[3][3], double out[3])
{
    double a[10][3], b[10][3];
    memcpy(a, ctrl, sizeof a);
    for (int n = 3; n > 0; n--) {
        const double *w = u[3 - n];
        for (int i = 0; i < n; i++)
            for (int j = 0; i + j < n; j++)
                for (int d = 0; d < 3; d++)
                    b[idx(n - 1, i, j)][d] = w[0] * a[idx(n, i + 1, j)][d] +
                                             w[1] * a[idx(n, i, j + 1)][d] +
                                             w[2] * a[idx(n, i, j)][d];
        memcpy(a, b, sizeof a);
    }
    memcpy(out, a[0], 3 * sizeof(double));
}

/* Domain position (barycentric in macro triangle t) of corner c of patch p. Three-split
 * patches are (V_i, V_i+1, O), six-split ones (V_i, m_i, O) and (m_i, V_i+1, O), the six of a
 * triangle from first[t] on (auto renumbers the split nodes of each component, so corners are
 * recognised by position, not by node id). */
static void corner_domain(const fl_mesh *m, const fl_g1_surface *s, const size_t *first, size_t p,
                          int c, double bc[3])
{
    uint32_t n = s->corner[3 * p + c], t = s->macro[p];
    const uint32_t *tri = m->tri + 3 * (size_t)t;
    bc[0] = bc[1] = bc[2] = 0;
    for (int k = 0; k < 3; k++)
        if (tri[k] == n) {
            bc[k] = 1;
            return;
        }
    if (c == 2) {
        bc[0] = bc[1] = bc[2] = 1.0 / 3;
        return;
    }
    /* six-split split point of edge i at lam from v_i; lam from the layout
     * Y_B - m = -rho (Y_A - m) (docs/smooth.md, split ratio) */
    size_t i = (p - first[t]) / 2, p0 = first[t] + 2 * i;
    const double *mm = s->ctrl + 30 * p0 + 3 * ix(0, 3), *ya = s->ctrl + 30 * p0 + 3 * ix(1, 2),
                 *yb = s->ctrl + 30 * (p0 + 1) + 3 * ix(2, 1);
    double aa = 0, ab = 0;
    for (int d = 0; d < 3; d++) {
        aa += (ya[d] - mm[d]) * (ya[d] - mm[d]);
        ab += (ya[d] - mm[d]) * (yb[d] - mm[d]);
    }
    double rho = -ab / aa, lam = 1 / (1 + rho);
    bc[i] = 1 - lam;
    bc[(i + 1) % 3] = lam;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: smooth_osc MESH three-split|six-split|pn|auto [SAMPLES]\n");
        return 2;
    }
    const char *names[] = {"three-split", "pn", "six-split", "two-split", "", "auto"};
    int scheme = -1;
    for (int k = 0; k < 6; k++)
        if (names[k][0] && !strcmp(argv[2], names[k])) scheme = k;
    unsigned samples = argc > 3 ? (unsigned)atoi(argv[3]) : 32;
    fl_mesh m;
    fl_error err;
    fl_g1_surface s = {0}, pn = {0};
    fl_g1_metrics mt;
    if (scheme < 0 || scheme == FL_G1_TWO_SPLIT || fl_read_mesh(argv[1], &m, &err)) {
        fprintf(stderr, "smooth_osc: bad scheme or unreadable mesh\n");
        return 1;
    }
    fl_g1_surface_options o = {.scheme = scheme}, opn = {.scheme = FL_G1_MACRO};
    double t0 = cpu_now();
    if (fl_g1_surface_build(&m, &o, &s, &err)) {
        fprintf(stderr, "smooth_osc: %s\n", err.message);
        return 1;
    }
    double cpu = cpu_now() - t0;
    if (fl_g1_surface_measure(&s, &m, samples, &mt, &err) ||
        fl_g1_surface_build(&m, &opn, &pn, &err)) {
        fprintf(stderr, "smooth_osc: %s\n", err.message);
        return 1;
    }
    double sum_len = 0, dmax = 0, dsum = 0;
    for (size_t h = 0; h < 3 * m.triangle_count; h++) {
        const double *a = m.xyz + 3 * m.tri[h], *b = m.xyz + 3 * m.tri[3 * (h / 3) + (h + 1) % 3];
        sum_len += sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                        (a[2] - b[2]) * (a[2] - b[2]));
    }
    double mean_len = sum_len / (3.0 * (double)m.triangle_count);
    size_t npts = 0, *first = malloc(m.triangle_count * sizeof *first);
    for (size_t t = 0; t < m.triangle_count; t++)
        first[t] = SIZE_MAX;
    for (size_t p = s.patch_count; p-- > 0;)
        first[s.macro[p]] = p;
    for (size_t p = 0; p < s.patch_count; p++) {
        double dom[3][3];
        for (int c = 0; c < 3; c++)
            corner_domain(&m, &s, first, p, c, dom[c]);
        const double *macro = pn.ctrl + 30 * (size_t)s.macro[p];
        for (int i = 0; i <= 3; i++)
            for (int j = 0; i + j <= 3; j++) {
                double u[3][3], q[3];
                int r = 0;
                for (int a = 0; a < i; a++)
                    memcpy(u[r++], dom[0], sizeof dom[0]);
                for (int a = 0; a < j; a++)
                    memcpy(u[r++], dom[1], sizeof dom[1]);
                while (r < 3)
                    memcpy(u[r++], dom[2], sizeof dom[2]);
                blossom(macro, (const double (*)[3])u, q);
                const double *x = s.ctrl + 30 * p + 3 * ix(i, j);
                double d = sqrt((x[0] - q[0]) * (x[0] - q[0]) + (x[1] - q[1]) * (x[1] - q[1]) +
                                (x[2] - q[2]) * (x[2] - q[2])) /
                           mean_len;
                dmax = fmax(dmax, d);
                dsum += d;
                npts++;
            }
    }
    printf("RESULT scheme=%s triangles=%zu patches=%zu six_split_triangles=%zu cpu_s=%.4f "
           "max_jump_deg=%.3g flips=%zu max_deviation=%.4g disp_max=%.4g disp_mean=%.4g "
           "repairs=%zu failures=%zu max_normal_error=%.3g\n",
           argv[2], m.triangle_count, s.patch_count, s.six_split_triangles, cpu,
           mt.max_edge_normal_jump_deg, mt.orientation_flips, mt.max_deviation, dmax,
           dsum / (double)npts, s.orientation_repairs, s.orientation_failures,
           mt.max_normal_error);
    free(first);
    fl_g1_surface_free(&s);
    fl_g1_surface_free(&pn);
    fl_mesh_free(&m);
    return 0;
}
