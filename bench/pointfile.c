/* See pointfile.h. */
#include "pointfile.h"

#include <stdio.h>
#include <stdlib.h>

double *bench_read_points(const char *path, int dim, size_t *n)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) {
        fprintf(stderr, "cannot open %s\n", path);
        return NULL;
    }
    long size = -1;
    if (fseek(fp, 0, SEEK_END) == 0) size = ftell(fp);
    size_t point = sizeof(double) * (size_t)dim;
    double *c = NULL;
    if (size > 0 && (size_t)size % point == 0 && fseek(fp, 0, SEEK_SET) == 0 &&
        (c = malloc((size_t)size)) &&
        fread(c, point, (size_t)size / point, fp) == (size_t)size / point) {
        *n = (size_t)size / point;
    } else {
        fprintf(stderr, "%s: not a file of %d doubles per point\n", path, dim);
        free(c);
        c = NULL;
    }
    fclose(fp);
    return c;
}
