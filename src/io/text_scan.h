/* Scanning numbers in text formats: one token to one double, and line-by-line reading of
 * numeric text files (.xyz, .xy, .csv). Shared by text_points.c, xy_polygon.c and json.c.
 *
 * Buffers are never assumed to be NUL-terminated: a token is copied into a bounded local
 * buffer before strtod sees it, so a parse can never read past `end`. strtod follows the
 * C library's LC_NUMERIC locale; the flintstone command never calls setlocale, so it parses in
 * the "C" locale ('.' as the decimal point). A program that sets another locale must expect
 * "1.5" to be rejected there. */
#ifndef FL_IO_TEXT_SCAN_H
#define FL_IO_TEXT_SCAN_H

#include <stddef.h>

#include "core/core.h"

/* Longest token taken as a number; a longer run of digits is reported as "not a number". */
#define FL_TEXT_MAX_TOKEN 256

typedef enum fl_number_scan {
    FL_NUMBER_OK = 0,
    FL_NUMBER_INVALID = 1,  /* the token is not (entirely) a number */
    FL_NUMBER_NONFINITE = 2 /* "nan", "inf", or a magnitude beyond DBL_MAX such as 1e999 */
} fl_number_scan;

/* Parses s[0..len) as one floating-point number (strtod syntax, whole token consumed). */
fl_number_scan fl_scan_double(const char *s, size_t len, double *value);

/* Copies s[0..len) into buf for an error message: at most ~24 characters, unprintable bytes
 * shown as '?', "..." when shortened. */
void fl_scan_quote(const char *s, size_t len, char *buf, size_t size);

typedef enum fl_line_kind {
    FL_LINE_EOF,     /* no more lines */
    FL_LINE_BLANK,   /* empty or whitespace only: separates rings in .xy polygons */
    FL_LINE_COMMENT, /* only a '#' comment after optional whitespace */
    FL_LINE_NUMBERS, /* numbers separated by whitespace, ',' or ';' (maybe a trailing comment) */
    FL_LINE_TEXT     /* has a token that is not a number: a header line, or an error */
} fl_line_kind;

/* A cursor over a numeric text file. A leading UTF-8 byte order mark is skipped; lines end at
 * '\n' and a '\r' before it is whitespace, so CRLF files read like LF files. */
typedef struct fl_text_lines {
    const char *p, *end;
    long line;      /* 1-based number of the line last returned */
    char bad[40];   /* FL_LINE_TEXT: the first token that is not a number, quoted */
    size_t numeric; /* FL_LINE_TEXT: how many of its tokens are numbers */
} fl_text_lines;

void fl_text_lines_init(fl_text_lines *t, const char *data, size_t size);

/* Reads the next line. For FL_LINE_NUMBERS, *count is how many numbers the line holds and the
 * first min(*count, max) are stored in values. A line whose tokens are all numbers but one is
 * NaN or infinite fails with FL_ERR_INPUT naming `name` and the line. */
fl_status fl_text_lines_next(fl_text_lines *t, const char *name, double *values, size_t max,
                             size_t *count, fl_line_kind *kind, fl_error *err);

#endif /* FL_IO_TEXT_SCAN_H */
