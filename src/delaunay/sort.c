/* Spatial sort and exact duplicate detection for the Delaunay triangulations.
 *
 * Incremental Delaunay construction spends its time in point location; inserting the points in
 * an order where consecutive points are close makes each walk a few steps long. A pure
 * space-filling-curve order loses the expected-case guarantee of a random order, so we use the
 * Biased Randomized Insertion Order of Amenta, Choi and Rote ("Incremental constructions con
 * BRIO", SoCG 2003): random rounds of geometrically growing size, each sorted along a Hilbert
 * curve. Keys are 64-bit Hilbert indices of the coordinates quantized on the bounding box, sorted
 * by LSD radix sort, so the whole order costs O(n). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay_internal.h"

/* The last BRIO round holds 1 - 1/BRIO_RATIO_DIV of the points still unplaced; rounds smaller
 * than BRIO_MIN_ROUND are merged into the first round. CGAL's multiscale sort uses the same 1/8. */
#define BRIO_RATIO_DIV 8
#define BRIO_MIN_ROUND 64
#define BRIO_SEED 0x5DEECE66DULL

static uint64_t splitmix64(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

static fl_status check_args(const double *coords, size_t n, int dim, const void *out, fl_error *err)
{
    if (dim != 2 && dim != 3)
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "dimension must be 2 or 3, got %d", dim);
    if (n > 0 && (!coords || !out))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "NULL point or output buffer");
    /* UINT32_MAX is reserved as "no point" in the triangulations' index arrays. */
    if (n >= UINT32_MAX)
        return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                       "%zu points exceed the limit of %u points per triangulation", n,
                       (unsigned)(UINT32_MAX - 1));
    return FL_OK;
}

static fl_status check_finite(const double *p, int dim, size_t index, fl_error *err)
{
    for (int k = 0; k < dim; k++)
        if (!isfinite(p[k]))
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "point %zu has a non-finite coordinate (%g); remove NaN/Inf points",
                           index, p[k]);
    return FL_OK;
}

/* ---- exact duplicates ----------------------------------------------------------------- */

/* Hash of the coordinates as the predicates see them: -0.0 and +0.0 are the same number. */
static uint64_t point_hash(const double *p, int dim)
{
    uint64_t h = 0x243F6A8885A308D3ULL;
    for (int k = 0; k < dim; k++) {
        double v = p[k] == 0.0 ? 0.0 : p[k];
        uint64_t bits;
        memcpy(&bits, &v, sizeof bits);
        h = (h ^ bits) * 0x9E3779B97F4A7C15ULL;
        h ^= h >> 29;
    }
    return h;
}

/* With NaN excluded, double == is exactly "bitwise equal after -0.0 -> +0.0". */
static int same_point(const double *a, const double *b, int dim)
{
    for (int k = 0; k < dim; k++)
        if (a[k] != b[k]) return 0;
    return 1;
}

fl_status fl_dt_unique(const double *coords, size_t n, int dim, uint32_t *rep, size_t *unique_count,
                       fl_error *err)
{
    fl_status st = check_args(coords, n, dim, rep, err);
    if (st != FL_OK) return st;
    if (!unique_count) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "NULL unique_count");
    size_t cap = 16;
    while (cap < 2 * n)
        cap *= 2;
    uint32_t *table = fl_alloc_array(cap, sizeof *table);
    if (!table)
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1,
                       "no memory for duplicate detection (%zu points)", n);
    memset(table, 0xFF, cap * sizeof *table);
    size_t unique = 0;
    for (size_t i = 0; i < n; i++) {
        const double *p = coords + i * (size_t)dim;
        st = check_finite(p, dim, i, err);
        if (st != FL_OK) break;
        /* Linear probing; points are inserted in index order, so the first point found with
         * equal coordinates is the smallest such index. */
        size_t slot = (size_t)point_hash(p, dim) & (cap - 1);
        while (table[slot] != UINT32_MAX && !same_point(coords + (size_t)table[slot] * dim, p, dim))
            slot = (slot + 1) & (cap - 1);
        if (table[slot] == UINT32_MAX) {
            table[slot] = (uint32_t)i;
            unique++;
        }
        rep[i] = table[slot];
    }
    free(table);
    if (st == FL_OK) *unique_count = unique;
    return st;
}

/* ---- Hilbert keys ----------------------------------------------------------------------- */

