/* Approximations from the 3D flintstone tree (thesis §7.3.2 levels, §7.3.3 adaptive).
 *
 * An approximation is a cut of the tree: a set of nodes such that every original triangle is
 * below exactly one of them. Nodes whose part of the surface is empty (coalescing paths,
 * thesis Fig. 7.12) cover no triangle and are discarded, as the thesis does. Algorithm 7.2
 * splits both triangles of a split side at the same vertex, but where shortest paths coalesce
 * a piece can gain or lose a corner that its neighbour does not see, and discarding an empty
 * node leaves its neighbours' sides unmatched; both show as triangle sides a->b without exactly
 * one partner b->a. The cut is therefore closed before it is returned: every node at such a side
 * is replaced by its (non-empty) children, and when the side belongs to an original triangle
 * (a leaf) the node covering the original triangle across it is refined instead. Each round
 * refines at least one node while some side is unmatched, and the cut of all leaves is the input
 * mesh (closed, oriented, manifold), so the loop ends with a crack-free closed mesh. Refining
 * only moves triangles closer to the surface's own triangles: the coverage (every original
 * triangle below exactly one cut node) and the certified error (largest node error of the cut;
 * nodes above the bound are refined again) stay valid. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "hal/hal3_internal.h"

/* What to refine before closing: level cut (nodes above `level`) or error cut (error > bound,
 * everything when bound is 0). */
typedef struct cut_rule {
    int by_level;
    uint32_t level;
    double bound;
} cut_rule;

static int wants_refine(const fl_hal3 *hal, const cut_rule *r, uint32_t n)
{
    const fl_hal3_node *nd = &hal->nodes[n];
    if (nd->kind == FL_HAL3_LEAF) return 0;
    if (r->by_level) return nd->level < r->level;
    return nd->error > r->bound || r->bound == 0;
}

/* Puts node n in the cut, descending while the rule asks; empty nodes are dropped. */
static void cut_add(const fl_hal3 *hal, const cut_rule *r, uint8_t *keep, uint32_t *stack,
                    uint32_t n)
{
    size_t top = 0;
    stack[top++] = n;
    while (top > 0) {
        uint32_t m = stack[--top];
        const fl_hal3_node *nd = &hal->nodes[m];
        if (nd->face_count == 0) continue;
        if (!wants_refine(hal, r, m)) {
            keep[m] = 1;
            continue;
        }
        for (uint32_t c = 0; c < nd->child_count; c++)
            stack[top++] = nd->child_first + c;
    }
}

/* Replaces cut node n by its children (a leaf stays). */
static int cut_refine(const fl_hal3 *hal, const cut_rule *r, uint8_t *keep, uint32_t *stack,
                      uint32_t n)
{
    const fl_hal3_node *nd = &hal->nodes[n];
    if (!keep[n] || nd->kind == FL_HAL3_LEAF) return 0;
    keep[n] = 0;
    for (uint32_t c = 0; c < nd->child_count; c++)
        cut_add(hal, r, keep, stack, nd->child_first + c);
    return 1;
}

static int cmp_u64(const void *x, const void *y)
{
    uint64_t a = *(const uint64_t *)x, b = *(const uint64_t *)y;
    return a < b ? -1 : a > b;
}

/* Number of entries equal to key in the sorted array. */
static size_t count_key(const uint64_t *a, size_t n, uint64_t key)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (a[mid] < key) lo = mid + 1;
        else hi = mid;
    }
    size_t c = 0;
    while (lo + c < n && a[lo + c] == key)
        c++;
    return c;
}

/* Scratch of the closure: original directed edges -> face, face -> leaf node. */
typedef struct oedge {
    uint64_t key; /* a << 32 | b */
    uint32_t face;
} oedge;

typedef struct closure {
    oedge *orig;       /* the 3T directed edges of the original triangles, sorted by key */
    uint32_t *leaf_of; /* per face: its leaf node */
    uint64_t *cut;     /* directed sides of the cut's triangles, sorted; then the fill's */
    size_t ncut;
    uint32_t *todo;    /* nodes to refine this round */
    uint64_t *open;    /* sides a->b of the cut without any b->a (the cracks) */
    uint32_t *cyc;     /* scratch: one crack walk, then its simple loops */
    uint32_t *walk;    /* scratch: the open sides of the walk */
    uint8_t *pinch;    /* per mesh vertex: more than one fan */
    uint8_t *used;
    fl_vec fill;       /* triangles closing the cracks, 3 vertex indices each */
} closure;

