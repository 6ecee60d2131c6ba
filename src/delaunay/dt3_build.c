/* The pipeline shared by fl_dt3_build and fl_rt3_build: validate, merge duplicates, order the
 * points (Hilbert BRIO), find a first tetrahedron, insert, and extract flat output arrays. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay_internal.h"
#include "delaunay/dt3_internal.h"

static const char *stage_name(int weighted)
{
    return weighted ? "regular 3d" : "delaunay 3d";
}

static fl_status check_input(const double *in, size_t n, int stride, fl_error *err)
{
    if (n > (size_t)UINT32_MAX - 2 || n > SIZE_MAX / (4 * sizeof(double)))
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "%zu points: at most 4294967293 are supported",
                       n);
    if (n && !in) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "the point array is NULL");
    for (size_t i = 0; i < n * (size_t)stride; i++)
        if (!isfinite(in[i]))
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "point %zu has a NaN or infinite %s",
                           i / (size_t)stride, i % (size_t)stride == 3 ? "weight" : "coordinate");
    return FL_OK;
}

/* Duplicates: points with equal centres. Among balls with one centre the heaviest (then the
 * first) is kept; an equal ball is its duplicate, a lighter one is hidden by it (its power
 * distance is larger everywhere). Fills out->duplicate_of and out->hidden, and the kept indices
 * into keep[0..*kc). `best` is n entries of scratch (weighted only). */
static fl_status merge_duplicates(const double *xyz, const double *in, size_t n, int weighted,
                                  dt3_output *out, uint32_t *best, uint32_t *keep, size_t *kc,
                                  fl_error *err)
{
    size_t unique = 0;
    uint32_t *rep = out->duplicate_of;
    fl_status st = fl_dt_unique(xyz, n, 3, rep, &unique, err);
    if (st != FL_OK) return st;
    *kc = 0;
    if (!weighted) {
        for (size_t i = 0; i < n; i++)
            if (rep[i] == i) keep[(*kc)++] = (uint32_t)i;
        return FL_OK;
    }
    for (size_t i = 0; i < n; i++)
        best[i] = (uint32_t)i;
    for (size_t i = 0; i < n; i++)
        if (in[4 * i + 3] > in[4 * (size_t)best[rep[i]] + 3]) best[rep[i]] = (uint32_t)i;
    for (size_t i = 0; i < n; i++) {
        uint32_t b = best[rep[i]];
        if (b == i) keep[(*kc)++] = (uint32_t)i;
        rep[i] = in[4 * i + 3] == in[4 * (size_t)b + 3] ? b : (uint32_t)i;
        if (rep[i] == i && b != i && fl_vec_push(&out->hidden, &(uint32_t){(uint32_t)i}, 1) != 0)
            return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    return FL_OK;
}

/* Are points a, b, c collinear? Exactly: all three coordinate projections are collinear. */
static int collinear(const double *a, const double *b, const double *c)
{
    if (fl_orient2d(a, b, c) != 0 || fl_orient2d(a + 1, b + 1, c + 1) != 0) return 0;
    const double axz[2] = {a[0], a[2]}, bxz[2] = {b[0], b[2]}, cxz[2] = {c[0], c[2]};
    return fl_orient2d(axz, bxz, cxz) == 0;
}

/* Local indices of four points that span 3D: the first two, the first point off their line,
 * the first point off their plane. Lower-dimensional input is an error that names its dimension. */
static fl_status first_tetrahedron(const double *pts, int stride, size_t n, uint32_t v[4],
                                   fl_error *err)
{
    const double *p0 = pts, *p1 = pts + stride;
    size_t i = 2;
    while (i < n && collinear(p0, p1, pts + i * stride))
        i++;
    if (i == n)
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                       "all %zu distinct points are collinear: a 3D triangulation needs 4 points "
                       "that do not lie in one plane",
                       n);
    const double *p2 = pts + i * stride;
    size_t j = 2;
    while (j < n && fl_orient3d(p0, p1, p2, pts + j * stride) == 0)
        j++;
    if (j == n)
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                       "all %zu distinct points are coplanar: a 3D triangulation needs 4 points "
                       "that do not lie in one plane (use the 2D triangulation for planar data)",
                       n);
    v[0] = 0;
    v[1] = 1;
    v[2] = (uint32_t)i;
    v[3] = (uint32_t)j;
    return FL_OK;
}