/* Bit i of v moved to bit 2i (2D) or 3i (3D, v < 2^21): the interleaving of a Morton code. */
static uint64_t spread2(uint32_t v)
{
    uint64_t x = v;
    x = (x | x << 16) & 0x0000FFFF0000FFFFULL;
    x = (x | x << 8) & 0x00FF00FF00FF00FFULL;
    x = (x | x << 4) & 0x0F0F0F0F0F0F0F0FULL;
    x = (x | x << 2) & 0x3333333333333333ULL;
    return (x | x << 1) & 0x5555555555555555ULL;
}

static uint64_t spread3(uint32_t v)
{
    uint64_t x = v & 0x1FFFFFu;
    x = (x | x << 32) & 0x001F00000000FFFFULL;
    x = (x | x << 16) & 0x001F0000FF0000FFULL;
    x = (x | x << 8) & 0x100F00F00F00F00FULL;
    x = (x | x << 4) & 0x10C30C30C30C30C3ULL;
    return (x | x << 2) & 0x1249249249249249ULL;
}

/* One level of Skilling's inverse "undo excess work" step on coordinate x[i] against x[0]: if
 * bit `level` of xi is set, reflect the low bits of x0, else swap the low bits of x0 and xi.
 * Branch-free: the coordinate bits are random, so branches on them would mispredict half the
 * time (that made the branchy form the most expensive part of the whole sort). */
#define HILBERT_UNDO(x0, xi, level, low)                                                           \
    do {                                                                                           \
        uint32_t set_ = 0u - (((xi) >> (level)) & 1u);                                             \
        uint32_t t_ = ((x0) ^ (xi)) & (low) & ~set_;                                               \
        (x0) ^= ((low)&set_) | t_;                                                                 \
        (xi) ^= t_;                                                                                \
    } while (0)

/* The Gray-code correction of Skilling's method: XOR of the low masks of the set bits of x. */
static uint32_t gray_fix(uint32_t x, int bits)
{
    uint32_t t = 0;
    for (int level = bits - 1; level > 0; level--)
        t ^= ((1u << level) - 1) & (0u - ((x >> level) & 1u));
    return t;
}

/* Hilbert index of a cell (each coordinate < 2^bits) by Skilling's transposition method
 * ("Programming the Hilbert curve", AIP Conf. Proc. 707, 2004): undo the excess rotations and
 * reflections level by level, Gray-encode, then interleave the bits, most significant first.
 * Written out per dimension so the coordinates stay in registers. */
static uint64_t hilbert_key2(uint32_t x0, uint32_t x1)
{
    for (int level = 31; level > 0; level--) {
        uint32_t low = (1u << level) - 1;
        HILBERT_UNDO(x0, x0, level, low);
        HILBERT_UNDO(x0, x1, level, low);
    }
    x1 ^= x0;
    uint32_t t = gray_fix(x1, 32);
    return spread2(x0 ^ t) << 1 | spread2(x1 ^ t);
}

static uint64_t hilbert_key3(uint32_t x0, uint32_t x1, uint32_t x2)
{
    for (int level = 20; level > 0; level--) {
        uint32_t low = (1u << level) - 1;
        HILBERT_UNDO(x0, x0, level, low);
        HILBERT_UNDO(x0, x1, level, low);
        HILBERT_UNDO(x0, x2, level, low);
    }
    x1 ^= x0;
    x2 ^= x1;
    uint32_t t = gray_fix(x2, 21);
    return spread3(x0 ^ t) << 2 | spread3(x1 ^ t) << 1 | spread3(x2 ^ t);
}

typedef struct bbox {
    double lo[3];
    double scale; /* cells per (halved) unit of length, the same on every axis */
} bbox;

/* One scale for all axes keeps the curve's cells square, so Hilbert neighbours stay close in
 * space even for flat point sets. Coordinates are halved before subtracting so that the extent
 * of points spread over the whole double range does not overflow. */