static uint64_t dkey(uint32_t a, uint32_t b)
{
    return (uint64_t)a << 32 | b;
}

static int cmp_oedge(const void *x, const void *y)
{
    uint64_t a = ((const oedge *)x)->key, b = ((const oedge *)y)->key;
    return a < b ? -1 : a > b;
}

/* The node of the cut covering original face f: its leaf's kept ancestor. */
static uint32_t cover_of(const fl_hal3 *hal, const closure *c, const uint8_t *keep, uint32_t f)
{
    int32_t n = (int32_t)c->leaf_of[f];
    while (n >= 0 && !keep[n])
        n = hal->nodes[n].parent;
    return n < 0 ? FL_HAL3_NONE : (uint32_t)n;
}

/* The face of the original mesh owning directed edge a->b, or FL_HAL3_NONE. */
static uint32_t orig_face(const fl_hal3 *hal, const closure *c, uint32_t a, uint32_t b)
{
    size_t n = 3 * hal->mesh.triangle_count, lo = 0, hi = n;
    uint64_t key = dkey(a, b);
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (c->orig[mid].key < key) lo = mid + 1;
        else hi = mid;
    }
    return lo < n && c->orig[lo].key == key ? c->orig[lo].face : FL_HAL3_NONE;
}

/* Whether every directed side of the cut and of the fill has exactly one reverse partner and
 * is used once. */
static int all_matched(closure *c)
{
    const uint32_t *f = c->fill.data;
    size_t n = c->ncut;
    for (size_t t = 0; t < c->fill.count / 3; t++)
        for (int k = 0; k < 3; k++)
            c->cut[n++] = dkey(f[3 * t + (size_t)k], f[3 * t + (size_t)(k + 1) % 3]);
    qsort(c->cut, n, sizeof *c->cut, cmp_u64);
    for (size_t i = 0; i < n; i++) {
        uint64_t rev = c->cut[i] << 32 | c->cut[i] >> 32;
        if ((i + 1 < n && c->cut[i + 1] == c->cut[i]) || count_key(c->cut, n, rev) != 1) return 0;
    }
    return 1;
}

/* Whether the segment {a, b} is a side of the cut or of the fill so far. */
static int has_segment(const closure *c, uint32_t a, uint32_t b)
{
    if (count_key(c->cut, c->ncut, dkey(a, b)) || count_key(c->cut, c->ncut, dkey(b, a)))
        return 1;
    const uint32_t *f = c->fill.data;
    for (size_t i = 0; i < c->fill.count; i++) {
        size_t base = i - i % 3, j = i % 3;
        if (f[i] == a && (f[base + (j + 1) % 3] == b || f[base + (j + 2) % 3] == b)) return 1;
    }
    return 0;
}

/* Triangulates one simple crack loop w[0..k-1] against its orientation, splitting it along a
 * diagonal that is a new segment (so no side gets a third triangle), preferring the most
 * balanced split. 1 done, 0 no such diagonal, -1 out of memory. */
static int fill_loop(closure *c, const uint32_t *w, size_t k)
{
    if (k < 3) return 0;
    if (k == 3) {
        uint32_t t[3] = {w[0], w[2], w[1]};
        return fl_vec_push(&c->fill, t, 3) ? -1 : 1;
    }
    for (size_t d = k / 2; d >= 2; d--)
        for (size_t i = 0; i < k; i++) {
            size_t j = (i + d) % k;
            if (has_segment(c, w[i], w[j])) continue;
            uint32_t *tmp = fl_alloc_array(k + 1, sizeof(uint32_t));
            if (!tmp) return -1;
            for (size_t q = 0; q <= d; q++)
                tmp[q] = w[(i + q) % k];
            int ok = fill_loop(c, tmp, d + 1);
            for (size_t q = 0; ok > 0 && q <= k - d; q++)
                tmp[q] = w[(j + q) % k];
            if (ok > 0) ok = fill_loop(c, tmp, k - d + 1);
            free(tmp);
            return ok;
        }
    return 0;
}

