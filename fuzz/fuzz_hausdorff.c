/* Fuzzes fl_hausdorff_meshes / fl_hausdorff_polylines on tiny decoded shapes (meshes of up to 6
 * vertices and 4 triangles of any topology, 2D/3D polylines of up to 6 points) with a coarse
 * precision, a sample budget and sometimes keep_field. Oracle (long double brute force,
 * tests/sweep/sweep_oracle.h, no code shared with src/sweep): for each direction, V = the largest
 * distance from a vertex of A to B and D = the largest over a dense barycentric grid of A (grid
 * step s) are lower bounds of the true h(A,B), and D + s is an upper bound (d(., B) is
 * 1-Lipschitz). The certified interval [lower, upper] must satisfy lower <= D + s and
 * upper >= max(V, D), lower <= upper, and the symmetric interval must be the max of the two;
 * every kept field value must equal the brute-force distance of its vertex. Inputs beyond
 * |x| <= 1e150 or NaN/Inf must be FL_ERR_INPUT. */
#include "fuzz_common.h"
#include "sweep/sweep_oracle.h"

#define HZ_N 8 /* dense grid steps per triangle edge / segment */

typedef struct hz_shape {
    size_t nv, ne; /* vertices, elements (triangles or segments) */
    int mesh;
    double xyz[3 * 6];
    uint32_t tri[3 * 4];
} hz_shape;

static ld hz_dist(const hz_shape *s, const double *p)
{
    ld best = INFINITY;
    for (size_t e = 0; e < s->ne; e++) {
        ld d = s->mesh ? oracle_mesh_element(s->xyz, s->tri, e, p)
                       : oracle_polyline_element(s->xyz, s->nv, e, p);
        if (d < best) best = d;
    }
    return best;
}

/* Directed brute force: *vmax over the vertices of the elements, *dense over the grid, *step. */
static void hz_directed(const hz_shape *a, const hz_shape *b, ld *vmax, ld *dense, double *step)
{
    *vmax = 0, *dense = 0, *step = 0;
    for (size_t e = 0; e < a->ne; e++) {
        const double *v[3];
        int k = a->mesh ? 3 : 2;
        for (int i = 0; i < k; i++)
            v[i] = a->xyz + 3 * (a->mesh ? (size_t)a->tri[3 * e + i] : (e + (size_t)i) % a->nv);
        if (k == 2) v[2] = v[1];
        for (int i = 0; i < k; i++) {
            ld d = hz_dist(b, v[i]);
            if (d > *vmax) *vmax = d;
            double len = 0;
            for (int x = 0; x < 3; x++) {
                double dx = v[i][x] - v[(i + 1) % k][x];
                len += dx * dx;
            }
            *step = fmax(*step, sqrt(len) / HZ_N);
        }
        for (int i = 0; i <= HZ_N; i++)
            for (int j = 0; i + j <= HZ_N; j++) {
                if (k == 2 && j > 0) break;
                double l0 = (double)i / HZ_N, l1 = (double)j / HZ_N, l2 = 1 - l0 - l1, p[3];
                for (int x = 0; x < 3; x++) p[x] = l0 * v[0][x] + l1 * v[1][x] + l2 * v[2][x];
                ld d = hz_dist(b, p);
                if (d > *dense) *dense = d;
            }
    }
}

/* Decodes one shape; returns 1 when it breaks the documented input rules. */
static int hz_decode(fz_in *in, int mesh, int dim, int closed, hz_shape *s, double *flat,
                     double *maxabs)
{
    int bad = 0;
    memset(s, 0, sizeof *s);
    s->mesh = mesh;
    s->nv = (mesh ? 1 : 0) + fz_byte(in) % 7;
    if (s->nv > 6) s->nv = 6;
    size_t nc = (size_t)(mesh ? 3 : dim) * s->nv;
    fz_coords(in, flat, nc);
    for (size_t i = 0; i < nc; i++) {
        if (!(fabs(flat[i]) <= 1e150)) bad = 1;
        else *maxabs = fmax(*maxabs, fabs(flat[i]));
    }
    for (size_t i = 0; i < s->nv; i++)
        for (int x = 0; x < 3; x++)
            s->xyz[3 * i + x] = mesh || x < dim ? flat[(mesh ? 3 : dim) * i + x] : 0;
    if (mesh) {
        s->ne = fz_byte(in) % 5;
        for (size_t i = 0; i < 3 * s->ne; i++) s->tri[i] = fz_byte(in) % s->nv;
        if (s->ne == 0) bad = 1;
    } else {
        s->ne = s->nv < 2 ? 0 : closed ? s->nv : s->nv - 1;
        if (s->nv < 2) bad = 1;
    }
    return bad;
}

static void hz_check_dir(const double *iv, const hz_shape *a, const hz_shape *b, double slack,
                         const char *name)
{
    ld vmax, dense;
    double step;
    hz_directed(a, b, &vmax, &dense, &step);
    FZ_ASSERT(iv[0] <= iv[1], "%s: lower %.17g > upper %.17g", name, iv[0], iv[1]);
    FZ_ASSERT((ld)iv[1] >= vmax - slack && (ld)iv[1] >= dense - slack,
              "%s: upper %.17g below a measured distance (vertices %.17Lg, dense %.17Lg)", name,
              iv[1], vmax, dense);
    FZ_ASSERT((ld)iv[0] <= dense + step + slack,
              "%s: lower %.17g above the Lipschitz bound %.17Lg + %.17g", name, iv[0], dense,
              step);
}

