/* The 3D flintstone tree (thesis §7.3.2, Algorithm 7.2).
 *
 * Level 0: the three vertices v_i, v_j, v_k on the smallest enclosing ball (when it touches only
 * two, the third is the vertex farthest from their line) and the shortest edge paths between
 * them split the sphere-like surface into two open polyhedra, approximated by the triangles
 * (i, j, k) and (i, k, j). Every further level refines all live nodes at once, in two passes as
 * Algorithm 7.2 prescribes: first every node decides which of its sides must be split (its own
 * small angles, or no interior vertex left) and the neighbour across such a side is told to
 * split it at the same vertex, the vertex of the side's path that best balances the lengths of
 * the two new sides; only then are the nodes split, each by a three-split at its interior vertex
 * v_q / v_r when none of its sides is split, or by the side splits of Fig. 7.10 otherwise. The
 * pieces are cut along shortest paths (hal3_region.c); a piece left without triangles (paths
 * that coalesce, Fig. 7.12) is discarded, a piece that is one original triangle with its three
 * corners is a leaf. A split vertex of a side must occur once in the loops of both nodes, so no
 * child has two equal corners. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "hal/hal3_internal.h"

#define FL_HAL3_PI 3.14159265358979323846

typedef struct live {
    uint32_t node;
    hal3_piece pc;
    uint32_t q;         /* three-split vertex or FL_HAL3_NONE */
    uint8_t mask;       /* sides to split */
    uint32_t m[3];      /* split vertex of each side */
    uint32_t m_any[3];  /* split vertex of each side allowing coalescing paths */
    int32_t partner[3]; /* live index across each side, -1 when none */
    uint8_t partner_side[3];
} live;

typedef struct side_rec {
    uint64_t hash;
    uint32_t live, side;
} side_rec;

typedef struct build {
    const fl_mesh *mesh;
    hal3_work w;
    fl_vec nodes, ties;
    live *cur, *next;
    size_t ncur, nnext, cap;
    uint32_t *count; /* per vertex: occurrences in the loop being inspected */
    double threshold;
} build;

/* ---- input ---- */

static fl_status check_input(const fl_mesh *mesh, fl_error *err)
{
    for (size_t i = 0; i < 3 * mesh->vertex_count; i++)
        if (!isfinite(mesh->xyz[i]))
            return fl_fail(err, FL_ERR_INPUT, NULL, -1, "hal3: vertex %zu is not finite", i / 3);
    /* Ball radii are stored squared: at 6e298 they overflowed and a flintstone excluded the
     * centroid of its own triangle (found by fuzz/fuzz_hal3.c); the sweep's range. */
    for (size_t i = 0; i < 3 * mesh->vertex_count; i++)
        if (fabs(mesh->xyz[i]) > 1e150)
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "hal3: vertex %zu is beyond the supported range |x| <= 1e150", i / 3);
    if (mesh->triangle_count < 4)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                       "hal3: %zu triangles: a closed surface needs at least 4",
                       mesh->triangle_count);
    fl_mesh_check_options o = {.skip_self_intersections = 1};
    fl_mesh_report r;
    fl_status st = fl_mesh_check(mesh, &o, &r, err);
    if (st != FL_OK) return st;
    if (r.boundary_edges)
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                     "not closed: %zu boundary edges; the HAL tree needs a closed surface",
                     r.boundary_edges);
    else if (!r.manifold)
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                     "not manifold: %zu non-manifold edges, %zu non-manifold vertices",
                     r.nonmanifold_edges, r.nonmanifold_vertices);
    else if (!r.oriented)
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                     "not oriented: %zu edges used twice in one direction", r.misoriented_edges);
    else if (r.components != 1)
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                     "%zu components: the HAL tree needs one connected surface", r.components);
    else if (r.genus != 0)
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                     "genus %lld: the HAL tree needs a sphere-like surface", r.genus);
    else if (r.degenerate_faces)
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1, "%zu degenerate triangles", r.degenerate_faces);
    fl_mesh_report_free(&r);
    return st;
}

/* ---- nodes ---- */

static fl_hal3_node *node_at(build *b, uint32_t i)
{
    return (fl_hal3_node *)b->nodes.data + i;
}

