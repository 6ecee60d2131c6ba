/* A uint64 -> uint32 hash map with linear probing (keys != UINT64_MAX), shared by the uniform
 * mesher (skin_mesh.c: grid points and grid edges) and the graded one (skin_graded.c: octree
 * corners and Delaunay edges). */
#ifndef FL_SKIN_MAP_H
#define FL_SKIN_MAP_H

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"

typedef struct u64map {
    uint64_t *key;
    uint32_t *val;
    size_t cap, count;
} u64map;

static inline uint64_t mix64(uint64_t x)
{
    x ^= x >> 33;
    x *= 0xff51afd7ed558ccdULL;
    x ^= x >> 33;
    x *= 0xc4ceb9fe1a85ec53ULL;
    return x ^ (x >> 33);
}

static inline int map_init(u64map *m, size_t cap)
{
    m->cap = 16;
    while (m->cap < 2 * cap)
        m->cap *= 2;
    m->count = 0;
    m->key = fl_alloc_array(m->cap, sizeof(uint64_t));
    m->val = fl_alloc_array(m->cap, sizeof(uint32_t));
    if (!m->key || !m->val) return -1;
    memset(m->key, 0xff, m->cap * sizeof(uint64_t));
    return 0;
}

static inline void map_free(u64map *m)
{
    free(m->key);
    free(m->val);
    memset(m, 0, sizeof *m);
}

/* The slot of key: holding it, or the empty slot where it belongs. */
static inline size_t map_slot(const u64map *m, uint64_t key)
{
    size_t i = (size_t)mix64(key) & (m->cap - 1);
    while (m->key[i] != UINT64_MAX && m->key[i] != key)
        i = (i + 1) & (m->cap - 1);
    return i;
}

static inline int map_grow(u64map *m)
{
    u64map g = {0};
    if (m->cap > SIZE_MAX / 4 || map_init(&g, m->cap)) {
        map_free(&g);
        return -1;
    }
    for (size_t i = 0; i < m->cap; i++)
        if (m->key[i] != UINT64_MAX) {
            size_t s = map_slot(&g, m->key[i]);
            g.key[s] = m->key[i];
            g.val[s] = m->val[i];
        }
    g.count = m->count;
    map_free(m);
    *m = g;
    return 0;
}

/* Inserts key -> val when absent. Returns the slot, or SIZE_MAX on allocation failure. */
static inline size_t map_put(u64map *m, uint64_t key, uint32_t val)
{
    if (2 * (m->count + 1) > m->cap && map_grow(m)) return SIZE_MAX;
    size_t s = map_slot(m, key);
    if (m->key[s] == UINT64_MAX) {
        m->key[s] = key;
        m->val[s] = val;
        m->count++;
    }
    return s;
}

#endif
