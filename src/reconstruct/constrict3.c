/* Boundary construction in 3D by constriction of the Delaunay tetrahedralization (thesis §5.3,
 * Algorithm 5.1). The region starts as every Delaunay tetrahedron; its boundary, the convex
 * hull, is a sphere. Boundary tetrahedra are removed one at a time in the order of their key,
 * and only when removal keeps the boundary a 2-sphere:
 *  - one boundary face, opposite vertex not on the boundary: the tetrahedron meets the rest of
 *    the region in the disc of its other three faces, whose rim is on the boundary and whose
 *    interior is not, so removal is a shelling step and the boundary stays a sphere;
 *  - two boundary faces (sharing edge cd), opposite edge ab not on the boundary: it meets the
 *    rest in the disc abc + abd, again with only its rim on the boundary;
 *  - three or four boundary faces: never (removal would pinch or empty the region).
 * A vertex, once on the boundary, stays there (the last tetrahedron at a vertex would have
 * three boundary faces there), so a tetrahedron that is not removable becomes removable again
 * only when its own boundary faces change; the heap is therefore invalidated lazily with a
 * per-tetrahedron version. */
#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reconstruct/constrict3_internal.h"

#define NONE UINT32_MAX

#define face_is_boundary constrict3_face_is_boundary

static unsigned boundary_mask(const constrict3_state *s, uint32_t t)
{
    unsigned m = 0;
    for (int k = 0; k < 4; k++)
        if (face_is_boundary(s, t, k)) m |= 1u << k;
    return m;
}

static int popcount4(unsigned m)
{
    return (int)((m & 1) + ((m >> 1) & 1) + ((m >> 2) & 1) + ((m >> 3) & 1));
}

/* 1 when edge uv of region tetrahedron t lies on the boundary: some tetrahedron around the
 * edge is removed, or the edge is on the convex hull. Walks the ring of Delaunay tetrahedra
 * around uv through the faces that contain it. */
static int edge_on_boundary(const constrict3_state *s, uint32_t t, uint32_t u, uint32_t v)
{
    uint32_t cur = t, prev = NONE;
    for (;;) {
        const uint32_t *c = s->tet + 4 * (size_t)cur;
        uint32_t next = NONE;
        int found = 0;
        for (int k = 0; k < 4 && !found; k++) {
            if (c[k] == u || c[k] == v) continue;
            uint32_t nb = s->adj[4 * (size_t)cur + k];
            if (nb == NONE || s->removed[nb]) return 1;
            if (nb != prev) {
                next = nb;
                found = 1;
            }
        }
        if (!found || next == t) return 0;
        prev = cur;
        cur = next;
    }
}

/* The boundary-face mask of region tetrahedron t when t is removable now (the §5.3 rules and
 * the kept faces of §5.7), else 0. */
static unsigned removable_mask(const constrict3_state *s, uint32_t t)
{
    const uint32_t *c = s->tet + 4 * (size_t)t;
    unsigned m = boundary_mask(s, t);
    int nb = popcount4(m);
    if (nb == 1) {
        int k = m == 1 ? 0 : m == 2 ? 1 : m == 4 ? 2 : 3;
        if (s->bfaces[c[k]] > 0) return 0;
    } else if (nb == 2) {
        int a = -1, b = -1;
        for (int k = 0; k < 4; k++)
            if (m & (1u << k)) {
                if (a < 0)
                    a = k;
                else
                    b = k;
            }
        if (edge_on_boundary(s, t, c[a], c[b])) return 0;
    } else {
        return 0;
    }
    if (s->keepmask && (s->keepmask[t] & m)) return 0; /* would delete a kept face (§5.7) */
    return m;
}

/* The removal key of region tetrahedron t, or NAN when t is not removable now. */
static double removal_key(const constrict3_state *s, uint32_t t, fl_reconstruct3_criterion crit)
{
    const uint32_t *c = s->tet + 4 * (size_t)t;
    unsigned m = removable_mask(s, t);
    if (!m) return NAN;
    double key = 0;
    if (crit == FL_RECONSTRUCT3_AREA_CHANGE)
        key = constrict3_area_change(s->p, c, m);
    else /* thesis §5.3 selection rule: the sum over the boundary faces */
        for (int k = 0; k < 4; k++)
            if (m & (1u << k))
                key += constrict3_gamma_indicator(s->p + 3 * (size_t)c[constrict3_face[k][0]],
                                                  s->p + 3 * (size_t)c[constrict3_face[k][1]],
                                                  s->p + 3 * (size_t)c[constrict3_face[k][2]],
                                                  s->p + 3 * (size_t)c[k]);
    /* coordinates near the double range can overflow the construction; such a tetrahedron is
     * still removable, just last (every real key is in [-2, 2]) */
    return isnan(key) ? 4.0 : key;
}

static int push_if_removable(const constrict3_state *s, constrict3_heap *h, uint32_t t,
                             fl_reconstruct3_criterion crit)
{
    double key = removal_key(s, t, crit);
    if (isnan(key)) return 0;
    constrict3_entry e = {key, t, s->version[t]};
    return constrict3_heap_push(h, e);
}

