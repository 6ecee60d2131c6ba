/* Exact signs of small sums of products of coordinate differences, for predicates that are
 * not determinants: distance comparisons, lune and strip tests, the diametral ball. Shared by
 * src/predicates (fl_diametral) and src/graphs. */
#ifndef FL_PREDICATES_DOT_SUM_H
#define FL_PREDICATES_DOT_SUM_H

/* The most terms fl_dot_sum_sign accepts. */
#define FL_DOT_SUM_MAX_TERMS 4

/* Exact sign of sum_{k < terms} coef[k] * (x[k] - y[k]) . (u[k] - w[k]) over `dim` (2 or 3)
 * coordinates, for every finite double input (coefficients included): the inputs are scaled
 * by powers of two into integers and the sum is evaluated in big integers. Returns 0 for
 * terms outside 1..FL_DOT_SUM_MAX_TERMS or other dims. */
int fl_dot_sum_sign(int terms, const double *coef, const double *const *x, const double *const *y,
                    const double *const *u, const double *const *w, int dim);

#endif