static int is_leaf(const fl_mesh *m, const hal3_piece *pc)
{
    if (pc->nf != 1 || pc->nl != 3) return 0;
    const uint32_t *t = m->tri + 3 * (size_t)pc->faces[0];
    for (int r = 0; r < 3; r++)
        if (t[r] == pc->loop[0] && t[(r + 1) % 3] == pc->loop[1] && t[(r + 2) % 3] == pc->loop[2])
            return 1;
    return 0;
}

/* A piece holding triangles whose corners coalesced to two distinct vertices (a digon between
 * two different paths): the loop vertex halfway along the longer segment between them becomes
 * the third corner. The neighbour across that segment does not split it, so the approximation
 * may have a crack there; this happens only where shortest paths coalesce. Returns 0 on
 * success. */
static int fix_corners(hal3_piece *pc)
{
    uint32_t cp[6];
    int n = 0;
    for (int i = 0; i < pc->nc; i++) {
        uint32_t v = pc->loop[pc->cpos[i]];
        int dup = 0;
        for (int j = 0; j < n; j++)
            dup |= pc->loop[cp[j]] == v;
        if (!dup) cp[n++] = pc->cpos[i];
    }
    if (n != 2) return -1;
    size_t a = cp[0], c = cp[1], l1 = c - a, l2 = pc->nl - l1;
    size_t mid = l1 >= l2 ? a + l1 / 2 : (c + l2 / 2) % pc->nl;
    uint32_t v = pc->loop[mid];
    if (v == pc->loop[a] || v == pc->loop[c]) return -1;
    uint32_t t[3] = {(uint32_t)a, (uint32_t)c, (uint32_t)mid};
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            if (t[j] < t[i]) {
                uint32_t x = t[i];
                t[i] = t[j], t[j] = x;
            }
    /* Rotate so that the first corner is at position 0. */
    uint32_t *rot = malloc(pc->nl * sizeof(uint32_t));
    if (!rot) return -1;
    for (size_t i = 0; i < pc->nl; i++)
        rot[i] = pc->loop[(t[0] + i) % pc->nl];
    memcpy(pc->loop, rot, pc->nl * sizeof(uint32_t));
    free(rot);
    pc->cpos[0] = 0, pc->cpos[1] = t[1] - t[0], pc->cpos[2] = t[2] - t[0];
    pc->nc = 3;
    return 0;
}

/* Adds the node of piece *pc (taken over) at `level`; a live entry unless it is a leaf.
 * Empty pieces are dropped: *added = 0. */
static fl_status add_node(build *b, hal3_piece *pc, uint32_t level, int32_t parent, int *added,
                          fl_error *err)
{
    *added = 0;
    int distinct = pc->nc == 3 && pc->loop[pc->cpos[0]] != pc->loop[pc->cpos[1]] &&
                   pc->loop[pc->cpos[1]] != pc->loop[pc->cpos[2]] &&
                   pc->loop[pc->cpos[2]] != pc->loop[pc->cpos[0]];
    if (!distinct && pc->nf > 0 && !fix_corners(pc)) distinct = 1;
    if (!distinct) {
        /* A degenerate triangle (coalescing corners): its sides pair up among themselves, so
         * dropping it keeps the level closed; it must not hold any triangle. */
        int bad = pc->nf != 0, nc = pc->nc;
        hal3_piece_free(pc);
        if (bad)
            return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                           "hal3: a degenerate piece (%d corners) holds triangles", nc);
        return FL_OK;
    }
    /* A piece without triangles but with three distinct corners (paths that coalesce, Fig.
     * 7.12) is kept: its sides are shared with its neighbours, and dropping it would open a
     * crack. It has no flintstone (it stands for no surface) and is refined until its
     * children degenerate. */
    fl_hal3_node nd;
    memset(&nd, 0, sizeof nd);
    for (int k = 0; k < 3; k++)
        nd.v[k] = pc->loop[pc->cpos[k]];
    nd.level = level;
    nd.parent = parent;
    nd.face = FL_HAL3_NONE;
    nd.split = FL_HAL3_NONE;
    nd.face_count = (uint32_t)pc->nf;
    if (fl_vec_push(&b->nodes, &nd, 1)) {
        hal3_piece_free(pc);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
    }
    uint32_t id = (uint32_t)(b->nodes.count - 1);
    fl_hal3_node *n = node_at(b, id);
    *added = 1;
    if (is_leaf(b->mesh, pc)) {
        n->face = pc->faces[0];
        hal3_leaf_ball(b->mesh, n);
        hal3_piece_free(pc);
        return FL_OK;
    }
    live *lv = &b->next[b->nnext++];
    memset(lv, 0, sizeof *lv);
    lv->node = id;
    lv->pc = *pc;
    memset(pc, 0, sizeof *pc);
    lv->q = hal3_flintstone(&b->w, n, &lv->pc);
    for (int k = 0; k < 3; k++)
        lv->partner[k] = -1;
    return FL_OK;
}

