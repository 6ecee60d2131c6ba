/* 2D Delaunay triangulation by incremental insertion (Bowyer-Watson) in BRIO order.
 *
 * The triangulation is kept as a triangulation of the sphere: every hull edge ab carries a
 * "ghost" triangle (a, b, GHOST) whose third vertex is a point at infinity, so hull edges need
 * no special case in point location or in the cavity search. Triangles live in one flat array
 * of 24-byte records (three vertices, three neighbour codes); a neighbour code is
 * (triangle << 2) | (edge index in that triangle), so crossing an edge never searches.
 *
 * Decisions (docs/delaunay.md, "## 2D"):
 *  - a real triangle abc is in conflict with p iff fl_incircle_sos(a,b,c,p) > 0: cocircular
 *    ties are broken by symbolic perturbation, consistently for the whole run;
 *  - a ghost triangle over the hull edge ab is in conflict with p iff p is strictly outside ab
 *    (exact fl_orient2d > 0) or in the open segment ab. This is the limit of the in-circle test
 *    as the third vertex goes to infinity, with points on the segment counted inside (they are
 *    strictly inside the circle of the real triangle across ab, so leaving the ghost out would
 *    create a flat triangle). Orientation is never perturbed, so no triangle is ever flat.
 * With these rules the conflict region of p is a connected, simply connected set of triangles
 * without interior vertices that is star-shaped from p; Bowyer-Watson replaces it by the fan of
 * p and its boundary edges. */
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay_internal.h"

#define GHOST (UINT32_MAX - 1) /* the vertex at infinity */
#define MAX_POINTS (1u << 29)  /* triangle << 2 must fit in 32 bits: 2n triangles < 2^30 */
#define PROGRESS_EVERY 65536

/* A triangle: vertices counterclockwise and, across the edge opposite corner k, the neighbour
 * code (triangle << 2) | (index of that edge in the neighbour). One 24-byte record, so that a
 * walk or cavity step usually touches a single cache line. */
typedef struct dt2_tri {
    uint32_t v[3];
    uint32_t nb[3];
} dt2_tri;

/* Inside the builder a vertex is its rank in the insertion order: the coordinates are copied in
 * that order, so the points a walk or cavity touches are close in memory as well as in space
 * (input indices of spatial neighbours are scattered). SoS still uses the input indices, so the
 * perturbation is the one fl_dt2_verify and other callers see. */
typedef struct dt2_builder {
    double *xy;         /* 2 per rank */
    const uint32_t *id; /* rank -> input index */
    dt2_tri *tri;
    size_t count, capacity;
    uint32_t *stack;    /* cavity-search frames: (triangle, next edge | edges left << 2) */
    uint32_t *cavity;   /* triangles of the cavity */
    uint32_t *boundary; /* (a, b, outside code) triples, in cyclic order */
    size_t stack_cap, cavity_cap, boundary_cap;
    uint32_t last; /* a real triangle near the last inserted point: the next walk's start */
    uint64_t rng;  /* for the stochastic walk */
} dt2_builder;

static inline int is_ghost(const dt2_tri *t)
{
    return t->v[0] == GHOST || t->v[1] == GHOST || t->v[2] == GHOST;
}

static inline const double *pt(const dt2_builder *b, uint32_t i)
{
    return b->xy + 2 * (size_t)i;
}

static inline void link(dt2_tri *tri, uint32_t t, int e, uint32_t u, int f)
{
    tri[t].nb[e] = (u << 2) | (uint32_t)f;
    tri[u].nb[f] = (t << 2) | (uint32_t)e;
}

/* p strictly inside the segment ab, for p on the line through a and b: compare along an axis
 * on which a and b differ (exact). */
static int strictly_between(const double *a, const double *b, const double *p)
{
    int k = a[0] != b[0] ? 0 : 1;
    double lo = a[k] < b[k] ? a[k] : b[k], hi = a[k] < b[k] ? b[k] : a[k];
    return lo < p[k] && p[k] < hi;
}