/* Closes the cracks: the open sides form closed loops (each crack is a side a->b of one
 * triangle facing the chain b -> ... -> a of the triangles across, e.g. where a coalescing-path
 * triangle was discarded, Fig. 7.12); each loop is filled by a fan of triangles oriented against
 * it, the triangles the neighbour split at the same vertex would have given (§7.3.2). They
 * cover no part of the surface, so the coverage and the certified error are unchanged.
 * Returns 0 when the loops cannot be followed or the result is not matched. */
static int fill_cracks(closure *c, size_t nopen)
{
    c->fill.count = 0;
    qsort(c->open, nopen, sizeof *c->open, cmp_u64);
    memset(c->used, 0, nopen);
    int failed = 0;
    for (size_t s = 0; s < nopen; s++) {
        if (c->used[s]) continue;
        uint32_t start = (uint32_t)(c->open[s] >> 32);
        size_t e = s, len = 0;
        int ok = 1;
        for (;;) {
            c->used[e] = 1;
            c->walk[len] = (uint32_t)e;
            c->cyc[len++] = (uint32_t)(c->open[e] >> 32);
            uint32_t v = (uint32_t)c->open[e];
            if (v == start) break;
            size_t lo = 0, hi = nopen;
            while (lo < hi) {
                size_t mid = lo + (hi - lo) / 2;
                if (c->open[mid] >> 32 < v) lo = mid + 1;
                else hi = mid;
            }
            while (lo < nopen && c->open[lo] >> 32 == v && c->used[lo])
                lo++;
            if (lo == nopen || c->open[lo] >> 32 != v) {
                ok = 0;
                break;
            }
            e = lo;
        }
        /* Split the closed walk at repeated vertices into simple loops; cyc[len..] is the
         * stack of vertices, walk[len..] the open side leaving each. A loop that cannot be
         * filled stays a crack: its nodes are refined (closure_round's second pass). */
        if (!ok) {
            for (size_t i = 0; i < len; i++)
                c->used[c->walk[i]] = 2;
            failed = 1;
            continue;
        }
        size_t top = 0;
        for (size_t i = 0; i <= len; i++) {
            uint32_t v = i < len ? c->cyc[i] : c->cyc[0];
            size_t j = top;
            while (j > 0 && c->cyc[len + j - 1] != v)
                j--;
            if (j == 0) {
                c->cyc[len + top] = v;
                c->walk[len + top++] = c->walk[i];
                continue;
            }
            size_t fill0 = c->fill.count;
            int r = fill_loop(c, c->cyc + len + j - 1, top - j + 1);
            if (r < 0) return -1;
            if (r == 0) {
                c->fill.count = fill0;
                for (size_t q = j - 1; q < top; q++)
                    c->used[c->walk[len + q]] = 2;
                failed = 1;
            }
            top = j;
            if (i < len) c->walk[len + top - 1] = c->walk[i];
        }
    }
    if (failed) return 0;
    if (all_matched(c)) return 1;
    memset(c->used, 2, nopen); /* not expected: refine at every crack */
    return 0;
}

/* Whether crack a->b is one fill_cracks could not close. */
static int failed_crack(const closure *c, size_t nopen, uint64_t key)
{
    size_t lo = 0, hi = nopen;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (c->open[mid] < key) lo = mid + 1;
        else hi = mid;
    }
    return lo < nopen && c->open[lo] == key && c->used[lo] == 2;
}

/* Vertices whose triangles (cut and fill) form more than one fan: the link of v is the set of
 * sides a->b opposite v, a union of cycles once every side has one partner; more than one
 * cycle is a pinch (two parts of the surface touching at v). Marks them in c->pinch and returns
 * their number, SIZE_MAX when out of memory. */
