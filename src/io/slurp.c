#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "io/io_internal.h"

fl_status fl_io_slurp(const char *path, char **data, size_t *size, fl_error *err)
{
    *data = NULL;
    *size = 0;
    FILE *fp = fopen(path, "rb");
    if (!fp) return fl_fail(err, FL_ERR_IO, path, -1, "cannot open: %s", strerror(errno));
    fl_vec buf;
    fl_vec_init(&buf, 1);
    char chunk[1 << 16];
    size_t n;
    while ((n = fread(chunk, 1, sizeof chunk, fp)) > 0) {
        if (fl_vec_push(&buf, chunk, n)) {
            fclose(fp);
            fl_vec_free(&buf);
            return fl_fail(err, FL_ERR_NOMEM, path, -1, "file too large to read into memory");
        }
    }
    int bad = ferror(fp);
    fclose(fp);
    if (bad || fl_vec_push(&buf, "", 1)) {
        fl_vec_free(&buf);
        return fl_fail(err, bad ? FL_ERR_IO : FL_ERR_NOMEM, path, -1, "read failed");
    }
    *size = buf.count - 1;
    *data = buf.data;
    return FL_OK;
}
