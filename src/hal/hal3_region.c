/* Cutting open polyhedra along shortest edge paths (thesis §7.3.2).
 *
 * A piece is a set of original triangles and the loop of edge paths around it. A cut computes a
 * shortest path of mesh edges (Dijkstra, Euclidean edge lengths) between two corners of the
 * loop, inside the piece, and splits the piece in two. Which triangle goes to which side is
 * decided topologically, never geometrically: each new loop seeds the triangles that own its
 * directed edges (the surface is oriented, so a directed edge a->b belongs to exactly one
 * triangle, the one on its left), and a flood fill that never crosses a loop or path edge
 * carries the labels over the rest of the piece. A loop that runs out and back along the same
 * edges (paths that partly coincide, "coalescing paths", Fig. 7.12) seeds nothing there: both
 * directions of such an edge cancel. The paths first avoid every loop vertex (so loops stay
 * simple), then, only when the piece is pinched, every corner, then nothing. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"
#include "hal/hal3_internal.h"

void hal3_piece_free(hal3_piece *pc)
{
    free(pc->faces);
    free(pc->loop);
    memset(pc, 0, sizeof *pc);
}

fl_status hal3_work_init(hal3_work *w, const fl_mesh *mesh, const fl_halfedges *he)
{
    memset(w, 0, sizeof *w);
    w->mesh = mesh;
    w->he = he;
    size_t nt = mesh->triangle_count, nv = mesh->vertex_count, ne = he->edge_count;
    w->heap_cap = 6 * nt + 16;
    w->face_mark = fl_calloc_array(nt, sizeof(uint32_t));
    w->edge_mark = fl_calloc_array(ne, sizeof(uint32_t));
    w->vert_mark = fl_calloc_array(nv, sizeof(uint32_t));
    w->vert_block = fl_calloc_array(nv, sizeof(uint32_t));
    w->dist_mark = fl_calloc_array(nv, sizeof(uint32_t));
    w->seed_a = fl_calloc_array(3 * nt, sizeof(uint32_t));
    w->seed_b = fl_calloc_array(3 * nt, sizeof(uint32_t));
    w->label = fl_calloc_array(nt, 1);
    w->dist = fl_alloc_array(nv, sizeof(double));
    w->pred = fl_alloc_array(nv, sizeof(uint32_t));
    w->heap_v = fl_alloc_array(w->heap_cap, sizeof(uint32_t));
    w->heap_d = fl_alloc_array(w->heap_cap, sizeof(double));
    w->queue = fl_alloc_array(nt + 1, sizeof(uint32_t));
    if (!w->face_mark || !w->edge_mark || !w->vert_mark || !w->vert_block || !w->dist_mark ||
        !w->seed_a || !w->seed_b || !w->label || !w->dist || !w->pred || !w->heap_v || !w->heap_d ||
        !w->queue) {
        hal3_work_free(w);
        return FL_ERR_NOMEM;
    }
    return FL_OK;
}

void hal3_work_free(hal3_work *w)
{
    free(w->face_mark);
    free(w->edge_mark);
    free(w->vert_mark);
    free(w->vert_block);
    free(w->dist_mark);
    free(w->seed_a);
    free(w->seed_b);
    free(w->label);
    free(w->dist);
    free(w->pred);
    free(w->heap_v);
    free(w->heap_d);
    free(w->queue);
    memset(w, 0, sizeof *w);
}

uint32_t hal3_halfedge(const hal3_work *w, uint32_t a, uint32_t b)
{
    const fl_halfedges *he = w->he;
    for (uint32_t c = he->vertex_start[a]; c < he->vertex_start[a + 1]; c++) {
        uint32_t h = he->vertex_corners[c];
        if (he->tri[fl_he_next(h)] == b) return h;
    }
    return FL_HAL3_NONE;
}

static uint32_t edge_of(const hal3_work *w, uint32_t a, uint32_t b)
{
    uint32_t h = hal3_halfedge(w, a, b);
    if (h == FL_HAL3_NONE) h = hal3_halfedge(w, b, a);
    return h == FL_HAL3_NONE ? FL_HAL3_NONE : w->he->halfedge_edge[h];
}

/* ---- Dijkstra over the piece marked with stamp rs ---- */