static size_t pinched_vertices(const fl_hal3 *hal, closure *c, const uint8_t *keep)
{
    const uint32_t *f = c->fill.data;
    size_t nf = c->fill.count / 3, n = 0;
    for (size_t i = 0; i < hal->node_count; i++)
        n += keep[i] != 0;
    oedge *lk = fl_alloc_array(3 * (n + nf) + 1, sizeof(oedge));
    uint8_t *seen = fl_calloc_array(3 * (n + nf) + 1, 1);
    if (!lk || !seen) {
        free(lk);
        free(seen);
        return SIZE_MAX;
    }
    memset(c->pinch, 0, hal->mesh.vertex_count);
    n = 0;
    for (size_t i = 0; i < hal->node_count + nf; i++) {
        const uint32_t *v = i < hal->node_count ? hal->nodes[i].v : f + 3 * (i - hal->node_count);
        if (i < hal->node_count && !keep[i]) continue;
        for (int k = 0; k < 3; k++)
            lk[n++] = (oedge){dkey(v[k], v[(k + 1) % 3]), v[(k + 2) % 3]};
    }
    qsort(lk, n, sizeof *lk, cmp_oedge);
    size_t bad = 0;
    for (size_t g = 0; g < n;) {
        uint32_t v = (uint32_t)(lk[g].key >> 32);
        size_t end = g, cycles = 0;
        while (end < n && lk[end].key >> 32 == v)
            end++;
        for (size_t s = g; s < end; s++) {
            if (seen[s]) continue;
            cycles++;
            for (size_t e = s; e < end && !seen[e];) {
                seen[e] = 1;
                uint64_t want = dkey(v, lk[e].face);
                size_t lo = g, hi = end;
                while (lo < hi) {
                    size_t mid = lo + (hi - lo) / 2;
                    if (lk[mid].key < want) lo = mid + 1;
                    else hi = mid;
                }
                if (lo == end || lk[lo].key != want) break;
                e = lo;
            }
        }
        c->pinch[v] = cycles > 1;
        bad += cycles > 1;
        g = end;
    }
    free(lk);
    free(seen);
    return bad;
}

/* Collects in c->todo the cut nodes at a pinched vertex, or when they are all leaves the nodes
 * covering the original triangles around it. */
static size_t refine_pinches(const fl_hal3 *hal, closure *c, const uint8_t *keep)
{
    size_t ntodo = 0;
    for (size_t n = 0; n < hal->node_count; n++) {
        if (!keep[n] || hal->nodes[n].kind == FL_HAL3_LEAF) continue;
        const uint32_t *v = hal->nodes[n].v;
        if (c->pinch[v[0]] || c->pinch[v[1]] || c->pinch[v[2]]) c->todo[ntodo++] = (uint32_t)n;
    }
    if (ntodo > 0) return ntodo;
    size_t nt = 3 * hal->mesh.triangle_count;
    for (size_t i = 0; i < nt; i++) {
        if (!c->pinch[c->orig[i].key >> 32]) continue;
        uint32_t m = cover_of(hal, c, keep, c->orig[i].face);
        if (m != FL_HAL3_NONE && hal->nodes[m].kind != FL_HAL3_LEAF) c->todo[ntodo++] = m;
    }
    return ntodo;
}

/* One closure round: sides used more than once (pillows, overlapping triangles) refine the nodes
 * at them; when there are none, the cracks are filled. Otherwise the nodes at a
 * crack are refined, and for a crack at a leaf (an original side) the node covering the
 * original triangle across it. Returns the number of nodes to refine (in c->todo), 0 when
 * closed; SIZE_MAX when out of memory. */
