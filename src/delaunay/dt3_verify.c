/* Independent checks of a 3D Delaunay or regular triangulation given as flat output arrays,
 * with the exact predicates. Local checks that imply the global ones: positive orientation and
 * symmetric adjacency make a pseudo-manifold; with a closed, locally convex boundary and the
 * Euler characteristic of a ball it is a triangulation of the hull; and a triangulation whose
 * every interior face and hull edge is locally Delaunay (regular) is Delaunay (regular): the
 * lifted complex is then locally, hence globally, convex (Delaunay lemma). */
#include <stdlib.h>
#include <string.h>

#include "delaunay/dt3_internal.h"

typedef struct vctx {
    const double *in;
    size_t n, stride;
    int weighted;
    size_t nt;
    const uint32_t *tet, *adj;
} vctx;

typedef struct face_rec {
    uint32_t v[3]; /* sorted */
    uint32_t t, k;
} face_rec;

static const double *P(const vctx *c, uint32_t i)
{
    return c->in + (size_t)i * c->stride;
}

static int cmp_face(const void *a, const void *b)
{
    const face_rec *x = a, *y = b;
    for (int i = 0; i < 3; i++)
        if (x->v[i] != y->v[i]) return x->v[i] < y->v[i] ? -1 : 1;
    return 0;
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

static void sort3(uint32_t v[3])
{
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2 - i; j++)
            if (v[j] > v[j + 1]) {
                uint32_t t = v[j];
                v[j] = v[j + 1];
                v[j + 1] = t;
            }
}

static face_rec face_of(const uint32_t *t4, uint32_t t, int k)
{
    face_rec f;
    for (int i = 0; i < 3; i++)
        f.v[i] = t4[dt3_face_corners[k][i]];
    sort3(f.v);
    f.t = t;
    f.k = (uint32_t)k;
    return f;
}

/* Is point e in conflict with tetrahedron t (exact, perturbed)? */
static int conflict(const vctx *c, size_t t, uint32_t e)
{
    const uint32_t *v = c->tet + 4 * t;
    return dt3_power_sos(c->weighted, P(c, v[0]), P(c, v[1]), P(c, v[2]), P(c, v[3]), P(c, e), v[0],
                         v[1], v[2], v[3], e) > 0;
}

static fl_status check_tets(const vctx *c, const uint8_t *kept, uint8_t *used, fl_error *err)
{
    for (size_t t = 0; t < c->nt; t++) {
        const uint32_t *v = c->tet + 4 * t;
        for (int i = 0; i < 4; i++) {
            if (v[i] >= c->n || !kept[v[i]])
                return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                               "tetrahedron %zu: corner %d is %u, not a vertex", t, i, v[i]);
            for (int j = 0; j < i; j++)
                if (v[i] == v[j])
                    return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                                   "tetrahedron %zu repeats point %u", t, v[i]);
            used[v[i]] = 1;
        }
        if (fl_orient3d(P(c, v[0]), P(c, v[1]), P(c, v[2]), P(c, v[3])) <= 0)
            return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                           "tetrahedron %zu (points %u %u %u %u) is not positively oriented", t,
                           v[0], v[1], v[2], v[3]);
    }
    return FL_OK;
}

/* Symmetric adjacency across equal faces, and each interior face locally Delaunay. */
static fl_status check_adjacency(const vctx *c, size_t *hull_sides, fl_error *err)
{
    *hull_sides = 0;
    for (size_t t = 0; t < c->nt; t++)
        for (int k = 0; k < 4; k++) {
            uint32_t u = c->adj[4 * t + k];
            if (u == UINT32_MAX) {
                (*hull_sides)++;
                continue;
            }
            int j = 0;
            while (j < 4 && !(u < c->nt && c->adj[4 * (size_t)u + j] == t))
                j++;
            face_rec a = face_of(c->tet + 4 * t, 0, k), b = a;
            if (j < 4) b = face_of(c->tet + 4 * (size_t)u, 0, j);
            if (j == 4 || cmp_face(&a, &b) != 0)
                return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                               "tetrahedra %zu and %u: adjacency is not symmetric", t, u);
            uint32_t e = c->tet[4 * (size_t)u + j];
            if (t < u && conflict(c, t, e))
                return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                               "point %u is inside the %s of neighbouring tetrahedron %zu", e,
                               c->weighted ? "orthogonal sphere" : "circumsphere", t);
        }
    return FL_OK;
}

