/* The priority queue of the sweep queries: a binary min-heap on an array sized once for all
 * the nodes of a hierarchy (a node is in the queue at most once), so queries allocate nothing
 * (§4.2: "a priority queue may be implemented as a binary heap using arrays"). */
#ifndef FL_SWEEP_HEAP_H
#define FL_SWEEP_HEAP_H

#include <stddef.h>
#include <stdint.h>

typedef struct fl_sweep_entry {
    double key;  /* priority: a lower bound on the region's distance (+ base, see query.c) */
    double base; /* the cursor's travelled distance when the bound was computed */
    uint32_t node;
    uint32_t partial; /* 1: the key is only the box bound; measure the element when at front */
} fl_sweep_entry;

typedef struct fl_sweep_heap {
    fl_sweep_entry *e;
    size_t n;
} fl_sweep_heap;

static inline void fl_sweep_heap_push(fl_sweep_heap *h, fl_sweep_entry x)
{
    size_t i = h->n++;
    while (i > 0 && h->e[(i - 1) / 2].key > x.key) {
        h->e[i] = h->e[(i - 1) / 2];
        i = (i - 1) / 2;
    }
    h->e[i] = x;
}

/* Puts x at the root, whose entry is dropped, and sifts it down: a pop and a push in one pass
 * (the cursor's refresh of a dirty front, query.c). */
static inline void fl_sweep_heap_replace_top(fl_sweep_heap *h, fl_sweep_entry x)
{
    size_t i = 0;
    for (;;) {
        size_t c = 2 * i + 1;
        if (c >= h->n) break;
        if (c + 1 < h->n && h->e[c + 1].key < h->e[c].key) c++;
        if (h->e[c].key >= x.key) break;
        h->e[i] = h->e[c];
        i = c;
    }
    h->e[i] = x;
}

static inline fl_sweep_entry fl_sweep_heap_pop(fl_sweep_heap *h)
{
    fl_sweep_entry top = h->e[0], last = h->e[--h->n];
    if (h->n > 0) fl_sweep_heap_replace_top(h, last);
    return top;
}

#endif /* FL_SWEEP_HEAP_H */
