/* Peer for the mesh-reading benchmarks: Open Asset Import Library (Debian libassimp-dev) through
 * its C API, timed with the same protocol as bench/ours_read.c (see bench/timing.h).
 *
 *   assimp_read [--weld] FILE [REPS]
 *
 * Without --weld, aiImportFile runs with no post-processing step at all (flags 0): assimp's
 * loader builds its scene and nothing else. Its STL loader then keeps three fresh vertices per
 * triangle, whereas fl_read_mesh welds coincident STL vertices; --weld asks assimp for the same
 * work: aiProcess_JoinIdenticalVertices, plus aiProcess_DropNormals because the join compares
 * every vertex attribute and STL gives each corner its facet's normal, which would keep the
 * corners of different facets apart. The vertex counts in the RESULT line show which work was
 * done. */
#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <stdio.h>
#include <string.h>

#include "../timing.h"

static int load(void *ctx, const char *path, void **result, size_t *vertices, size_t *triangles)
{
    unsigned flags = *(const unsigned *)ctx;
    const struct aiScene *scene = aiImportFile(path, flags);
    if (!scene) {
        fprintf(stderr, "assimp: %s: %s\n", path, aiGetErrorString());
        return 1;
    }
    *result = (void *)scene;
    *vertices = *triangles = 0;
    for (unsigned i = 0; i < scene->mNumMeshes; i++) {
        *vertices += scene->mMeshes[i]->mNumVertices;
        *triangles += scene->mMeshes[i]->mNumFaces;
    }
    return 0;
}

static void release(void *ctx, void *result)
{
    (void)ctx;
    aiReleaseImport((const struct aiScene *)result);
}

int main(int argc, char **argv)
{
    unsigned flags = 0;
    const char *name = "assimp";
    if (argc > 1 && strcmp(argv[1], "--weld") == 0) {
        flags = aiProcess_JoinIdenticalVertices | aiProcess_DropNormals;
        name = "assimp+weld";
        argv[1] = argv[0];
        argc--;
        argv++;
    }
    const char *path;
    int reps;
    if (bench_parse_args(argc, argv, &path, &reps)) return 2;
    bench_reader reader = {name, load, release, &flags};
    return bench_time_reader(&reader, path, reps) ? 1 : 0;
}
