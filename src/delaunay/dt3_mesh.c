/* The tetrahedron store and Bowyer-Watson insertion shared by the Delaunay (dt3.c) and the
 * regular (rt3.c) triangulation. Flat arrays, a free list for deleted tetrahedra, no
 * allocation per tetrahedron; see dt3_internal.h for the layout. */
#include <stdlib.h>
#include <string.h>

#include "delaunay/dt3_internal.h"

const int dt3_face_corners[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

static const double *pt(const dt3_mesh *m, uint32_t v)
{
    return m->pts + (size_t)v * m->stride;
}

static int grow_store(dt3_mesh *m, size_t need)
{
    if (need <= m->cap) return 0;
    if (need > DT3_MAX_TETS) return -1;
    size_t cap = m->cap ? m->cap : 64;
    while (cap < need)
        cap = cap + cap / 2;
    if (cap > DT3_MAX_TETS) cap = DT3_MAX_TETS;
    uint32_t *cell = fl_realloc_array(m->cell, cap, 8 * sizeof *cell);
    if (!cell) return -1;
    m->cell = cell;
    uint8_t *mark = fl_realloc_array(m->mark, cap, 1);
    if (!mark) return -1;
    memset(mark + m->cap, 0, cap - m->cap);
    m->mark = mark;
    m->cap = cap;
    return 0;
}

/* A slot for a new tetrahedron: from the free list, else appended. DT3_NONE when out of memory. */
static uint32_t new_tet(dt3_mesh *m)
{
    if (m->free_head != DT3_NONE) {
        uint32_t t = m->free_head;
        m->free_head = dt3_n(m, t)[0];
        return t;
    }
    if (grow_store(m, m->slots + 1) != 0) return DT3_NONE;
    return (uint32_t)m->slots++;
}

static void free_tet(dt3_mesh *m, uint32_t t)
{
    dt3_v(m, t)[0] = DT3_DEAD;
    dt3_n(m, t)[0] = m->free_head;
    m->free_head = t;
}

static void link(dt3_mesh *m, uint32_t t, int k, uint32_t u, int j)
{
    dt3_n(m, t)[k] = (u << 2) | (uint32_t)j;
    dt3_n(m, u)[j] = (t << 2) | (uint32_t)k;
}

/* Links the tetrahedra t[0..count) to each other wherever they share a face (by comparing
 * vertex sets): only for the five tetrahedra of the initial triangulation. */
static void link_by_search(dt3_mesh *m, const uint32_t *t, int count)
{
    for (int i = 0; i < count; i++)
        for (int j = i + 1; j < count; j++)
            for (int k = 0; k < 4; k++)
                for (int l = 0; l < 4; l++) {
                    const uint32_t *a = dt3_v(m, t[i]), *b = dt3_v(m, t[j]);
                    int shared = 0;
                    for (int x = 0; x < 4; x++)
                        for (int y = 0; y < 4; y++)
                            shared += x != k && y != l && a[x] == b[y];
                    if (shared == 3) link(m, t[i], k, t[j], l);
                }
}

int dt3_mesh_init(dt3_mesh *m, const uint32_t v[4], size_t expected_points)
{
    size_t slots = expected_points < DT3_MAX_TETS / 8 ? expected_points * 7 + 16 : DT3_MAX_TETS;
    m->free_head = DT3_NONE;
    m->rng = 0x9E3779B97F4A7C15ULL;
    fl_vec_init(&m->cavity, sizeof(uint32_t));
    fl_vec_init(&m->touched, sizeof(uint32_t));
    fl_vec_init(&m->boundary, sizeof(uint32_t));
    fl_vec_init(&m->created, sizeof(uint32_t));
    if (grow_store(m, slots) != 0) return -1;
    uint32_t q[4] = {v[0], v[1], v[2], v[3]};
    if (fl_orient3d(pt(m, q[0]), pt(m, q[1]), pt(m, q[2]), pt(m, q[3])) < 0) {
        q[0] = v[1];
        q[1] = v[0];
    }
    uint32_t t[5];
    t[0] = new_tet(m);
    memcpy(dt3_v(m, t[0]), q, sizeof q);
    for (int k = 0; k < 4; k++) {
        /* Replace corner k by the infinite vertex and swap two other corners: the infinite
         * vertex then lies on the far side of face k, as the orientation convention asks. */
        uint32_t u = new_tet(m), *w = dt3_v(m, u);
        memcpy(w, q, sizeof q);
        w[k] = DT3_INF;
        uint32_t tmp = w[(k + 1) & 3];
        w[(k + 1) & 3] = w[(k + 2) & 3];
        w[(k + 2) & 3] = tmp;
        t[k + 1] = u;
    }
    link_by_search(m, t, 5);
    m->last = t[0];
    return 0;
}

void dt3_mesh_free(dt3_mesh *m)
{
    free(m->cell);
    free(m->mark);
    free(m->vstamp);
    fl_vec_free(&m->cavity);
    fl_vec_free(&m->touched);
    fl_vec_free(&m->boundary);
    fl_vec_free(&m->created);
    memset(m, 0, sizeof *m);
}

/* Orientation of tetrahedron t with corner k replaced by q: positive when q is on the same side
 * of face k as corner k (for the infinite corner: strictly outside the hull face). */
static int orient_replaced(const dt3_mesh *m, uint32_t t, int k, const double *q)
{
    const uint32_t *v = dt3_v(m, t);
    const double *p[4];
    for (int i = 0; i < 4; i++)
        p[i] = i == k ? q : pt(m, v[i]);
    return fl_orient3d(p[0], p[1], p[2], p[3]);
}

static int inf_corner(const dt3_mesh *m, uint32_t t)
{
    const uint32_t *v = dt3_v(m, t);
    for (int i = 0; i < 4; i++)
        if (v[i] == DT3_INF) return i;
    return -1;
}

/* Finds, for the new point q, a tetrahedron whose closed region contains it (finite), or an
 * infinite one whose hull face q sees strictly. */
static uint32_t locate(dt3_mesh *m, const double *q)
{
    uint32_t t = m->last, prev = DT3_NONE;
    int k = inf_corner(m, t);
    if (k >= 0) t = dt3_n(m, t)[k] >> 2;
    for (;;) {
        /* Visibility walk, crossing a face only when q is strictly beyond it. Starting at a
         * random face makes it terminate with probability 1 on any triangulation; not stepping
         * straight back saves a test (Devillers, Pion, Teillaud: "Walking in a
         * triangulation", the remembering stochastic walk). */
        m->rng ^= m->rng << 13;
        m->rng ^= m->rng >> 7;
        m->rng ^= m->rng << 17;
        int start = (int)(m->rng >> 62), moved = 0;
        for (int i = 0; i < 4 && !moved; i++) {
            k = (start + i) & 3;
            uint32_t u = dt3_n(m, t)[k] >> 2;
            if (u == prev || orient_replaced(m, t, k, q) >= 0) continue;
            prev = t;
            t = u;
            moved = 1;
        }
        if (!moved || dt3_is_infinite(m, t)) return t;
    }
}

static inline int finite_conflict(const dt3_mesh *m, uint32_t t, uint32_t p)
{
    const uint32_t *v = dt3_v(m, t);
    const double *a = pt(m, v[0]), *b = pt(m, v[1]), *c = pt(m, v[2]), *d = pt(m, v[3]);
    /* The unperturbed test first: it decides almost always, without loading the indices. */
    int s = m->weighted ? fl_insphere_weighted(a, b, c, d, pt(m, p))
                        : fl_insphere(a, b, c, d, pt(m, p));
    if (s == 0)
        s = dt3_power_sos(m->weighted, a, b, c, d, pt(m, p), m->gid[v[0]], m->gid[v[1]],
                          m->gid[v[2]], m->gid[v[3]], m->gid[p]);
    return s > 0;
}

/* Is point p in conflict with tetrahedron t (finite or infinite)? */
static inline int in_conflict(const dt3_mesh *m, uint32_t t, uint32_t p)
{
    int k = inf_corner(m, t);
    if (k < 0) return finite_conflict(m, t, p);
    int o = orient_replaced(m, t, k, pt(m, p));
    if (o != 0) return o > 0;
    /* p lies in the plane of the hull face. The perturbed test against the finite tetrahedron
     * behind the face decides, because any sphere through the face cuts its plane in the face's
     * circumcircle: conflict iff p is inside that circle, with the same tie-break as the finite
     * tetrahedron. So the two tetrahedra on the face are in the cavity together or not at all,
     * and the cavity never produces a flat tetrahedron (face, p). */
    return finite_conflict(m, dt3_n(m, t)[k] >> 2, p);
}

/* ---- Bowyer-Watson insertion ---- */

/* fl_vec_push of one uint32 without the call in the common case. */
static inline int push_u32(fl_vec *v, uint32_t x)
{
    if (v->count == v->capacity && fl_vec_reserve(v, v->count + 1) != 0) return -1;
    ((uint32_t *)v->data)[v->count++] = x;
    return 0;
}

/* Breadth-first search of the tetrahedra in conflict with p from t (which is). The conflict
 * region is connected: it is the set of lower-hull facets visible from the lifted p. Marks:
 * 1 in the cavity, 2 tested and not in conflict; boundary collects the cavity faces (t << 2 | k)
 * whose neighbour is not in conflict. */
static int find_cavity(dt3_mesh *m, uint32_t t, uint32_t p)
{
    m->cavity.count = m->touched.count = m->boundary.count = 0;
    if (push_u32(&m->cavity, t) != 0) return -1;
    m->mark[t] = 1;
    for (size_t i = 0; i < m->cavity.count; i++) {
        uint32_t c = ((const uint32_t *)m->cavity.data)[i];
        for (int k = 0; k < 4; k++) {
            uint32_t u = dt3_n(m, c)[k] >> 2;
            if (m->mark[u] == 0) {
                int in = in_conflict(m, u, p);
                m->mark[u] = in ? 1 : 2;
                if (push_u32(in ? &m->cavity : &m->touched, u) != 0) return -1;
            }
            if (m->mark[u] == 2 && push_u32(&m->boundary, (c << 2) | (uint32_t)k) != 0) return -1;
        }
    }
    return 0;
}

/* Corner of tetrahedron v other than corner `skip` and the corners holding a and b. */
static int third_corner(const uint32_t *v, int skip, uint32_t a, uint32_t b)
{
    int i = 0;
    while (i == skip || v[i] == a || v[i] == b)
        i++;
    return i;
}

/* The new tetrahedron's face through p and the cavity edge ab, found by turning around ab
 * through the cavity from boundary face (c, k) to the other boundary face on ab (the cavity is
 * a ball, so the turn ends there). fill_cavity has left in every boundary face's slot the link
 * to the new tetrahedron on it, which is how the end of the turn is recognised (mark 0).
 * Corner j of c is the corner of the boundary face off ab. Returns (tetrahedron << 2 | corner). */
static uint32_t across_edge(const dt3_mesh *m, uint32_t c, int k, int j)
{
    const uint32_t *cv = dt3_v(m, c);
    int ia = 0;
    while (ia == j || ia == k)
        ia++;
    uint32_t a = cv[ia], b = cv[6 - j - k - ia];
    uint32_t cur = c;
    int exit = j; /* leave cur through its face opposite `exit`, the other face on ab */
    for (;;) {
        uint32_t link = dt3_n(m, cur)[exit], n = link >> 2;
        const uint32_t *v = dt3_v(m, cur);
        int w = third_corner(v, exit, a, b);
        if (m->mark[n] != 1) /* n is the new tetrahedron on (cur, exit), laid out like cur */
            return (n << 2) | (uint32_t)w;
        const uint32_t *nv = dt3_v(m, n);
        int e = 0;
        while (nv[e] != v[w])
            e++;
        cur = n;
        exit = e;
    }
}

/* Cones every boundary face to p. The new tetrahedron keeps the corners of the cavity
 * tetrahedron with the corner opposite the face replaced by p: p sees the face from that side,
 * so the orientation is kept. */
static int fill_cavity(dt3_mesh *m, uint32_t p)
{
    size_t nb = m->boundary.count;
    if (grow_store(m, m->slots + nb) != 0 || fl_vec_reserve(&m->created, nb) != 0) return -1;
    uint32_t *bf = m->boundary.data, *created = m->created.data;
    m->created.count = nb;
    for (size_t i = 0; i < nb; i++) {
        uint32_t c = bf[i] >> 2, u = new_tet(m);
        int k = (int)(bf[i] & 3);
        uint32_t outer = dt3_n(m, c)[k];
        memcpy(dt3_v(m, u), dt3_v(m, c), 4 * sizeof(uint32_t));
        dt3_v(m, u)[k] = p;
        for (int j = 0; j < 4; j++)
            dt3_n(m, u)[j] = DT3_NONE;
        link(m, u, k, outer >> 2, (int)(outer & 3));
        dt3_n(m, c)[k] = (u << 2) | (uint32_t)k; /* the cavity is discarded */
        created[i] = u;
    }
    for (size_t i = 0; i < nb; i++) {
        uint32_t c = bf[i] >> 2, u = created[i];
        int k = (int)(bf[i] & 3);
        for (int j = 0; j < 4; j++)
            if (j != k && dt3_n(m, u)[j] == DT3_NONE) {
                uint32_t other = across_edge(m, c, k, j);
                link(m, u, j, other >> 2, (int)(other & 3));
            }
    }
    return 0;
}

/* Vertices of the cavity that are on no boundary face disappear: the new point hides them.
 * Only possible for weighted points (a Delaunay vertex is never inside a cavity). */
static int collect_hidden(dt3_mesh *m, uint32_t p, fl_vec *hidden)
{
    uint32_t stamp = p + 1;
    const uint32_t *bf = m->boundary.data, *cav = m->cavity.data;
    for (size_t i = 0; i < m->boundary.count; i++) {
        const uint32_t *v = dt3_v(m, bf[i] >> 2);
        for (int j = 0; j < 4; j++)
            if (j != (int)(bf[i] & 3) && v[j] != DT3_INF) m->vstamp[v[j]] = stamp;
    }
    for (size_t i = 0; i < m->cavity.count; i++) {
        const uint32_t *v = dt3_v(m, cav[i]);
        for (int j = 0; j < 4; j++) {
            if (v[j] == DT3_INF || m->vstamp[v[j]] == stamp) continue;
            m->vstamp[v[j]] = stamp;
            if (push_u32(hidden, v[j]) != 0) return -1;
        }
    }
    return 0;
}

dt3_insert_result dt3_insert(dt3_mesh *m, uint32_t p, fl_vec *hidden)
{
    uint32_t t = locate(m, pt(m, p));
    if (!in_conflict(m, t, p)) return DT3_REDUNDANT;
    int fail = find_cavity(m, t, p);
    if (!fail && m->weighted) fail = collect_hidden(m, p, hidden);
    if (!fail) fail = fill_cavity(m, p);
    const uint32_t *cav = m->cavity.data, *touched = m->touched.data;
    for (size_t i = 0; i < m->touched.count; i++)
        m->mark[touched[i]] = 0;
    for (size_t i = 0; i < m->cavity.count; i++) {
        m->mark[cav[i]] = 0;
        if (!fail) free_tet(m, cav[i]);
    }
    if (fail) return DT3_NOMEM;
    m->last = ((const uint32_t *)m->created.data)[0];
    return DT3_INSERTED;
}
