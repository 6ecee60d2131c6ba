/* The priority queue of Algorithm 5.1 (thesis §5.5): candidate deletions in key order.
 * Entries are never updated in place; stale ones are recognised when popped (line 5 of the
 * algorithm re-checks removability anyway), which keeps every operation O(log n).
 *
 * Parking. On a closed curve most entries are never popped: every edge between consecutive
 * samples is pushed once, with the far side's apex, and its key (the γ-indicator of a very thin
 * triangle, close to 1) is never reached because every point joins the boundary first; measured
 * on 1e6 samples, all ~9.8e5 pops had keys below -0.25 and the ~5.3e5 entries left at the end
 * keys above 0.95. A plain heap grew to those 5.3e5 entries (13 MB, far beyond the caches) and
 * every pop walked ten levels of it. Here an entry whose key is at least the current bar is
 * parked in an unsorted array (an append); the heap holds only keys below the bar and stays
 * small. When the heap runs empty the bar is raised along a fixed ladder and the parked entries
 * now below it move into the heap (one pass over the parked array per step; the bar never
 * falls until the queue is cleared, so there are at most as many passes as steps).
 * Every heap key is below the bar and every parked key at or above it (or NaN), so the least
 * entry is in the heap whenever the heap is not empty: the order of pops is exactly the order
 * of a single priority queue over all entries.
 *
 * The heap is 4-ary: a pop walks down log_4 instead of log_2 levels, and the four children of
 * a node are adjacent in memory, so it meets about half the cache misses of a binary heap.
 * The order is a strict total order on distinct entries (below), so the sequence of pops — and
 * with it the result of constriction — is the same as with any other correct priority queue. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reconstruct/constrict2_internal.h"

enum { ARITY = 4 };

/* The bars, increasing. γ-indicators lie in [-1, 1] and area-change keys in [0, 1] (skeleton
 * keys are negative); past the last bar every entry, NaN keys included, goes to the heap. */
static const double ladder[] = {0.5, 0.875, 0.984375, 1.0, HUGE_VAL};
enum { LEVELS = sizeof ladder / sizeof *ladder };

/* Whether e waits in the parked array at the current bar. NaN is parked until the end. */
static inline int parks(const c2_heap *h, double key)
{
    return h->level < LEVELS && !(key < ladder[h->level]);
}

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

/* Makes room for one more entry. `lent` (may be NULL) marks *items as memory that is not ours:
 * it is copied, not reallocated, and the flag cleared. */
static int reserve(c2_entry **items, size_t *capacity, size_t count, int *lent)
{
    if (count < *capacity) return 0;
    size_t cap = *capacity ? 2 * *capacity : 256;
    c2_entry *grown;
    if (lent && *lent) {
        grown = fl_alloc_array(cap, sizeof *grown);
        if (grown) memcpy(grown, *items, count * sizeof *grown);
    } else {
        grown = fl_realloc_array(*items, cap, sizeof *grown);
    }
    if (!grown) return -1;
    if (lent) *lent = 0;
    *items = grown;
    *capacity = cap;
    return 0;
}

static int heap_push(c2_heap *h, c2_entry e)
{
    if (reserve(&h->items, &h->capacity, h->heaped, &h->items_lent)) return -1;
    size_t i = h->heaped++;
    while (i > 0) {
        size_t parent = (i - 1) / ARITY;
        if (!entry_less(h, &e, &h->items[parent])) break;
        h->items[i] = h->items[parent];
        i = parent;
    }
    h->items[i] = e;
    return 0;
}

double c2_heap_first_bar(void)
{
    return ladder[0];
}

/* Computes a lazy entry's key as c2_key would (the γ-indicator): bit for bit the value an
 * eager push would have stored, so the order of pops does not change. */
static inline void resolve(const c2_heap *h, c2_entry *e)
{
    if (!e->lazy) return;
    const double *xy = h->xy;
    e->key =
        c2_gamma_indicator(xy + 2 * (size_t)e->a, xy + 2 * (size_t)e->b, xy + 2 * (size_t)e->c);
    e->lazy = 0;
}

int c2_heap_push(c2_heap *h, c2_entry e)
{
    if (h->level > 0) resolve(h, &e);
    if (e.lazy || parks(h, e.key)) {
        if (reserve(&h->parked, &h->parked_capacity, h->parked_count, &h->parked_lent)) return -1;
        h->parked[h->parked_count++] = e;
    } else if (heap_push(h, e)) {
        return -1;
    }
    h->count++;
    return 0;
}

/* The heap is empty: raises the bar until some parked entry is below it and moves those into
 * the heap, keeping the others (in their order) parked. */
static int unpark(c2_heap *h)
{
    while (h->heaped == 0 && h->level < LEVELS) {
        h->level++;
        size_t kept = 0;
        for (size_t i = 0; i < h->parked_count; i++) {
            c2_entry e = h->parked[i];
            resolve(h, &e);
            if (parks(h, e.key)) {
                h->parked[kept++] = e;
            } else if (heap_push(h, e)) {
                /* out of memory: put the rest back so that nothing is lost */
                for (; i < h->parked_count; i++)
                    h->parked[kept++] = h->parked[i];
                h->parked_count = kept;
                return -1;
            }
        }
        h->parked_count = kept;
    }
    return 0;
}

int c2_heap_pop(c2_heap *h, c2_entry *out)
{
    if (h->heaped == 0 && unpark(h)) return -1;
    c2_entry top = h->items[0], last = h->items[--h->heaped];
    size_t i = 0, n = h->heaped;
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
    h->count--;
    *out = top;
    return 0;
}

void c2_heap_clear(c2_heap *h)
{
    h->heaped = h->parked_count = h->count = 0;
    h->level = 0;
}

/* An eighth for the heap proper, the rest for the parked entries: on the 1e6-point curve the
 * heap peaked at 45 421 entries and the parked array at about 5.3e5. */
void c2_heap_lend(c2_heap *h, void *memory, size_t bytes)
{
    size_t heap_entries = bytes / 8 / sizeof *h->items;
    size_t parked_entries = (bytes - heap_entries * sizeof *h->items) / sizeof *h->parked;
    if (h->items || h->parked || heap_entries == 0 || parked_entries == 0) return;
    h->items = memory;
    h->capacity = heap_entries;
    h->items_lent = 1;
    h->parked = h->items + heap_entries;
    h->parked_capacity = parked_entries;
    h->parked_lent = 1;
}

void c2_heap_free(c2_heap *h)
{
    if (!h->items_lent) free(h->items);
    if (!h->parked_lent) free(h->parked);
    memset(h, 0, sizeof *h);
}
