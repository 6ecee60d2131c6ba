/* Fuzzes the G1 smoothing of src/smooth: fl_g1_curve_build (+ sample) on a decoded polygon of up
 * to 2 rings of up to 8 vertices, and fl_g1_surface_build (three-split and PN/macro, every
 * weighting, + tessellate) on a small closed mesh from fz_closed_mesh, sometimes broken.
 * Invariants: never a crash; input breaking the documented rules (decided independently: exact
 * predicates for the 180-degree spike, fl_mesh_check for the mesh) gives FL_ERR_INPUT; on
 * success every output is finite, the curve / patches interpolate the vertices (relative
 * 1e-9), the control points next to a vertex lie on its tangent line / in its tangent plane,
 * tangents and normals are unit, and the tessellation of a closed mesh is closed. */
#include "fuzz_common.h"

#define SM_TOL 1e-9

static int sm_close(const double *a, const double *b, int dim, double scale)
{
    for (int k = 0; k < dim; k++)
        if (!(fabs(a[k] - b[k]) <= SM_TOL * scale)) return 0;
    return 1;
}

/* The ring turns back by 180 degrees at v (a, v, b exactly collinear, v outside segment ab; or
 * a == b). On a line that is not vertical x orders the points; else y does. */
static int sm_spike(const double *a, const double *v, const double *b)
{
    if (fl_orient2d(a, v, b) != 0) return 0;
    int k = (a[0] == v[0] && v[0] == b[0]) ? 1 : 0;
    return (a[k] - v[k] > 0) == (b[k] - v[k] > 0) && a[k] != v[k] && b[k] != v[k];
}

static void sm_curve(fz_in *in, uint8_t head)
{
    double xy[2 * 16];
    size_t ring_start[3] = {0}, polygon_start[2] = {0, 1}, rings = 1 + ((head >> 2) & 1), n = 0;
    int bad = 0;
    double scale = 0;
    for (size_t r = 0; r < rings; r++) {
        size_t k = fz_byte(in) % 9;
        if (k < 3) bad = 1;
        if (fz_coords(in, xy + 2 * n, 2 * k)) bad = 1;
        for (size_t i = 0; i < 2 * k; i++) /* the documented range */
            if (fabs(xy[2 * n + i]) > 1e150) bad = 1;
        for (size_t i = 0; i < k; i++) {
            const double *a = xy + 2 * (n + (i + k - 1) % k), *v = xy + 2 * (n + i),
                         *b = xy + 2 * (n + (i + 1) % k);
            if (k >= 3 && !bad && ((v[0] == b[0] && v[1] == b[1]) || sm_spike(a, v, b)))
                bad = 1;
            scale = fmax(scale, fmax(fabs(v[0]), fabs(v[1])));
        }
        n += k;
        ring_start[r + 1] = n;
    }
    polygon_start[1] = rings;
    fl_polygon poly = {n, xy, rings, ring_start, 1, polygon_start};
    fl_g1_curve_options o = {(head >> 3) & 3, (head & 32) ? 0.25 : 0};
    fl_g1_curve c;
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st = fl_g1_curve_build(&poly, &o, &c, &err);
    fz_check_status(st, &err, "fl_g1_curve_build");
    if (bad) {
        FZ_ASSERT(st == FL_ERR_INPUT, "bad polygon gave %d: %s", (int)st, err.message);
        FZ_ASSERT(c.ctrl == NULL && c.vertex_count == 0, "*out not zeroed on failure");
        return;
    }
    FZ_ASSERT(st == FL_OK, "valid polygon rejected (%d): %s", (int)st, err.message);
    FZ_ASSERT(c.vertex_count == n && c.ring_count == rings, "structure");
    for (size_t r = 0; r < rings; r++)
        for (size_t i = ring_start[r]; i < ring_start[r + 1]; i++) {
            size_t next = i + 1 < ring_start[r + 1] ? i + 1 : ring_start[r];
            const double *p = c.ctrl + 8 * i, *t = c.tangent + 2 * i;
            for (int k = 0; k < 8; k++) FZ_ASSERT(isfinite(p[k]), "segment %zu not finite", i);
            FZ_ASSERT(sm_close(p, xy + 2 * i, 2, scale) && sm_close(p + 6, xy + 2 * next, 2, scale),
                      "segment %zu does not interpolate its vertices", i);
            FZ_ASSERT(fabs(hypot(t[0], t[1]) - 1) <= 1e-9, "tangent %zu not unit", i);
            /* G1: p1 - p0 along the tangent at i (projection heuristic, §9.2). */
            double d[2] = {p[2] - p[0], p[3] - p[1]};
            FZ_ASSERT(fabs(d[0] * t[1] - d[1] * t[0]) <= SM_TOL * scale + 1e-300,
                      "p1 of segment %zu off the tangent line", i);
            double q[2];
            fl_g1_curve_eval(&c, i, 0.0, q, NULL);
            FZ_ASSERT(sm_close(q, xy + 2 * i, 2, scale), "eval(0) != vertex %zu", i);
        }
    fl_polygon smp;
    st = fl_g1_curve_sample(&c, 1 + (head >> 6), &smp, &err);
    fz_check_status(st, &err, "fl_g1_curve_sample");
    FZ_ASSERT(st == FL_OK, "sample failed: %s", err.message);
    FZ_ASSERT(smp.vertex_count == n * (1 + (head >> 6)), "sample count");
    for (size_t i = 0; i < 2 * smp.vertex_count; i++) FZ_ASSERT(isfinite(smp.xy[i]), "sample");
    fl_polygon_free(&smp);
    fl_g1_curve_free(&c);
}