/* ---- side paths ---- */

/* Side k of a piece: loop positions cpos[k] .. cpos[k+1] (wrapping); its length in vertices. */
static size_t side_len(const hal3_piece *pc, int k)
{
    size_t a = pc->cpos[k], e = k == 2 ? pc->nl : pc->cpos[k + 1];
    return e - a + 1;
}

static uint32_t side_vertex(const hal3_piece *pc, int k, size_t i)
{
    return pc->loop[(pc->cpos[k] + i) % pc->nl];
}

/* FNV-1a of the side read from its lower end vertex, so the two nodes sharing a side agree. */
static uint64_t side_hash(const hal3_piece *pc, int k)
{
    size_t n = side_len(pc, k);
    int rev = side_vertex(pc, k, 0) > side_vertex(pc, k, n - 1);
    uint64_t h = 1469598103934665603ull;
    for (size_t i = 0; i < n; i++) {
        uint32_t v = side_vertex(pc, k, rev ? n - 1 - i : i);
        for (int s = 0; s < 32; s += 8)
            h = (h ^ ((v >> s) & 255u)) * 1099511628211ull;
    }
    return h;
}

static int same_side(const hal3_piece *a, int ka, const hal3_piece *b, int kb)
{
    size_t n = side_len(a, ka);
    if (side_len(b, kb) != n) return 0;
    for (size_t i = 0; i < n; i++)
        if (side_vertex(a, ka, i) != side_vertex(b, kb, n - 1 - i)) return 0;
    return 1;
}

static int cmp_rec(const void *x, const void *y)
{
    const side_rec *a = x, *b = y;
    if (a->hash != b->hash) return a->hash < b->hash ? -1 : 1;
    return a->live < b->live ? -1 : a->live > b->live;
}

static fl_status find_partners(build *b, fl_error *err)
{
    side_rec *r = fl_alloc_array(3 * b->ncur + 1, sizeof *r);
    if (!r) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
    size_t n = 0;
    for (size_t i = 0; i < b->ncur; i++)
        for (int k = 0; k < 3; k++)
            r[n++] = (side_rec){side_hash(&b->cur[i].pc, k), (uint32_t)i, (uint32_t)k};
    qsort(r, n, sizeof *r, cmp_rec);
    for (size_t i = 0; i + 1 < n; i++) {
        if (r[i].hash != r[i + 1].hash) continue;
        live *x = &b->cur[r[i].live], *y = &b->cur[r[i + 1].live];
        if (!same_side(&x->pc, (int)r[i].side, &y->pc, (int)r[i + 1].side)) continue;
        x->partner[r[i].side] = (int32_t)r[i + 1].live;
        x->partner_side[r[i].side] = (uint8_t)r[i + 1].side;
        y->partner[r[i + 1].side] = (int32_t)r[i].live;
        y->partner_side[r[i + 1].side] = (uint8_t)r[i].side;
        i++;
    }
    free(r);
    return FL_OK;
}

static void count_loop(build *b, const hal3_piece *pc, int delta)
{
    for (size_t i = 0; i < pc->nl; i++)
        b->count[pc->loop[i]] += (uint32_t)delta;
}

static double dist3(const fl_mesh *m, uint32_t a, uint32_t c)
{
    const double *p = m->xyz + 3 * (size_t)a, *q = m->xyz + 3 * (size_t)c;
    return sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                (p[2] - q[2]) * (p[2] - q[2]));
}