static void heap_push(hal3_work *w, size_t *n, uint32_t v, double d)
{
    size_t i = (*n)++;
    while (i > 0) {
        size_t p = (i - 1) / 2;
        if (w->heap_d[p] <= d) break;
        w->heap_d[i] = w->heap_d[p];
        w->heap_v[i] = w->heap_v[p];
        i = p;
    }
    w->heap_d[i] = d;
    w->heap_v[i] = v;
}

static uint32_t heap_pop(hal3_work *w, size_t *n, double *d)
{
    uint32_t top = w->heap_v[0];
    *d = w->heap_d[0];
    double ld = w->heap_d[--*n];
    uint32_t lv = w->heap_v[*n];
    size_t i = 0;
    for (;;) {
        size_t c = 2 * i + 1;
        if (c >= *n) break;
        if (c + 1 < *n && w->heap_d[c + 1] < w->heap_d[c]) c++;
        if (w->heap_d[c] >= ld) break;
        w->heap_d[i] = w->heap_d[c];
        w->heap_v[i] = w->heap_v[c];
        i = c;
    }
    w->heap_d[i] = ld;
    w->heap_v[i] = lv;
    return top;
}

static double edge_length(const fl_mesh *m, uint32_t a, uint32_t b)
{
    const double *p = m->xyz + 3 * (size_t)a, *q = m->xyz + 3 * (size_t)b;
    return sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                (p[2] - q[2]) * (p[2] - q[2]));
}

/* An edge is in the piece when one of its triangles is, or when it is on the loop/a path. */
static int edge_usable(const hal3_work *w, uint32_t h, uint32_t rs)
{
    const fl_halfedges *he = w->he;
    if (w->edge_mark[he->halfedge_edge[h]] == rs || w->face_mark[h / 3] == rs) return 1;
    uint32_t t = he->twin[h];
    return t != FL_HE_NONE && w->face_mark[t / 3] == rs;
}

/* Shortest paths from src to the nt targets. mode 0: loop vertices (vert_mark == rs) and
 * blocked vertices (vert_block == rs) are not passed through; mode 1: only blocked ones;
 * mode 2: nothing is. Returns 1 when every target was reached (pred then holds the tree). */
static int dijkstra(hal3_work *w, uint32_t rs, uint32_t src, const uint32_t *tg, int nt, int mode)
{
    const fl_halfedges *he = w->he;
    uint32_t ds = ++w->stamp;
    size_t n = 0;
    int left = nt;
    w->dist_mark[src] = ds;
    w->dist[src] = 0;
    w->pred[src] = FL_HAL3_NONE;
    heap_push(w, &n, src, 0);
    while (n > 0 && left > 0) {
        double d;
        uint32_t v = heap_pop(w, &n, &d);
        if (d > w->dist[v]) continue;
        for (int k = 0; k < nt; k++)
            if (tg[k] == v) left--;
        if (v != src &&
            ((mode < 2 && w->vert_block[v] == rs) || (mode == 0 && w->vert_mark[v] == rs)))
            continue;
        for (uint32_t c = he->vertex_start[v]; c < he->vertex_start[v + 1]; c++) {
            uint32_t h = he->vertex_corners[c];
            uint32_t hs[2] = {h, fl_he_prev(h)};
            uint32_t nb[2] = {he->tri[fl_he_next(h)], he->tri[fl_he_prev(h)]};
            for (int s = 0; s < 2; s++) {
                if (!edge_usable(w, hs[s], rs)) continue;
                uint32_t u = nb[s];
                double nd = d + edge_length(w->mesh, v, u);
                if (w->dist_mark[u] == ds && w->dist[u] <= nd) continue;
                if (n >= w->heap_cap) return 0;
                w->dist_mark[u] = ds;
                w->dist[u] = nd;
                w->pred[u] = v;
                heap_push(w, &n, u, nd);
            }
        }
    }
    return left <= 0;
}

static int shortest_tree(hal3_work *w, uint32_t rs, uint32_t src, const uint32_t *tg, int nt)
{
    for (int mode = 0; mode < 3; mode++)
        if (dijkstra(w, rs, src, tg, nt, mode)) return 1;
    return 0;
}

