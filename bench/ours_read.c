/* Our side of the mesh-reading benchmarks: fl_read_mesh, timed with the protocol of
 * bench/timing.h (page cache warmed, one warm-up run, median of REPS runs, free untimed).
 *
 *   ours_read FILE [REPS]
 */
#include <stdio.h>
#include <stdlib.h>

#include "flintstone.h"
#include "timing.h"

static int load(void *ctx, const char *path, void **result, size_t *vertices, size_t *triangles)
{
    (void)ctx;
    fl_mesh *mesh = calloc(1, sizeof *mesh);
    fl_error err;
    if (!mesh) return 1;
    if (fl_read_mesh(path, mesh, &err) != FL_OK) {
        char msg[1200];
        fl_error_format(&err, msg, sizeof msg);
        fprintf(stderr, "ours: %s\n", msg);
        free(mesh);
        return 1;
    }
    *result = mesh;
    *vertices = mesh->vertex_count;
    *triangles = mesh->triangle_count;
    return 0;
}

static void release(void *ctx, void *result)
{
    (void)ctx;
    fl_mesh_free(result);
    free(result);
}

int main(int argc, char **argv)
{
    const char *path;
    int reps;
    if (bench_parse_args(argc, argv, &path, &reps)) return 2;
    bench_reader reader = {"ours", load, release, NULL};
    return bench_time_reader(&reader, path, reps) ? 1 : 0;
}