static int in_conflict(const dt2_builder *b, const dt2_tri *t, uint32_t p)
{
    const uint32_t *v = t->v;
    const double *q = pt(b, p);
    int k = v[0] == GHOST ? 0 : v[1] == GHOST ? 1 : v[2] == GHOST ? 2 : -1;
    if (k < 0)
        return fl_incircle_sos(pt(b, v[0]), pt(b, v[1]), pt(b, v[2]), q, b->id[v[0]], b->id[v[1]],
                               b->id[v[2]], b->id[p]) > 0;
    /* Ghost (a, c, GHOST): the real triangle across ac is (c, a, x), so outside is left of ac. */
    const double *a = pt(b, v[(k + 1) % 3]), *c = pt(b, v[(k + 2) % 3]);
    int o = fl_orient2d(a, c, q);
    return o > 0 || (o == 0 && strictly_between(a, c, q));
}

/* Visibility walk from the last real triangle towards p (Devillers, Pion, Teillaud, "Walking in
 * a triangulation", 2002). The first edge tried is random (stochastic walk), which makes the walk
 * terminate with probability 1 on any triangulation; the edge just crossed is not retested.
 * Returns a triangle in conflict with p: a real triangle whose closure contains p (p is then
 * strictly inside its circumcircle, as p is not a vertex), or a ghost whose hull edge p sees. */
static uint32_t locate(dt2_builder *b, uint32_t p)
{
    const double *q = pt(b, p);
    uint32_t t = b->last, came_from = 3; /* edge index of t we entered through, 3 = none */
    for (;;) {
        b->rng ^= b->rng << 13;
        b->rng ^= b->rng >> 7;
        b->rng ^= b->rng << 17;
        uint32_t first = (uint32_t)(b->rng % 3), e;
        const dt2_tri *tr = b->tri + t;
        for (e = 0; e < 3; e++) {
            uint32_t k = first + e < 3 ? first + e : first + e - 3;
            if (k == came_from) continue;
            const uint32_t *v = tr->v;
            if (fl_orient2d(pt(b, v[k == 2 ? 0 : k + 1]), pt(b, v[k == 0 ? 2 : k - 1]), q) < 0) {
                t = tr->nb[k] >> 2;
                came_from = tr->nb[k] & 3;
                break;
            }
        }
        if (e == 3 || is_ghost(b->tri + t)) return t; /* a ghost: p is outside its hull edge */
    }
}

/* Makes room for `need` entries; on failure the buffer is left as it was. */
static int grow(uint32_t **a, size_t *cap, size_t need)
{
    if (need <= *cap) return 0;
    size_t c = *cap ? *cap : 64;
    while (c < need)
        c *= 2;
    uint32_t *p = fl_realloc_array(*a, c, sizeof *p);
    if (!p) return -1;
    *a = p;
    *cap = c;
    return 0;
}

/* Collects the conflict region of p, found depth first from t0, and its boundary edges, each
 * with its two vertices and the code of the triangle outside. The region is a tree of
 * triangles (it has no interior vertex), so no triangle is reached twice and no marks are
 * needed; looking across the edges of each triangle in counterclockwise order, starting after
 * the edge we came in by, emits the boundary in counterclockwise order around p. A region
 * larger than the triangulation would mean a cycle, which the theory excludes: reported. */