/* Appends the tree path src -> t (src first) to out (room for nv entries); its length. */
static size_t tree_path(const hal3_work *w, uint32_t t, uint32_t *out)
{
    size_t n = 0;
    for (uint32_t v = t; v != FL_HAL3_NONE; v = w->pred[v])
        out[n++] = v;
    for (size_t i = 0; i < n / 2; i++) {
        uint32_t x = out[i];
        out[i] = out[n - 1 - i];
        out[n - 1 - i] = x;
    }
    return n;
}

/* ---- labelling ---- */

static int mark_loop_edges(hal3_work *w, const uint32_t *loop, size_t n, uint32_t rs)
{
    for (size_t i = 0; i < n; i++) {
        uint32_t e = edge_of(w, loop[i], loop[(i + 1) % n]);
        if (e == FL_HAL3_NONE) return -1;
        w->edge_mark[e] = rs;
    }
    return 0;
}

/* Seeds label `lab` from the directed edges of loop (stamp st in seeds[]), cancelling edges
 * used in both directions. Returns -1 on a conflict. */
static int seed_loop(hal3_work *w, uint32_t *seeds, const uint32_t *loop, size_t n, uint32_t rs,
                     uint8_t lab, size_t *qn)
{
    uint32_t st = ++w->stamp;
    for (size_t i = 0; i < n; i++)
        seeds[hal3_halfedge(w, loop[i], loop[(i + 1) % n])] = st;
    for (size_t i = 0; i < n; i++) {
        uint32_t h = hal3_halfedge(w, loop[i], loop[(i + 1) % n]);
        uint32_t r = hal3_halfedge(w, loop[(i + 1) % n], loop[i]);
        if (r != FL_HAL3_NONE && seeds[r] == st) continue;
        uint32_t f = h / 3;
        if (w->face_mark[f] != rs) continue;
        if (w->label[f] == lab) continue;
        if (w->label[f] != 0) return -1;
        w->label[f] = lab;
        w->queue[(*qn)++] = f;
    }
    return 0;
}

/* Labels the faces (marked rs, cut edges marked rs) 1 from loop A and 2 from loop B; then
 * distributes them. */
static fl_status partition(hal3_work *w, const uint32_t *faces, size_t nf, uint32_t rs,
                           hal3_piece *a, hal3_piece *b, fl_error *err)
{
    const fl_halfedges *he = w->he;
    for (size_t i = 0; i < nf; i++)
        w->label[faces[i]] = 0;
    size_t qn = 0;
    if (seed_loop(w, w->seed_a, a->loop, a->nl, rs, 1, &qn) ||
        seed_loop(w, w->seed_b, b->loop, b->nl, rs, 2, &qn))
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                       "hal3: a triangle lies on both sides of a cut");
    for (size_t qi = 0; qi < qn; qi++) {
        uint32_t f = w->queue[qi];
        for (uint32_t k = 0; k < 3; k++) {
            uint32_t h = 3 * f + k;
            if (w->edge_mark[he->halfedge_edge[h]] == rs || he->twin[h] == FL_HE_NONE) continue;
            uint32_t g = he->twin[h] / 3;
            if (w->face_mark[g] != rs) continue;
            if (w->label[g] == 0) {
                w->label[g] = w->label[f];
                w->queue[qn++] = g;
            } else if (w->label[g] != w->label[f]) {
                return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                               "hal3: the two sides of a cut are connected");
            }
        }
    }
    if (qn != nf)
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                       "hal3: %zu triangles were reached by neither side of a cut", nf - qn);
    size_t na = 0;
    for (size_t i = 0; i < nf; i++)
        na += w->label[faces[i]] == 1;
    a->faces = fl_alloc_array(na + 1, sizeof(uint32_t));
    b->faces = fl_alloc_array(nf - na + 1, sizeof(uint32_t));
    if (!a->faces || !b->faces) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
    for (size_t i = 0; i < nf; i++) {
        if (w->label[faces[i]] == 1)
            a->faces[a->nf++] = faces[i];
        else
            b->faces[b->nf++] = faces[i];
    }
    return FL_OK;
}

/* ---- cuts ---- */

