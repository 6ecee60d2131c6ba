/* Unlocking 3D constriction (thesis §5.4) by 2-3 flips inside the region.
 *
 * Constriction locks when every boundary tetrahedron is blocked (its opposite vertex or edge is
 * already on the boundary) while points remain inside. §5.4 then augments the Delaunay graph with
 * the triangles of γ([-1,1],[c0,1]), c0 < 0, forming tetrahedra that overlap the Delaunay ones,
 * and deletes every triangle that crosses a removed tetrahedron. Here the same overlapping
 * tetrahedra are brought in by a move that keeps the region a proper tetrahedralization, so the
 * boundary stays embedded and the interior tetrahedra stay valid output:
 *
 *   Let t1 = xyzw be a region tetrahedron with a boundary face wxy, and t2 = xyzp its region
 *   neighbour across xyz, p an inside point. When the segment wp crosses the interior of
 *   triangle xyz (three exact orient3d tests of equal, non-zero sign), t1 ∪ t2 is a convex
 *   bipyramid and the 2-3 flip replaces it by wpxy, wpyz, wpzx: the same volume, the same outer
 *   faces, so the region and its boundary do not change. The triangle xyz leaves the graph
 *   (it is the triangle that crosses the new tetrahedra) and wpx, wpy, wpz join it; these are
 *   triangles of γ([-1,1],[c0,1]) for c0 = their c1' (Def. 3.3). Now wpxy has one boundary
 *   face, wxy, and its opposite vertex p is inside, so the ordinary rule of §5.3 may remove it
 *   - a shelling step, after which the boundary is again an embedded sphere, with p on it.
 *
 * Each lock takes, per inside point, the candidate flip with the smallest γ-indicator of the
 * tetrahedron it makes removable (the selection rule of constriction), makes the ones that do
 * not share a tetrahedron, and hands the new tetrahedra back to constriction. A point that got a
 * flip is on the boundary by the next lock (its removable tetrahedron is removed, or becomes
 * unremovable only because p reached the boundary), so every lock with a flip makes progress and
 * the number of locks is at most the number of inside points. Kept faces (§5.7) are never flipped
 * and never opened. What this does not do: 3-2 or 4-4 flips, or chains of flips, so a point
 * with no such bipyramid next to the boundary stays inside (the reason says so). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reconstruct/constrict3_internal.h"

#define NONE UINT32_MAX

typedef struct candidate {
    double key;
    uint32_t t1, t2, v1, v2; /* tetrahedra and their versions when found */
    uint32_t p;              /* the inside point */
    int kw;                  /* corner of t1 opposite the shared face */
    uint32_t t3, v3;         /* two-step candidates: t2 holds no p; t3 (apex p) is first flipped
                                with t2 across t2's face opposite corner kv; NONE otherwise */
    int kv;
} candidate;

static int cand_cmp(const void *x, const void *y)
{
    const candidate *a = x, *b = y;
    if (a->key != b->key) return a->key < b->key ? -1 : 1;
    return a->t1 < b->t1 ? -1 : a->t1 > b->t1 ? 1 : (a->kw > b->kw) - (a->kw < b->kw);
}

static const double *pt(const constrict3_state *s, uint32_t i)
{
    return s->p + 3 * (size_t)i;
}

/* 1 when segment wp crosses the interior of triangle xyz (exact). */
static int crosses(const constrict3_state *s, uint32_t w, uint32_t p, const uint32_t *xyz)
{
    int s0 = fl_orient3d(pt(s, w), pt(s, p), pt(s, xyz[0]), pt(s, xyz[1]));
    int s1 = fl_orient3d(pt(s, w), pt(s, p), pt(s, xyz[1]), pt(s, xyz[2]));
    int s2 = fl_orient3d(pt(s, w), pt(s, p), pt(s, xyz[2]), pt(s, xyz[0]));
    return s0 != 0 && s0 == s1 && s1 == s2;
}

/* Corner of tetrahedron t whose vertex is not among f[0..2]. */
static int corner_not_in(const constrict3_state *s, uint32_t t, const uint32_t *f)
{
    for (int k = 0; k < 4; k++) {
        uint32_t v = s->tet[4 * (size_t)t + k];
        if (v != f[0] && v != f[1] && v != f[2]) return k;
    }
    return -1;
}

typedef struct cand_vec {
    candidate *a;
    size_t count, cap;
} cand_vec;

static int cand_push(cand_vec *v, candidate c)
{
    if (v->count == v->cap) {
        size_t cap = v->cap ? 2 * v->cap : 64;
        candidate *a = fl_realloc_array(v->a, cap, sizeof *a);
        if (!a) return -1;
        v->a = a;
        v->cap = cap;
    }
    v->a[v->count++] = c;
    return 0;
}

