/* Where a skin mesh's topology differs from the skin's: the components of a closed mesh, and
 * boxes round its local handles and its small components (skin_mesh_defects), for the graded
 * mesher's local refinement (skin_graded.c, fl_skin_options.repair).
 *
 * Why windows: a grid coarser than a narrow gap of the skin can bridge the gap once and make a
 * handle a few cells across (the npm bunny's grade-4 mesh, docs/skin.md round 16), or miss the
 * narrow channel of a pocket and make a bubble. Both are small. The genus of the part of the
 * mesh in a window, a compact orientable surface with boundary, is (2C - chi - B) / 2 (C its
 * components, B its boundary loops), at most the genus of the whole mesh; a window of 8 to 16
 * faces' size that holds genus holds a handle of about that size. Windows come in one family
 * per band of face size (faces of longest edge in [2^L, 2^(L+1)) times the smallest), so the
 * window follows the local cell of a graded grid. A real handle of the skin larger than its
 * windows is never flagged; a smaller one is (refining round it costs time, not correctness:
 * the caller stops when the numbers match or after its rounds).
 *
 * The part in a window: the faces whose centroid lies in it. Its vertices are split into fans
 * (corners joined across the part's interior edges), so a vertex whose faces leave and come
 * back counts once per sector, and each boundary fan has exactly two boundary edges. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "skin/skin_internal.h"
#include "skin/skin_map.h"

#define WINDOW_FACES 8 /* a window is this many times its band's smallest longest edge, twice */
#define KEY_BITS 21    /* bits an axis in a stride cell's key */
#define MAX_BUBBLES 64 /* small components boxed a call */

long long skin_mesh_components(const fl_mesh *m)
{
    size_t nv = m->vertex_count ? m->vertex_count : 1;
    uint32_t *parent = fl_alloc_array(nv, sizeof *parent);
    unsigned char *used = calloc(nv, 1);
    if (!parent || !used) {
        free(parent);
        free(used);
        return -1;
    }
    for (size_t i = 0; i < m->vertex_count; i++)
        parent[i] = (uint32_t)i;
    for (size_t t = 0; t < m->triangle_count; t++) {
        const uint32_t *v = m->tri + 3 * t;
        for (int k = 0; k < 3; k++) {
            used[v[k]] = 1;
            fl_uf_union(parent, v[0], v[k]);
        }
    }
    long long count = 0;
    for (size_t i = 0; i < m->vertex_count; i++)
        count += used[i] && fl_uf_find(parent, (uint32_t)i) == i;
    free(parent);
    free(used);
    return count;
}

typedef struct defects {
    const fl_mesh *m;
    uint32_t *twin;     /* half-edge 3f + j (v[j] -> v[j+1]) -> the opposite half-edge */
    double *cen;        /* face centroids */
    float *len;         /* longest edge a face */
    int32_t *loc;       /* face -> index in the current window, -1 outside */
    uint32_t *list;     /* the current window's faces */
    uint32_t *corner;   /* union-find over the window's corners (3 a face) */
    uint32_t *comp;     /* union-find over the window's faces */
    uint32_t *bloop;    /* union-find over the window's corners' boundary half-edges */
    uint32_t *bfirst;   /* fan -> first boundary half-edge met at it */
    fl_vec *boxes;      /* skin_box */
    const double *xyzw; /* the balls */
    size_t n;
    fl_vec sub; /* double[4]: the balls meeting a window */
} defects;

static fl_status nomem(fl_error *err)
{
    return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "skin: out of memory");
}

/* twin[], centroids and longest edges; FL_ERR_INPUT when the mesh is not a closed 2-manifold
 * (the graded mesher's contract). */