static int find_cavity(dt2_builder *b, uint32_t t0, uint32_t p, size_t *ncav, size_t *nbnd)
{
    size_t top = 0, nc = 0, nb = 0;
    b->stack[top++] = t0;
    b->stack[top++] = 0 | 3u << 2; /* edge 0 next, 3 edges left */
    b->cavity[nc++] = t0;
    while (top > 0) {
        uint32_t frame = b->stack[top - 1], e = frame & 3, left = frame >> 2;
        if (left == 0) {
            top -= 2;
            continue;
        }
        const dt2_tri *t = b->tri + b->stack[top - 2];
        b->stack[top - 1] = (e == 2 ? 0 : e + 1) | (left - 1) << 2;
        uint32_t code = t->nb[e], u = code >> 2;
        if (in_conflict(b, b->tri + u, p)) {
            if (nc >= b->count) return -2;
            if (grow(&b->stack, &b->stack_cap, top + 2) || grow(&b->cavity, &b->cavity_cap, nc + 1))
                return -1;
            uint32_t entry = code & 3; /* skip the edge back to t: 2 edges left */
            b->stack[top++] = u;
            b->stack[top++] = (entry == 2 ? 0 : entry + 1) | 2u << 2;
            b->cavity[nc++] = u;
        } else {
            if (grow(&b->boundary, &b->boundary_cap, 3 * nb + 3)) return -1;
            b->boundary[3 * nb] = t->v[e == 2 ? 0 : e + 1];
            b->boundary[3 * nb + 1] = t->v[e == 0 ? 2 : e - 1];
            b->boundary[3 * nb + 2] = code;
            nb++;
        }
    }
    *ncav = nc;
    *nbnd = nb;
    return 0;
}

/* Replaces the cavity by the fan of p over its boundary edges: new triangle (a, b, p) for the
 * boundary edge a -> b. A disk of c triangles without interior vertices has c + 2 boundary
 * edges, so the cavity's slots are reused and two triangles are appended. Consecutive boundary
 * edges share a vertex, so consecutive fan triangles are neighbours. */
static void fill_cavity(dt2_builder *b, uint32_t p, size_t ncav, size_t nbnd)
{
    uint32_t first = 0, prev = 0;
    for (size_t i = 0; i < nbnd; i++) {
        uint32_t s = i < ncav ? b->cavity[i] : (uint32_t)b->count++;
        const uint32_t *bd = b->boundary + 3 * i;
        dt2_tri *t = b->tri + s;
        t->v[0] = bd[0];
        t->v[1] = bd[1];
        t->v[2] = p;
        link(b->tri, s, 2, bd[2] >> 2, (int)(bd[2] & 3));
        if (bd[0] != GHOST && bd[1] != GHOST) b->last = s;
        /* This triangle's edge p -> a (opposite corner 1) is the previous one's a -> p. */
        if (i == 0)
            first = s;
        else
            link(b->tri, prev, 0, s, 1);
        prev = s;
    }
    link(b->tri, prev, 0, first, 1);
}

static fl_status insert(dt2_builder *b, uint32_t p, fl_error *err)
{
    uint32_t t0 = locate(b, p);
    size_t ncav = 0, nbnd = 0;
    int found = find_cavity(b, t0, p, &ncav, &nbnd);
    if (found == -1)
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "no memory for the insertion cavity");
    if (found != 0 || nbnd != ncav + 2 || b->count + 2 > b->capacity)
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                       "internal error: the cavity of point %u is not a disk", (unsigned)p);
    fill_cavity(b, p, ncav, nbnd);
    return FL_OK;
}

/* The first triangle: a, c1, c2 counterclockwise, and one ghost per edge. */
static void start_triangulation(dt2_builder *b, uint32_t a, uint32_t c1, uint32_t c2)
{
    uint32_t init[4][3] = {{a, c1, c2}, {c2, c1, GHOST}, {a, c2, GHOST}, {c1, a, GHOST}};
    for (int t = 0; t < 4; t++)
        memcpy(b->tri[t].v, init[t], sizeof init[t]);
    b->count = 4;
    /* Match every directed edge x -> y with its reverse y -> x. */
    for (uint32_t t = 0; t < 4; t++)
        for (int e = 0; e < 3; e++)
            for (uint32_t u = t + 1; u < 4; u++)
                for (int f = 0; f < 3; f++)
                    if (init[t][(e + 1) % 3] == init[u][(f + 2) % 3] &&
                        init[t][(e + 2) % 3] == init[u][(f + 1) % 3])
                        link(b->tri, t, e, u, f);
    b->last = 0;
}