/* The split vertex of side k of x (shared with its partner): the path vertex occurring once in
 * both loops that best balances the two new sides' lengths, FL_HAL3_NONE when there is none.
 * *any receives the best vertex of the path's interior that is no corner, also when it occurs
 * more often: splitting there leaves a degenerate triangle (coalescing paths, §7.3.2), which is
 * discarded, and is used only by a node that cannot be refined otherwise. */
static uint32_t split_vertex(build *b, const live *x, int k, uint32_t *any)
{
    size_t n = side_len(&x->pc, k);
    *any = FL_HAL3_NONE;
    if (n < 3) return FL_HAL3_NONE;
    const live *y = x->partner[k] >= 0 ? &b->cur[x->partner[k]] : NULL;
    count_loop(b, &x->pc, 1);
    if (y) count_loop(b, &y->pc, 1);
    const fl_hal3_node *nd = node_at(b, x->node);
    double total = 0;
    for (size_t i = 0; i + 1 < n; i++)
        total += dist3(b->mesh, side_vertex(&x->pc, k, i), side_vertex(&x->pc, k, i + 1));
    uint32_t best = FL_HAL3_NONE;
    double best_gap = INFINITY, any_gap = INFINITY, pre = 0;
    for (size_t i = 1; i + 1 < n; i++) {
        uint32_t v = side_vertex(&x->pc, k, i);
        pre += dist3(b->mesh, side_vertex(&x->pc, k, i - 1), v);
        double gap = fabs(2 * pre - total);
        /* A corner may be the split vertex of an empty node only: its children degenerate. */
        int corner = v == nd->v[0] || v == nd->v[1] || v == nd->v[2];
        if (corner && nd->face_count) continue;
        if (y) {
            const fl_hal3_node *ny = node_at(b, y->node);
            int ycorner = v == ny->v[0] || v == ny->v[1] || v == ny->v[2];
            if (ycorner && ny->face_count) continue;
            corner |= ycorner;
        }
        if (gap < any_gap) any_gap = gap, *any = v;
        if (corner) continue;
        if (b->count[v] != (y ? 2u : 1u)) continue;
        if (gap < best_gap) best_gap = gap, best = v;
    }
    count_loop(b, &x->pc, -1);
    if (y) count_loop(b, &y->pc, -1);
    return best;
}

static double corner_angle(const fl_mesh *m, uint32_t a, uint32_t p, uint32_t c)
{
    const double *A = m->xyz + 3 * (size_t)a, *P = m->xyz + 3 * (size_t)p,
                 *C = m->xyz + 3 * (size_t)c;
    double u[3], v[3];
    for (int k = 0; k < 3; k++)
        u[k] = P[k] - A[k], v[k] = C[k] - A[k];
    double d = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    double cr[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                    u[0] * v[1] - u[1] * v[0]};
    return atan2(sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]), d);
}

/* Which sides a node wants split (Fig. 7.10): one small angle, its two sides; two small
 * angles, the side between them; no interior vertex, every splittable side. */
static uint8_t desired_sides(build *b, const live *x, const uint32_t *mv)
{
    const fl_hal3_node *n = node_at(b, x->node);
    uint8_t ok = 0;
    for (int k = 0; k < 3; k++)
        if (mv[k] != FL_HAL3_NONE) ok |= (uint8_t)(1u << k);
    if (x->q == FL_HAL3_NONE) return ok;
    /* A pillow (the partner across all three sides is one node, as the two roots): side splits
     * would split both halves alike into flat double sheets whose edges carry four triangles;
     * three-splits at their own interior vertices give a closed bipyramid instead. */
    if (x->partner[0] >= 0 && x->partner[0] == x->partner[1] && x->partner[1] == x->partner[2])
        return 0;
    int small[3], ns = 0;
    for (int k = 0; k < 3; k++) {
        small[k] =
            corner_angle(b->mesh, n->v[k], n->v[(k + 1) % 3], n->v[(k + 2) % 3]) < b->threshold;
        ns += small[k];
    }
    uint8_t want = 0;
    if (ns == 1) {
        for (int k = 0; k < 3; k++)
            if (small[k]) want = (uint8_t)((1u << k) | (1u << ((k + 2) % 3)));
    } else if (ns == 2) {
        for (int k = 0; k < 3; k++)
            if (small[k] && small[(k + 1) % 3]) want = (uint8_t)(1u << k);
    } else if (ns == 3) {
        want = 7;
    }
    return want & ok;
}