static void count_face(constrict3_state *s, uint32_t t, int k, int delta)
{
    for (int i = 0; i < 3; i++) {
        uint32_t v = s->tet[4 * (size_t)t + constrict3_face[k][i]];
        if (delta > 0 && s->bfaces[v]++ == 0) s->on_boundary++;
        if (delta < 0) {
            /* a boundary vertex has >= 3 boundary faces and a removal takes at most two of
             * them before adding new ones, so this never reaches 0 (see the file comment) */
            assert(s->bfaces[v] > 1);
            s->bfaces[v]--;
        }
    }
}

/* Removes region tetrahedron t: its boundary faces leave the boundary, its other faces join
 * it, and its region neighbours get new versions and candidate entries. */
static int remove_tet(constrict3_state *s, constrict3_heap *h, uint32_t t,
                      fl_reconstruct3_criterion crit)
{
    s->removed[t] = 1;
    s->region_count--;
    for (int k = 0; k < 4; k++) {
        uint32_t nb = s->adj[4 * (size_t)t + k];
        if (nb == NONE || s->removed[nb]) {
            count_face(s, t, k, -1);
            continue;
        }
        count_face(s, t, k, +1);
        if (s->keepmask && (s->keepmask[t] >> k & 1)) s->keep_on++;
        s->version[nb]++;
        if (push_if_removable(s, h, nb, crit) != 0) return -1;
    }
    return 0;
}

static int initial_boundary(constrict3_state *s, constrict3_heap *h, fl_reconstruct3_criterion crit)
{
    for (uint32_t t = 0; t < s->tet_count; t++) {
        int on_hull = 0;
        for (int k = 0; k < 4; k++)
            if (s->adj[4 * (size_t)t + k] == NONE) {
                count_face(s, t, k, +1);
                on_hull = 1;
            }
        if (on_hull && push_if_removable(s, h, t, crit) != 0) return -1;
    }
    return 0;
}

#ifndef NDEBUG
/* Full sphere check after step `step`: every step for small triangulations, at powers of two
 * otherwise, so debug builds stay near-linear. */
static void debug_check(const constrict3_state *s, size_t n, size_t step)
{
    if (s->tet_count <= 4000 || (step & (step - 1)) == 0)
        assert(constrict3_boundary_is_sphere(s, n));
}
#else
#define debug_check(s, n, step) ((void)(s), (void)(n), (void)(step))
#endif

typedef struct push_ctx {
    constrict3_heap *h;
    fl_reconstruct3_criterion crit;
} push_ctx;

static int push_cb(constrict3_state *s, void *ctx, uint32_t t)
{
    push_ctx *c = ctx;
    return push_if_removable(s, c->h, t, c->crit);
}

/* Algorithm 5.1, lines 3-8, followed by `extra` removals; when locked with points inside,
 * unlocking flips (§5.4, constrict3_unlock.c) and on; when stalled with points inside, the
 * chase of constrict3_chase.c (early flips, then removals near the inside points). Returns FL_OK, or FL_ERR_NOMEM /
 * FL_ERR_ALGORITHM (cancelled) through err. */
static fl_status constrict(constrict3_state *s, size_t unique, const fl_reconstruct3_options *opt,
                           fl_reconstruction3 *out, fl_error *err)
{
    constrict3_heap h = {0};
    push_ctx ctx = {&h, opt->criterion};
    fl_status st = FL_OK;
    constrict3_chase chase;
    constrict3_chase_init(&chase, s->on_boundary);
    if (initial_boundary(s, &h, opt->criterion) != 0) goto nomem;
    chase.last_on = s->on_boundary;
    size_t steps = 0;
    out->extra_removed = 0;
    for (;;) {
        int all_on = s->on_boundary >= unique && s->keep_on >= s->keep_total;
        int chasing = s->on_boundary < unique && !opt->no_augment;
        if (h.count == 0 && chasing) {
            int rc = constrict3_chase_widen(s, &chase, &h);
            if (rc < 0) goto nomem;
            if (rc > 0) continue;
        }
        if (h.count == 0) {
            if (all_on || opt->no_augment) break;
            size_t flips = 0;
            if (constrict3_unlock(s, push_cb, &ctx, INFINITY, &flips)) goto nomem;
            out->flip_count += flips;
            if (flips == 0) break; /* locked for good: the reason says why */
            continue;
        }
        if (all_on && out->extra_removed >= opt->extra) break;
        constrict3_entry e = constrict3_heap_pop(&h);
        if (s->removed[e.tet] || e.version != s->version[e.tet])
            continue; /* stale: a newer entry exists if it is still removable */
        if (!removable_mask(s, e.tet))
            continue; /* its vertex or edge joined the boundary meanwhile (Alg. 5.1 line 5); its
                         key is the one pushed: a key changes only with the version */
        if (chasing) {
            int rc = constrict3_chase_before(s, &chase, &h, e, push_cb, &ctx, &out->flip_count);
            if (rc < 0) goto nomem;
            if (rc > 0) continue;
        }
        if (remove_tet(s, &h, e.tet, opt->criterion) != 0) goto nomem;
        if (constrict3_chase_after(s, &chase, &h) != 0) goto nomem;
        if (all_on) out->extra_removed++;
        debug_check(s, s->n, ++steps);
        if ((steps & 4095) == 0 && fl_progress(opt->progress, opt->progress_user, "constriction 3d",
                                               (double)s->on_boundary / (double)unique)) {
            st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
            goto done;
        }
    }
    assert(constrict3_boundary_is_sphere(s, s->n));
done:
    constrict3_heap_free(&h);
    constrict3_chase_free(&chase);
    return st;
nomem:
    constrict3_heap_free(&h);
    constrict3_chase_free(&chase);
    return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory in 3D constriction");
}