/* Finds three non-collinear points among the first of `order` and moves the third to position
 * 2; returns 0 when all points are collinear. */
static int choose_first_triangle(const double *xy, uint32_t *order, size_t m)
{
    for (size_t j = 2; j < m; j++) {
        int o = fl_orient2d(xy + 2 * (size_t)order[0], xy + 2 * (size_t)order[1],
                            xy + 2 * (size_t)order[j]);
        if (o == 0) continue;
        uint32_t t = order[2];
        order[2] = order[j];
        order[j] = t;
        if (o < 0) {
            t = order[0];
            order[0] = order[1];
            order[1] = t;
        }
        return 1;
    }
    return 0;
}

static void builder_free(dt2_builder *b)
{
    free(b->xy);
    free(b->tri);
    free(b->stack);
    free(b->cavity);
    free(b->boundary);
}

/* Triangles with ghosts: a sphere triangulation of m + 1 vertices has 2(m + 1) - 4 faces, so
 * `tri` (from fl_dt2_build, room for 2m) never grows. The coordinate copy gets 24 bytes a point
 * rather than 16 because its memory becomes the output adjacency (see extract). */
static int builder_init(dt2_builder *b, const double *xy, const uint32_t *order, size_t m,
                        dt2_tri *tri)
{
    memset(b, 0, sizeof *b);
    b->id = order;
    b->xy = fl_alloc_array(m, 3 * sizeof *b->xy);
    b->capacity = 2 * m;
    b->tri = tri;
    b->rng = 0x2545F4914F6CDD1DULL;
    if (b->xy)
        for (size_t i = 0; i < m; i++) {
            b->xy[2 * i] = xy[2 * (size_t)order[i]];
            b->xy[2 * i + 1] = xy[2 * (size_t)order[i] + 1];
        }
    if (!b->xy || !b->tri || grow(&b->stack, &b->stack_cap, 128) ||
        grow(&b->cavity, &b->cavity_cap, 64) || grow(&b->boundary, &b->boundary_cap, 192))
        return -1;
    return 0;
}

static void compute_circumcenters(const double *xy, const uint32_t *tri, size_t count, double *cc)
{
    for (size_t t = 0; t < count; t++) {
        const double *a = xy + 2 * (size_t)tri[3 * t], *p = xy + 2 * (size_t)tri[3 * t + 1],
                     *q = xy + 2 * (size_t)tri[3 * t + 2];
        /* Relative to a, which keeps the rounding error proportional to the triangle's size. */
        double bx = p[0] - a[0], by = p[1] - a[1], cx = q[0] - a[0], cy = q[1] - a[1];
        double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy, d = 2.0 * (bx * cy - by * cx);
        cc[2 * t] = a[0] + (cy * b2 - by * c2) / d;
        cc[2 * t + 1] = a[1] + (bx * c2 - cx * b2) / d;
    }
}

/* Hull: from ghost (a, b, GHOST) (hull traversed b -> a), the ghost across the edge GHOST -> a
 * is (c, a, GHOST), the next hull edge a -> c. Vertices as id[rank], or ranks when id is NULL. */
static inline void extract_hull(const dt2_builder *b, const uint32_t *id, uint32_t ghost, size_t h,
                                uint32_t *hull)
{
    uint32_t g = ghost;
    for (size_t i = 0; i < h; i++) {
        const dt2_tri *t = b->tri + g;
        int k = t->v[0] == GHOST ? 0 : t->v[1] == GHOST ? 1 : 2;
        uint32_t v = t->v[(k + 1) % 3];
        hull[i] = id ? id[v] : v;
        g = t->nb[(k + 2) % 3] >> 2;
    }
}

/* Exchanges the records at i and j and repoints every neighbour code, theirs included (i and j
 * may be neighbours). Codes are remapped first and back-pointers written after, so a
 * back-pointer written twice gets the same value twice. */