static fl_status decide_splits(build *b, fl_error *err)
{
    fl_status st = find_partners(b, err);
    if (st != FL_OK) return st;
    for (size_t i = 0; i < b->ncur; i++) {
        live *x = &b->cur[i];
        for (int k = 0; k < 3; k++) {
            int32_t y = x->partner[k];
            if (y >= 0 && (size_t)y < i) continue; /* decided by the partner */
            x->m[k] = split_vertex(b, x, k, &x->m_any[k]);
            if (y >= 0) {
                b->cur[y].m[x->partner_side[k]] = x->m[k];
                b->cur[y].m_any[x->partner_side[k]] = x->m_any[k];
            }
        }
    }
    for (size_t i = 0; i < b->ncur; i++) {
        live *x = &b->cur[i];
        uint8_t want = desired_sides(b, x, x->m);
        if (x->q == FL_HAL3_NONE && want == 0) {
            /* Stuck otherwise: accept split vertices on coalescing paths. */
            for (int k = 0; k < 3; k++) {
                if (x->m_any[k] == FL_HAL3_NONE) continue;
                want |= (uint8_t)(1u << k);
                x->m[k] = x->m_any[k];
                if (x->partner[k] >= 0) b->cur[x->partner[k]].m[x->partner_side[k]] = x->m[k];
            }
        }
        x->mask |= want;
        for (int k = 0; k < 3; k++) {
            if (!(want >> k & 1) || x->partner[k] < 0) continue;
            b->cur[x->partner[k]].mask |= (uint8_t)(1u << x->partner_side[k]);
        }
    }
    for (size_t i = 0; i < b->ncur; i++) {
        live *x = &b->cur[i];
        for (int k = 0; k < 3; k++) {
            int32_t y = x->partner[k];
            if ((x->mask >> k & 1) && y > (int32_t)i) {
                uint32_t t[2] = {x->node, b->cur[y].node};
                if (fl_vec_push(&b->ties, t, 2))
                    return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
            }
        }
    }
    return FL_OK;
}

/* ---- splitting one node ---- */

/* The first corner at vertex v other than corner `not`. */
static int corner_index(const hal3_piece *pc, uint32_t v, int not )
{
    for (int i = 0; i < pc->nc; i++)
        if (i != not &&pc->loop[pc->cpos[i]] == v) return i;
    return -1;
}

/* Applies the cuts (u, w, via) in order to the pieces; every cut goes to the piece holding both
 * corners. On return pieces[0..*np) are the children. */
static fl_status apply_cuts(build *b, hal3_piece *pcs, int *np, const uint32_t (*cuts)[3],
                            int ncuts, fl_error *err)
{
    for (int c = 0; c < ncuts; c++) {
        /* The piece holding both corners; a piece of three corners is a child already (when
         * coalescing paths merged two split vertices, the cut would run along its side), and a
         * cut whose corners vanished with a dropped degenerate piece is not needed. */
        for (int p = 0; p < *np; p++) {
            int iu = corner_index(&pcs[p], cuts[c][0], -1);
            int iw = corner_index(&pcs[p], cuts[c][1], iu);
            if (iu < 0 || iw < 0) continue;
            if (pcs[p].nc < 4 && cuts[c][2] == FL_HAL3_NONE) continue;
            if (iu > iw) {
                int t = iu;
                iu = iw, iw = t;
            }
            hal3_piece a, bb;
            fl_status st = hal3_cut(&b->w, &pcs[p], iu, iw, cuts[c][2], &a, &bb, err);
            if (st != FL_OK) {
                hal3_piece_free(&a);
                hal3_piece_free(&bb);
                return st;
            }
            hal3_piece_free(&pcs[p]);
            pcs[p] = a;
            pcs[(*np)++] = bb;
            break;
        }
    }
    return FL_OK;
}

