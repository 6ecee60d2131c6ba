/* Listing the final boundary (the polygon of Algorithm 5.1) in order. The boundary is a linked
 * cycle bnext[] over vertex indices, which follow the input order, not the curve: walking it is
 * a chain of dependent cache misses, one per vertex (on a 1e6-point curve, a tenth of the whole
 * constriction time went into that walk). Cutting the cycle at sample vertices ("seeds") into
 * segments lets several walks run at once, so the processor overlaps their misses; a second
 * interleaved walk writes every segment at its offset. The order is the same as a single walk
 * from `start` (pure list ranking; no geometry is involved). */
#include <stdlib.h>

#include "reconstruct/constrict2_internal.h"

enum {
    ORDER_SERIAL = 4096, /* shorter boundaries: one plain walk */
    ORDER_WALKERS = 16,  /* walks in flight */
    ORDER_SHIFT = 26     /* seeds: about one boundary vertex in 2^(32-26) = 64 */
};

/* A seed is `start` or a vertex whose hashed index falls in the lowest 1/64 (any input order,
 * curve order included, spreads them along the boundary). */
static int is_seed(uint32_t v, uint32_t start)
{
    return v == start || (uint32_t)(v * 0x9e3779b1u) >> ORDER_SHIFT == 0;
}

static void walk_serial(const c2_state *s, uint32_t start, uint32_t *out)
{
    uint32_t v = start;
    for (size_t i = 0; i < s->boundary_count; i++) {
        out[i] = v;
        v = s->bnext[v];
    }
}

/* Index of seed vertex v in the increasing list seed[0..ns-1]. */
static size_t seed_index(const uint32_t *seed, size_t ns, uint32_t v)
{
    size_t lo = 0, hi = ns;
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (seed[mid] <= v)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

typedef struct walker {
    size_t seed; /* index of the seed this walk started from */
    uint32_t cur;
    size_t count; /* vertices of the segment seen so far */
} walker;

/* Walks every segment, W at a time. Without `out`: fills len[] (vertices of the segment from
 * seed i up to the next seed, exclusive) and next[] (that seed's index). With `out`: writes
 * segment i at out + off[i]. Returns 0, or -1 when a segment is longer than the boundary (a
 * broken cycle; the caller falls back to the plain walk, which is bounded). */
static int walk_segments(const c2_state *s, uint32_t start, const uint32_t *seed, size_t ns,
                         uint32_t *len, uint32_t *next, const uint32_t *off, uint32_t *out)
{
    walker w[ORDER_WALKERS];
    size_t active = 0, started = 0, m = s->boundary_count;
    while (active < ORDER_WALKERS && started < ns) {
        w[active] = (walker){started, seed[started], 0};
        active++, started++;
    }
    while (active > 0) {
        for (size_t k = 0; k < active;) {
            walker *q = &w[k];
            if (out) {
                size_t at = (size_t)off[q->seed] + q->count;
                if (at >= m) return -1;
                out[at] = q->cur;
            }
            if (++q->count > m) return -1;
            uint32_t nx = s->bnext[q->cur];
            if (!is_seed(nx, start)) {
                q->cur = nx;
                k++;
                continue;
            }
            if (!out) {
                len[q->seed] = (uint32_t)q->count;
                next[q->seed] = (uint32_t)seed_index(seed, ns, nx);
            }
            if (started < ns) {
                *q = (walker){started, seed[started], 0};
                started++;
                k++;
            } else {
                *q = w[--active];
            }
        }
    }
    return 0;
}

/* Fills out[0..boundary_count-1] with the boundary cycle from `start` (a boundary vertex).
 * 0, or -1 when out of memory. */
int c2_boundary_order(const c2_state *s, uint32_t start, uint32_t *out)
{
    size_t m = s->boundary_count, ns = 0;
    if (m < ORDER_SERIAL) {
        walk_serial(s, start, out);
        return 0;
    }
    for (size_t v = 0; v < s->n; v++)
        ns += s->on_boundary[v] && is_seed((uint32_t)v, start);
    uint32_t *seed = fl_alloc_array(ns, 4 * sizeof *seed);
    if (!seed) return -1;
    uint32_t *len = seed + ns, *next = len + ns, *off = next + ns;
    ns = 0;
    for (size_t v = 0; v < s->n; v++)
        if (s->on_boundary[v] && is_seed((uint32_t)v, start)) seed[ns++] = (uint32_t)v;
    for (size_t k = 0; k < ns; k++)
        off[k] = UINT32_MAX; /* unset: phase 3 refuses to write there */
    int ok = walk_segments(s, start, seed, ns, len, next, NULL, NULL) == 0;
    size_t pos = 0, i = seed_index(seed, ns, start);
    for (size_t k = 0; k < ns && ok; k++, i = next[i]) {
        off[i] = (uint32_t)pos;
        pos += len[i];
        ok = pos <= m;
    }
    ok = ok && pos == m && walk_segments(s, start, seed, ns, len, next, off, out) == 0;
    if (!ok) walk_serial(s, start, out);
    free(seed);
    return 0;
}