static void swap_records(dt2_tri *tri, uint32_t i, uint32_t j)
{
    dt2_tri moved[2] = {tri[j], tri[i]}; /* the records that end at i and at j */
    uint32_t pos[2] = {i, j};
    for (int r = 0; r < 2; r++)
        for (int k = 0; k < 3; k++) {
            uint32_t x = moved[r].nb[k] >> 2;
            x = x == i ? j : x == j ? i : x;
            moved[r].nb[k] = (x << 2) | (moved[r].nb[k] & 3);
        }
    tri[i] = moved[0];
    tri[j] = moved[1];
    for (int r = 0; r < 2; r++)
        for (int k = 0; k < 3; k++) {
            uint32_t code = tri[pos[r]].nb[k];
            tri[code >> 2].nb[code & 3] = (pos[r] << 2) | (uint32_t)k;
        }
}

/* Moves the ghosts behind the real triangles (there are only as many ghosts as hull edges, so
 * few swaps); afterwards a real triangle's output index is its storage index, and extraction is
 * one sequential pass. Returns the number of real triangles. */
static size_t partition_ghosts(dt2_builder *b)
{
    size_t lo = 0, hi = b->count;
    while (lo < hi) {
        if (!is_ghost(b->tri + lo))
            lo++;
        else if (is_ghost(b->tri + hi - 1))
            hi--;
        else
            swap_records(b->tri, (uint32_t)lo++, (uint32_t)--hi);
    }
    return lo;
}

/* Shrinks a buffer whose tail is no longer needed; keeps it whole if the system refuses. */
static void *shrink(void *p, size_t bytes)
{
    void *q = realloc(p, bytes ? bytes : 1);
    return q ? q : p;
}

/* Rewrites the first `real` records as 3 vertices each (id[rank], or ranks when id is NULL) at
 * the start of the record memory, and their neighbours (UINT32_MAX for a ghost) into adj.
 * Inlined with a constant id, so fl_dt2_build's loop keeps its form. */
static inline void write_triangles(dt2_builder *b, size_t real, const uint32_t *id, uint32_t *adj)
{
    uint32_t *tri = (uint32_t *)b->tri;
    for (size_t t = 0; t < real; t++) {
        dt2_tri rec = b->tri[t];
        for (int k = 0; k < 3; k++) {
            uint32_t u = rec.nb[k] >> 2;
            tri[3 * t + k] = id ? id[rec.v[k]] : rec.v[k];
            adj[3 * t + k] = u < real ? u : UINT32_MAX;
        }
    }
}

/* Writes the real triangles into *out with input indices for vertices. The output arrays reuse
 * the builder's memory instead of fresh pages: record t (24 bytes at 24t) becomes the 12 bytes
 * of out->tri at 12t, which never overlaps a record not yet read; out->adj goes where the
 * coordinate copy was (no longer needed). Both buffers then pass to *out. */
static fl_status extract(dt2_builder *b, const double *xy, int want_cc, fl_dt2 *out, fl_error *err)
{
    size_t real = partition_ghosts(b);
    out->triangle_count = real;
    out->hull_count = b->count - real;
    out->hull = fl_alloc_array(out->hull_count, sizeof *out->hull);
    if (want_cc) out->circumcenters = fl_alloc_array(real, 2 * sizeof *out->circumcenters);
    if (!out->hull || (want_cc && !out->circumcenters))
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "no memory for %zu output triangles", real);
    extract_hull(b, b->id, (uint32_t)real, out->hull_count, out->hull);
    write_triangles(b, real, b->id, (uint32_t *)b->xy);
    out->tri = shrink(b->tri, real * 3 * sizeof *out->tri);
    out->adj = shrink(b->xy, real * 3 * sizeof *out->adj);
    b->tri = NULL;
    b->xy = NULL;
    if (want_cc) compute_circumcenters(xy, out->tri, real, out->circumcenters);
    return FL_OK;
}