/* Appends the caller's indices of the local points in `local` to `hidden`. */
static fl_status report_hidden(const dt3_mesh *m, const fl_vec *local, fl_vec *hidden,
                               fl_error *err)
{
    for (size_t k = 0; k < local->count; k++) {
        uint32_t g = m->gid[((const uint32_t *)local->data)[k]];
        if (fl_vec_push(hidden, &g, 1) != 0)
            return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    }
    return FL_OK;
}

/* Inserts every point but the first tetrahedron's, in order. A ball can be hidden on arrival
 * (DT3_REDUNDANT) or later, swallowed by another ball's cavity; both are reported. A point
 * never is redundant without weights (its containing tetrahedron's circumsphere contains it):
 * that is reported as an internal error rather than trusted. */
static fl_status insert_all(dt3_mesh *m, size_t n, const uint32_t v[4], fl_progress_fn progress,
                            void *user, fl_vec *hidden, fl_error *err)
{
    fl_vec swallowed;
    fl_vec_init(&swallowed, sizeof(uint32_t));
    fl_status st = FL_OK;
    const char *stage = stage_name(m->weighted);
    for (size_t i = 2; i < n && st == FL_OK; i++) {
        if (i == v[2] || i == v[3]) continue;
        if ((i & 0x3fff) == 0 && fl_progress(progress, user, stage, (double)i / (double)n)) {
            st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
            break;
        }
        swallowed.count = 0;
        dt3_insert_result r = dt3_insert(m, (uint32_t)i, &swallowed);
        if (r == DT3_NOMEM)
            st = fl_fail(err, FL_ERR_NOMEM, NULL, -1,
                         "out of memory after %zu of %zu points (the store holds at most 2^30 "
                         "tetrahedra)",
                         i, n);
        else if (r == DT3_REDUNDANT && !m->weighted)
            st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                         "internal error: point %u is in conflict with no tetrahedron", m->gid[i]);
        else if (r == DT3_REDUNDANT && fl_vec_push(&swallowed, &(uint32_t){(uint32_t)i}, 1) != 0)
            st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
        if (st == FL_OK) st = report_hidden(m, &swallowed, hidden, err);
    }
    fl_vec_free(&swallowed);
    if (st == FL_OK) fl_progress(progress, user, stage, 1.0);
    return st;
}

/* Centre and weight of the ball orthogonal to the four balls p[0..3] (weight 0 when
 * unweighted: then the circumcentre and the squared circumradius). With x = centre - p0 the
 * orthogonality conditions |x - (pi - p0)|^2 - wi = |x|^2 - w0 are the linear system
 * 2 (pi - p0) . x = |pi - p0|^2 - wi + w0, solved by Cramer's rule. A construction: floating. */
static void orthogonal_ball(const double *const p[4], int weighted, double out[4])
{
    double e[3][3], r[3];
    for (int i = 0; i < 3; i++) {
        for (int k = 0; k < 3; k++)
            e[i][k] = p[i + 1][k] - p[0][k];
        r[i] = e[i][0] * e[i][0] + e[i][1] * e[i][1] + e[i][2] * e[i][2];
        if (weighted) r[i] -= p[i + 1][3] - p[0][3];
    }
    double c12[3], c20[3], c01[3];
    for (int k = 0; k < 3; k++) {
        int a = (k + 1) % 3, b = (k + 2) % 3;
        c12[k] = e[1][a] * e[2][b] - e[1][b] * e[2][a];
        c20[k] = e[2][a] * e[0][b] - e[2][b] * e[0][a];
        c01[k] = e[0][a] * e[1][b] - e[0][b] * e[1][a];
    }
    double det2 = 2.0 * (e[0][0] * c12[0] + e[0][1] * c12[1] + e[0][2] * c12[2]);
    double x2 = 0;
    for (int k = 0; k < 3; k++) {
        double x = (r[0] * c12[k] + r[1] * c20[k] + r[2] * c01[k]) / det2;
        out[k] = p[0][k] + x;
        x2 += x * x;
    }
    out[3] = x2 - (weighted ? p[0][3] : 0.0);
}

/* The hull face of infinite tetrahedron s, read from its finite neighbour so that it is
 * counterclockwise seen from outside. */
