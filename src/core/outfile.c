#define _POSIX_C_SOURCE 200809L
/* Atomic output: write to a temporary next to the target, rename when complete. rename(2) on
 * the same file system replaces the target in one step, so readers see the old file or the
 * new one, never a half-written one. */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "core/core.h"

fl_status fl_out_open(fl_out_file *out, const char *path, int binary, fl_error *err)
{
    memset(out, 0, sizeof *out);
    size_t n = strlen(path);
    if (n == 0 || n >= sizeof out->path)
        return fl_fail(err, FL_ERR_USAGE, path, -1, "output path is empty or too long");
    memcpy(out->path, path, n + 1);
    snprintf(out->tmp_path, sizeof out->tmp_path, "%s.tmp.%ld", path, (long)getpid());
    out->fp = fopen(out->tmp_path, binary ? "wb" : "w");
    if (!out->fp)
        return fl_fail(err, FL_ERR_IO, path, -1, "cannot create output file: %s", strerror(errno));
    return FL_OK;
}

fl_status fl_out_commit(fl_out_file *out, fl_error *err)
{
    if (!out->fp) return fl_fail(err, FL_ERR_IO, out->path, -1, "output file is not open");
    int bad = ferror(out->fp);
    int saved = errno;
    if (fclose(out->fp) != 0 && !bad) {
        bad = 1;
        saved = errno;
    }
    out->fp = NULL;
    if (bad) {
        remove(out->tmp_path);
        return fl_fail(err, FL_ERR_IO, out->path, -1, "write failed: %s", strerror(saved));
    }
    if (rename(out->tmp_path, out->path) != 0) {
        saved = errno;
        remove(out->tmp_path);
        return fl_fail(err, FL_ERR_IO, out->path, -1, "cannot replace output file: %s",
                       strerror(saved));
    }
    return FL_OK;
}

void fl_out_abort(fl_out_file *out)
{
    if (out->fp) {
        fclose(out->fp);
        out->fp = NULL;
    }
    if (out->tmp_path[0]) remove(out->tmp_path);
}

void fl_path_extension(const char *path, char *ext, size_t size)
{
    if (size == 0) return;
    ext[0] = '\0';
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    if (!dot || dot == base) return;
    size_t i = 0;
    for (const char *p = dot + 1; *p && i + 1 < size; p++)
        ext[i++] = (char)tolower((unsigned char)*p);
    ext[i] = '\0';
}