/* The same for fl_dt2_build_ranked: vertices stay ranks, the coordinate copy (in rank order)
 * passes to *out, and the adjacency gets memory of its own (measured: faster at 1e6 points
 * than moving the coordinates to a right-sized buffer and putting the adjacency in their
 * place, as extract does). The record memory is not shrunk: the half after the 12-byte
 * triangles (the records' second half, touched by the build) is lent to the caller as
 * out->spare, since a fresh page costs a fault of several microseconds on first touch. */
static fl_status extract_ranked(dt2_builder *b, fl_dt2_ranked *out, fl_error *err)
{
    size_t real = partition_ghosts(b), m = out->unique_count;
    out->triangle_count = real;
    out->hull_count = b->count - real;
    out->hull = fl_alloc_array(out->hull_count, sizeof *out->hull);
    out->adj = fl_alloc_array(real, 3 * sizeof *out->adj);
    if (!out->hull || !out->adj)
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "no memory for %zu output triangles", real);
    extract_hull(b, NULL, (uint32_t)real, out->hull_count, out->hull);
    write_triangles(b, real, NULL, out->adj);
    size_t used = (real * 3 * sizeof *out->tri + 15) & ~(size_t)15;
    size_t all = b->capacity * sizeof *b->tri;
    out->tri = (uint32_t *)b->tri;
    out->spare = used < all ? (unsigned char *)b->tri + used : NULL;
    out->spare_bytes = used < all ? all - used : 0;
    out->xy = shrink(b->xy, m * 2 * sizeof *out->xy);
    b->tri = NULL;
    b->xy = NULL;
    return FL_OK;
}

/* Unique points (first of each kind) in spatial insertion order; `scratch` is lent to the sort. */
static fl_status insertion_order(const double *xy, const fl_dt2 *out, void *scratch,
                                 size_t scratch_bytes, uint32_t **order, fl_error *err)
{
    size_t m = out->unique_count, j = 0;
    uint32_t *ids = NULL;
    *order = fl_alloc_array(m, sizeof **order);
    if (m < out->point_count) ids = fl_alloc_array(m, sizeof *ids);
    if (!*order || (m < out->point_count && !ids)) {
        free(ids);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "no memory to order %zu points", m);
    }
    for (size_t i = 0; ids && i < out->point_count; i++)
        if (out->duplicate_of[i] == i) ids[j++] = (uint32_t)i;
    fl_status st = fl_dt_brio_order_in(xy, ids, m, 2, *order, scratch, scratch_bytes, err);
    free(ids);
    return st;
}

/* Takes ownership of `tri` (room for 2m triangles). Extracts into *ranked when it is not NULL
 * (its unique_count set), else into *out. */
static fl_status triangulate(const double *xy, uint32_t *order, dt2_tri *tri,
                             const fl_dt2_options *opt, fl_dt2 *out, fl_dt2_ranked *ranked,
                             fl_error *err)
{
    size_t m = out->unique_count;
    if (!choose_first_triangle(xy, order, m)) {
        free(tri);
        return fl_fail(err, FL_ERR_ALGORITHM, NULL, -1,
                       "all %zu distinct points are collinear: the Delaunay triangulation is "
                       "1-dimensional",
                       m);
    }
    dt2_builder b;
    fl_status st = FL_OK;
    if (builder_init(&b, xy, order, m, tri)) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "no memory to triangulate %zu points", m);
    } else {
        start_triangulation(&b, 0, 1, 2);
        for (size_t i = 3; i < m && st == FL_OK; i++) {
            if (i % PROGRESS_EVERY == 0 &&
                fl_progress(opt->progress, opt->progress_user, "delaunay 2d", (double)i / m))
                st = fl_fail(err, FL_ERR_ALGORITHM, NULL, -1, "cancelled");
            else
                st = insert(&b, (uint32_t)i, err);
        }
        if (st == FL_OK && ranked) st = extract_ranked(&b, ranked, err);
        if (st == FL_OK && !ranked) st = extract(&b, xy, opt->want_circumcenters, out, err);
    }
    builder_free(&b);
    return st;
}

