/* Helpers shared by the io tests: parse a string literal, check an error's line and message,
 * capture a writer's output through a temporary file. */
#ifndef IO_TEST_UTIL_H
#define IO_TEST_UTIL_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fl_test.h"

/* Checks that err holds FL_ERR_INPUT at `line` with `needle` in its message. */
#define CHECK_INPUT_ERROR(status, err, want_line, needle)                                          \
    do {                                                                                           \
        CHECK_EQ_INT((status), FL_ERR_INPUT);                                                      \
        CHECK_EQ_INT((err).line, (want_line));                                                     \
        CHECK_MSG(strstr((err).message, (needle)) != NULL, "message '%s' lacks '%s'",              \
                  (err).message, (needle));                                                        \
    } while (0)

/* A malloc'ed copy of s without a terminating NUL, so ASan catches any read past the end. */
static inline char *io_test_unterminated(const char *s, size_t *size)
{
    *size = strlen(s);
    char *p = malloc(*size ? *size : 1);
    if (p) memcpy(p, s, *size);
    return p;
}

/* Runs a writer into a temporary file and returns its bytes, NUL-terminated (caller frees). */
#define IO_TEST_CAPTURE(call_with_fp, out_text, out_size, status)                                  \
    do {                                                                                           \
        FILE *fp = tmpfile();                                                                      \
        (out_text) = NULL;                                                                         \
        (out_size) = 0;                                                                            \
        CHECK(fp != NULL);                                                                         \
        if (!fp) break;                                                                            \
        (status) = call_with_fp;                                                                   \
        long n_ = ftell(fp);                                                                       \
        rewind(fp);                                                                                \
        (out_text) = malloc((size_t)n_ + 1);                                                       \
        (out_size) = fread((out_text), 1, (size_t)n_, fp);                                         \
        (out_text)[(out_size)] = '\0';                                                             \
        fclose(fp);                                                                                \
    } while (0)

#endif /* IO_TEST_UTIL_H */