static void hz_check_field(const fl_hausdorff_field *f, const hz_shape *other, double slack,
                           const char *name)
{
    FZ_ASSERT(f->mesh.vertex_count > 0 && f->distance, "%s: empty field", name);
    for (size_t i = 0; i < f->mesh.vertex_count; i++) {
        const double *p = f->mesh.xyz + 3 * i;
        FZ_ASSERT(isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]), "%s: vertex", name);
        ld d = hz_dist(other, p);
        FZ_ASSERT(fabsl((ld)f->distance[i] - d) <= slack,
                  "%s: field distance %zu = %.17g, brute force %.17Lg", name, i, f->distance[i],
                  d);
    }
    for (size_t t = 0; t < 3 * f->mesh.triangle_count; t++)
        FZ_ASSERT(f->mesh.tri[t] < f->mesh.vertex_count, "%s: field index", name);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    uint8_t head = fz_byte(&in), opts = fz_byte(&in);
    int kind = head % 3; /* 0 meshes, 1 polylines 2D, 2 polylines 3D */
    int dim = kind == 1 ? 2 : 3;
    int ca = (head >> 2) & 1, cb = (head >> 3) & 1;
    hz_shape a, b;
    double fa[3 * 6], fb[3 * 6], maxabs = 0;
    int bad = hz_decode(&in, kind == 0, dim, ca, &a, fa, &maxabs);
    bad |= hz_decode(&in, kind == 0, dim, cb, &b, fb, &maxabs);
    fl_hausdorff_options o = {0};
    static const double rel[4] = {0.3, 0.1, 0.03, 0.0};
    o.relative = rel[opts & 3];
    if ((opts & 3) == 3) o.precision = 0.5; /* absolute */
    o.max_samples = (opts & 4) ? 300 : 3000;
    o.both_directions = (opts >> 3) & 1;
    o.keep_field = (opts >> 4) & 1;
    fl_hausdorff_result r;
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st;
    if (kind == 0) {
        fl_mesh ma = {a.nv, a.xyz, a.ne, a.tri}, mb = {b.nv, b.xyz, b.ne, b.tri};
        st = fl_hausdorff_meshes(&ma, &mb, &o, &r, &err);
    } else {
        st = fl_hausdorff_polylines(fa, a.nv, ca, fb, b.nv, cb, dim, &o, &r, &err);
    }
    fz_check_status(st, &err, "fl_hausdorff");
    if (st != FL_OK) {
        FZ_ASSERT(bad, "valid shapes rejected: %s", err.message);
        FZ_ASSERT(st == FL_ERR_INPUT, "bad shape gave %d: %s", (int)st, err.message);
        FZ_ASSERT(r.field_ab.distance == NULL && r.field_ba.distance == NULL, "not zeroed");
        return 0;
    }
    FZ_ASSERT(!bad, "out-of-range shape accepted");
    /* The header promises slack of about 1e-14 of the coordinates; squared distances
     * underflow below ~1e-154 (fuzz_sweep), the absolute resolution. */
    double slack = 1e-9 * maxabs + 1e-150;
    hz_check_dir(r.h_ab, &a, &b, slack, "h_ab");
    hz_check_dir(r.h_ba, &b, &a, slack, "h_ba");
    FZ_ASSERT(r.hausdorff[0] == fmax(r.h_ab[0], r.h_ba[0]) &&
                  r.hausdorff[1] == fmax(r.h_ab[1], r.h_ba[1]),
              "symmetric [%.17g, %.17g] is not the max of the directed ones", r.hausdorff[0],
              r.hausdorff[1]);
    /* where[0] lies on the shape named by where_on_b and realizes the lower bound. */
    const hz_shape *on = r.where_on_b ? &b : &a, *other = r.where_on_b ? &a : &b;
    FZ_ASSERT(hz_dist(on, r.where[0]) <= slack, "where[0] is not on its shape");
    FZ_ASSERT(fabsl(hz_dist(other, r.where[0]) - (ld)r.hausdorff[0]) <= slack,
              "where[0] is %.17Lg from the other shape, lower bound %.17g",
              hz_dist(other, r.where[0]), r.hausdorff[0]);
    FZ_ASSERT(r.samples <= o.max_samples + 64 || !r.budget_exhausted, "sample budget");
    /* Precisions below ~1e-12 of the coordinates are documented as unreachable. */
    if (!r.budget_exhausted && o.both_directions && o.precision > 1e-10 * maxabs)
        FZ_ASSERT(r.h_ab[1] - r.h_ab[0] <= o.precision + slack, "precision not reached");
    if (o.keep_field) {
        hz_check_field(&r.field_ab, &b, slack, "field_ab");
        hz_check_field(&r.field_ba, &a, slack, "field_ba");
    }
    fl_hausdorff_result_free(&r);
    return 0;
}