/* What fl_g1_surface_build requires, decided by fl_mesh_check (fuzzed on its own against a
 * brute force by fuzz_mesh_check) and a finiteness scan. */
static int sm_mesh_bad(const fl_mesh *m)
{
    for (size_t i = 0; i < 3 * m->vertex_count; i++)
        if (!(fabs(m->xyz[i]) <= 1e150)) return 1; /* NaN/Inf or beyond the documented range */
    fl_mesh_check_options co = {.skip_self_intersections = 1};
    fl_mesh_report rep;
    fl_error err;
    if (fl_mesh_check(m, &co, &rep, &err) != FL_OK) return 1;
    int bad = !rep.closed || !rep.manifold || !rep.oriented || rep.degenerate_faces ||
              rep.unreferenced_vertices;
    fl_mesh_report_free(&rep);
    return bad;
}

static void sm_surface(fz_in *in, uint8_t head)
{
    double xyz[3 * 14];
    uint32_t tri[3 * 24];
    size_t nv, nt;
    fz_closed_mesh(in, head & 4, xyz, tri, &nv, &nt);
    fl_mesh m = {nv, xyz, nt, tri};
    int bad = sm_mesh_bad(&m);
    double scale = 0;
    for (size_t i = 0; i < 3 * nv; i++) scale = fmax(scale, fabs(xyz[i]));
    /* Bit 1 (unused before round 4, so older corpus entries keep their meaning) picks the
     * six-split or the two-split instead of the three-split / PN patches. */
    int scheme = (head >> 3) & 1;
    if (head & 2) scheme = scheme ? FL_G1_TWO_SPLIT : FL_G1_SIX_SPLIT;
    /* Round 9: auto (both schemes built and measured; per component) in place of the
     * two-split when the top bit (tessellation density) is also set. */
    if ((head & 2) && scheme == FL_G1_TWO_SPLIT && (head & 128)) scheme = FL_G1_AUTO;
    fl_g1_surface_options o = {scheme, (head >> 4) & 3, (head & 64) ? 0.4 : 0};
    fl_g1_surface s;
    fl_error err;
    memset(&err, 0, sizeof err);
    fl_status st = fl_g1_surface_build(&m, &o, &s, &err);
    fz_check_status(st, &err, "fl_g1_surface_build");
    if (bad) {
        FZ_ASSERT(st == FL_ERR_INPUT, "bad mesh gave %d: %s", (int)st, err.message);
        FZ_ASSERT(s.ctrl == NULL && s.patch_count == 0, "*out not zeroed on failure");
        return;
    }
    /* A valid mesh may still have a vertex whose normal sum vanishes (FL_ERR_INPUT, documented
     * for fl_g1_vertex_normals) or no solution of eq. 9.3a (FL_ERR_ALGORITHM, three-split). */
    if (st != FL_OK) {
        FZ_ASSERT(st == FL_ERR_INPUT || (st == FL_ERR_ALGORITHM && o.scheme != FL_G1_MACRO),
                  "valid mesh failed (%d): %s", (int)st, err.message);
        FZ_ASSERT(s.ctrl == NULL && s.patch_count == 0, "*out not zeroed on failure");
        return;
    }
    FZ_ASSERT(s.vertex_count == nv, "vertex count");
    /* Patches: one (PN), three or six a triangle; a two-split pair has four for its two. */
    FZ_ASSERT(s.six_split_triangles <= nt, "%zu six-split triangles", s.six_split_triangles);
    size_t want = o.scheme == FL_G1_MACRO       ? nt
                  : o.scheme == FL_G1_SIX_SPLIT ? 6 * nt
                  : o.scheme == FL_G1_AUTO      ? 3 * nt + 3 * s.six_split_triangles
                                                : 3 * nt - 2 * s.two_split_pairs;
    FZ_ASSERT(2 * s.two_split_pairs <= nt, "%zu pairs of %zu triangles", s.two_split_pairs, nt);
    FZ_ASSERT(s.patch_count == want, "patch count %zu, expected %zu", s.patch_count, want);
    for (size_t i = 0; i < nv; i++) {
        const double *nr = s.normal + 3 * i;
        FZ_ASSERT(fabs(sqrt(nr[0] * nr[0] + nr[1] * nr[1] + nr[2] * nr[2]) - 1) <= 1e-9,
                  "normal %zu not unit: %.17g %.17g %.17g (mesh scale %g)", i, nr[0], nr[1], nr[2],
                  scale);
    }
    /* Corner b300 / b030 / b003 of every patch is its corner node; for a mesh vertex it must be
     * the vertex, and the adjacent control points (b210, b201 at corner 0) lie in the tangent
     * plane of the vertex normal (G1 interpolation of the estimated normals). */
    static const int corner_ctrl[3] = {0, 6, 9}, next_ctrl[3][2] = {{1, 2}, {3, 7}, {5, 8}};
    for (size_t p = 0; p < s.patch_count; p++) {
        const double *c = s.ctrl + 30 * p;
        for (int k = 0; k < 30; k++) FZ_ASSERT(isfinite(c[k]), "patch %zu not finite", p);
        FZ_ASSERT(s.macro[p] < nt, "macro index");
        for (int k = 0; k < 3; k++) {
            uint32_t node = s.corner[3 * p + k];
            FZ_ASSERT(node < s.node_count, "corner node");
            if (node >= nv) continue;
            const double *b = c + 3 * corner_ctrl[k], *nr = s.normal + 3 * node;
            FZ_ASSERT(sm_close(b, xyz + 3 * node, 3, scale),
                      "patch %zu corner %d is not vertex %u", p, k, node);
            for (int j = 0; j < 2; j++) {
                const double *e = c + 3 * next_ctrl[k][j];
                double dot = 0, len = 0;
                for (int x = 0; x < 3; x++) {
                    dot += (e[x] - b[x]) * nr[x];
                    len += (e[x] - b[x]) * (e[x] - b[x]);
                }
                FZ_ASSERT(fabs(dot) <= 1e-7 * sqrt(len) + SM_TOL * scale + 1e-300,
                          "patch %zu: control point next to vertex %u leaves its tangent plane "
                          "(%.3g of %.3g)", p, node, dot, sqrt(len));
            }
        }
    }
    fl_mesh tm;
    double *tn = NULL;
    st = fl_g1_surface_tessellate(&s, 1 + (head >> 7), &tm, &tn, &err);
    fz_check_status(st, &err, "fl_g1_surface_tessellate");
    FZ_ASSERT(st == FL_OK, "tessellate failed: %s", err.message);
    for (size_t i = 0; i < 3 * tm.vertex_count; i++)
        FZ_ASSERT(isfinite(tm.xyz[i]) && isfinite(tn[i]), "tessellation not finite");
    fl_mesh_check_options co = {.skip_self_intersections = 1};
    fl_mesh_report rep;
    st = fl_mesh_check(&tm, &co, &rep, &err);
    FZ_ASSERT(st == FL_OK && rep.closed, "tessellation of a closed mesh is not closed");
    fl_mesh_report_free(&rep);
    free(tn);
    fl_mesh_free(&tm);
    fl_g1_surface_free(&s);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    uint8_t head = fz_byte(&in);
    if (head & 1) sm_surface(&in, head);
    else sm_curve(&in, head);
    return 0;
}
