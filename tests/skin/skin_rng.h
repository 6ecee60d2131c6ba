/* The xorshift64 generator the skin tests draw their random ball sets from: uniform in [0, 1)
 * with 53 random bits. Each test keeps its own state (and seed), so its sets do not depend on
 * other tests. */
#ifndef FL_TEST_SKIN_RNG_H
#define FL_TEST_SKIN_RNG_H

#include <stdint.h>

static inline double skin_rng_next(uint64_t *state)
{
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    return (double)(*state >> 11) / 9007199254740992.0;
}

#endif /* FL_TEST_SKIN_RNG_H */
