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

/* BRIO rounds (see brio_round): each holds about 7/8 of the points not in a later round, as in
 * CGAL's multiscale sort; rounds expected to be smaller than BRIO_MIN_ROUND merge. */
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

/* Hash table slots for n points: a power of two, at least 2n (load factor <= 1/2). */
static size_t unique_table_slots(size_t n)
{
    size_t cap = 16;
    while (cap < 2 * n)
        cap *= 2;
    return cap;
}

size_t fl_dt_unique_scratch_bytes(size_t n)
{
    return n > SIZE_MAX / 16 ? SIZE_MAX : unique_table_slots(n) * sizeof(uint32_t);
}

fl_status fl_dt_unique(const double *coords, size_t n, int dim, uint32_t *rep, size_t *unique_count,
                       fl_error *err)
{
    return fl_dt_unique_in(coords, n, dim, rep, unique_count, NULL, 0, err);
}

fl_status fl_dt_unique_in(const double *coords, size_t n, int dim, uint32_t *rep,
                          size_t *unique_count, void *scratch, size_t scratch_bytes, fl_error *err)
{
    fl_status st = check_args(coords, n, dim, rep, err);
    if (st != FL_OK) return st;
    if (!unique_count) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "NULL unique_count");
    size_t cap = unique_table_slots(n);
    int own = !scratch || scratch_bytes < fl_dt_unique_scratch_bytes(n);
    uint32_t *table = own ? fl_alloc_array(cap, sizeof *table) : scratch;
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
    if (own) free(table);
    if (st == FL_OK) *unique_count = unique;
    return st;
}

/* ---- Hilbert keys ----------------------------------------------------------------------- */

/* Bit i of v (v < 2^21) moved to bit 3i: the interleaving of a 3D Morton code. */
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

/* 2D: the Hilbert curve as a 4-state automaton read from the top bit down. In the canonical
 * frame the curve visits the quadrants (x, y) = (0,0), (0,1), (1,1), (1,0) as digits 0..3, and
 * the sub-curve of digit 0 is transposed, of digit 3 anti-transposed, of digits 1 and 2 as is.
 * The frames (identity, transpose, anti-transpose, half turn) form the Klein group, coded so
 * that composing two is XOR of their codes. hilbert2_table advances the automaton four levels
 * (a nibble of each coordinate) per lookup: entry = (8 digit bits << 2) | next frame. */
typedef uint16_t hilbert2_table[4][256];

static void hilbert2_make_table(hilbert2_table table)
{
    static const uint8_t digit[2][2] = {{0, 1}, {3, 2}}; /* digit[x][y], canonical frame */
    static const uint8_t sub_frame[4] = {1, 0, 0, 2};
    for (unsigned frame = 0; frame < 4; frame++)
        for (unsigned nib = 0; nib < 256; nib++) {
            unsigned f = frame, digits = 0;
            for (int level = 3; level >= 0; level--) {
                unsigned x = (nib >> (4 + level)) & 1, y = (nib >> level) & 1, cx = x, cy = y;
                if (f & 1) { /* transpose or half turn: see the frame codes above */
                    cx = f == 1 ? y : 1 - x;
                    cy = f == 1 ? x : 1 - y;
                } else if (f == 2) {
                    cx = 1 - y;
                    cy = 1 - x;
                }
                unsigned d = digit[cx][cy];
                digits = digits << 2 | d;
                f ^= sub_frame[d];
            }
            table[frame][nib] = (uint16_t)(digits << 2 | f);
        }
}

static uint64_t hilbert_key2(const hilbert2_table table, uint32_t x, uint32_t y)
{
    uint64_t key = 0;
    unsigned frame = 0;
    for (int shift = 28; shift >= 0; shift -= 4) {
        unsigned e = table[frame][((x >> shift) & 15) << 4 | ((y >> shift) & 15)];
        key = key << 8 | e >> 2;
        frame = e & 3;
    }
    return key;
}

