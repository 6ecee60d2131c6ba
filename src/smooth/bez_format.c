/* The .bez text format for cubic Bézier triangle nets (docs/formats.md, "Bézier nets"):
 *
 *   flintstone-bez 1
 *   patches N
 *   c0 c1 c2              corner nodes of patch 0 (shared nodes = shared corners)
 *   x y z                 ten control points b300 b210 b201 b120 b111 b102 b030 b021 b012 b003
 *   ...
 *
 * '#' starts a comment; blank lines are ignored. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "smooth/smooth_internal.h"

fl_status fl_g1_write_bez(const char *path, const fl_g1_surface *s, fl_error *err)
{
    if (!path || !s) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "NULL argument");
    fl_out_file out;
    fl_status st = fl_out_open(&out, path, 0, err);
    if (st) return st;
    fprintf(out.fp,
            "flintstone-bez 1\n# cubic Bezier triangles, 10 control points each in the "
            "order b300 b210 b201 b120 b111 b102 b030 b021 b012 b003\npatches %zu\n",
            s->patch_count);
    for (size_t p = 0; p < s->patch_count; p++) {
        fprintf(out.fp, "%u %u %u\n", s->corner[3 * p], s->corner[3 * p + 1], s->corner[3 * p + 2]);
        for (int k = 0; k < 10; k++) {
            const double *c = s->ctrl + 30 * p + 3 * k;
            fprintf(out.fp, "%.17g %.17g %.17g\n", c[0], c[1], c[2]);
        }
    }
    return fl_out_commit(&out, err);
}

typedef struct bez_reader {
    FILE *fp;
    const char *path;
    long line;
    char buf[1024];
} bez_reader;

/* Next line that is not blank or a comment; 0 at end of file. */
static int next_line(bez_reader *r)
{
    while (fgets(r->buf, sizeof r->buf, r->fp)) {
        r->line++;
        char *hash = strchr(r->buf, '#');
        if (hash) *hash = '\0';
        if (strspn(r->buf, " \t\r\n") != strlen(r->buf)) return 1;
    }
    return 0;
}

/* Parses exactly n numbers from the current line into v; 0 on success. */
static int parse_numbers(const char *s, double *v, int n)
{
    char *end;
    for (int i = 0; i < n; i++) {
        errno = 0;
        v[i] = strtod(s, &end);
        if (end == s || !isfinite(v[i])) return -1;
        s = end;
    }
    return strspn(s, " \t\r\n") == strlen(s) ? 0 : -1;
}

static fl_status read_patches(bez_reader *r, fl_g1_surface *out, fl_error *err)
{
    size_t n = 0;
    char tail[8];
    if (!next_line(r) || sscanf(r->buf, "flintstone-bez 1 %1s", tail) > 0 ||
        strncmp(r->buf, "flintstone-bez 1", 16) != 0)
        return fl_fail(err, FL_ERR_INPUT, r->path, r->line, "expected 'flintstone-bez 1'");
    if (!next_line(r) || sscanf(r->buf, "patches %zu", &n) != 1 || n == 0 || n > (1u << 28))
        return fl_fail(err, FL_ERR_INPUT, r->path, r->line, "expected 'patches N', N >= 1");
    /* The arrays grow with the patches actually read, so a short file claiming 2^28 patches
     * does not reserve 64 GB up front (fuzz_read_bez). */
    size_t cap = 0;
    for (size_t p = 0; p < n; p++) {
        if (p == cap) {
            cap = cap ? (cap > n / 2 ? n : 2 * cap) : (n < 256 ? n : 256);
            double *ctrl = fl_realloc_array(out->ctrl, cap, 30 * sizeof(double));
            if (ctrl) out->ctrl = ctrl;
            uint32_t *corner = fl_realloc_array(out->corner, cap, 3 * sizeof(uint32_t));
            if (corner) out->corner = corner;
            if (!ctrl || !corner) return fl_fail(err, FL_ERR_NOMEM, NULL, -1, "out of memory");
        }
        out->patch_count = p + 1;
        double c[3];
        if (!next_line(r) || parse_numbers(r->buf, c, 3))
            return fl_fail(err, FL_ERR_INPUT, r->path, r->line,
                           "patch %zu: expected three corner node numbers", p);
        for (int k = 0; k < 3; k++) {
            if (c[k] < 0 || c[k] >= 4294967295.0 || c[k] != floor(c[k]))
                return fl_fail(err, FL_ERR_INPUT, r->path, r->line, "bad node number");
            out->corner[3 * p + k] = (uint32_t)c[k];
            if ((size_t)c[k] + 1 > out->node_count) out->node_count = (size_t)c[k] + 1;
        }
        for (int k = 0; k < 10; k++)
            if (!next_line(r) || parse_numbers(r->buf, out->ctrl + 30 * p + 3 * k, 3))
                return fl_fail(err, FL_ERR_INPUT, r->path, r->line,
                               "patch %zu: expected control point %d as 3 finite numbers", p, k);
    }
    if (next_line(r))
        return fl_fail(err, FL_ERR_INPUT, r->path, r->line, "data after the last patch");
    return FL_OK;
}

fl_status fl_g1_read_bez(const char *path, fl_g1_surface *out, fl_error *err)
{
    if (out) memset(out, 0, sizeof *out);
    if (!path || !out) return fl_fail(err, FL_ERR_USAGE, NULL, -1, "NULL argument");
    bez_reader r = {.fp = fopen(path, "r"), .path = path};
    if (!r.fp) return fl_fail(err, FL_ERR_IO, path, -1, "cannot open: %s", strerror(errno));
    fl_status st = read_patches(&r, out, err);
    fclose(r.fp);
    if (st) fl_g1_surface_free(out);
    return st;
}
