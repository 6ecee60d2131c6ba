/* Independent exact oracles for the predicate tests, in GMP rationals (mpq_set_d is exact).
 * They work on the full matrices with rows (p, [lift,] 1) in argument order - not on the
 * coordinate differences the library uses - and compute determinants by Gaussian elimination
 * (plain) or by Leibniz's formula over polynomials in eps (perturbed). */
#ifndef FL_TEST_PREDICATES_ORACLE_H
#define FL_TEST_PREDICATES_ORACLE_H

#include <gmp.h>
#include <stdint.h>
#include <stdlib.h>

/* Exact sign of det(m) for an n x n rational matrix (n <= 5); m is destroyed. */
static inline int oracle_det_sign(mpq_t m[5][5], int n)
{
    int sign = 1;
    mpq_t f, t;
    mpq_inits(f, t, NULL);
    for (int col = 0; col < n; col++) {
        int piv = -1;
        for (int r = col; r < n && piv < 0; r++)
            if (mpq_sgn(m[r][col]) != 0) piv = r;
        if (piv < 0) {
            sign = 0;
            break;
        }
        if (piv != col) {
            for (int j = 0; j < n; j++)
                mpq_swap(m[piv][j], m[col][j]);
            sign = -sign;
        }
        if (mpq_sgn(m[col][col]) < 0) sign = -sign;
        for (int r = col + 1; r < n; r++) {
            if (mpq_sgn(m[r][col]) == 0) continue;
            mpq_div(f, m[r][col], m[col][col]);
            for (int j = col; j < n; j++) {
                mpq_mul(t, f, m[col][j]);
                mpq_sub(m[r][j], m[r][j], t);
            }
        }
    }
    mpq_clears(f, t, NULL);
    return sign;
}

/* Fills row (x_0..x_{dim-1}, [|x|^2 - w,] 1) of point p; the weight is p[dim] if weighted. */
static inline void oracle_row(mpq_t *row, const double *p, int dim, int lifted, int weighted)
{
    int j = 0;
    for (; j < dim; j++)
        mpq_set_d(row[j], p[j]);
    if (lifted) {
        mpq_t sq;
        mpq_init(sq);
        mpq_set_ui(row[j], 0, 1);
        for (int k = 0; k < dim; k++) {
            mpq_mul(sq, row[k], row[k]);
            mpq_add(row[j], row[j], sq);
        }
        if (weighted) {
            mpq_set_d(sq, p[dim]);
            mpq_sub(row[j], row[j], sq);
        }
        mpq_clear(sq);
        j++;
    }
    mpq_set_ui(row[j], 1, 1);
}

/* Exact sign of det[(p_k, [lift_k,] 1)] over the n = dim + 1 + lifted points. */
static inline int oracle_sign(const double *const *pts, int dim, int lifted, int weighted)
{
    int n = dim + 1 + lifted;
    mpq_t m[5][5];
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            mpq_init(m[i][j]);
    for (int i = 0; i < n; i++)
        oracle_row(m[i], pts[i], dim, lifted, weighted);
    int s = oracle_det_sign(m, n);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            mpq_clear(m[i][j]);
    return s;
}

/* ---- perturbed determinants as polynomials in eps ----
 * Entry (r, c) is val + pcoef * eps^(2^key) when pcoef != 0. A product of entries gives a
 * monomial eps^(sum of 2^key) for a set of distinct keys; its magnitude order (smaller
 * exponent = larger) compares the sets by their largest differing key. */
typedef struct sym_term {
    uint64_t keys[5]; /* descending */
    int nkeys;
    mpq_t coef;
} sym_term;

static inline int sym_term_cmp(const sym_term *a, const sym_term *b)
{
    for (int i = 0;; i++) {
        if (i == a->nkeys || i == b->nkeys) return (i < a->nkeys) - (i < b->nkeys);
        if (a->keys[i] != b->keys[i]) return a->keys[i] < b->keys[i] ? -1 : 1;
    }
}

typedef struct sym_matrix {
    int n;
    mpq_t val[5][5];
    int pcoef[5][5];
    uint64_t key[5][5];
    sym_term *terms;
    int nterms;
} sym_matrix;

static inline void sym_add_key(sym_term *t, uint64_t key)
{
    int i = t->nkeys++;
    while (i > 0 && t->keys[i - 1] < key) {
        t->keys[i] = t->keys[i - 1];
        i--;
    }
    t->keys[i] = key;
}

/* Expands every choice (value or eps part) of the entries on permutation perm. */
static inline void sym_expand(sym_matrix *s, const int *perm, int sign, int row, sym_term *acc)
{
    if (row == s->n) {
        sym_term *t = &s->terms[s->nterms++];
        mpq_init(t->coef);
        mpq_set(t->coef, acc->coef);
        if (sign < 0) mpq_neg(t->coef, t->coef);
        t->nkeys = acc->nkeys;
        for (int i = 0; i < acc->nkeys; i++)
            t->keys[i] = acc->keys[i];
        return;
    }
    int c = perm[row];
    sym_term next;
    mpq_init(next.coef);
    mpq_mul(next.coef, acc->coef, s->val[row][c]);
    next.nkeys = acc->nkeys;
    for (int i = 0; i < acc->nkeys; i++)
        next.keys[i] = acc->keys[i];
    if (mpq_sgn(next.coef) != 0) sym_expand(s, perm, sign, row + 1, &next);
    if (s->pcoef[row][c] != 0) {
        mpq_set(next.coef, acc->coef);
        if (s->pcoef[row][c] < 0) mpq_neg(next.coef, next.coef);
        sym_add_key(&next, s->key[row][c]);
        sym_expand(s, perm, sign, row + 1, &next);
    }
    mpq_clear(next.coef);
}