static size_t closure_round(const fl_hal3 *hal, closure *c, const uint8_t *keep)
{
    size_t ncut = 0, ntodo = 0, nopen = 0;
    for (size_t n = 0; n < hal->node_count; n++)
        if (keep[n])
            for (int k = 0; k < 3; k++)
                c->cut[ncut++] = dkey(hal->nodes[n].v[k], hal->nodes[n].v[(k + 1) % 3]);
    qsort(c->cut, ncut, sizeof *c->cut, cmp_u64);
    c->ncut = ncut;
    c->fill.count = 0;
    for (int pass = 0; pass < 2 && ntodo == 0; pass++) {
        for (size_t n = 0; n < hal->node_count; n++) {
            if (!keep[n]) continue;
            const fl_hal3_node *nd = &hal->nodes[n];
            for (int k = 0; k < 3; k++) {
                uint32_t a = nd->v[k], b = nd->v[(k + 1) % 3];
                size_t ca = count_key(c->cut, ncut, dkey(a, b));
                size_t cb = count_key(c->cut, ncut, dkey(b, a));
                if (ca == 1 && cb == 1) continue;
                if (pass == 0) {
                    if (ca == 1 && cb == 0) {
                        c->open[nopen++] = dkey(a, b);
                        continue;
                    }
                } else if (ca != 1 || cb != 0 || !failed_crack(c, nopen, dkey(a, b))) {
                    continue;
                }
                if (nd->kind != FL_HAL3_LEAF) {
                    c->todo[ntodo++] = (uint32_t)n;
                    continue;
                }
                /* An original side: its partner is in the original triangle across it. */
                uint32_t f = orig_face(hal, c, b, a);
                uint32_t m = f == FL_HAL3_NONE ? FL_HAL3_NONE : cover_of(hal, c, keep, f);
                if (m != FL_HAL3_NONE && hal->nodes[m].kind != FL_HAL3_LEAF) c->todo[ntodo++] = m;
            }
        }
        if (pass == 0 && ntodo == 0) {
            int ok = nopen ? fill_cracks(c, nopen) : 1;
            if (ok < 0) return SIZE_MAX;
            if (ok) {
                size_t np = pinched_vertices(hal, c, keep);
                if (np == SIZE_MAX) return SIZE_MAX;
                return np ? refine_pinches(hal, c, keep) : 0;
            }
            c->fill.count = 0;
        }
    }
    return ntodo;
}

/* Closes the cut `keep` (see the top of the file); *fill receives the crack triangles. */
static fl_status close_cut(const fl_hal3 *hal, const cut_rule *r, uint8_t *keep, uint32_t *stack,
                           fl_vec *fill, fl_error *err)
{
    size_t nt = hal->mesh.triangle_count, nn = hal->node_count;
    closure c;
    memset(&c, 0, sizeof c);
    fl_vec_init(&c.fill, sizeof(uint32_t));
    c.orig = fl_alloc_array(3 * nt + 1, sizeof(oedge));
    c.leaf_of = fl_alloc_array(nt + 1, sizeof(uint32_t));
    c.cut = fl_alloc_array(12 * nn + 1, sizeof(uint64_t));
    c.todo = fl_alloc_array(3 * nn + 1, sizeof(uint32_t));
    c.open = fl_alloc_array(3 * nn + 1, sizeof(uint64_t));
    c.cyc = fl_alloc_array(6 * nn + 1, sizeof(uint32_t));
    c.used = fl_alloc_array(3 * nn + 1, 1);
    c.walk = fl_alloc_array(6 * nn + 1, sizeof(uint32_t));
    c.pinch = fl_calloc_array(hal->mesh.vertex_count + 1, 1);
    fl_status st = FL_OK;
    if (!c.orig || !c.leaf_of || !c.cut || !c.todo || !c.open || !c.cyc || !c.used || !c.walk ||
        !c.pinch) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
        goto done;
    }
    for (size_t t = 0; t < nt; t++)
        for (int k = 0; k < 3; k++) {
            c.orig[3 * t + (size_t)k].key =
                dkey(hal->mesh.tri[3 * t + (size_t)k], hal->mesh.tri[3 * t + (size_t)(k + 1) % 3]);
            c.orig[3 * t + (size_t)k].face = (uint32_t)t;
        }
    qsort(c.orig, 3 * nt, sizeof *c.orig, cmp_oedge);
    for (size_t n = 0; n < nn; n++)
        if (hal->nodes[n].kind == FL_HAL3_LEAF) c.leaf_of[hal->nodes[n].face] = (uint32_t)n;
    for (;;) {
        size_t ntodo = closure_round(hal, &c, keep), done = 0;
        if (ntodo == SIZE_MAX) {
            st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
            break;
        }
        if (ntodo == 0) break;
        for (size_t i = 0; i < ntodo; i++)
            done += (size_t)cut_refine(hal, r, keep, stack, c.todo[i]);
        if (done == 0) {
            /* Cannot happen: an unmatched side means some cut node is not a leaf. */
            st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                         "hal3: approximation could not be closed");
            break;
        }
    }
    if (st == FL_OK) {
        *fill = c.fill;
        memset(&c.fill, 0, sizeof c.fill);
    }