static bbox bounding_box(const double *coords, const uint32_t *ids, size_t n, int dim, int bits)
{
    bbox b;
    double hi[3];
    for (int k = 0; k < dim; k++) {
        b.lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    for (size_t i = 0; i < n; i++) {
        const double *p = coords + (size_t)(ids ? ids[i] : i) * dim;
        for (int k = 0; k < dim; k++) {
            if (p[k] < b.lo[k]) b.lo[k] = p[k];
            if (p[k] > hi[k]) hi[k] = p[k];
        }
    }
    double extent = 0.0;
    for (int k = 0; k < dim; k++)
        if (0.5 * hi[k] - 0.5 * b.lo[k] > extent) extent = 0.5 * hi[k] - 0.5 * b.lo[k];
    b.scale = extent > 0.0 ? (double)((1ULL << bits) - 1) / extent : 0.0;
    return b;
}

static uint64_t point_key(const double *p, const bbox *b, int dim, int bits)
{
    uint32_t cell[3];
    double max_cell = (double)((1ULL << bits) - 1);
    for (int k = 0; k < dim; k++) {
        double c = (0.5 * p[k] - 0.5 * b->lo[k]) * b->scale;
        cell[k] = (uint32_t)(c < max_cell ? c : max_cell);
    }
    return dim == 2 ? hilbert_key2(cell[0], cell[1]) : hilbert_key3(cell[0], cell[1], cell[2]);
}

/* ---- radix sort of (key, id) pairs --------------------------------------------------------- */

/* LSD radix sort by bytes; a byte position on which all keys agree is skipped. The result is
 * left in key/id; tkey/tid are scratch of the same length. */
static void radix_sort(uint64_t *key, uint32_t *id, uint64_t *tkey, uint32_t *tid, size_t m)
{
    if (m < 2) return;
    size_t count[8][256];
    memset(count, 0, sizeof count);
    for (size_t i = 0; i < m; i++)
        for (int b = 0; b < 8; b++)
            count[b][(key[i] >> (8 * b)) & 0xFF]++;
    uint64_t *src_k = key, *dst_k = tkey;
    uint32_t *src_i = id, *dst_i = tid;
    for (int b = 0; b < 8; b++) {
        if (count[b][(src_k[0] >> (8 * b)) & 0xFF] == m) continue;
        size_t pos[256], sum = 0;
        for (int v = 0; v < 256; v++) {
            pos[v] = sum;
            sum += count[b][v];
        }
        for (size_t i = 0; i < m; i++) {
            size_t d = pos[(src_k[i] >> (8 * b)) & 0xFF]++;
            dst_k[d] = src_k[i];
            dst_i[d] = src_i[i];
        }
        uint64_t *tk = src_k;
        src_k = dst_k;
        dst_k = tk;
        uint32_t *ti = src_i;
        src_i = dst_i;
        dst_i = ti;
    }
    if (src_k != key) {
        memcpy(key, src_k, m * sizeof *key);
        memcpy(id, src_i, m * sizeof *id);
    }
}

/* ---- BRIO -------------------------------------------------------------------------------- */

/* Fisher-Yates shuffle of the pairs (key[i], id[i]). */
static void shuffle(uint64_t *key, uint32_t *id, size_t n)
{
    uint64_t state = BRIO_SEED;
    for (size_t i = n; i > 1; i--) {
        size_t j = (size_t)(splitmix64(&state) % i);
        uint64_t k = key[i - 1];
        key[i - 1] = key[j];
        key[j] = k;
        uint32_t t = id[i - 1];
        id[i - 1] = id[j];
        id[j] = t;
    }
}

fl_status fl_dt_brio_order(const double *coords, const uint32_t *ids, size_t n, int dim,
                           uint32_t *order_out, fl_error *err)
{
    fl_status st = check_args(coords, n, dim, order_out, err);
    if (st != FL_OK) return st;
    for (size_t i = 0; i < n; i++) {
        size_t id = ids ? ids[i] : i;
        st = check_finite(coords + id * (size_t)dim, dim, id, err);
        if (st != FL_OK) return st;
    }
    if (n == 0) return FL_OK;
    uint64_t *key = fl_alloc_array(n, sizeof *key);
    uint64_t *tkey = fl_alloc_array(n, sizeof *tkey);
    uint32_t *tid = fl_alloc_array(n, sizeof *tid);
    if (!key || !tkey || !tid) {
        free(key);
        free(tkey);
        free(tid);
        return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "no memory to sort %zu points", n);
    }
    int bits = dim == 2 ? 32 : 21; /* dim * bits <= 64 */
    bbox box = bounding_box(coords, ids, n, dim, bits);
    /* Keys in input order (sequential reads of the coordinates), then shuffled with the ids. */
    for (size_t i = 0; i < n; i++) {
        order_out[i] = ids ? ids[i] : (uint32_t)i;
        key[i] = point_key(coords + (size_t)order_out[i] * dim, &box, dim, bits);
    }
    shuffle(key, order_out, n);
    /* Rounds from last to first: [m/8, m) is a round, then recurse on [0, m/8). */
    size_t m = n;
    while (m / BRIO_RATIO_DIV >= BRIO_MIN_ROUND) {
        size_t k = m / BRIO_RATIO_DIV;
        radix_sort(key + k, order_out + k, tkey, tid, m - k);
        m = k;
    }
    radix_sort(key, order_out, tkey, tid, m);
    free(key);
    free(tkey);
    free(tid);
    return FL_OK;
}