static void fill_hull_face(const dt3_mesh *m, uint32_t s, uint32_t *face)
{
    const uint32_t *v = dt3_v(m, s);
    int k = 0;
    while (v[k] != DT3_INF)
        k++;
    uint32_t link = dt3_n(m, s)[k], f = link >> 2;
    const int *c = dt3_face_corners[link & 3];
    for (int i = 0; i < 3; i++)
        face[i] = m->gid[dt3_v(m, f)[c[i]]];
}

/* Hull faces and centres: everything that needs the store in local numbering. */
static fl_status extract_extras(const dt3_mesh *m, const uint32_t *newid, int want_centers,
                                dt3_output *out, fl_error *err)
{
    size_t cs = m->weighted ? 4 : 3;
    out->hull_faces = fl_alloc_array(out->hull_face_count, 3 * sizeof(uint32_t));
    out->centers = want_centers ? fl_alloc_array(out->tet_count, cs * sizeof(double)) : NULL;
    if (!out->hull_faces || (want_centers && !out->centers))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for %zu tetrahedra",
                       out->tet_count);
    for (size_t s = 0, h = 0; s < m->slots; s++) {
        const uint32_t *v = dt3_v(m, s);
        if (newid[s] == DT3_NONE && v[0] != DT3_DEAD)
            fill_hull_face(m, (uint32_t)s, out->hull_faces + 3 * h++);
        if (newid[s] == DT3_NONE || !want_centers) continue;
        const double *p[4];
        double c[4];
        for (int k = 0; k < 4; k++)
            p[k] = m->pts + (size_t)v[k] * m->stride;
        orthogonal_ball(p, m->weighted, c);
        memcpy(out->centers + cs * newid[s], c, cs * sizeof(double));
    }
    return FL_OK;
}

/* Turns the store into the output in place: finite tetrahedra are moved down to their new
 * index (never above their slot, so nothing unread is overwritten), corners become caller
 * indices and links become tetrahedron indices; then the links are copied out and the corners
 * packed 4 a tetrahedron. The store's block becomes out->tet. */
static fl_status compact_store(dt3_mesh *m, const uint32_t *newid, dt3_output *out, fl_error *err)
{
    size_t nt = out->tet_count;
    out->adj = fl_alloc_array(nt, 4 * sizeof *out->adj);
    if (!out->adj)
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for %zu tetrahedra", nt);
    for (size_t s = 0; s < m->slots; s++) {
        size_t d = newid[s];
        if (d == DT3_NONE) continue;
        const uint32_t *v = dt3_v(m, s), *n = dt3_n(m, s);
        for (int k = 0; k < 4; k++)
            out->adj[4 * d + k] = newid[n[k] >> 2];
        uint32_t g[4] = {m->gid[v[0]], m->gid[v[1]], m->gid[v[2]], m->gid[v[3]]};
        memcpy(m->cell + 4 * d, g, sizeof g);
    }
    uint32_t *tet = fl_realloc_array(m->cell, nt ? nt : 1, 4 * sizeof *tet);
    out->tet = tet ? tet : m->cell; /* a failed shrink keeps the larger block */
    m->cell = NULL;
    return FL_OK;
}

static fl_status extract(dt3_mesh *m, int want_centers, dt3_output *out, fl_error *err)
{
    uint32_t *newid = fl_alloc_array(m->slots, sizeof *newid);
    if (!newid) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    out->tet_count = out->hull_face_count = 0;
    for (size_t s = 0; s < m->slots; s++) {
        newid[s] = DT3_NONE;
        if (dt3_v(m, s)[0] == DT3_DEAD) continue;
        if (dt3_is_infinite(m, (uint32_t)s))
            out->hull_face_count++;
        else
            newid[s] = (uint32_t)out->tet_count++;
    }
    fl_status st = extract_extras(m, newid, want_centers, out, err);
    if (st == FL_OK) st = compact_store(m, newid, out, err);
    free(newid);
    return st;
}

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return x < y ? -1 : x > y;
}

void dt3_output_free(dt3_output *out)
{
    free(out->duplicate_of);
    fl_vec_free(&out->hidden);
    free(out->tet);
    free(out->adj);
    free(out->hull_faces);
    free(out->centers);
    memset(out, 0, sizeof *out);
}

