/* Constrained constriction in 3D (thesis §5.7): triangles F the user requires on the boundary.
 * §5.7 adds the faces of F that are not in the γ-graph and exchanges boundary tetrahedra
 * lazily when a removal would delete one; here every kept triangle must already be a face of the
 * Delaunay tetrahedralization (else the call fails with FL_ERR_INPUT), so no exchange is
 * needed: a tetrahedron whose boundary face is kept is never removable (constrict3.c
 * removal_key), and the unlocking flips never flip a kept face away (constrict3_unlock.c). A
 * kept face that is interior becomes a boundary face when the tetrahedron on either side goes;
 * if constriction locks first, the result reports it (keep_missing). */
#include <stdlib.h>
#include <string.h>

#include "reconstruct/constrict3_internal.h"

typedef struct kept_face {
    uint32_t v[3]; /* ascending */
    size_t index;  /* in the caller's list, for messages */
} kept_face;

static int kept_cmp(const void *x, const void *y)
{
    const kept_face *a = x, *b = y;
    for (int i = 0; i < 3; i++)
        if (a->v[i] != b->v[i]) return a->v[i] < b->v[i] ? -1 : 1;
    return 0;
}

static void sort3(uint32_t *v)
{
    uint32_t t;
    if (v[0] > v[1]) t = v[0], v[0] = v[1], v[1] = t;
    if (v[1] > v[2]) t = v[1], v[1] = v[2], v[2] = t;
    if (v[0] > v[1]) t = v[0], v[0] = v[1], v[1] = t;
}

/* Validates the triples and returns them sorted and without repeats (*count updated). */
static fl_status collect(const constrict3_state *s, const uint32_t *rep, const uint32_t *keep,
                         size_t *count, kept_face *f, fl_error *err)
{
    for (size_t i = 0; i < *count; i++) {
        const uint32_t *k = keep + 3 * i;
        for (int j = 0; j < 3; j++)
            if (k[j] >= s->n)
                return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                               "kept triangle %zu (%u %u %u): index out of range (%zu points)", i,
                               k[0], k[1], k[2], s->n);
        for (int j = 0; j < 3; j++)
            f[i].v[j] = rep[k[j]];
        f[i].index = i;
        sort3(f[i].v);
        if (f[i].v[0] == f[i].v[1] || f[i].v[1] == f[i].v[2])
            return fl_fail(err, FL_ERR_INPUT, NULL, -1,
                           "kept triangle %zu (%u %u %u) repeats a point (or a duplicate of it)", i,
                           k[0], k[1], k[2]);
    }
    qsort(f, *count, sizeof *f, kept_cmp);
    size_t m = 0;
    for (size_t i = 0; i < *count; i++)
        if (m == 0 || kept_cmp(&f[m - 1], &f[i]) != 0) f[m++] = f[i];
    *count = m;
    return FL_OK;
}

fl_status constrict3_mark_kept(constrict3_state *s, const uint32_t *rep, const uint32_t *keep,
                               size_t count, fl_error *err)
{
    kept_face *f = fl_alloc_array(count, sizeof *f);
    uint8_t *found = fl_calloc_array(count, 1);
    s->keepmask = fl_calloc_array(s->cap, 1);
    fl_status st = FL_OK;
    if (!f || !found || !s->keepmask) {
        st = fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory for kept triangles");
        goto done;
    }
    st = collect(s, rep, keep, &count, f, err);
    if (st != FL_OK) goto done;
    for (size_t t = 0; t < s->tet_count; t++)
        for (int k = 0; k < 4; k++) {
            kept_face key;
            for (int j = 0; j < 3; j++)
                key.v[j] = s->tet[4 * t + constrict3_face[k][j]];
            sort3(key.v);
            kept_face *hit = bsearch(&key, f, count, sizeof *f, kept_cmp);
            if (!hit) continue;
            s->keepmask[t] |= (uint8_t)(1u << k);
            found[hit - f] = 1;
            if (s->adj[4 * t + k] == UINT32_MAX) s->keep_on++; /* on the convex hull */
        }
    for (size_t i = 0; i < count; i++)
        if (!found[i]) {
            const uint32_t *k = keep + 3 * f[i].index;
            st = fl_fail(err, FL_ERR_INPUT, NULL, -1,
                         "kept triangle %zu (%u %u %u) is not a face of the Delaunay "
                         "tetrahedralization, so constrained constriction cannot keep it "
                         "(thesis §5.7; only Delaunay faces can be kept)",
                         f[i].index, k[0], k[1], k[2]);
            goto done;
        }
    s->keep_total = count;
done:
    free(f);
    free(found);
    return st;
}