/* Pushes cd once per boundary face of t1 (other than the shared one) that the flip would open,
 * keyed by the γ-indicator of that face with respect to p, plus `penalty`. */
static int push_each_face(const constrict3_state *s, candidate *cd, unsigned bmask, double penalty,
                          cand_vec *out)
{
    const uint32_t *c = s->tet + 4 * (size_t)cd->t1;
    for (int kz = 0; kz < 4; kz++) {
        if (kz == cd->kw || !(bmask >> kz & 1)) continue;
        if (s->keepmask && (s->keepmask[cd->t1] >> kz & 1)) continue;
        const int *f = constrict3_face[kz];
        cd->key = constrict3_gamma_indicator(pt(s, c[f[0]]), pt(s, c[f[1]]), pt(s, c[f[2]]),
                                             pt(s, cd->p));
        cd->key = isnan(cd->key) ? 4.0 + penalty : cd->key + penalty;
        if (cand_push(out, *cd) != 0) return -1;
    }
    return 0;
}

/* The candidate flips of region tetrahedron t1 (see the file comment). */
static int candidates_of(const constrict3_state *s, uint32_t t1, unsigned bmask, cand_vec *out)
{
    const uint32_t *c = s->tet + 4 * (size_t)t1;
    for (int kw = 0; kw < 4; kw++) {
        uint32_t t2 = s->adj[4 * (size_t)t1 + kw];
        if (t2 == NONE || s->removed[t2]) continue;
        if (s->keepmask && (s->keepmask[t1] >> kw & 1)) continue; /* xyz is kept */
        uint32_t xyz[3];
        for (int i = 0; i < 3; i++)
            xyz[i] = c[constrict3_face[kw][i]];
        int kq = corner_not_in(s, t2, xyz);
        uint32_t p = s->tet[4 * (size_t)t2 + kq];
        candidate cd = {0, t1, t2, s->version[t1], s->version[t2], p, kw, NONE, 0, 0};
        if (s->bfaces[p] == 0) {
            if (crosses(s, c[kw], p, xyz) && push_each_face(s, &cd, bmask, 0, out) != 0) return -1;
            continue;
        }
        /* two steps: t2 = xyzq with q on the boundary; a neighbour t3 of t2 across the face
         * opposite v in {x, y, z} with apex p inside; flipping t2, t3 makes x y z p (vp must
         * cross that face), which the second flip takes with t1 (wp must cross xyz) */
        for (int kv = 0; kv < 4; kv++) {
            if (kv == kq) continue;
            uint32_t t3 = s->adj[4 * (size_t)t2 + kv];
            if (t3 == NONE || s->removed[t3]) continue;
            if (s->keepmask && (s->keepmask[t2] >> kv & 1)) continue;
            uint32_t f2[3];
            for (int i = 0; i < 3; i++)
                f2[i] = s->tet[4 * (size_t)t2 + constrict3_face[kv][i]];
            cd.p = s->tet[4 * (size_t)t3 + corner_not_in(s, t3, f2)];
            if (s->bfaces[cd.p] != 0 || !crosses(s, c[kw], cd.p, xyz) ||
                !crosses(s, s->tet[4 * (size_t)t2 + kv], cd.p, f2))
                continue;
            cd.t3 = t3;
            cd.v3 = s->version[t3];
            cd.kv = kv;
            if (push_each_face(s, &cd, bmask, 1.0, out) != 0) return -1;
        }
    }
    return 0;
}

static int grow(constrict3_state *s)
{
    size_t cap = 2 * s->cap + 16;
    uint32_t *tet = fl_realloc_array(s->tet, cap, 4 * sizeof *tet);
    if (tet) s->tet = tet;
    uint32_t *adj = fl_realloc_array(s->adj, cap, 4 * sizeof *adj);
    if (adj) s->adj = adj;
    uint8_t *removed = fl_realloc_array(s->removed, cap, 1);
    if (removed) s->removed = removed;
    uint32_t *version = fl_realloc_array(s->version, cap, sizeof *version);
    if (version) s->version = version;
    uint8_t *keepmask = s->keepmask ? fl_realloc_array(s->keepmask, cap, 1) : NULL;
    if (keepmask) s->keepmask = keepmask;
    if (!tet || !adj || !removed || !version || (s->keepmask && !keepmask)) return -1;
    s->cap = cap;
    return 0;
}

/* Points the neighbour across face f (of an old tetrahedron) at slot `to`. */
static void relink(constrict3_state *s, uint32_t nb, const uint32_t *f, uint32_t to)
{
    if (nb == NONE) return;
    s->adj[4 * (size_t)nb + corner_not_in(s, nb, f)] = to;
}