/* Kept points in BRIO order, copied contiguously (local numbering = insertion order) so that
 * consecutive insertions touch nearby memory; gid maps back to the caller's indices. */
static fl_status order_points(const double *in, const double *xyz, int stride, uint32_t *keep,
                              size_t kc, double **pts, uint32_t **gid, fl_error *err)
{
    *gid = fl_alloc_array(kc, sizeof **gid);
    *pts = fl_alloc_array(kc, (size_t)stride * sizeof **pts);
    if (!*gid || !*pts)
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for %zu points", kc);
    fl_status st = fl_dt_brio_order(xyz, keep, kc, 3, *gid, err);
    if (st != FL_OK) return st;
    for (size_t i = 0; i < kc; i++)
        memcpy(*pts + i * (size_t)stride, in + (size_t)(*gid)[i] * (size_t)stride,
               (size_t)stride * sizeof(double));
    return FL_OK;
}

/* Positions, duplicates, order: everything before the first insertion. */
static fl_status prepare(const double *in, size_t n, int weighted, dt3_output *out, double **pts,
                         uint32_t **gid, size_t *kc, fl_error *err)
{
    int stride = weighted ? 4 : 3;
    double *xyz = NULL;
    uint32_t *keep = fl_alloc_array(n, sizeof *keep), *best = NULL;
    out->duplicate_of = fl_alloc_array(n, sizeof *out->duplicate_of);
    fl_status st = keep && out->duplicate_of ? FL_OK : FL_ERR_NOMEM;
    if (st == FL_OK && weighted) {
        xyz = fl_alloc_array(n, 3 * sizeof *xyz);
        best = fl_alloc_array(n, sizeof *best);
        st = xyz && best ? FL_OK : FL_ERR_NOMEM;
        for (size_t i = 0; st == FL_OK && i < n; i++)
            memcpy(xyz + 3 * i, in + 4 * i, 3 * sizeof *xyz);
    }
    const double *pos = weighted ? xyz : in;
    if (st != FL_OK)
        fl_fail(err, st, NULL, -1, "out of memory for %zu points", n);
    else
        st = merge_duplicates(pos, in, n, weighted, out, best, keep, kc, err);
    if (st == FL_OK && *kc < 4)
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                     "a 3D triangulation needs at least 4 distinct points, got %zu", *kc);
    if (st == FL_OK) st = order_points(in, pos, stride, keep, *kc, pts, gid, err);
    free(keep);
    free(best);
    free(xyz);
    return st;
}

fl_status dt3_build(const double *in, size_t n, int weighted, fl_progress_fn progress, void *user,
                    int want_centers, dt3_output *out, fl_error *err)
{
    memset(out, 0, sizeof *out);
    fl_vec_init(&out->hidden, sizeof(uint32_t));
    dt3_mesh m;
    memset(&m, 0, sizeof m);
    double *pts = NULL;
    uint32_t *gid = NULL, v[4];
    size_t kc = 0;
    fl_status st = check_input(in, n, weighted ? 4 : 3, err);
    if (st == FL_OK) st = prepare(in, n, weighted, out, &pts, &gid, &kc, err);
    if (st == FL_OK) st = first_tetrahedron(pts, weighted ? 4 : 3, kc, v, err);
    if (st == FL_OK) {
        m.pts = pts;
        m.stride = weighted ? 4 : 3;
        m.weighted = weighted;
        m.gid = gid;
        m.vstamp = weighted ? fl_calloc_array(kc, sizeof *m.vstamp) : NULL;
        if ((weighted && !m.vstamp) || dt3_mesh_init(&m, v, kc) != 0)
            st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for %zu points", kc);
    }
    size_t hidden_before = out->hidden.count;
    if (st == FL_OK) st = insert_all(&m, kc, v, progress, user, &out->hidden, err);
    if (st == FL_OK) st = extract(&m, want_centers, out, err);
    out->vertex_count = kc - (out->hidden.count - hidden_before);
    if (out->hidden.count > 1)
        qsort(out->hidden.data, out->hidden.count, sizeof(uint32_t), cmp_u32);
    dt3_mesh_free(&m);
    free(pts);
    free(gid);
    if (st != FL_OK) dt3_output_free(out);
    return st;
}