/* V - E + F - T = 1 for a triangulated 3-ball. */
static fl_status check_euler(const vctx *c, size_t vertices, size_t hull_sides, fl_error *err)
{
    uint64_t *e = fl_alloc_array(c->nt ? c->nt : 1, 6 * sizeof *e);
    if (!e) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    size_t ne = 0;
    for (size_t t = 0; t < c->nt; t++)
        for (int i = 0; i < 4; i++)
            for (int j = i + 1; j < 4; j++) {
                uint64_t a = c->tet[4 * t + i], b = c->tet[4 * t + j];
                e[ne++] = a < b ? a << 32 | b : b << 32 | a;
            }
    qsort(e, ne, sizeof *e, cmp_u64);
    size_t edges = 0;
    for (size_t i = 0; i < ne; i++)
        edges += i == 0 || e[i] != e[i - 1];
    free(e);
    size_t faces = (4 * c->nt + hull_sides) / 2;
    long long chi = (long long)vertices - (long long)edges + (long long)faces - (long long)c->nt;
    if (chi != 1)
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                       "Euler characteristic V-E+F-T = %lld, not 1 (%zu vertices, %zu edges, "
                       "%zu faces, %zu tetrahedra)",
                       chi, vertices, edges, faces, c->nt);
    return FL_OK;
}

typedef struct edge_rec {
    uint64_t key;
    uint32_t face, apex; /* hull face and its corner off the edge */
} edge_rec;

static int cmp_edge(const void *a, const void *b)
{
    const edge_rec *x = a, *y = b;
    return x->key < y->key ? -1 : x->key > y->key;
}

/* Across each hull edge, the apex of one hull face must not see the other face from outside;
 * when coplanar it must not be in the face's circumcircle (the perturbed test against the
 * tetrahedron behind the face, as the insertion decides it). */
static fl_status check_hull_edges(const vctx *c, size_t nh, const uint32_t *hull,
                                  const uint32_t *hull_tet, fl_error *err)
{
    edge_rec *e = fl_alloc_array(nh ? nh : 1, 3 * sizeof *e);
    if (!e) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    for (size_t h = 0; h < nh; h++)
        for (int i = 0; i < 3; i++) {
            uint64_t a = hull[3 * h + i], b = hull[3 * h + (i + 1) % 3];
            e[3 * h + i] = (edge_rec){a < b ? a << 32 | b : b << 32 | a, (uint32_t)h,
                                      hull[3 * h + (i + 2) % 3]};
        }
    qsort(e, 3 * nh, sizeof *e, cmp_edge);
    fl_status st = FL_OK;
    for (size_t i = 0; i < 3 * nh && st == FL_OK; i += 2) {
        if (i + 1 >= 3 * nh || e[i].key != e[i + 1].key ||
            (i + 2 < 3 * nh && e[i + 2].key == e[i].key)) {
            st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                         "hull edge %u-%u is not shared by exactly two hull faces",
                         (uint32_t)(e[i].key >> 32), (uint32_t)e[i].key);
            break;
        }
        for (int s = 0; s < 2 && st == FL_OK; s++) {
            const edge_rec *f = &e[i + (size_t)s], *g = &e[i + 1 - (size_t)s];
            const uint32_t *v = hull + 3 * (size_t)f->face;
            int o = fl_orient3d(P(c, v[0]), P(c, v[1]), P(c, v[2]), P(c, g->apex));
            if (o < 0 || (o == 0 && conflict(c, hull_tet[f->face], g->apex)))
                st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                             "hull face %u and point %u: the hull is not %s there", f->face,
                             g->apex, o < 0 ? "convex" : "Delaunay in its plane");
        }
    }
    free(e);
    return st;
}

/* The listed hull faces are exactly the tetrahedron faces without a neighbour, oriented
 * outward; then the hull edges. */