/* Splits pc's loop at corners u < wc, which are at the same vertex. */
static fl_status pinch(hal3_work *w, const hal3_piece *pc, int u, int wc, uint32_t rs,
                       hal3_piece *a, hal3_piece *b, fl_error *err)
{
    size_t pu = pc->cpos[u], pw = pc->cpos[wc];
    a->nl = pw - pu;
    b->nl = pc->nl - a->nl;
    a->loop = fl_alloc_array(a->nl + 1, sizeof(uint32_t));
    b->loop = fl_alloc_array(b->nl + 1, sizeof(uint32_t));
    if (!a->loop || !b->loop) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
    size_t k = 0;
    for (size_t i = pu; i < pw; i++)
        a->loop[k++] = pc->loop[i];
    k = 0;
    for (size_t i = pw; i < pc->nl; i++)
        b->loop[k++] = pc->loop[i];
    for (size_t i = 0; i < pu; i++)
        b->loop[k++] = pc->loop[i];
    for (int i = u; i < wc; i++)
        a->cpos[a->nc++] = pc->cpos[i] - (uint32_t)pu;
    for (int i = wc; i < pc->nc; i++)
        b->cpos[b->nc++] = pc->cpos[i] - (uint32_t)pw;
    for (int i = 0; i < u; i++)
        b->cpos[b->nc++] = pc->cpos[i] + (uint32_t)(pc->nl - pw);
    return partition(w, pc->faces, pc->nf, rs, a, b, err);
}

fl_status hal3_cut(hal3_work *w, const hal3_piece *pc, int u, int wc, uint32_t via, hal3_piece *a,
                   hal3_piece *b, fl_error *err)
{
    memset(a, 0, sizeof *a);
    memset(b, 0, sizeof *b);
    uint32_t rs = ++w->stamp;
    for (size_t i = 0; i < pc->nf; i++)
        w->face_mark[pc->faces[i]] = rs;
    for (size_t i = 0; i < pc->nl; i++)
        w->vert_mark[pc->loop[i]] = rs;
    for (int i = 0; i < pc->nc; i++)
        w->vert_block[pc->loop[pc->cpos[i]]] = rs;
    if (mark_loop_edges(w, pc->loop, pc->nl, rs))
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "hal3: a loop edge is not a mesh edge");
    size_t pu = pc->cpos[u], pw = pc->cpos[wc];
    uint32_t vu = pc->loop[pu], vw = pc->loop[pw];
    size_t nv = w->mesh->vertex_count;
    uint32_t *path = fl_alloc_array(2 * nv + 2, sizeof(uint32_t));
    if (!path) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
    size_t len, iv = 0;
    if (vu == vw) {
        /* Two corners at one vertex (a side split where paths coalesce): the loop is split
         * there without a new path. */
        free(path);
        return pinch(w, pc, u, wc, rs, a, b, err);
    }
    if (via == FL_HAL3_NONE) {
        if (!shortest_tree(w, rs, vu, &vw, 1)) goto nopath;
        len = tree_path(w, vw, path);
    } else {
        /* via -> vu first; via -> vw then avoids that path, so the cut is a simple path
         * (paths sharing a prefix would leave a corner at the end of a slit). */
        if (!shortest_tree(w, rs, via, &vu, 1)) goto nopath;
        size_t l1 = tree_path(w, vu, path); /* via .. vu, reversed below to vu .. via */
        for (size_t i = 1; i < l1; i++)
            w->vert_block[path[i]] = rs;
        if (!shortest_tree(w, rs, via, &vw, 1)) goto nopath;
        for (size_t i = 0; i < l1 / 2; i++) {
            uint32_t x = path[i];
            path[i] = path[l1 - 1 - i];
            path[l1 - 1 - i] = x;
        }
        iv = l1 - 1;
        len = l1 - 1 + tree_path(w, vw, path + l1 - 1);
    }
    for (size_t i = 0; i + 1 < len; i++)
        w->edge_mark[edge_of(w, path[i], path[i + 1])] = rs;
    size_t in = len >= 2 ? len - 2 : 0; /* interior vertices of the path */
    a->nl = pw - pu + 1 + in;
    b->nl = pc->nl - (pw - pu) + 1 + in;
    a->loop = fl_alloc_array(a->nl, sizeof(uint32_t));
    b->loop = fl_alloc_array(b->nl, sizeof(uint32_t));
    if (!a->loop || !b->loop) {
        free(path);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
    }
    size_t k = 0;
    for (size_t i = pu; i <= pw; i++)
        a->loop[k++] = pc->loop[i];
    for (size_t i = 0; i < in; i++)
        a->loop[k++] = path[len - 2 - i];
    for (int i = u; i <= wc; i++)
        a->cpos[a->nc++] = pc->cpos[i] - (uint32_t)pu;
    if (via != FL_HAL3_NONE) a->cpos[a->nc++] = (uint32_t)(pw - pu + 1 + (len - 2 - iv));
    k = 0;
    for (size_t i = pw; i < pc->nl; i++)
        b->loop[k++] = pc->loop[i];
    for (size_t i = 0; i <= pu; i++)
        b->loop[k++] = pc->loop[i];
    for (size_t i = 0; i < in; i++)
        b->loop[k++] = path[1 + i];
    for (int i = wc; i < pc->nc; i++)
        b->cpos[b->nc++] = pc->cpos[i] - (uint32_t)pw;
    for (int i = 0; i <= u; i++)
        b->cpos[b->nc++] = pc->cpos[i] + (uint32_t)(pc->nl - pw);
    if (via != FL_HAL3_NONE) b->cpos[b->nc++] = (uint32_t)(pc->nl - pw + pu + 1 + (iv - 1));
    free(path);
    return partition(w, pc->faces, pc->nf, rs, a, b, err);