/* Inserts the split vertices of the sides in mask as corners of the piece. */
static void add_side_corners(hal3_piece *pc, uint8_t mask, const uint32_t *m)
{
    uint32_t cp[6];
    int n = 0;
    for (int k = 0; k < 3; k++) {
        cp[n++] = pc->cpos[k];
        if (!(mask >> k & 1)) continue;
        size_t len = side_len(pc, k);
        for (size_t i = 1; i + 1 < len; i++)
            if (side_vertex(pc, k, i) == m[k]) {
                cp[n++] = (uint32_t)(pc->cpos[k] + i);
                break;
            }
    }
    memcpy(pc->cpos, cp, sizeof cp);
    pc->nc = n;
}

static int cut_count(build *b, const live *x, const uint32_t *c, uint32_t (*cuts)[3])
{
    const uint32_t *m = x->m;
    uint8_t mask = x->mask;
    uint32_t N = FL_HAL3_NONE;
    int n = 0;
    if (mask == 0) { /* three-split at v_q (Fig. 7.9) */
        cuts[n][0] = c[0], cuts[n][1] = c[1], cuts[n++][2] = x->q;
        cuts[n][0] = x->q, cuts[n][1] = c[2], cuts[n++][2] = N;
        return n;
    }
    int ns = (mask & 1) + (mask >> 1 & 1) + (mask >> 2 & 1);
    if (ns == 1) {
        for (int k = 0; k < 3; k++)
            if (mask >> k & 1) cuts[n][0] = m[k], cuts[n][1] = c[(k + 2) % 3], cuts[n++][2] = N;
    } else if (ns == 2) {
        int k = (mask & 1) && (mask & 2) ? 0 : (mask & 2) && (mask & 4) ? 1 : 2;
        /* sides k and k+1 split, around corner k+1; then the quad m_k c_{k+1}.. is cut by the
         * shorter diagonal. */
        uint32_t mk = m[k], mk1 = m[(k + 1) % 3], ck = c[k], ck2 = c[(k + 2) % 3];
        cuts[n][0] = mk, cuts[n][1] = mk1, cuts[n++][2] = N;
        if (dist3(b->mesh, mk1, ck) <= dist3(b->mesh, ck2, mk))
            cuts[n][0] = mk1, cuts[n][1] = ck, cuts[n++][2] = N;
        else
            cuts[n][0] = ck2, cuts[n][1] = mk, cuts[n++][2] = N;
    } else {
        cuts[n][0] = m[0], cuts[n][1] = m[2], cuts[n++][2] = N;
        cuts[n][0] = m[0], cuts[n][1] = m[1], cuts[n++][2] = N;
        cuts[n][0] = m[1], cuts[n][1] = m[2], cuts[n++][2] = N;
    }
    return n;
}

static fl_status split_node(build *b, live *x, fl_error *err)
{
    fl_hal3_node *nd = node_at(b, x->node);
    uint32_t c[3] = {nd->v[0], nd->v[1], nd->v[2]};
    uint32_t level = nd->level + 1;
    if (x->mask == 0 && x->q == FL_HAL3_NONE)
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                       "hal3: refinement stuck at triangle (%u, %u, %u) (%zu triangles, no "
                       "interior vertex, no side to split)",
                       c[0], c[1], c[2], x->pc.nf);
    if (x->mask == 0) nd->split = x->q;
    add_side_corners(&x->pc, x->mask, x->m);
    uint32_t cuts[3][3];
    int ncuts = cut_count(b, x, c, cuts);
    hal3_piece pcs[5];
    memset(pcs, 0, sizeof pcs);
    pcs[0] = x->pc;
    memset(&x->pc, 0, sizeof x->pc);
    int np = 1;
    fl_status st = apply_cuts(b, pcs, &np, (const uint32_t(*)[3])cuts, ncuts, err);
    uint32_t first = (uint32_t)b->nodes.count, count = 0;
    for (int p = 0; p < np; p++) {
        int added = 0;
        if (st == FL_OK) st = add_node(b, &pcs[p], level, (int32_t)x->node, &added, err);
        hal3_piece_free(&pcs[p]);
        count += (uint32_t)added;
    }
    nd = node_at(b, x->node);
    nd->child_first = first;
    nd->child_count = count;
    return st;
}

/* ---- level 0 ---- */