static fl_status setup(defects *d, fl_error *err)
{
    const fl_mesh *m = d->m;
    size_t F = m->triangle_count, H = 3 * F;
    d->twin = fl_alloc_array(H, sizeof *d->twin);
    d->cen = fl_alloc_array(F, 3 * sizeof(double));
    d->len = fl_alloc_array(F, sizeof *d->len);
    if (!d->twin || !d->cen || !d->len) return nomem(err);
    u64map e;
    if (map_init(&e, H / 2 + 16)) return nomem(err);
    fl_status st = FL_OK;
    for (size_t h = 0; h < H && !st; h++) {
        uint32_t a = m->tri[h], b = m->tri[h / 3 * 3 + (h % 3 + 1) % 3];
        uint64_t key = (uint64_t)(a < b ? a : b) << 32 | (a < b ? b : a);
        size_t s = map_slot(&e, key);
        if (e.key[s] == key) {
            uint32_t o = e.val[s];
            if (o == UINT32_MAX) {
                st = fl_fail(err, FL_ERR_INPUT, NULL, -1, "skin: mesh edge with > 2 faces");
                break;
            }
            d->twin[h] = o;
            d->twin[o] = (uint32_t)h;
            e.val[s] = UINT32_MAX;
        } else if (map_put(&e, key, (uint32_t)h) == SIZE_MAX)
            st = nomem(err);
    }
    for (size_t i = 0; i < e.cap && !st; i++)
        if (e.key[i] != UINT64_MAX && e.val[i] != UINT32_MAX)
            st = fl_fail(err, FL_ERR_INPUT, NULL, -1, "skin: mesh edge with one face");
    map_free(&e);
    for (size_t f = 0; f < F && !st; f++) {
        const double *p[3];
        for (int k = 0; k < 3; k++)
            p[k] = m->xyz + 3 * (size_t)m->tri[3 * f + k];
        double l2 = 0;
        for (int k = 0; k < 3; k++) {
            const double *a = p[k], *b = p[(k + 1) % 3];
            l2 = fmax(l2, (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                              (a[2] - b[2]) * (a[2] - b[2]));
        }
        d->len[f] = (float)sqrt(l2);
        for (int c = 0; c < 3; c++)
            d->cen[3 * f + c] = (p[0][c] + p[1][c] + p[2][c]) / 3;
    }
    return st;
}

/* Genus (times 2) of the window's part list[0, L), whose faces have loc set. */
static long long window_genus2(defects *d, size_t L)
{
    for (size_t i = 0; i < 3 * L; i++) {
        d->corner[i] = (uint32_t)i;
        d->bloop[i] = (uint32_t)i;
        d->bfirst[i] = UINT32_MAX;
    }
    for (size_t i = 0; i < L; i++)
        d->comp[i] = (uint32_t)i;
    long long E = 0;
    for (size_t i = 0; i < L; i++) {
        uint32_t f = d->list[i];
        for (uint32_t j = 0; j < 3; j++) {
            uint32_t h = 3 * f + j, t = d->twin[h], g = t / 3, tj = t % 3;
            if (d->loc[g] < 0) {
                E++;
                continue;
            }
            if (h > t) continue;
            E++;
            uint32_t gi = (uint32_t)d->loc[g];
            fl_uf_union(d->corner, 3 * (uint32_t)i + j, 3 * gi + (tj + 1) % 3);
            fl_uf_union(d->corner, 3 * (uint32_t)i + (j + 1) % 3, 3 * gi + tj);
            fl_uf_union(d->comp, (uint32_t)i, gi);
        }
    }
    long long V = 0, C = 0, B = 0;
    for (size_t i = 0; i < 3 * L; i++)
        V += fl_uf_find(d->corner, (uint32_t)i) == i;
    for (size_t i = 0; i < L; i++)
        C += fl_uf_find(d->comp, (uint32_t)i) == i;
    /* boundary loops: boundary half-edges joined at their end fans */
    for (size_t i = 0; i < L; i++) {
        uint32_t f = d->list[i];
        for (uint32_t j = 0; j < 3; j++) {
            if (d->loc[d->twin[3 * f + j] / 3] >= 0) continue;
            uint32_t me = 3 * (uint32_t)i + j;
            uint32_t ends[2] = {fl_uf_find(d->corner, me),
                                fl_uf_find(d->corner, 3 * (uint32_t)i + (j + 1) % 3)};
            for (int q = 0; q < 2; q++) {
                if (d->bfirst[ends[q]] == UINT32_MAX)
                    d->bfirst[ends[q]] = me;
                else
                    fl_uf_union(d->bloop, d->bfirst[ends[q]], me);
            }
        }
    }
    for (size_t i = 0; i < L; i++) {
        uint32_t f = d->list[i];
        for (uint32_t j = 0; j < 3; j++)
            if (d->loc[d->twin[3 * f + j] / 3] < 0)
                B += fl_uf_find(d->bloop, 3 * (uint32_t)i + j) == 3 * i + j;
    }
    long long chi = V - E + (long long)L;
    return 2 * C - chi - B;
}

typedef struct keyed {
    uint64_t key;
    uint32_t face;
} keyed;

static int keyed_cmp(const void *a, const void *b)
{
    const keyed *x = a, *y = b;
    if (x->key != y->key) return x->key < y->key ? -1 : 1;
    return x->face < y->face ? -1 : x->face > y->face;
}

static uint64_t cell_key(const int64_t q[3])
{
    return (uint64_t)q[2] << (2 * KEY_BITS) | (uint64_t)q[1] << KEY_BITS | (uint64_t)q[0];
}

/* b1 of the union of the balls that meet the box. A handle of the skin inside the box is a
 * tunnel of the skin body, whose loop round it lies in the box and in the body, hence in these
 * balls (body^t is inside the union), and is not contractible there since it is not in the
 * whole union: such a window has b1 >= its genus. A handle the grid made by bridging a gap has
 * no tunnel of the balls behind it. (A window whose balls close a loop elsewhere is skipped:
 * the test errs towards not refining.) */
static fl_status local_b1(defects *d, const skin_box *box, long long *b1, fl_error *err)
{
    d->sub.count = 0;
    for (size_t i = 0; i < d->n; i++) {
        const double *b = d->xyzw + 4 * i;
        if (!(b[3] > 0)) continue;
        double d2 = 0;
        for (int c = 0; c < 3; c++) {
            double e = fmax(fmax(box->lo[c] - b[c], b[c] - box->hi[c]), 0);
            d2 += e * e;
        }
        if (d2 < b[3] && fl_vec_push(&d->sub, b, 1)) return nomem(err);
    }
    long long betti[3] = {0, 0, 0};
    fl_status st = FL_OK;
    if (d->sub.count > 0) st = fl_balls_union_betti(d->sub.data, d->sub.count, betti, err);
    *b1 = betti[1];
    return st;
}

/* 1 when the window [lo, lo + side]^3 holds the centre of a box boxes[first..] of a finer band
 * (cell below h): the window's handle is that box's, boxed at its own size. */
static int holds_finer(const fl_vec *boxes, size_t first, const double lo[3], double side, double h)
{
    for (size_t i = first; i < boxes->count; i++) {
        const skin_box *b = (const skin_box *)boxes->data + i;
        if (!(b->h < h)) continue;
        int in = 1;
        for (int c = 0; c < 3; c++) {
            double m = (b->lo[c] + b->hi[c]) / 2;
            in &= m >= lo[c] && m <= lo[c] + side;
        }
        if (in) return 1;
    }
    return 0;
}

/* The windows of band L (faces of longest edge in [2^L, 2^(L+1)) lam0): side
 * 2 WINDOW_FACES 2^L lam0, stride half of it, each holding a band-L face; a window whose part
 * has genus becomes a box of cell lam0 2^L / 2. */
static fl_status band_windows(defects *d, int L, double lam0, const double lo[3],
                              const double hi[3], size_t first, fl_error *err)
{
    const fl_mesh *m = d->m;
    size_t F = m->triangle_count;
    double band = lam0 * ldexp(1, L), stride = WINDOW_FACES * band;
    for (int c = 0; c < 3; c++)
        if ((hi[c] - lo[c]) / stride >= (double)((1 << KEY_BITS) - 4))
            return FL_OK; /* too fine for the keys: this band's windows are not searched */
    u64map active;
    if (map_init(&active, 1024)) return nomem(err);
    fl_vec faces;
    fl_vec_init(&faces, sizeof(keyed));
    fl_status st = FL_OK;
    /* the windows (anchor cell a covers cells a + {0,1}^3) that hold a band-L face */
    for (size_t f = 0; f < F && !st; f++) {
        if (!(d->len[f] >= band && d->len[f] < 2 * band)) continue;
        int64_t q[3];
        for (int c = 0; c < 3; c++)
            q[c] = (int64_t)floor((d->cen[3 * f + c] - lo[c]) / stride) + 1;
        for (unsigned b = 0; b < 8; b++) {
            int64_t a[3] = {q[0] - (b & 1), q[1] - (b >> 1 & 1), q[2] - (b >> 2 & 1)};
            if (map_put(&active, cell_key(a), 0) == SIZE_MAX) st = nomem(err);
        }
    }
    /* every face in an active window, by cell */
    for (size_t f = 0; f < F && !st; f++) {
        int64_t q[3];
        for (int c = 0; c < 3; c++)
            q[c] = (int64_t)floor((d->cen[3 * f + c] - lo[c]) / stride) + 1;
        for (unsigned b = 0; b < 8; b++) {
            int64_t a[3] = {q[0] - (b & 1), q[1] - (b >> 1 & 1), q[2] - (b >> 2 & 1)};
            uint64_t k = cell_key(a);
            if (active.key[map_slot(&active, k)] != k) continue;
            keyed e = {cell_key(q), (uint32_t)f};
            if (fl_vec_push(&faces, &e, 1)) st = nomem(err);
            break;
        }
    }
    if (!st) qsort(faces.data, faces.count, sizeof(keyed), keyed_cmp);
    const keyed *fk = faces.data;
    /* each active window: its 8 cells' runs */
    for (size_t s = 0; s < active.cap && !st; s++) {
        uint64_t ak = active.key[s];
        if (ak == UINT64_MAX) continue;
        int64_t a[3] = {(int64_t)(ak & ((1u << KEY_BITS) - 1)),
                        (int64_t)(ak >> KEY_BITS & ((1u << KEY_BITS) - 1)),
                        (int64_t)(ak >> (2 * KEY_BITS))};
        size_t n = 0;
        for (unsigned b = 0; b < 8; b++) {
            int64_t q[3] = {a[0] + (b & 1), a[1] + (b >> 1 & 1), a[2] + (b >> 2 & 1)};
            uint64_t k = cell_key(q);
            size_t l = 0, r = faces.count; /* first entry >= k */
            while (l < r) {
                size_t mid = l + (r - l) / 2;
                if (fk[mid].key < k)
                    l = mid + 1;
                else
                    r = mid;
            }
            for (; l < faces.count && fk[l].key == k; l++) {
                d->loc[fk[l].face] = (int32_t)n;
                d->list[n++] = fk[l].face;
            }
        }
        skin_box box;
        for (int c = 0; c < 3; c++) {
            box.lo[c] = lo[c] + (double)(a[c] - 1) * stride;
            box.hi[c] = box.lo[c] + 2 * stride;
        }
        long long genus2 = 0, b1 = 0;
        if (n > 0 && !holds_finer(d->boxes, first, box.lo, 2 * stride, band / 2))
            genus2 = window_genus2(d, n);
        if (genus2 > 0) st = local_b1(d, &box, &b1, err);
        if (!st && genus2 > 2 * b1) {
            box.h = band;
            /* a window boxed before, still with a handle: half its cells again */
            for (size_t i = 0; i < first; i++) {
                const skin_box *o = (const skin_box *)d->boxes->data + i;
                int meet = 1;
                for (int c = 0; c < 3; c++)
                    meet &= o->lo[c] <= box.hi[c] && o->hi[c] >= box.lo[c];
                if (meet) box.h = fmin(box.h, o->h / 2);
            }
            if (fl_vec_push(d->boxes, &box, 1)) st = nomem(err);
        }
        for (size_t i = 0; i < n; i++)
            d->loc[d->list[i]] = -1;
    }
    map_free(&active);
    fl_vec_free(&faces);
    return st;
}

/* The `extra` components with the fewest faces: their bounding box grown by its size on every
 * side, cells of a quarter of its size (at most their longest edge). */
static fl_status small_components(defects *d, long long extra, fl_error *err)
{
    const fl_mesh *m = d->m;
    size_t F = m->triangle_count;
    uint32_t *comp = d->comp; /* over faces, sized F */
    for (size_t f = 0; f < F; f++)
        comp[f] = (uint32_t)f;
    for (size_t h = 0; h < 3 * F; h++)
        fl_uf_union(comp, (uint32_t)(h / 3), d->twin[h] / 3);
    /* count faces a root, then pick the smallest `extra` roots */
    uint32_t *size = calloc(F, sizeof *size);
    if (!size) return nomem(err);
    for (size_t f = 0; f < F; f++)
        size[fl_uf_find(comp, (uint32_t)f)]++;
    fl_status st = FL_OK;
    if (extra > MAX_BUBBLES) extra = MAX_BUBBLES;
    for (long long k = 0; k < extra && !st; k++) {
        uint32_t best = UINT32_MAX;
        for (size_t f = 0; f < F; f++)
            if (size[f] > 0 && (best == UINT32_MAX || size[f] < size[best])) best = (uint32_t)f;
        if (best == UINT32_MAX) break;
        size[best] = 0;
        skin_box box = {
            {HUGE_VAL, HUGE_VAL, HUGE_VAL}, {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}, HUGE_VAL};
        for (size_t f = 0; f < F; f++) {
            if (fl_uf_find(comp, (uint32_t)f) != best) continue;
            for (int c = 0; c < 3; c++) {
                box.lo[c] = fmin(box.lo[c], d->cen[3 * f + c]);
                box.hi[c] = fmax(box.hi[c], d->cen[3 * f + c]);
            }
            box.h = fmin(box.h, d->len[f]);
        }
        double ext = 0;
        for (int c = 0; c < 3; c++)
            ext = fmax(ext, box.hi[c] - box.lo[c]);
        ext = fmax(ext, box.h);
        for (int c = 0; c < 3; c++) {
            box.lo[c] -= ext;
            box.hi[c] += ext;
        }
        box.h = fmin(box.h, ext / 4);
        if (fl_vec_push(d->boxes, &box, 1)) st = nomem(err);
    }
    free(size);
    return st;
}

fl_status skin_mesh_defects(const fl_mesh *m, const double *xyzw, size_t n, int handles,
                            long long extra_components, fl_vec *boxes, fl_error *err)
{
    defects d;
    memset(&d, 0, sizeof d);
    d.m = m;
    d.boxes = boxes;
    d.xyzw = xyzw;
    d.n = n;
    fl_vec_init(&d.sub, 4 * sizeof(double));
    size_t F = m->triangle_count;
    if (F == 0) return FL_OK;
    if (F >= UINT32_MAX / 3)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1, "skin: mesh too large to inspect");
    fl_status st = setup(&d, err);
    d.loc = fl_alloc_array(F, sizeof *d.loc);
    d.list = fl_alloc_array(F, sizeof *d.list);
    d.comp = fl_alloc_array(F, sizeof *d.comp);
    d.corner = fl_alloc_array(F, 3 * sizeof *d.corner);
    d.bloop = fl_alloc_array(F, 3 * sizeof *d.bloop);
    d.bfirst = fl_alloc_array(F, 3 * sizeof *d.bfirst);
    if (!st && (!d.loc || !d.list || !d.comp || !d.corner || !d.bloop || !d.bfirst))
        st = nomem(err);
    if (!st) {
        for (size_t f = 0; f < F; f++)
            d.loc[f] = -1;
        double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
        double lam0 = HUGE_VAL, lam1 = 0;
        for (size_t f = 0; f < F; f++) {
            for (int c = 0; c < 3; c++) {
                lo[c] = fmin(lo[c], d.cen[3 * f + c]);
                hi[c] = fmax(hi[c], d.cen[3 * f + c]);
            }
            if (d.len[f] > 0) lam0 = fmin(lam0, d.len[f]);
            lam1 = fmax(lam1, d.len[f]);
        }
        size_t first = boxes->count;
        /* the finest band with a handle only: a coarser one's may be the skin's own, and the
         * next round sees whether any is left */
        for (int L = 0; handles && !st && lam0 < HUGE_VAL && lam0 * ldexp(1, L) <= lam1 && L < 64 &&
                        boxes->count == first;
             L++)
            st = band_windows(&d, L, lam0, lo, hi, first, err);
    }
    if (!st && extra_components > 0) st = small_components(&d, extra_components, err);
    free(d.twin);
    free(d.cen);
    free(d.len);
    free(d.loc);
    free(d.list);
    free(d.comp);
    free(d.corner);
    free(d.bloop);
    free(d.bfirst);
    fl_vec_free(&d.sub);
    return st;
}