nopath:
    free(path);
    return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                   "hal3: no edge path inside an open polyhedron between vertices %u and %u", vu,
                   vw);
}

fl_status hal3_cut_sphere(hal3_work *w, uint32_t i, uint32_t j, uint32_t k, hal3_piece *a,
                          hal3_piece *b, fl_error *err)
{
    memset(a, 0, sizeof *a);
    memset(b, 0, sizeof *b);
    size_t nt = w->mesh->triangle_count, nv = w->mesh->vertex_count;
    uint32_t rs = ++w->stamp;
    uint32_t *faces = fl_alloc_array(nt, sizeof(uint32_t));
    uint32_t *cyc = fl_alloc_array(3 * nv + 3, sizeof(uint32_t));
    fl_status st = FL_OK;
    if (!faces || !cyc) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
        goto done;
    }
    for (size_t f = 0; f < nt; f++) {
        faces[f] = (uint32_t)f;
        w->face_mark[f] = rs;
    }
    /* i -> j avoiding k; j -> k avoiding i and the first path; k -> i avoiding both paths, so
     * that the cycle is simple and splits the sphere into two discs (mode 0 blocks marked
     * vertices; the fallbacks only matter for pinched surfaces). */
    uint32_t ends[4] = {i, j, k, i};
    size_t n = 0;
    w->vert_mark[k] = rs;
    w->vert_block[k] = rs;
    for (int s = 0; s < 3; s++) {
        if (s == 1) w->vert_block[i] = rs;
        if (s == 2) w->vert_block[j] = rs;
        if (!shortest_tree(w, rs, ends[s], &ends[s + 1], 1)) {
            st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "hal3: the surface is not connected");
            goto done;
        }
        size_t l = tree_path(w, ends[s + 1], cyc + n);
        for (size_t t = 0; t < l; t++)
            w->vert_mark[cyc[n + t]] = rs;
        n += l - 1; /* the end vertex starts the next path */
    }
    if (mark_loop_edges(w, cyc, n, rs)) {
        st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "hal3: a path edge is not a mesh edge");
        goto done;
    }
    size_t pj = 0, pk = 0;
    for (size_t t = 1; t < n; t++) {
        if (cyc[t] == j && !pj) pj = t;
        if (cyc[t] == k && pj && !pk) pk = t;
    }
    a->loop = fl_alloc_array(n, sizeof(uint32_t));
    b->loop = fl_alloc_array(n, sizeof(uint32_t));
    if (!a->loop || !b->loop) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "hal3: out of memory");
        goto done;
    }
    a->nl = b->nl = n;
    for (size_t t = 0; t < n; t++) {
        a->loop[t] = cyc[t];
        b->loop[t] = cyc[(n - t) % n];
    }
    a->nc = b->nc = 3;
    a->cpos[0] = 0, a->cpos[1] = (uint32_t)pj, a->cpos[2] = (uint32_t)pk;
    b->cpos[0] = 0, b->cpos[1] = (uint32_t)(n - pk), b->cpos[2] = (uint32_t)(n - pj);
    st = partition(w, faces, nt, rs, a, b, err);
done:
    free(faces);
    free(cyc);
    return st;
}