/* v_i, v_j, v_k over the vertices the triangles use (a reconstruction may leave points inside). */
static fl_status choose_root(const fl_mesh *m, double ball[4], uint32_t r[3], fl_error *err)
{
    uint32_t *ids = fl_alloc_array(m->vertex_count + 1, sizeof(uint32_t));
    uint8_t *used = fl_calloc_array(m->vertex_count + 1, 1);
    double *xyz = fl_alloc_array(3 * m->vertex_count + 3, sizeof(double));
    if (!ids || !used || !xyz) {
        free(ids), free(used), free(xyz);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
    }
    for (size_t t = 0; t < 3 * m->triangle_count; t++)
        used[m->tri[t]] = 1;
    size_t n = 0;
    for (size_t v = 0; v < m->vertex_count; v++)
        if (used[v]) {
            memcpy(xyz + 3 * n, m->xyz + 3 * v, 3 * sizeof(double));
            ids[n++] = (uint32_t)v;
        }
    uint32_t sup[4];
    int ns = 0;
    hal3_min_ball(xyz, n, ball, sup, &ns);
    r[0] = ids[sup[0]];
    r[1] = ns > 1 ? ids[sup[1]] : ids[sup[0] == 0 ? 1 : 0];
    if (ns > 2) {
        r[2] = ids[sup[2]];
    } else {
        /* Two support vertices: the third is the vertex farthest from their line, which makes
         * the level-0 triangle as fat as possible. */
        const double *a = m->xyz + 3 * (size_t)r[0], *c = m->xyz + 3 * (size_t)r[1];
        double d[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]}, best = -1;
        for (size_t i = 0; i < n; i++) {
            const double *x = xyz + 3 * i;
            double u[3] = {x[0] - a[0], x[1] - a[1], x[2] - a[2]};
            double cr[3] = {u[1] * d[2] - u[2] * d[1], u[2] * d[0] - u[0] * d[2],
                            u[0] * d[1] - u[1] * d[0]};
            double h = cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2];
            if (h > best) best = h, r[2] = ids[i];
        }
    }
    free(ids), free(used), free(xyz);
    return FL_OK;
}

static fl_status copy_mesh(const fl_mesh *in, fl_mesh *out, fl_error *err)
{
    out->vertex_count = in->vertex_count;
    out->triangle_count = in->triangle_count;
    out->xyz = fl_alloc_array(3 * in->vertex_count, sizeof(double));
    out->tri = fl_alloc_array(3 * in->triangle_count, sizeof(uint32_t));
    if (!out->xyz || !out->tri) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
    memcpy(out->xyz, in->xyz, 3 * in->vertex_count * sizeof(double));
    memcpy(out->tri, in->tri, 3 * in->triangle_count * sizeof(uint32_t));
    return FL_OK;
}

/* The exact bounding box of the vertices the triangles use (min and max are exact on doubles;
 * the input is finite, checked before). Every triangle lies in it (a box is convex), so two
 * trees with disjoint boxes have no common point: fl_hal3_intersect's early exit. */
static void bounding_box(const fl_mesh *m, double box[6])
{
    for (int k = 0; k < 3; k++)
        box[k] = INFINITY, box[3 + k] = -INFINITY;
    for (size_t t = 0; t < 3 * m->triangle_count; t++) {
        const double *p = m->xyz + 3 * (size_t)m->tri[t];
        for (int k = 0; k < 3; k++) {
            if (p[k] < box[k]) box[k] = p[k];
            if (p[k] > box[3 + k]) box[3 + k] = p[k];
        }
    }
}

static fl_status levels(build *b, const fl_hal3_options *opt, fl_hal3 *out, fl_error *err)
{
    fl_status st = FL_OK;
    uint32_t level = 0, max_level = 2 * (uint32_t)b->mesh->triangle_count + 64;
    while (b->nnext > 0 && st == FL_OK) {
        live *t = b->cur;
        b->cur = b->next, b->ncur = b->nnext;
        b->next = t, b->nnext = 0;
        if (++level > max_level)
            return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "hal3: refinement does not end");
        if (opt && opt->progress &&
            opt->progress(opt->progress_user, "hal3", fmin(1.0, level / 64.0)))
            return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
        st = decide_splits(b, err);
        for (size_t i = 0; i < b->ncur && st == FL_OK; i++)
            st = split_node(b, &b->cur[i], err);
        for (size_t i = 0; i < b->ncur; i++)
            hal3_piece_free(&b->cur[i].pc);
        b->ncur = 0;
    }
    out->depth = level;
    return st;
}