/* 3D: Skilling's transposition method ("Programming the Hilbert curve", AIP Conf. Proc. 707,
 * 2004): undo the excess rotations and reflections level by level, Gray-encode, then interleave
 * the bits, most significant first. Written out so the coordinates stay in registers. */
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

static uint64_t point_key(const double *p, const bbox *b, const hilbert2_table table, int dim,
                          int bits)
{
    uint32_t cell[3];
    double max_cell = (double)((1ULL << bits) - 1);
    for (int k = 0; k < dim; k++) {
        double c = (0.5 * p[k] - 0.5 * b->lo[k]) * b->scale;
        cell[k] = (uint32_t)(c < max_cell ? c : max_cell);
    }
    return dim == 2 ? hilbert_key2(table, cell[0], cell[1])
                    : hilbert_key3(cell[0], cell[1], cell[2]);
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

/* The BRIO round of a point, 0 first: a point moves one round earlier with probability 1/8
 * (three random bits all zero), at most `deepest` times; so the last round holds about 7/8 of
 * the points, the one before 7/8 of the rest, ... (Amenta, Choi, Rote: each point's round is an
 * independent random choice). The randomness is a hash of the id, so no shuffle (and none of
 * its cache misses) is needed and the order is deterministic. */
static uint64_t brio_round(uint32_t id, unsigned deepest)
{
    uint64_t state = BRIO_SEED ^ id, z = splitmix64(&state);
    unsigned depth = 0;
    while (depth < deepest && (z & 7) == 0) {
        depth++;
        z >>= 3;
    }
    return deepest - depth;
}

size_t fl_dt_brio_scratch_bytes(size_t n)
{
    return n > SIZE_MAX / 20 ? SIZE_MAX : 20 * n; /* two 64-bit keys and one 32-bit id each */
}

fl_status fl_dt_brio_order(const double *coords, const uint32_t *ids, size_t n, int dim,
                           uint32_t *order_out, fl_error *err)
{
    return fl_dt_brio_order_in(coords, ids, n, dim, order_out, NULL, 0, err);
}

fl_status fl_dt_brio_order_in(const double *coords, const uint32_t *ids, size_t n, int dim,
                              uint32_t *order_out, void *scratch, size_t scratch_bytes,
                              fl_error *err)
{
    fl_status st = check_args(coords, n, dim, order_out, err);
    if (st != FL_OK) return st;
    for (size_t i = 0; i < n; i++) {
        size_t id = ids ? ids[i] : i;
        st = check_finite(coords + id * (size_t)dim, dim, id, err);
        if (st != FL_OK) return st;
    }
    if (n == 0) return FL_OK;
    int own = !scratch || scratch_bytes < fl_dt_brio_scratch_bytes(n);
    uint64_t *key = own ? fl_alloc_array(n, 20) : scratch;
    if (!key) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "no memory to sort %zu points", n);
    uint64_t *tkey = key + n;
    uint32_t *tid = (uint32_t *)(tkey + n);
    /* Rounds expected to hold fewer than BRIO_MIN_ROUND points merge into the first. */
    unsigned deepest = 0;
    while (deepest < 15 && (n >> (3 * (deepest + 1))) >= BRIO_MIN_ROUND)
        deepest++;
    int bits = dim == 2 ? 32 : 21; /* dim * bits <= 64 */
    bbox box = bounding_box(coords, ids, n, dim, bits);
    hilbert2_table table;
    if (dim == 2) hilbert2_make_table(table);
    /* One sort by (round, Hilbert index): the round takes the top 4 bits, the Hilbert key keeps
     * its leading 60 (30 bits per axis in 2D, 20 in 3D). */
    for (size_t i = 0; i < n; i++) {
        order_out[i] = ids ? ids[i] : (uint32_t)i;
        uint64_t h = point_key(coords + (size_t)order_out[i] * dim, &box, table, dim, bits);
        key[i] = brio_round(order_out[i], deepest) << 60 | h >> 4;
    }
    radix_sort(key, order_out, tkey, tid, n);
    if (own) free(key);
    return FL_OK;
}