/* fl_dt2_build and fl_dt2_build_ranked: *out gets the duplicates, and the triangles unless
 * `ranked` is given (then they go there, and *order_out gets the insertion order). */
static fl_status build(const double *xy, size_t n, const fl_dt2_options *opt, fl_dt2 *out,
                       fl_dt2_ranked *ranked, uint32_t **order_out, fl_error *err)
{
    static const fl_dt2_options defaults = {0};
    if (!opt) opt = &defaults;
    if (n > 0 && !xy) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_dt2_build: NULL points");
    if (n > MAX_POINTS)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                       "%zu points exceed the 2D triangulation's limit of %u points", n,
                       (unsigned)MAX_POINTS);
    out->point_count = n;
    out->duplicate_of = fl_alloc_array(n, sizeof *out->duplicate_of);
    /* The triangle array, sized for n distinct points (pages never touched cost nothing), is
     * first lent as scratch to the duplicate detection and the sort. */
    size_t work_bytes = (n > 2 ? 2 * n : 1) * sizeof(dt2_tri);
    dt2_tri *work = fl_alloc_array(n > 2 ? 2 * n : 1, sizeof *work);
    if ((!out->duplicate_of && n > 0) || !work) {
        free(work);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "no memory for %zu points", n);
    }
    fl_status st =
        fl_dt_unique_in(xy, n, 2, out->duplicate_of, &out->unique_count, work, work_bytes, err);
    if (st == FL_OK && out->unique_count < 3)
        st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                     "a 2D Delaunay triangulation needs at least 3 distinct points, got %zu "
                     "(of %zu input points)",
                     out->unique_count, n);
    uint32_t *order = NULL;
    if (st == FL_OK) st = insertion_order(xy, out, work, work_bytes, &order, err);
    if (ranked) ranked->unique_count = out->unique_count;
    if (st == FL_OK)
        st = triangulate(xy, order, work, opt, out, ranked, err);
    else
        free(work);
    if (order_out && st == FL_OK)
        *order_out = order;
    else
        free(order);
    if (st == FL_OK) fl_progress(opt->progress, opt->progress_user, "delaunay 2d", 1.0);
    if (st != FL_OK) fl_dt2_free(out);
    return st;
}

fl_status fl_dt2_build(const double *xy, size_t n, const fl_dt2_options *opt, fl_dt2 *out,
                       fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_dt2_build: NULL output");
    memset(out, 0, sizeof *out);
    return build(xy, n, opt, out, NULL, NULL, err);
}

/* ==== 2D triangulation in its insertion numbering (delaunay_internal.h) ==== */
fl_status fl_dt2_build_ranked(const double *xy, size_t n, const fl_dt2_options *opt,
                              fl_dt2_ranked *out, fl_error *err)
{
    if (!out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_dt2_build_ranked: NULL output");
    memset(out, 0, sizeof *out);
    fl_dt2 dup = {0};
    fl_status st = build(xy, n, opt, &dup, out, &out->order, err);
    if (st != FL_OK) {
        fl_dt2_ranked_free(out);
        return st;
    }
    out->point_count = dup.point_count;
    out->duplicate_of = dup.duplicate_of;
    dup.duplicate_of = NULL;
    fl_dt2_free(&dup);
    return FL_OK;
}

void fl_dt2_ranked_free(fl_dt2_ranked *dt)
{
    if (!dt) return;
    free(dt->duplicate_of);
    free(dt->order);
    free(dt->xy);
    free(dt->tri);
    free(dt->adj);
    free(dt->hull);
    memset(dt, 0, sizeof *dt);
}
/* end of 2D triangulation in its insertion numbering */

void fl_dt2_free(fl_dt2 *dt)
{
    if (!dt) return;
    free(dt->duplicate_of);
    free(dt->tri);
    free(dt->adj);
    free(dt->hull);
    free(dt->circumcenters);
    memset(dt, 0, sizeof *dt);
}
