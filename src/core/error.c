/* Error values: every fallible call fills an fl_error that a user can act on. */
#include <stdio.h>
#include <string.h>

#include "core/core.h"

#ifndef FL_VERSION_STRING
#define FL_VERSION_STRING "0.0.0"
#endif

const char *fl_version(void) { return FL_VERSION_STRING; }

const char *fl_status_string(fl_status status)
{
    switch (status) {
    case FL_OK:
        return "ok";
    case FL_ERR_USAGE:
        return "usage error";
    case FL_ERR_INPUT:
        return "bad input";
    case FL_ERR_ALGORITHM:
        return "algorithm could not complete";
    case FL_ERR_IO:
        return "I/O failure";
    case FL_ERR_NOMEM:
        return "out of memory";
    }
    return "unknown status";
}

void fl_error_clear(fl_error *err)
{
    if (!err) return;
    err->status = FL_OK;
    err->file[0] = '\0';
    err->line = -1;
    err->offset = -1;
    err->message[0] = '\0';
}

static void set_file(fl_error *err, const char *file)
{
    if (!file) {
        err->file[0] = '\0';
        return;
    }
    size_t n = strlen(file);
    if (n >= sizeof err->file) n = sizeof err->file - 1;
    memcpy(err->file, file, n);
    err->file[n] = '\0';
}

/* Fills err. The arguments may be err's own message or file (wrapping an inner error:
 * "skin: %s", err->message), so they are formatted and copied before the struct is cleared. */
static fl_status fail_v(fl_error *err, fl_status status, const char *file, long line,
                        long long offset, const char *fmt, va_list ap)
{
    char msg[sizeof err->message], where[sizeof err->file];
    vsnprintf(msg, sizeof msg, fmt, ap);
    snprintf(where, sizeof where, "%s", file ? file : "");
    fl_error_clear(err);
    err->status = status;
    set_file(err, file ? where : NULL);
    err->line = line < 0 ? -1 : line;
    err->offset = offset < 0 ? -1 : offset;
    memcpy(err->message, msg, sizeof msg);
    return status;
}

fl_status fl_fail(fl_error *err, fl_status status, const char *file, long line, const char *fmt,
                  ...)
{
    if (!err) return status;
    va_list ap;
    va_start(ap, fmt);
    fail_v(err, status, file, line, -1, fmt, ap);
    va_end(ap);
    return status;
}

fl_status fl_fail_at_offset(fl_error *err, fl_status status, const char *file, long long offset,
                            const char *fmt, ...)
{
    if (!err) return status;
    va_list ap;
    va_start(ap, fmt);
    fail_v(err, status, file, -1, offset, fmt, ap);
    va_end(ap);
    return status;
}

void fl_error_format(const fl_error *err, char *buf, size_t size)
{
    if (!buf || size == 0) return;
    if (!err) {
        snprintf(buf, size, "unknown error");
        return;
    }
    const char *msg = err->message[0] ? err->message : fl_status_string(err->status);
    if (err->file[0] && err->line >= 0)
        snprintf(buf, size, "%s:%ld: %s", err->file, err->line, msg);
    else if (err->file[0] && err->offset >= 0)
        snprintf(buf, size, "%s: byte %lld: %s", err->file, err->offset, msg);
    else if (err->file[0])
        snprintf(buf, size, "%s: %s", err->file, msg);
    else
        snprintf(buf, size, "%s", msg);
}
