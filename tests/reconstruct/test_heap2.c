/* The priority queue of constriction (src/reconstruct/heap2.c, a 4-ary heap of the keys below a
 * bar plus an unsorted array of the parked keys at or above it) against a sorted array: whatever
 * the interleaving of pushes and pops, every pop must return the least entry still queued in the
 * order the thesis' Algorithm 5.1 relies on (key, then the input indices of a, b, c), so that
 * runs are deterministic and independent of the queue's implementation. */
#include <string.h>

#include "fl_test.h"
#include "reconstruct/constrict2_internal.h"

static uint64_t rng = 0x243f6a8885a308d3ull;

static uint32_t next_u32(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (uint32_t)(rng >> 32);
}

/* The oracle's order, written independently of heap2.c: NaN keys after all numbers. */
static const uint32_t *oracle_orig;

static int oracle_cmp(const void *px, const void *py)
{
    const c2_entry *x = px, *y = py;
    int xn = isnan(x->key), yn = isnan(y->key);
    if (xn != yn) return xn ? 1 : -1;
    if (!xn && x->key != y->key) return x->key < y->key ? -1 : 1;
    uint32_t kx[3] = {x->a, x->b, x->c}, ky[3] = {y->a, y->b, y->c};
    for (int i = 0; i < 3; i++) {
        uint32_t u = oracle_orig ? oracle_orig[kx[i]] : kx[i];
        uint32_t v = oracle_orig ? oracle_orig[ky[i]] : ky[i];
        if (u != v) return u < v ? -1 : 1;
    }
    return 0;
}

static int same_entry(c2_entry x, c2_entry y)
{
    return oracle_cmp(&x, &y) == 0;
}

static c2_entry pop(c2_heap *h)
{
    c2_entry e = {NAN, C2_NONE, C2_NONE, C2_NONE, 0};
    CHECK(c2_heap_pop(h, &e) == 0);
    return e;
}

/* Keys from a small set (many ties, a few NaN; values on both sides of every bar of heap2.c's
 * ladder and on the bars themselves, infinities), indices from a small range (ties on a and b).
 * The ladder is not read from heap2.c: these keys straddle any bars in [-1, 1]. */
static c2_entry random_entry(void)
{
    static const double keys[] = {-1,   -0.25,    0,      0.125, 0.5, 0.75,      0.875,   0.9,
                                  0.99, 0.984375, 0.9999, 1,     2,   -HUGE_VAL, HUGE_VAL};
    enum { NKEYS = sizeof keys / sizeof *keys };
    c2_entry e = {0, 0, 0, 0, 0};
    uint32_t r = next_u32() % 64;
    e.key = r == 0 ? NAN : r < 32 ? keys[r % NKEYS] : (double)(next_u32() % 1000) / 499.5 - 1.0;
    e.a = next_u32() % 8;
    e.b = next_u32() % 8;
    e.c = next_u32() % 8;
    return e;
}

/* Pushes and pops at random (more pushes early, more pops late), checking each pop against the
 * minimum of the oracle's multiset. */
static void run_against_oracle(const uint32_t *orig, size_t ops)
{
    c2_heap h = {0};
    h.orig = orig;
    oracle_orig = orig;
    c2_entry *all = malloc(ops * sizeof *all);
    size_t count = 0, mismatches = 0, pops = 0;
    for (size_t i = 0; i < ops; i++) {
        int push = count == 0 || next_u32() % 100 < (i < ops / 2 ? 70u : 30u);
        if (push) {
            c2_entry e = random_entry();
            CHECK(c2_heap_push(&h, e) == 0);
            all[count++] = e;
            continue;
        }
        qsort(all, count, sizeof *all, oracle_cmp);
        c2_entry got = pop(&h);
        mismatches += !same_entry(got, all[0]);
        memmove(all, all + 1, (count - 1) * sizeof *all);
        count--;
        pops++;
        CHECK_EQ_INT(h.count, count);
    }
    CHECK(pops > ops / 4);
    CHECK_EQ_INT(mismatches, 0);
    free(all);
    c2_heap_free(&h);
}

static void test_heap_pops_the_least_entry_with_ties_on_indices(void)
{
    run_against_oracle(NULL, 4000);
}