static fl_status check_hull(const vctx *c, size_t nh, const uint32_t *hull, size_t hull_sides,
                            fl_error *err)
{
    if (nh != hull_sides)
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                       "%zu hull faces listed, but %zu tetrahedron faces have no neighbour", nh,
                       hull_sides);
    face_rec *mine = fl_alloc_array(nh ? nh : 1, sizeof *mine);
    face_rec *listed = fl_alloc_array(nh ? nh : 1, sizeof *listed);
    uint32_t *hull_tet = fl_alloc_array(nh ? nh : 1, sizeof *hull_tet);
    fl_status st = mine && listed && hull_tet ? FL_OK : FL_ERR_NOMEM;
    if (st != FL_OK) fl_fail(err, st, NULL, -1, "out of memory");
    for (size_t t = 0, m = 0; st == FL_OK && t < c->nt; t++)
        for (int k = 0; k < 4; k++)
            if (c->adj[4 * t + k] == UINT32_MAX)
                mine[m++] = face_of(c->tet + 4 * t, (uint32_t)t, k);
    for (size_t h = 0; st == FL_OK && h < nh; h++) {
        listed[h].v[0] = hull[3 * h];
        listed[h].v[1] = hull[3 * h + 1];
        listed[h].v[2] = hull[3 * h + 2];
        sort3(listed[h].v);
        listed[h].t = (uint32_t)h;
    }
    if (st == FL_OK) {
        qsort(mine, nh, sizeof *mine, cmp_face);
        qsort(listed, nh, sizeof *listed, cmp_face);
    }
    for (size_t i = 0; st == FL_OK && i < nh; i++) {
        const uint32_t *f = hull + 3 * (size_t)listed[i].t;
        if (cmp_face(&mine[i], &listed[i]) != 0) {
            st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                         "hull face %u (%u %u %u) is not a free tetrahedron face", listed[i].t,
                         f[0], f[1], f[2]);
            break;
        }
        uint32_t apex = c->tet[4 * (size_t)mine[i].t + mine[i].k];
        hull_tet[listed[i].t] = mine[i].t;
        if (fl_orient3d(P(c, f[0]), P(c, f[1]), P(c, f[2]), P(c, apex)) <= 0)
            st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                         "hull face %u (%u %u %u) is not oriented outward", listed[i].t, f[0], f[1],
                         f[2]);
    }
    if (st == FL_OK) st = check_hull_edges(c, nh, hull, hull_tet, err);
    free(mine);
    free(listed);
    free(hull_tet);
    return st;
}

fl_status dt3_verify(const double *in, size_t n, int weighted, const uint8_t *kept,
                     size_t tet_count, const uint32_t *tet, const uint32_t *adj,
                     size_t hull_face_count, const uint32_t *hull_faces, fl_error *err)
{
    vctx c = {in, n, weighted ? 4 : 3, weighted, tet_count, tet, adj};
    if (tet_count && (!tet || !adj || !hull_faces))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "verify: NULL triangulation arrays");
    uint8_t *used = fl_calloc_array(n ? n : 1, 1);
    if (!used) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
    size_t hull_sides = 0, vertices = 0, expected = 0;
    fl_status st = check_tets(&c, kept, used, err);
    if (st == FL_OK) st = check_adjacency(&c, &hull_sides, err);
    for (size_t i = 0; i < n; i++) {
        vertices += used[i];
        expected += kept[i] != 0;
    }
    if (st == FL_OK && vertices != expected)
        st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                     "%zu points should be vertices, but the tetrahedra use %zu", expected,
                     vertices);
    if (st == FL_OK) st = check_hull(&c, hull_face_count, hull_faces, hull_sides, err);
    if (st == FL_OK) st = check_euler(&c, vertices, hull_sides, err);
    free(used);
    return st;
}

/* Visibility walk over the output adjacency to a tetrahedron whose closed region holds q.
 * UINT32_MAX when q is outside the hull or the walk does not end (an invalid triangulation). */
static uint32_t locate_output(const vctx *c, const double *q)
{
    uint32_t t = 0;
    for (size_t steps = 0; steps <= 4 * c->nt + 8; steps++) {
        const uint32_t *v = c->tet + 4 * (size_t)t;
        int k = 0;
        for (; k < 4; k++) {
            const double *p[4] = {P(c, v[0]), P(c, v[1]), P(c, v[2]), P(c, v[3])};
            p[k] = q;
            if (fl_orient3d(p[0], p[1], p[2], p[3]) < 0) break;
        }
        if (k == 4) return t;
        t = c->adj[4 * (size_t)t + k];
        if (t == UINT32_MAX) return t;
    }
    return UINT32_MAX;
}

fl_status dt3_verify_hidden(const double *in, size_t n, size_t hidden_count, const uint32_t *hidden,
                            size_t tet_count, const uint32_t *tet, const uint32_t *adj,
                            fl_error *err)
{
    vctx c = {in, n, 4, 1, tet_count, tet, adj};
    if (hidden_count && !tet_count)
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "hidden balls but no tetrahedra");
    for (size_t i = 0; i < hidden_count; i++) {
        uint32_t h = hidden[i];
        if (h >= n || (i > 0 && h <= hidden[i - 1]))
            return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                           "hidden list entry %zu (%u) is out of range or not ascending", i, h);
        uint32_t t = locate_output(&c, P(&c, h));
        if (t == UINT32_MAX)
            return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                           "hidden ball %u: its centre is not inside the triangulated hull", h);
        if (conflict(&c, t, h))
            return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                           "hidden ball %u is in conflict with tetrahedron %u: it should be a "
                           "vertex",
                           h, t);
    }
    return FL_OK;
}
