/* Lists, for each mesh file given, what fl_read_mesh makes of it and whether the triangle mesh
 * is closed, for bench/cache/manifest.txt (validation proper is `flintstone check`'s job):
 *
 *   mesh_census FILE...
 *   <file> vertices=V triangles=T closed=yes|no oriented=yes|no boundary_edges=B
 *          nonmanifold_edges=N degenerate=D euler=X
 *
 * closed: every edge is shared by exactly two triangles and no triangle repeats a vertex
 * ("no-triangles" for a file that holds only vertices, i.e. a point set).
 * oriented: closed, and the two triangles of every edge walk it in opposite directions.
 * euler: V' - E + T over the V' vertices that triangles use (2 - 2g for a closed connected
 * orientable surface of genus g). A file the reader rejects gets "error: <message>". */
#include <stdio.h>
#include <stdlib.h>

#include "flintstone.h"

typedef struct census {
    size_t used_vertices, edges, boundary, nonmanifold, degenerate, misoriented;
} census;

/* An undirected edge as (min << 32 | max) << 1 | direction, so sorting groups an edge's uses. */
static int compare_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

static void count_edges(const uint64_t *keys, size_t n, census *c)
{
    for (size_t i = 0; i < n;) {
        size_t j = i, forward = 0;
        while (j < n && keys[j] >> 1 == keys[i] >> 1)
            forward += keys[j++] & 1;
        size_t uses = j - i;
        c->edges++;
        if (uses == 1) c->boundary++;
        if (uses > 2) c->nonmanifold++;
        if (uses == 2 && forward != 1) c->misoriented++;
        i = j;
    }
}

static int take_census(const fl_mesh *m, census *c)
{
    uint64_t *keys = malloc(3 * m->triangle_count * sizeof *keys + 1);
    unsigned char *used = calloc(m->vertex_count + 1, 1);
    size_t n = 0;
    if (!keys || !used) {
        free(keys);
        free(used);
        return 1;
    }
    for (size_t t = 0; t < m->triangle_count; t++) {
        const uint32_t *v = m->tri + 3 * t;
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) c->degenerate++;
        for (int k = 0; k < 3; k++) {
            uint64_t a = v[k], b = v[(k + 1) % 3];
            keys[n++] = a < b ? (a << 32 | b) << 1 | 1 : (b << 32 | a) << 1;
            used[v[k]] = 1;
        }
    }
    qsort(keys, n, sizeof *keys, compare_u64);
    count_edges(keys, n, c);
    for (size_t i = 0; i < m->vertex_count; i++)
        c->used_vertices += used[i];
    free(keys);
    free(used);
    return 0;
}

int main(int argc, char **argv)
{
    int failures = 0;
    for (int i = 1; i < argc; i++) {
        fl_mesh mesh = {0};
        fl_error err;
        census c = {0};
        if (fl_read_mesh(argv[i], &mesh, &err) != FL_OK) {
            char msg[1200];
            fl_error_format(&err, msg, sizeof msg);
            printf("%s error: %s\n", argv[i], msg);
            continue;
        }
        if (take_census(&mesh, &c)) {
            fprintf(stderr, "mesh_census: out of memory on %s\n", argv[i]);
            failures++;
        } else {
            int closed = mesh.triangle_count > 0 && c.boundary == 0 && c.nonmanifold == 0 &&
                         c.degenerate == 0;
            const char *closed_word = mesh.triangle_count == 0 ? "no-triangles"
                                      : closed                 ? "yes"
                                                               : "no";
            printf("%s vertices=%zu triangles=%zu closed=%s oriented=%s boundary_edges=%zu "
                   "nonmanifold_edges=%zu degenerate=%zu euler=%lld\n",
                   argv[i], mesh.vertex_count, mesh.triangle_count, closed_word,
                   closed && c.misoriented == 0 ? "yes" : "no", c.boundary, c.nonmanifold,
                   c.degenerate,
                   (long long)c.used_vertices - (long long)c.edges +
                       (long long)mesh.triangle_count);
        }
        fl_mesh_free(&mesh);
    }
    return failures ? 1 : 0;
}