static void test_heap_breaks_ties_by_input_indices_through_orig(void)
{
    /* orig reverses the internal numbering: ties must follow orig, not the raw indices. */
    static const uint32_t orig[8] = {7, 6, 5, 4, 3, 2, 1, 0};
    run_against_oracle(orig, 4000);
    c2_heap h = {0};
    h.orig = orig;
    c2_entry lo = {0.5, 1, 2, 3, 0}, hi = {0.5, 0, 2, 3, 0}; /* orig[1] = 6 < orig[0] = 7 */
    CHECK(c2_heap_push(&h, hi) == 0);
    CHECK(c2_heap_push(&h, lo) == 0);
    CHECK_EQ_INT(pop(&h).a, 1);
    CHECK_EQ_INT(pop(&h).a, 0);
    c2_heap_free(&h);
}

static void test_heap_survives_growth_past_many_levels(void)
{
    /* 20000 distinct keys pushed in decreasing order (every push sifts to the root), popped in
     * increasing order. */
    c2_heap h = {0};
    size_t n = 20000, wrong = 0;
    for (size_t i = 0; i < n; i++) {
        c2_entry e = {(double)(n - i), (uint32_t)i, 0, 0, 0};
        CHECK(c2_heap_push(&h, e) == 0);
    }
    for (size_t i = 0; i < n; i++)
        wrong += pop(&h).key != (double)(i + 1);
    CHECK_EQ_INT(wrong, 0);
    CHECK_EQ_INT(h.count, 0);
    c2_heap_free(&h);
}

/* Keys in (-1, 1] pushed in decreasing order interleaved with pops, then emptied: the queue must
 * return every entry exactly once in order even though most were parked above a bar when they
 * came (bars are raised only when the heap part runs empty). After c2_heap_clear it starts over
 * with low keys. */
static void test_heap_parks_high_keys_and_returns_them_in_order(void)
{
    c2_heap h = {0};
    size_t n = 5000, wrong = 0;
    double prev = -HUGE_VAL;
    for (size_t i = 0; i < n; i++) {
        c2_entry e = {1.0 - 2.0 * (double)i / (double)n, (uint32_t)i, 0, 0, 0};
        CHECK(c2_heap_push(&h, e) == 0);
        if (i % 3 == 2) {
            c2_entry got = pop(&h);
            wrong += got.key != e.key; /* the newest is the least so far */
        }
    }
    while (h.count > 0) {
        c2_entry got = pop(&h);
        wrong += got.key < prev;
        prev = got.key;
    }
    CHECK_EQ_INT(wrong, 0);
    c2_entry hi = {0.999, 1, 0, 0, 0}, lo = {-0.5, 2, 0, 0, 0};
    CHECK(c2_heap_push(&h, hi) == 0);
    c2_heap_clear(&h);
    CHECK_EQ_INT(h.count, 0);
    CHECK(c2_heap_push(&h, hi) == 0);
    CHECK(c2_heap_push(&h, lo) == 0);
    CHECK_EQ_INT(pop(&h).a, 2);
    CHECK_EQ_INT(pop(&h).a, 1);
    CHECK_EQ_INT(h.count, 0);
    c2_heap_free(&h);
}

/* Lazily parked keys (lazy entries, computed from the points only when the bar is raised past
 * them or when pushed after it moved) against the same entries with their γ-indicators
 * computed up front: the sequence of pops must be the same, entry for entry and key for key.
 * Apexes on both sides of the first bar, so lazy entries meet eager ones in the heap. */