fl_status fl_hal3_build(const fl_mesh *mesh, const fl_hal3_options *opt, fl_hal3 *out,
                        fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal3_build: NULL argument");
    memset(out, 0, sizeof *out);
    if (!mesh || (mesh->vertex_count && !mesh->xyz) || (mesh->triangle_count && !mesh->tri))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal3_build: NULL argument");
    double th = opt && opt->angle_threshold != 0 ? opt->angle_threshold : FL_HAL3_PI / 4;
    if (!(th >= 0 && th <= FL_HAL3_PI / 3))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1,
                       "hal3_build: angle threshold outside [0, pi/3]");
    fl_status st = check_input(mesh, err);
    if (st != FL_OK) return st;
    build b;
    memset(&b, 0, sizeof b);
    b.mesh = &out->mesh;
    b.threshold = th;
    fl_vec_init(&b.nodes, sizeof(fl_hal3_node));
    fl_vec_init(&b.ties, sizeof(uint32_t));
    fl_halfedges he;
    memset(&he, 0, sizeof he);
    st = copy_mesh(mesh, &out->mesh, err);
    if (st == FL_OK) st = fl_halfedges_build(&out->mesh, &he, err);
    if (st == FL_OK && hal3_work_init(&b.w, &out->mesh, &he) != FL_OK)
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
    b.cap = mesh->triangle_count + 2;
    b.cur = fl_calloc_array(b.cap, sizeof(live));
    b.next = fl_calloc_array(b.cap, sizeof(live));
    b.count = fl_calloc_array(mesh->vertex_count, sizeof(uint32_t));
    if (st == FL_OK && (!b.cur || !b.next || !b.count))
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
    if (st == FL_OK) {
        uint32_t r[3] = {0, 0, 0}; /* set by choose_root on success; zeroed for -O2 analysis */
        hal3_piece pa, pb;
        memset(&pa, 0, sizeof pa);
        memset(&pb, 0, sizeof pb);
        st = choose_root(&out->mesh, out->ball, r, err);
        if (st == FL_OK) st = hal3_cut_sphere(&b.w, r[0], r[1], r[2], &pa, &pb, err);
        int added;
        if (st == FL_OK) st = add_node(&b, &pa, 0, -1, &added, err);
        if (st == FL_OK && !added)
            st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "hal3: empty root");
        if (st == FL_OK) st = add_node(&b, &pb, 0, -1, &added, err);
        if (st == FL_OK && !added)
            st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "hal3: empty root");
        hal3_piece_free(&pa);
        hal3_piece_free(&pb);
    }
    if (st == FL_OK) {
        out->ball[3] = 0;
        for (size_t t = 0; t < 3 * mesh->triangle_count; t++)
            out->ball[3] =
                fmax(out->ball[3], fl_hal3_d2(out->ball, out->mesh.xyz + 3 * (size_t)mesh->tri[t]));
        bounding_box(&out->mesh, out->box);
        st = levels(&b, opt, out, err);
    }
    for (size_t i = 0; i < b.ncur; i++)
        hal3_piece_free(&b.cur[i].pc);
    for (size_t i = 0; i < b.nnext; i++)
        hal3_piece_free(&b.next[i].pc);
    free(b.cur);
    free(b.next);
    free(b.count);
    hal3_work_free(&b.w);
    fl_halfedges_free(&he);
    out->nodes = b.nodes.data;
    out->node_count = b.nodes.count;
    out->ties = b.ties.data;
    out->tie_count = b.ties.count / 2;
    if (st != FL_OK) fl_hal3_free(out);
    return st;
}

void fl_hal3_free(fl_hal3 *hal)
{
    if (!hal) return;
    fl_mesh_free(&hal->mesh);
    free(hal->nodes);
    free(hal->ties);
    memset(hal, 0, sizeof *hal);
}
