/* The priority queue of Algorithm 5.1 (thesis §5.5): a 4-ary min-heap of candidate deletions.
 * Entries are never updated in place; stale ones are recognised when popped (line 5 of the
 * algorithm re-checks removability anyway), which keeps every operation O(log n).
 * On a 1e6-point curve the heap holds up to ~1e6 entries (most of them stale at the end), far
 * beyond the caches: a pop walks down log_4 instead of log_2 levels, and the four children of a
 * node are adjacent in memory, so it meets about half the cache misses of a binary heap.
 * The order is a strict total order on distinct entries (below), so the sequence of pops — and
 * with it the result of constriction — is the same as with any other correct priority queue. */
#include <math.h>
#include <stdlib.h>

#include "reconstruct/constrict2_internal.h"

enum { ARITY = 4 };

/* Ties (equal keys: common on grids) compare input indices, so the order of deletions is the
 * same whatever the internal numbering. */
static int tie_less(const c2_heap *h, const c2_entry *x, const c2_entry *y)
{
    const uint32_t *o = h->orig;
    if (x->a != y->a) return o ? o[x->a] < o[y->a] : x->a < y->a;
    if (x->b != y->b) return o ? o[x->b] < o[y->b] : x->b < y->b;
    if (x->c != y->c) return o ? o[x->c] < o[y->c] : x->c < y->c;
    return 0;
}

/* Key order, NaN after every number (a key overflowing on coordinates near the double range;
 * without this a NaN would compare neither less nor greater and the order would depend on the
 * heap's shape), then the tie-break. */
static inline int entry_less(const c2_heap *h, const c2_entry *x, const c2_entry *y)
{
    if (x->key < y->key) return 1;
    if (x->key > y->key) return 0;
    int xn = isnan(x->key), yn = isnan(y->key);
    if (xn != yn) return yn;
    return tie_less(h, x, y);
}

int c2_heap_push(c2_heap *h, c2_entry e)
{
    if (h->count == h->capacity) {
        size_t cap = h->capacity ? 2 * h->capacity : 256;
        c2_entry *items = fl_realloc_array(h->items, cap, sizeof *items);
        if (!items) return -1;
        h->items = items;
        h->capacity = cap;
    }
    size_t i = h->count++;
    while (i > 0) {
        size_t parent = (i - 1) / ARITY;
        if (!entry_less(h, &e, &h->items[parent])) break;
        h->items[i] = h->items[parent];
        i = parent;
    }
    h->items[i] = e;
    return 0;
}

c2_entry c2_heap_pop(c2_heap *h)
{
    c2_entry top = h->items[0], last = h->items[--h->count];
    size_t i = 0, n = h->count;
    for (;;) {
        size_t first = ARITY * i + 1;
        if (first >= n) break;
        size_t end = first + ARITY < n ? first + ARITY : n, best = first;
        for (size_t child = first + 1; child < end; child++)
            if (entry_less(h, &h->items[child], &h->items[best])) best = child;
        if (!entry_less(h, &h->items[best], &last)) break;
        h->items[i] = h->items[best];
        i = best;
    }
    if (n > 0) h->items[i] = last;
    return top;
}

void c2_heap_free(c2_heap *h)
{
    free(h->items);
    h->items = NULL;
    h->count = h->capacity = 0;
    h->orig = NULL;
}