static fl_status validate(const double *xyz, size_t n, const fl_reconstruct3_options *opt,
                          fl_reconstruction3 *out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_reconstruct3: out is NULL");
    memset(out, 0, sizeof *out);
    if (!xyz && n > 0) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_reconstruct3: xyz is NULL");
    if (opt->criterion != FL_RECONSTRUCT3_GAMMA && opt->criterion != FL_RECONSTRUCT3_AREA_CHANGE)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "fl_reconstruct3: unknown criterion %d (use 0 = gamma, 1 = area change)",
                       (int)opt->criterion);
    if (!opt->keep && opt->keep_count)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_reconstruct3: keep is NULL");
    return FL_OK;
}

static void describe_lock(fl_reconstruction3 *out, const fl_reconstruct3_options *opt)
{
    size_t in = out->points_inside;
    const char *why = opt->no_augment ? "augmentation is off"
                                      : "no 2-3 flip at the boundary reaches an inside point";
    if (out->keep_missing && !in)
        snprintf(out->reason, sizeof out->reason,
                 "%zu kept triangle(s) not on the boundary: constriction locked before reaching "
                 "them (thesis §5.7; kept faces block the way)",
                 out->keep_missing);
    else
        snprintf(out->reason, sizeof out->reason,
                 "constriction locked with %zu point(s) inside%s: no boundary tetrahedron is "
                 "removable without a non-manifold boundary (thesis §4.3.3, §5.4) and %s",
                 in, out->keep_missing ? ", kept triangles missing" : "", why);
}

fl_status fl_reconstruct3(const double *xyz, size_t n, const fl_reconstruct3_options *opt,
                          fl_reconstruction3 *out, fl_error *err)
{
    fl_reconstruct3_options defaults = {0};
    if (!opt) opt = &defaults;
    fl_status st = validate(xyz, n, opt, out, err);
    if (st != FL_OK) return st;
    fl_dt3 dt = {0};
    fl_dt3_options dopt = {opt->progress, opt->progress_user, 0};
    st = fl_dt3_build(xyz, n, &dopt, &dt, err);
    if (st != FL_OK) return st;
    /* the state takes over the triangulation's arrays: unlocking flips grow and change them */
    constrict3_state s = {0};
    fl_vec_init(&s.added, sizeof(uint32_t));
    s.p = xyz;
    s.n = n;
    s.tet_count = s.cap = s.region_count = dt.tet_count;
    s.tet = dt.tet;
    s.adj = dt.adj;
    dt.tet = dt.adj = NULL;
    s.removed = fl_calloc_array(dt.tet_count, 1);
    s.version = fl_calloc_array(dt.tet_count, sizeof *s.version);
    s.bfaces = fl_calloc_array(n, sizeof *s.bfaces);
    if (!s.removed || !s.version || !s.bfaces) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory in 3D constriction");
        goto done;
    }
    if (opt->keep_count) {
        st = constrict3_mark_kept(&s, dt.duplicate_of, opt->keep, opt->keep_count, err);
        if (st != FL_OK) goto done;
    }
    st = constrict(&s, dt.unique_count, opt, out, err);
    if (st != FL_OK) goto done;
    if (constrict3_augmented_c0(&s, dt.duplicate_of, &out->augmented_c0) != 0) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory in 3D constriction");
        goto done;
    }
    out->point_count = n;
    out->unique_count = dt.unique_count;
    out->delaunay_tet_count = dt.tet_count;
    out->removed_count = s.tet_count - s.region_count;
    if (constrict3_extract(&s, dt.duplicate_of, n, out) != 0) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory in 3D constriction");
        goto done;
    }
    out->keep_missing = s.keep_total - s.keep_on;
    out->all_on_boundary = out->points_inside == 0 && out->keep_missing == 0;
    if (!out->all_on_boundary) describe_lock(out, opt);
done:
    if (st != FL_OK) fl_reconstruction3_free(out);
    free(s.tet);
    free(s.adj);
    free(s.removed);
    free(s.version);
    free(s.keepmask);
    free(s.bfaces);
    fl_vec_free(&s.added);
    fl_dt3_free(&dt);
    return st;
}

void fl_reconstruction3_free(fl_reconstruction3 *rec)
{
    if (!rec) return;
    free(rec->tri);
    free(rec->tet);
    free(rec->inside);
    memset(rec, 0, sizeof *rec);
}
