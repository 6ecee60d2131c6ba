/* Sign-magnitude integers on caller-provided limbs: just enough arithmetic (add, subtract,
 * multiply) to evaluate the predicate determinants exactly. Schoolbook multiplication is right
 * here: the exact stage runs rarely and its operands are usually one to three limbs long. */
#include <math.h>

#include "predicates/predicates_internal.h"

int fl_big_low_exponent(double x)
{
    int e;
    /* frexp is exact and handles subnormals: |x| = f * 2^e with f in [0.5, 1), so
     * m = f * 2^53 is an integer below 2^53 (an exact scaling) and |x| = m * 2^(e - 53). */
    uint64_t m = (uint64_t)ldexp(frexp(fabs(x), &e), 53);
    e -= 53;
    while ((m & 1) == 0) {
        m >>= 1;
        e++;
    }
    return e;
}

void fl_big_set_double(fl_big *r, double x, int emin)
{
    r->len = 0;
    r->neg = 0;
    if (x == 0) return;
    int e;
    uint64_t m = (uint64_t)ldexp(frexp(fabs(x), &e), 53);
    int shift = e - 53 - emin; /* may be negative when m has trailing zero bits */
    while (shift < 0) {
        m >>= 1; /* drops only zero bits: the caller guarantees the lowest set bit >= emin */
        shift++;
    }
    int word = shift / 32, bit = shift % 32;
    for (int i = 0; i < word; i++)
        r->limb[i] = 0;
    /* m < 2^53 shifted by < 32 bits fits in 85 bits: three limbs. */
    uint64_t lo = (m << bit) & 0xffffffffu;
    uint64_t mid = bit ? (m >> (32 - bit)) : (m >> 32);
    r->limb[word] = (uint32_t)lo;
    r->limb[word + 1] = (uint32_t)(mid & 0xffffffffu);
    r->limb[word + 2] = (uint32_t)(mid >> 32);
    r->len = word + 3;
    while (r->len > 0 && r->limb[r->len - 1] == 0)
        r->len--;
    r->neg = x < 0;
}

static void trim(fl_big *r)
{
    while (r->len > 0 && r->limb[r->len - 1] == 0)
        r->len--;
    if (r->len == 0) r->neg = 0;
}

static int mag_cmp(const fl_big *a, const fl_big *b)
{
    if (a->len != b->len) return a->len < b->len ? -1 : 1;
    for (int i = a->len - 1; i >= 0; i--)
        if (a->limb[i] != b->limb[i]) return a->limb[i] < b->limb[i] ? -1 : 1;
    return 0;
}

/* |r| = |a| + |b|. */
static void mag_add(fl_big *r, const fl_big *a, const fl_big *b)
{
    int n = a->len > b->len ? a->len : b->len;
    uint64_t carry = 0;
    for (int i = 0; i < n; i++) {
        uint64_t s = carry;
        if (i < a->len) s += a->limb[i];
        if (i < b->len) s += b->limb[i];
        r->limb[i] = (uint32_t)s;
        carry = s >> 32;
    }
    r->len = n;
    if (carry) r->limb[r->len++] = (uint32_t)carry;
}

/* |r| = |a| - |b| for |a| >= |b|. */
static void mag_sub(fl_big *r, const fl_big *a, const fl_big *b)
{
    uint64_t borrow = 0;
    for (int i = 0; i < a->len; i++) {
        uint64_t bi = (i < b->len ? b->limb[i] : 0) + borrow;
        uint64_t ai = a->limb[i];
        borrow = ai < bi;
        r->limb[i] = (uint32_t)(ai - bi + (borrow << 32));
    }
    r->len = a->len;
    trim(r);
}

/* r = a + (negate_b ? -b : b): the one signed addition behind add and sub. */
static void signed_add(fl_big *r, const fl_big *a, const fl_big *b, int negate_b)
{
    int a_neg = a->neg, b_neg = b->neg ^ negate_b;
    if (b->len == 0) b_neg = 0;
    if (a_neg == b_neg) {
        mag_add(r, a, b);
        r->neg = a_neg;
    } else if (mag_cmp(a, b) >= 0) {
        mag_sub(r, a, b);
        r->neg = a_neg;
    } else {
        mag_sub(r, b, a);
        r->neg = b_neg;
    }
    trim(r);
}

void fl_big_add(fl_big *r, const fl_big *a, const fl_big *b)
{
    signed_add(r, a, b, 0);
}

void fl_big_sub(fl_big *r, const fl_big *a, const fl_big *b)
{
    signed_add(r, a, b, 1);
}

void fl_big_mul(fl_big *r, const fl_big *a, const fl_big *b)
{
    if (a->len == 0 || b->len == 0) {
        r->len = 0;
        r->neg = 0;
        return;
    }
    int n = a->len + b->len;
    for (int i = 0; i < n; i++)
        r->limb[i] = 0;
    for (int i = 0; i < a->len; i++) {
        uint64_t carry = 0, ai = a->limb[i];
        /* ai * bj + r + carry <= (2^32-1)^2 + 2 (2^32-1) < 2^64: no overflow. */
        for (int j = 0; j < b->len; j++) {
            uint64_t t = ai * b->limb[j] + r->limb[i + j] + carry;
            r->limb[i + j] = (uint32_t)t;
            carry = t >> 32;
        }
        r->limb[i + b->len] = (uint32_t)carry;
    }
    r->len = n;
    r->neg = a->neg ^ b->neg;
    trim(r);
}
