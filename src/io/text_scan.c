#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "io/text_scan.h"

/* Clinger's fast path (W. D. Clinger, "How to read floating point numbers accurately", PLDI
 * 1990): when the decimal significand w is at most 2^53 and 10^k has |k| <= 22, both are exact
 * doubles, so w * 10^k (or w / 10^-k) is one correctly rounded IEEE operation and equals what a
 * correctly rounding strtod returns. It covers the usual "%.6f"-style coordinates; anything else
 * (more than 15-16 digits, hex, nan, ...) goes to strtod. It needs operations evaluated in
 * double precision (FLT_EVAL_METHOD 0, as on x86-64 and AArch64), not x87 extended. */
static int fast_decimal(const char *p, const char *end, double *value)
{
#if FLT_EVAL_METHOD != 0
    return 0;
#endif
    static const double pow10[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                     1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                     1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    int negative = p < end && *p == '-';
    if (p < end && (*p == '-' || *p == '+')) p++;
    uint64_t w = 0;
    int digits = 0, any = 0, exp10 = 0, fraction = 0;
    for (; p < end; p++) {
        if (*p == '.' && !fraction) {
            fraction = 1;
            continue;
        }
        if (*p < '0' || *p > '9') break;
        any = 1;
        exp10 -= fraction;
        if (w == 0 && *p == '0') continue; /* leading zeros carry no digits */
        if (++digits > 19) return 0;       /* w would overflow 64 bits */
        w = w * 10 + (uint64_t)(*p - '0');
    }
    if (!any) return 0;
    if (p < end && (*p == 'e' || *p == 'E')) {
        int minus = ++p < end && *p == '-';
        if (p < end && (*p == '-' || *p == '+')) p++;
        if (p == end || *p < '0' || *p > '9') return 0;
        int e = 0;
        for (; p < end && *p >= '0' && *p <= '9'; p++)
            if (e < 10000) e = e * 10 + (*p - '0');
        exp10 += minus ? -e : e;
    }
    if (p != end || w > (UINT64_C(1) << 53) || exp10 < -22 || exp10 > 22) return 0;
    double v = exp10 < 0 ? (double)w / pow10[-exp10] : (double)w * pow10[exp10];
    *value = negative ? -v : v;
    return 1;
}

fl_number_scan fl_scan_double(const char *s, size_t len, double *value)
{
    if (fast_decimal(s, s + len, value)) return FL_NUMBER_OK;
    /* strtod needs a NUL-terminated string and would skip leading whitespace; the bounded copy
     * gives it exactly the token, so it cannot run past the caller's buffer. */
    char buf[FL_TEXT_MAX_TOKEN];
    if (len == 0 || len >= sizeof buf) return FL_NUMBER_INVALID;
    if (s[0] == ' ' || (s[0] >= '\t' && s[0] <= '\r')) return FL_NUMBER_INVALID;
    memcpy(buf, s, len);
    buf[len] = '\0';
    char *stop;
    double v = strtod(buf, &stop);
    if (stop != buf + len) return FL_NUMBER_INVALID;
    /* ERANGE on underflow still gives a usable finite value; overflow gives HUGE_VAL. */
    if (!isfinite(v)) return FL_NUMBER_NONFINITE;
    *value = v;
    return FL_NUMBER_OK;
}

void fl_scan_quote(const char *s, size_t len, char *buf, size_t size)
{
    if (size == 0) return;
    size_t keep = len > 24 ? 24 : len;
    if (keep + 4 > size) keep = size > 4 ? size - 4 : 0;
    size_t i = 0;
    for (; i < keep; i++) {
        unsigned char c = (unsigned char)s[i];
        buf[i] = (c >= 0x20 && c < 0x7f) ? (char)c : '?';
    }
    if (keep < len && i + 3 < size) {
        memcpy(buf + i, "...", 3);
        i += 3;
    }
    buf[i] = '\0';
}

void fl_text_lines_init(fl_text_lines *t, const char *data, size_t size)
{
    t->p = data;
    t->end = data + size;
    t->line = 0;
    t->bad[0] = '\0';
    t->numeric = 0;
    if (size >= 3 && memcmp(data, "\xEF\xBB\xBF", 3) == 0) t->p += 3;
}

static int is_separator(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' || c == ',' || c == ';';
}

/* The end of the token starting at p: the next separator, '#', newline or the buffer end. */
static const char *token_end(const char *p, const char *end)
{
    while (p < end && *p != '\n' && *p != '#' && !is_separator(*p))
        p++;
    return p;
}

fl_status fl_text_lines_next(fl_text_lines *t, const char *name, double *values, size_t max,
                             size_t *count, fl_line_kind *kind, fl_error *err)
{
    *count = 0;
    if (t->p >= t->end) {
        *kind = FL_LINE_EOF;
        return FL_OK;
    }
    t->line++;
    const char *p = t->p, *end = t->end;
    int comment = 0, text = 0;
    t->numeric = 0;
    const char *nonfinite = NULL;
    size_t nonfinite_len = 0;
    while (p < end && *p != '\n') {
        if (is_separator(*p)) {
            p++;
        } else if (*p == '#') {
            comment = 1;
            while (p < end && *p != '\n')
                p++;
        } else {
            const char *e = token_end(p, end);
            double v = 0.0;
            fl_number_scan s = fl_scan_double(p, (size_t)(e - p), &v);
            if (s == FL_NUMBER_INVALID && !text) {
                text = 1;
                fl_scan_quote(p, (size_t)(e - p), t->bad, sizeof t->bad);
            } else if (s == FL_NUMBER_NONFINITE && !nonfinite) {
                nonfinite = p;
                nonfinite_len = (size_t)(e - p);
            }
            if (s != FL_NUMBER_INVALID) t->numeric++;
            if (*count < max) values[*count] = v;
            (*count)++;
            p = e;
        }
    }
    t->p = p < end ? p + 1 : end;
    if (text) {
        *kind = FL_LINE_TEXT;
    } else if (nonfinite) {
        char q[40];
        fl_scan_quote(nonfinite, nonfinite_len, q, sizeof q);
        return fl_fail(err, FL_ERR_INPUT, name, t->line,
                       "coordinate '%s' is not a finite number (NaN, infinity or beyond "
                       "the double range)",
                       q);
    } else if (*count > 0) {
        *kind = FL_LINE_NUMBERS;
    } else {
        *kind = comment ? FL_LINE_COMMENT : FL_LINE_BLANK;
    }
    return FL_OK;
}
