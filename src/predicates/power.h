/* Internal interface of the power-distance predicates of the skin (power.c): exact signs of the
 * determinants that decide the skin's mixed-cell walk and the dual complex of a union of balls.
 * They take plain coordinates: a ball is a pointer to four doubles "x y z w" (centre, weight =
 * squared radius), a point a pointer to three. Not part of the public API. */
#ifndef FL_PREDICATES_POWER_H
#define FL_PREDICATES_POWER_H

/* ---- the link test of the mixed-cell walk (src/skin/skin_cell.c) ----
 *
 * pts[0..k] are the balls z_0 .. z_k of a simplex X, k <= 2, pts[k+1..2] repeat pts[3] (they
 * take part in the range checks and the integer scaling), pts[3] is a ball b of X's link and
 * pts[4] the query point x (three coordinates); 0 < t < 1. With a = z_0, e_i = z_i - a,
 * e_b = z_b - a, d = x - a, G_ij = e_i.e_j (i, j < k), g_i = e_i.e_b, u_i = t r_i - e_i.d and
 * c = t r_b - e_b.d, r_i = (|e_i|^2 - w_i + w_0) / 2 (r_b the same for b), the sign returned is
 * that of the (k+1) x (k+1) determinant
 *     det M = det [[G, g], [u^T, c]] = det G (c - u^T G^-1 g),
 * i.e. (det G > 0 for a simplex) the sign of pi_b(v) - pi_X(v) at v = f + q / t, where f is the
 * focus of X and x - f = p + q with q orthogonal to aff X (power.c has the derivation). */

/* The sign of det M (-1 or 1) when a floating-point evaluation with a rigorous bound on its
 * error decides it; 0 when it does not (the bound covers zero, an input is outside 0 and
 * [2^-100, 2^100] in magnitude, or k > 2 or t outside (0, 1)). Never a wrong nonzero sign. */
int fl_power_link_filter(const double *const *pts, int k, double t);

/* The exact sign of det M: -1, 0 or 1, evaluated in big integers; 2 when it cannot be decided
 * (k > 2, t outside (0, 1), a non-finite input, an exponent range beyond 4200 bits or 1 - et
 * > 1000 for t = odd * 2^et, out of memory). */
int fl_power_link_exact(const double *const *pts, int k, double t);

/* ---- the bordered determinants of the dual complex (src/skin/skin_euler.c) ----
 *
 * z[0..k] are the balls of a simplex X, 0 <= k <= 3, with affinely independent centres; in
 * FL_BORDERED_LINK mode z[k+1] is a ball b of its link (k <= 2). With a = z_0, e_i = z_i - a
 * (i = 1..k), G_ij = e_i.e_j, s_i = |e_i|^2 - w_i + w_0 (s_b the same for b), g_i = e_i.e_b:
 *  - FL_BORDERED_LINK:  the sign of det [[G, g], [s^T, s_b]], that of pi_b(f) - pi_X(f);
 *  - FL_BORDERED_POWER: the sign of det [[G, s], [s^T, 4 w_0]], the OPPOSITE of pi_X(f)'s,
 * where f is the focus of X (the point of aff X with equal power to its balls). */
enum { FL_BORDERED_LINK = 0, FL_BORDERED_POWER = 1 };

/* The sign (-1, 0 or 1) when floating point certifies it (0 only when every entry is exactly
 * zero), else 2: not certified, or an input outside the filter's range. */
int fl_power_bordered_filter(const double *const *z, int k, int mode);

/* The exact sign, -1, 0 or 1, in big integers; 2 when out of memory or an input is not finite. */
int fl_power_bordered_exact(const double *const *z, int k, int mode);

/* fl_power_bordered_filter, else fl_power_bordered_exact: the exact sign; 2 as for the latter. */
int fl_power_bordered_sign(const double *const *z, int k, int mode);

#endif /* FL_PREDICATES_POWER_H */