static void test_heap_lazy_keys_pop_as_computed_keys(void)
{
    enum { NP = 64, OPS = 3000 };
    double xy[2 * NP];
    unsigned long long st = 99;
    for (int i = 0; i < 2 * NP; i++)
        xy[i] = fl_test_rand01(&st) * (i % 7 == 0 ? 1e-3 : 1.0);
    c2_heap lazy = {0}, eager = {0};
    lazy.xy = xy;
    size_t wrong = 0, pushed_lazy = 0;
    for (int op = 0; op < OPS; op++) {
        if (op % 4 == 3 && eager.count > 0) {
            c2_entry x = pop(&eager), y = pop(&lazy);
            wrong += x.a != y.a || x.b != y.b || x.c != y.c || memcmp(&x.key, &y.key, 8) != 0;
            continue;
        }
        uint32_t a = next_u32() % NP, b = next_u32() % NP, c = next_u32() % NP;
        const double *pa = xy + 2 * a, *pb = xy + 2 * b, *pc = xy + 2 * c;
        double key = c2_gamma_indicator(pa, pb, pc);
        c2_entry e = {key, a, b, c, 0}, l = e;
        if (c2_gamma_at_least(pa, pb, pc, c2_heap_first_bar())) {
            l.key = NAN; /* must not be read */
            l.lazy = 1;
            pushed_lazy++;
        }
        CHECK(c2_heap_push(&eager, e) == 0);
        CHECK(c2_heap_push(&lazy, l) == 0);
    }
    while (eager.count > 0 && lazy.count > 0) {
        c2_entry x = pop(&eager), y = pop(&lazy);
        wrong += x.a != y.a || x.b != y.b || x.c != y.c || memcmp(&x.key, &y.key, 8) != 0;
    }
    CHECK(eager.count == 0 && lazy.count == 0);
    CHECK_EQ_INT(wrong, 0);
    CHECK(pushed_lazy > 100); /* the test exercised the lazy path */
    c2_heap_free(&lazy);
    c2_heap_free(&eager);
}

/* Entries in lent memory (c2_heap_lend, as fl_reconstruct2 lends the Delaunay builder's spare
 * memory): a lent buffer too small for all heap and parked entries must be outgrown by a copy
 * (the lent memory is neither reallocated nor freed: it lies inside a guarded array here, whose
 * guard must stay intact) and the pops must be those of a queue that owns all its memory. */
static void test_heap_lent_memory_is_copied_when_outgrown(void)
{
    enum { LENT = 48, GUARD = 8, N = 3000 };
    c2_entry buf[LENT + GUARD];
    for (int i = 0; i < LENT + GUARD; i++)
        buf[i] = (c2_entry){-7.0, 7, 7, 7, 0};
    c2_heap lent = {0}, own = {0};
    oracle_orig = NULL;
    c2_heap_lend(&lent, buf, LENT * sizeof *buf);
    CHECK_EQ_INT(lent.parked_lent, 1);
    CHECK_EQ_INT(lent.items_lent, 1);
    CHECK(lent.items == buf && lent.capacity == LENT / 8 && lent.parked == buf + LENT / 8);
    size_t wrong = 0;
    for (int i = 0; i < N; i++) {
        c2_entry e = random_entry();
        CHECK(c2_heap_push(&lent, e) == 0);
        CHECK(c2_heap_push(&own, e) == 0);
        if (i % 5 == 4) wrong += !same_entry(pop(&lent), pop(&own));
    }
    CHECK_EQ_INT(lent.parked_lent, 0); /* outgrown: the entries were copied out */
    CHECK_EQ_INT(lent.items_lent, 0);
    while (own.count > 0 && lent.count > 0)
        wrong += !same_entry(pop(&lent), pop(&own));
    CHECK(own.count == 0 && lent.count == 0);
    CHECK_EQ_INT(wrong, 0);
    for (int i = LENT; i < LENT + GUARD; i++)
        wrong += buf[i].key != -7.0 || buf[i].a != 7;
    CHECK_EQ_INT(wrong, 0);
    c2_heap_free(&lent); /* must not free buf (ASan would report it) */
    c2_heap_free(&own);
}

int main(void)
{
    static const fl_test_case cases[] = {
        FL_TEST_CASE(test_heap_pops_the_least_entry_with_ties_on_indices),
        FL_TEST_CASE(test_heap_breaks_ties_by_input_indices_through_orig),
        FL_TEST_CASE(test_heap_survives_growth_past_many_levels),
        FL_TEST_CASE(test_heap_parks_high_keys_and_returns_them_in_order),
        FL_TEST_CASE(test_heap_lazy_keys_pop_as_computed_keys),
        FL_TEST_CASE(test_heap_lent_memory_is_copied_when_outgrown),
    };
    return fl_test_run(cases, sizeof cases / sizeof *cases);
}
