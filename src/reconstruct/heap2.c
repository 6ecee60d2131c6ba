/* The priority queue of Algorithm 5.1 (thesis §5.5): a binary min-heap of candidate deletions.
 * Entries are never updated in place; stale ones are recognised when popped (line 5 of the
 * algorithm re-checks removability anyway), which keeps every operation O(log n). */
#include <stdlib.h>

#include "reconstruct/constrict2_internal.h"

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

static inline int entry_less(const c2_heap *h, const c2_entry *x, const c2_entry *y)
{
    if (x->key != y->key) return x->key < y->key;
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
        size_t parent = (i - 1) / 2;
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
        size_t child = 2 * i + 1;
        if (child >= n) break;
        if (child + 1 < n && entry_less(h, &h->items[child + 1], &h->items[child])) child++;
        if (!entry_less(h, &h->items[child], &last)) break;
        h->items[i] = h->items[child];
        i = child;
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