/* The 2-3 flip of the file comment. slot[i] receives the tetrahedron without xyz[i]. */
static void flip23(constrict3_state *s, const candidate *cd, uint32_t slot[3])
{
    uint32_t o1[4], o2[4], a1[4], a2[4];
    uint8_t k1 = s->keepmask ? s->keepmask[cd->t1] : 0, k2 = s->keepmask ? s->keepmask[cd->t2] : 0;
    memcpy(o1, s->tet + 4 * (size_t)cd->t1, sizeof o1);
    memcpy(o2, s->tet + 4 * (size_t)cd->t2, sizeof o2);
    memcpy(a1, s->adj + 4 * (size_t)cd->t1, sizeof a1);
    memcpy(a2, s->adj + 4 * (size_t)cd->t2, sizeof a2);
    uint32_t w = o1[cd->kw], xyz[3];
    for (int i = 0; i < 3; i++)
        xyz[i] = o1[constrict3_face[cd->kw][i]];
    slot[0] = cd->t1;
    slot[1] = cd->t2;
    slot[2] = (uint32_t)s->tet_count++;
    for (int i = 0; i < 3; i++) {
        uint32_t q[4] = {xyz[0], xyz[1], xyz[2], w};
        q[i] = cd->p;
        if (fl_orient3d(pt(s, q[0]), pt(s, q[1]), pt(s, q[2]), pt(s, q[3])) < 0) {
            uint32_t tmp = q[0];
            q[0] = q[1], q[1] = tmp;
        }
        memcpy(s->tet + 4 * (size_t)slot[i], q, sizeof q);
        s->removed[slot[i]] = 0;
        if (s->keepmask) s->keepmask[slot[i]] = 0;
    }
    for (int i = 0; i < 3; i++) {
        uint32_t *q = s->tet + 4 * (size_t)slot[i];
        for (int k = 0; k < 4; k++) {
            uint32_t f[3], m = 0, nb;
            for (int j = 0; j < 4; j++)
                if (j != k) f[m++] = q[j];
            int keep = 0;
            if (q[k] == w || q[k] == cd->p) { /* an outer face of the old t2 (or t1) */
                const uint32_t *o = q[k] == w ? o2 : o1, *a = q[k] == w ? a2 : a1;
                int kk = -1;
                for (int j = 0; j < 4; j++)
                    if (o[j] != f[0] && o[j] != f[1] && o[j] != f[2]) kk = j;
                nb = a[kk];
                keep = ((q[k] == w ? k2 : k1) >> kk) & 1;
                relink(s, nb, f, slot[i]);
            } else { /* the new face w p * shared with the tetrahedron without q[k] */
                int j = q[k] == xyz[0] ? 0 : q[k] == xyz[1] ? 1 : 2;
                nb = slot[j];
            }
            s->adj[4 * (size_t)slot[i] + k] = nb;
            if (keep) s->keepmask[slot[i]] |= (uint8_t)(1u << k);
        }
    }
    s->version[slot[0]]++;
    s->version[slot[1]]++;
    s->version[slot[2]] = 0;
    s->region_count++;
}

/* Records the triangles w p x, w p y, w p z that a flip adds (input indices), for the
 * augmented_c0 report (constrict3_augmented_c0). */
static int record_added(constrict3_state *s, uint32_t w, uint32_t p, const uint32_t *xyz)
{
    for (int i = 0; i < 3; i++) {
        uint32_t tri[3] = {w, p, xyz[i]};
        if (fl_vec_push(&s->added, tri, 3) != 0) return -1;
    }
    return 0;
}

/* The smallest c0 for which γ([-1,1],[c0,1]) holds every triangle the flips added: by Def. 3.3
 * a triangle is in it when some N_γ(c, c') with c' >= c0 is empty, i.e. when its largest empty
 * neighbourhood's c1' is >= c0. A triangle without any empty neighbourhood counts as -1, the end
 * of the range. All triangles are evaluated at the end in one fl_gamma_simplices_min_c1 call
 * over the distinct points, which scans all points only for the few triangles that lower the
 * minimum: evaluating each against every point as it was added cost O(N) a flip and dominated
 * large runs (3x the Delaunay time at 10^5 points). */
int constrict3_augmented_c0(const constrict3_state *s, const uint32_t *dup, double *c0)
{
    size_t m = s->added.count / 3;
    *c0 = NAN;
    if (m == 0) return 0;
    double *u = fl_alloc_array(s->n, 3 * sizeof *u);
    uint32_t *map = fl_alloc_array(s->n, sizeof *map), *tri = fl_alloc_array(m, 3 * sizeof *tri);
    int rc = -1;
    if (!u || !map || !tri) goto done;
    size_t un = 0;
    for (size_t i = 0; i < s->n; i++) {
        if (dup[i] != i) continue;
        memcpy(u + 3 * un, s->p + 3 * i, 3 * sizeof *u);
        map[i] = (uint32_t)un++;
    }
    const uint32_t *a = s->added.data;
    for (size_t i = 0; i < 3 * m; i++) tri[i] = map[a[i]];
    if (fl_gamma_simplices_min_c1(u, un, 3, tri, m, c0, NULL, NULL) != FL_OK) goto done;
    rc = 0;
done:
    free(u);
    free(map);
    free(tri);
    return rc;
}