static inline void sym_permutations(sym_matrix *s, int *perm, int k, int sign)
{
    /* n <= 5 (the matrices are 5 x 5); saying so keeps gcc -O2 -Warray-bounds from assuming
     * k could reach 5 inside the loop below */
    if (s->n > 5 || k > 5) return;
    if (k == s->n) {
        sym_term one;
        mpq_init(one.coef);
        mpq_set_ui(one.coef, 1, 1);
        one.nkeys = 0;
        sym_expand(s, perm, sign, 0, &one);
        mpq_clear(one.coef);
        return;
    }
    for (int i = k; i < s->n; i++) {
        int t = perm[k];
        perm[k] = perm[i];
        perm[i] = t;
        sym_permutations(s, perm, k + 1, i == k ? sign : -sign);
        perm[i] = perm[k];
        perm[k] = t;
    }
}

/* Sign of the lowest-order nonzero coefficient of det(s) as a polynomial in eps. */
static inline int sym_sign(sym_matrix *s)
{
    int fact = 1, perm[5];
    for (int i = 2; i <= s->n; i++)
        fact *= i;
    s->terms = malloc(sizeof(sym_term) * (size_t)fact * 32);
    s->nterms = 0;
    for (int i = 0; i < s->n; i++)
        perm[i] = i;
    sym_permutations(s, perm, 0, 1);
    /* selection of the smallest monomial with nonzero total, one group at a time */
    int result = 0, *done = calloc((size_t)s->nterms, sizeof(int));
    mpq_t sum;
    mpq_init(sum);
    for (;;) {
        int best = -1;
        for (int i = 0; i < s->nterms; i++)
            if (!done[i] && (best < 0 || sym_term_cmp(&s->terms[i], &s->terms[best]) < 0)) best = i;
        if (best < 0) break;
        mpq_set_ui(sum, 0, 1);
        for (int i = 0; i < s->nterms; i++)
            if (!done[i] && sym_term_cmp(&s->terms[i], &s->terms[best]) == 0) {
                mpq_add(sum, sum, s->terms[i].coef);
                done[i] = 1;
            }
        if (mpq_sgn(sum) != 0) {
            result = mpq_sgn(sum);
            break;
        }
    }
    mpq_clear(sum);
    free(done);
    for (int i = 0; i < s->nterms; i++)
        mpq_clear(s->terms[i].coef);
    free(s->terms);
    return result;
}

/* Simulation of Simplicity for orientation, straight from Edelsbrunner-Mucke: coordinate j of
 * the point with index i is p_ij + eps^(2^(i*dim + dim-1-j)). */
static inline int oracle_orient_sos(const double *const *pts, const uint32_t *idx, int dim)
{
    sym_matrix s;
    s.n = dim + 1;
    for (int r = 0; r < s.n; r++) {
        for (int c = 0; c < s.n; c++) {
            mpq_init(s.val[r][c]);
            s.pcoef[r][c] = 0;
            s.key[r][c] = 0;
        }
        oracle_row(s.val[r], pts[r], dim, 0, 0);
        for (int j = 0; j < dim; j++) {
            s.pcoef[r][j] = 1;
            s.key[r][j] = (uint64_t)idx[r] * (uint64_t)dim + (uint64_t)(dim - 1 - j);
        }
    }
    int res = sym_sign(&s);
    for (int r = 0; r < s.n; r++)
        for (int c = 0; c < s.n; c++)
            mpq_clear(s.val[r][c]);
    return res;
}

/* The lift perturbation: the lift of the point with index i becomes lift - eps^(2^(2^32 - i))
 * (its weight grows), so a higher index is perturbed more. */
static inline int oracle_lift_sos(const double *const *pts, const uint32_t *idx, int dim,
                                  int weighted)
{
    sym_matrix s;
    s.n = dim + 2;
    for (int r = 0; r < s.n; r++) {
        for (int c = 0; c < s.n; c++) {
            mpq_init(s.val[r][c]);
            s.pcoef[r][c] = 0;
            s.key[r][c] = 0;
        }
        oracle_row(s.val[r], pts[r], dim, 1, weighted);
        s.pcoef[r][dim] = -1;
        s.key[r][dim] = (1ull << 32) - idx[r];
    }
    int res = sym_sign(&s);
    for (int r = 0; r < s.n; r++)
        for (int c = 0; c < s.n; c++)
            mpq_clear(s.val[r][c]);
    return res;
}

#endif /* FL_TEST_PREDICATES_ORACLE_H */
