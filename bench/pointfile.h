/* The point files of the Delaunay benchmarks (PREFIX.bin of bench/gen_points.c): raw native
 * doubles, `dim` per point, nothing else. Read once before any timing by both sides. */
#ifndef FL_BENCH_POINTFILE_H
#define FL_BENCH_POINTFILE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Reads PATH as dim doubles per point; returns a malloc'd array (free with free()) and sets *n,
 * or prints why to stderr and returns NULL (also when the size is not a multiple of a point). */
double *bench_read_points(const char *path, int dim, size_t *n);

#ifdef __cplusplus
}
#endif

#endif /* FL_BENCH_POINTFILE_H */
