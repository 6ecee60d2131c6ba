/* A minimal test harness: each tests/<module>/test_*.c is one executable and one ctest test.
 * A test function checks properties with CHECK*; a failed check prints where and why and marks
 * the test failed, and the run continues with the next test. The executable prints
 * "N passed, N failed" and exits non-zero when anything failed. */
#ifndef FL_TEST_H
#define FL_TEST_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "flintstone.h"

static int fl_test_failed_checks;

#define CHECK(cond)                                                                                \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond);             \
            fl_test_failed_checks++;                                                               \
        }                                                                                          \
    } while (0)

#define CHECK_MSG(cond, ...)                                                                       \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            fprintf(stderr, "%s:%d: check failed: %s: ", __FILE__, __LINE__, #cond);             \
            fprintf(stderr, __VA_ARGS__);                                                          \
            fputc('\n', stderr);                                                                   \
            fl_test_failed_checks++;                                                               \
        }                                                                                          \
    } while (0)

#define CHECK_EQ_INT(a, b)                                                                         \
    do {                                                                                           \
        long long fl_a_ = (long long)(a), fl_b_ = (long long)(b);                                  \
        if (fl_a_ != fl_b_) {                                                                      \
            fprintf(stderr, "%s:%d: check failed: %s == %s (%lld vs %lld)\n", __FILE__, __LINE__, \
                    #a, #b, fl_a_, fl_b_);                                                         \
            fl_test_failed_checks++;                                                               \
        }                                                                                          \
    } while (0)

#define CHECK_NEAR(a, b, tol)                                                                      \
    do {                                                                                           \
        double fl_a_ = (double)(a), fl_b_ = (double)(b);                                           \
        if (!(fabs(fl_a_ - fl_b_) <= (tol))) {                                                     \
            fprintf(stderr, "%s:%d: check failed: %s ~ %s (%.17g vs %.17g, tol %g)\n", __FILE__,  \
                    __LINE__, #a, #b, fl_a_, fl_b_, (double)(tol));                                \
            fl_test_failed_checks++;                                                               \
        }                                                                                          \
    } while (0)

/* Checks a status and prints the error message when it is not the expected one. */
#define CHECK_STATUS(call, expected, errp)                                                         \
    do {                                                                                           \
        fl_status fl_s_ = (call);                                                                  \
        if (fl_s_ != (expected)) {                                                                 \
            char fl_buf_[1200];                                                                    \
            fl_error_format((errp), fl_buf_, sizeof fl_buf_);                                      \
            fprintf(stderr, "%s:%d: %s returned %d, expected %d (%s)\n", __FILE__, __LINE__,      \
                    #call, (int)fl_s_, (int)(expected), fl_buf_);                                  \
            fl_test_failed_checks++;                                                               \
        }                                                                                          \
    } while (0)

typedef struct fl_test_case {
    const char *name;
    void (*fn)(void);
} fl_test_case;

#define FL_TEST_CASE(fn) {#fn, fn}

static inline int fl_test_run(const fl_test_case *cases, size_t n)
{
    int passed = 0, failed = 0;
    for (size_t i = 0; i < n; i++) {
        int before = fl_test_failed_checks;
        cases[i].fn();
        if (fl_test_failed_checks == before) {
            passed++;
            printf("ok   %s\n", cases[i].name);
        } else {
            failed++;
            printf("FAIL %s\n", cases[i].name);
        }
    }
    printf("%d passed, %d failed\n", passed, failed);
    return failed ? 1 : 0;
}

#define FL_TEST_MAIN(...)                                                                          \
    int main(void)                                                                                 \
    {                                                                                              \
        static const fl_test_case cases[] = {__VA_ARGS__};                                         \
        return fl_test_run(cases, sizeof cases / sizeof cases[0]);                                 \
    }

/* A deterministic 64-bit generator (splitmix64) so failures reproduce. */
static inline unsigned long long fl_test_rand_u64(unsigned long long *state)
{
    unsigned long long z = (*state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

/* Uniform double in [0,1). */
static inline double fl_test_rand01(unsigned long long *state)
{
    return (double)(fl_test_rand_u64(state) >> 11) * (1.0 / 9007199254740992.0);
}

#endif /* FL_TEST_H */
