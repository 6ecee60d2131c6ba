/* The volume invariant shared by the mesh tests (test_mesh.c, test_sweep_dynamic.c,
 * test_sweep_keyframes.c): checked against the long-double oracle. */
#ifndef SWEEP_VOLUME_CHECK_H
#define SWEEP_VOLUME_CHECK_H

#include <stdint.h>
#include <stdlib.h>

#include "fl_test.h"
#include "sweep/sweep_internal.h"
#include "sweep_oracle.h"

/* The invariant the queries rest on (§4.1): every vertex below a node lies within its ε. */
static inline void check_volumes(const fl_sweep *s, const fl_mesh *m)
{
    uint32_t *stack = malloc(s->node_count * sizeof *stack);
    int bad = 0;
    for (size_t i = 0; i < s->node_count; i++) {
        const fl_sweep_node *node = s->nodes + i;
        size_t top = 0;
        stack[top++] = (uint32_t)i;
        while (top > 0) {
            const fl_sweep_node *d = s->nodes + stack[--top];
            if (d->child[0] != FL_SWEEP_LEAF) {
                stack[top++] = d->child[0];
                stack[top++] = d->child[1];
                continue;
            }
            for (int k = 0; k < 3; k++) {
                const double *p = oracle_vertex(m->xyz, m->tri, d->element, k);
                bad += oracle_triangle(p, node->v, node->v + 3, node->v + 6) > node->eps;
            }
        }
    }
    CHECK_MSG(bad == 0, "%d vertices outside their volumes", bad);
    free(stack);
}

#endif /* SWEEP_VOLUME_CHECK_H */