/* Marks the region tetrahedra within two steps (across faces) of a tetrahedron with an inside
 * vertex: every candidate's t1 is among them (its t2, or t3, holds p), so the predicates run
 * only there and a lock costs one cheap pass over the tetrahedra instead of one with exact
 * tests at every boundary tetrahedron. */
static int mark_near_inside(const constrict3_state *s, uint8_t **near)
{
    *near = fl_calloc_array(s->tet_count, 1);
    if (!*near) return -1;
    for (size_t t = 0; t < s->tet_count; t++) {
        if (s->removed[t]) continue;
        const uint32_t *c = s->tet + 4 * t;
        if (s->bfaces[c[0]] && s->bfaces[c[1]] && s->bfaces[c[2]] && s->bfaces[c[3]]) continue;
        for (int i = 0; i < 4; i++) {
            uint32_t nb = s->adj[4 * t + i];
            if (nb == NONE || s->removed[nb]) continue;
            (*near)[nb] = 1;
            for (int j = 0; j < 4; j++) {
                uint32_t nb2 = s->adj[4 * (size_t)nb + j];
                if (nb2 != NONE) (*near)[nb2] = 1;
            }
        }
    }
    return 0;
}

int constrict3_unlock(constrict3_state *s, constrict3_push_fn push, void *ctx, double max_key,
                      size_t *flips)
{
    cand_vec v = {0};
    uint8_t *used = NULL;
    int rc = -1;
    uint8_t *near = NULL;
    *flips = 0;
    if (mark_near_inside(s, &near) != 0) goto done;
    for (uint32_t t = 0; t < s->tet_count; t++) {
        if (s->removed[t] || !near[t]) continue;
        unsigned m = 0;
        for (int k = 0; k < 4; k++)
            m |= (unsigned)constrict3_face_is_boundary(s, t, k) << k;
        if (m && candidates_of(s, t, m, &v) != 0) goto done;
    }
    if (v.count == 0) {
        rc = 0;
        goto done;
    }
    qsort(v.a, v.count, sizeof *v.a, cand_cmp);
    used = fl_calloc_array(s->n, 1);
    if (!used) goto done;
    for (size_t i = 0; i < v.count; i++) {
        const candidate *cd = &v.a[i];
        if (!(cd->key < max_key)) break;
        if (used[cd->p] || s->version[cd->t1] != cd->v1 || s->version[cd->t2] != cd->v2 ||
            (cd->t3 != NONE && s->version[cd->t3] != cd->v3))
            continue; /* this point has its flip, or a tetrahedron was flipped already */
        if (s->tet_count + 2 > s->cap && grow(s) != 0) goto done;
        candidate second = *cd;
        if (cd->t3 != NONE) { /* first step: t2 with t3, giving x y z p next to t1 */
            const uint32_t *o2 = s->tet + 4 * (size_t)cd->t2;
            uint32_t vx = o2[cd->kv], f2[3];
            for (int j = 0; j < 3; j++)
                f2[j] = o2[constrict3_face[cd->kv][j]];
            candidate first = {0, cd->t2, cd->t3, 0, 0, cd->p, cd->kv, NONE, 0, 0};
            uint32_t slot[3];
            flip23(s, &first, slot);
            (*flips)++;
            if (record_added(s, vx, cd->p, f2) != 0) goto done;
            second.t2 = s->adj[4 * (size_t)cd->t1 + cd->kw];
            for (int j = 0; j < 3; j++)
                if (push(s, ctx, slot[j]) != 0) goto done;
        }
        cd = &second;
        const uint32_t *o1 = s->tet + 4 * (size_t)cd->t1;
        uint32_t w = o1[cd->kw], xyz[3];
        for (int j = 0; j < 3; j++)
            xyz[j] = o1[constrict3_face[cd->kw][j]];
        uint32_t slot[3];
        flip23(s, cd, slot);
        used[cd->p] = 1;
        (*flips)++;
        if (record_added(s, w, cd->p, xyz) != 0) goto done;
        for (int j = 0; j < 3; j++)
            if (push(s, ctx, slot[j]) != 0) goto done;
    }
    rc = 0;
done:
    free(near);
    free(v.a);
    free(used);
    return rc;
}