done:
    fl_vec_free(&c.fill);
    free(c.orig);
    free(c.leaf_of);
    free(c.cut);
    free(c.todo);
    free(c.open);
    free(c.cyc);
    free(c.used);
    free(c.walk);
    free(c.pinch);
    return st;
}

/* Writes the triangles of the nodes with keep[n] != 0 and the nf fill triangles as a compact
 * mesh. */
static fl_status cut_mesh(const fl_hal3 *hal, const uint8_t *keep, const uint32_t *fill, size_t nf,
                         fl_mesh *out, fl_error *err)
{
    memset(out, 0, sizeof *out);
    size_t nt = nf;
    for (size_t n = 0; n < hal->node_count; n++)
        nt += keep[n] != 0;
    uint32_t *map = fl_alloc_array(hal->mesh.vertex_count + 1, sizeof(uint32_t));
    out->tri = fl_alloc_array(3 * nt + 1, sizeof(uint32_t));
    out->xyz = fl_alloc_array(3 * hal->mesh.vertex_count + 1, sizeof(double));
    if (!map || !out->tri || !out->xyz) {
        free(map);
        fl_mesh_free(out);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
    }
    memset(map, 0xff, hal->mesh.vertex_count * sizeof(uint32_t));
    for (size_t n = 0; n < hal->node_count; n++) {
        if (!keep[n]) continue;
        for (int k = 0; k < 3; k++) {
            uint32_t v = hal->nodes[n].v[k];
            if (map[v] == UINT32_MAX) {
                map[v] = (uint32_t)out->vertex_count++;
                memcpy(out->xyz + 3 * (size_t)map[v], hal->mesh.xyz + 3 * (size_t)v,
                       3 * sizeof(double));
            }
            out->tri[3 * out->triangle_count + (size_t)k] = map[v];
        }
        out->triangle_count++;
    }
    for (size_t t = 0; t < nf; t++, out->triangle_count++)
        for (int k = 0; k < 3; k++)
            out->tri[3 * out->triangle_count + (size_t)k] = map[fill[3 * t + (size_t)k]];
    free(map);
    return FL_OK;
}

/* The closed cut of `rule` as a mesh; *error and *level of its nodes. */
static fl_status approximate(const fl_hal3 *hal, const cut_rule *rule, fl_mesh *out,
                             double *error, uint32_t *level, fl_error *err)
{
    memset(out, 0, sizeof *out);
    size_t nn = hal->node_count;
    uint8_t *keep = fl_calloc_array(nn + 1, 1);
    uint32_t *stack = fl_alloc_array(nn + 1, sizeof(uint32_t));
    fl_vec fill;
    fl_vec_init(&fill, sizeof(uint32_t));
    fl_status st = FL_OK;
    if (!keep || !stack) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
        goto done;
    }
    for (uint32_t root = 0; root < 2 && root < nn; root++)
        cut_add(hal, rule, keep, stack, root);
    st = close_cut(hal, rule, keep, stack, &fill, err);
    if (st != FL_OK) goto done;
    double e = 0;
    uint32_t lv = 0;
    for (size_t n = 0; n < nn; n++)
        if (keep[n]) {
            e = fmax(e, hal->nodes[n].error);
            lv = hal->nodes[n].level > lv ? hal->nodes[n].level : lv;
        }
    st = cut_mesh(hal, keep, fill.data, fill.count / 3, out, err);
    if (st == FL_OK && error) *error = e;
    if (st == FL_OK && level) *level = lv;
done:
    fl_vec_free(&fill);
    free(keep);
    free(stack);
    return st;
}

fl_status fl_hal3_approximate_level(const fl_hal3 *hal, uint32_t level, fl_mesh *out, double *error,
                                    fl_error *err)
{
    if (!hal || !out)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal3_approximate: NULL argument");
    cut_rule r = {.by_level = 1, .level = level};
    return approximate(hal, &r, out, error, NULL, err);
}

fl_status fl_hal3_approximate_error(const fl_hal3 *hal, double max_error, fl_mesh *out,
                                    double *error, uint32_t *level, fl_error *err)
{
    if (!hal || !out)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal3_approximate: NULL argument");
    if (!(max_error >= 0))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "hal3_approximate: error bound must be >= 0");
    cut_rule r = {.by_level = 0, .bound = max_error};
    return approximate(hal, &r, out, error, level, err);
}
