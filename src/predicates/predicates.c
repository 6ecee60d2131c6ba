/* The predicates' fast path: a semi-static floating-point filter in front of the exact stage.
 *
 * The filter evaluates the determinant in doubles and accepts its sign when |det| exceeds a
 * bound on the rounding error. The bound is C * (product of the largest coordinate
 * differences along each axis), derived Shewchuk/FPG style from two rules, writing u = 2^-53
 * for the unit roundoff and e(x) for the error bound of a computed x, B(x) for a bound on |x|:
 *   product:  e(x*y) <= B(x) e(y) + B(y) e(x) + u B(x) B(y)
 *   sum:      e(x+y) <= e(x) + e(y) + u (B(x) + B(y))
 * starting from the computed differences d = fl(p - q), e(d) <= u |d| (their rounding is part
 * of the error: the filter decides the sign of the determinant of the *exact* differences).
 * Each function states the first-order coefficient it obtains; the constant used is one u
 * larger, which covers the O(u^2) terms, the rounding of the bound itself, and the absolute
 * error 2^-1075 of any product that underflows (see the range guards below).
 *
 * Range guards: the rules above assume no overflow and no underflow. The filter is used only
 * when every per-axis maximum m lies in [LO, HI] for the predicate's degree k, with HI^k small
 * enough that no intermediate can overflow, and LO^k large enough that (a) the bound C * m^k
 * is a normal number and (b) an underflowed product, whose absolute error 2^-1075 is
 * multiplied afterwards by at most the other factors, contributes far less than u * bound.
 * Outside the guards (and when the filter is inconclusive) the exact stage decides. */
#include <math.h>

#include "flintstone.h"
#include "predicates/predicates_internal.h"

#define U 0x1p-53

static inline double max2(double a, double b)
{
    return a > b ? a : b;
}
static inline double max3(double a, double b, double c)
{
    return max2(max2(a, b), c);
}
static inline double max4(double a, double b, double c, double d)
{
    return max2(max2(a, b), max2(c, d));
}
static inline int in_range(double m, double lo, double hi)
{
    return m >= lo && m <= hi;
}

/* Degree 2. det = acx*bcy - acy*bcx: each product has error 3 u mx my (two rounded differences,
 * one rounded product), the subtraction adds u * 2 mx my: 8 u mx my in total.
 * Guards: 2 HI^2 < 2^1023; 9u LO^2 normal and 2 * 2^-1075 << u LO^2. */
#define O2_C (9 * U)
#define O2_LO 0x1p-480
#define O2_HI 0x1p+480

int fl_orient2d(const double *a, const double *b, const double *c)
{
    double acx = a[0] - c[0], bcx = b[0] - c[0];
    double acy = a[1] - c[1], bcy = b[1] - c[1];
    double det = acx * bcy - acy * bcx;
    double mx = max2(fabs(acx), fabs(bcx)), my = max2(fabs(acy), fabs(bcy));
    if (in_range(mx, O2_LO, O2_HI) && in_range(my, O2_LO, O2_HI)) {
        double eps = O2_C * mx * my;
        if (det > eps) return 1;
        if (det < -eps) return -1;
    }
    const double *p[3] = {a, b, c};
    return fl_exact_det_sign(p, 3, 2, 0, 0);
}

/* Degree 3, expansion along z: each 2x2 minor has error 8 u mx my and magnitude <= 2 mx my;
 * times a z difference, 12 u M (M = mx my mz) and magnitude <= 2M; the two sums add 4u M
 * and 6u M: 46 u M. Guards: 6 HI^3 < 2^1023; 47u LO^3 normal; an underflowed 2x2 product
 * (error 2^-1075) is multiplied by at most mz, negligible against u mx my mz as mx my >= LO^2. */
#define O3_C (47 * U)
#define O3_LO 0x1p-320
#define O3_HI 0x1p+320

int fl_orient3d(const double *a, const double *b, const double *c, const double *d)
{
    double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
    double det = adz * (bdx * cdy - cdx * bdy) + bdz * (cdx * ady - adx * cdy) +
                 cdz * (adx * bdy - bdx * ady);
    double mx = max3(fabs(adx), fabs(bdx), fabs(cdx));
    double my = max3(fabs(ady), fabs(bdy), fabs(cdy));
    double mz = max3(fabs(adz), fabs(bdz), fabs(cdz));
    if (in_range(mx, O3_LO, O3_HI) && in_range(my, O3_LO, O3_HI) && in_range(mz, O3_LO, O3_HI)) {
        double eps = O3_C * mx * my * mz;
        if (det > eps) return 1;
        if (det < -eps) return -1;
    }
    const double *p[4] = {a, b, c, d};
    return fl_exact_det_sign(p, 4, 3, 0, 0);
}

/* Degree 4 (coordinates) with the lift l = dx^2 + dy^2 - dw. With mm = max(mx, my) and
 * Lambda = mm^2 + mw (mw = largest weight difference, 0 unweighted): B(l) <= 2 Lambda and
 * e(l) <= 10 u Lambda (squares 3u each, sum u, the weight difference and the subtraction);
 * the 2x2 minors have error 8 u mx my and magnitude 2 mx my; each product l * minor has
 * error (2*8 + 2*10 + 4) u = 40 u Lambda mx my and magnitude 4 Lambda mx my; the two sums add
 * 8u and 12u: 140 u Lambda mx my (128 u when unweighted; 140 is used for both).
 * Guards: 24 HI^4 < 2^1023 (Lambda <= 2 HI^2); 141u LO^4 normal; underflows are multiplied by
 * at most 2 Lambda or 2 mx my, negligible against u Lambda mx my. */
#define IC_C (141 * U)
#define IC_LO 0x1p-240
#define IC_HI 0x1p+240

static int incircle_filter(const double *a, const double *b, const double *c, const double *d,
                           double adw, double bdw, double cdw)
{
    double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    double alift = (adx * adx + ady * ady) - adw;
    double blift = (bdx * bdx + bdy * bdy) - bdw;
    double clift = (cdx * cdx + cdy * cdy) - cdw;
    double det = alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) +
                 clift * (adx * bdy - bdx * ady);
    double mx = max3(fabs(adx), fabs(bdx), fabs(cdx));
    double my = max3(fabs(ady), fabs(bdy), fabs(cdy));
    double mw = max3(fabs(adw), fabs(bdw), fabs(cdw));
    if (in_range(mx, IC_LO, IC_HI) && in_range(my, IC_LO, IC_HI) && mw <= IC_HI * IC_HI) {
        double mm = max2(mx, my);
        double eps = IC_C * (mm * mm + mw) * mx * my;
        if (det > eps) return 1;
        if (det < -eps) return -1;
    }
    return 0;
}

int fl_incircle(const double *a, const double *b, const double *c, const double *d)
{
    int s = incircle_filter(a, b, c, d, 0, 0, 0);
    if (s) return s;
    const double *p[4] = {a, b, c, d};
    return fl_exact_det_sign(p, 4, 2, 1, 0);
}

int fl_incircle_weighted(const double *a, const double *b, const double *c, const double *d)
{
    int s = incircle_filter(a, b, c, d, a[2] - d[2], b[2] - d[2], c[2] - d[2]);
    if (s) return s;
    const double *p[4] = {a, b, c, d};
    return fl_exact_det_sign(p, 4, 2, 1, 1);
}

/* Degree 5 with the lift l = dx^2 + dy^2 + dz^2 - dw. Lambda = mm^2 + mw as in 2D,
 * M3 = mx my mz: B(l) <= 3 Lambda, e(l) <= 17 u Lambda; the 3x3 minors (abc, ...) have error
 * 46 u M3 and magnitude 6 M3 (as in orient3d); each l * minor has error
 * (3*46 + 6*17 + 18) u = 258 u Lambda M3 and magnitude 18 Lambda M3; the three sums add
 * 36u, 36u and 72u: 1176 u Lambda M3 (1104 u when unweighted; 1176 is used for both).
 * Guards: 144 HI^5 < 2^1023; 1177u LO^5 normal; underflows are multiplied by at most
 * 3 Lambda mz or 6 M3, negligible against u Lambda M3. */
#define IS_C (1177 * U)
#define IS_LO 0x1p-190
#define IS_HI 0x1p+190

static int insphere_filter(const double *a, const double *b, const double *c, const double *d,
                           const double *e, const double *dw)
{
    double aex = a[0] - e[0], bex = b[0] - e[0], cex = c[0] - e[0], dex = d[0] - e[0];
    double aey = a[1] - e[1], bey = b[1] - e[1], cey = c[1] - e[1], dey = d[1] - e[1];
    double aez = a[2] - e[2], bez = b[2] - e[2], cez = c[2] - e[2], dez = d[2] - e[2];
    double ab = aex * bey - bex * aey, bc = bex * cey - cex * bey;
    double cd = cex * dey - dex * cey, da = dex * aey - aex * dey;
    double ac = aex * cey - cex * aey, bd = bex * dey - dex * bey;
    double abc = aez * bc - bez * ac + cez * ab;
    double bcd = bez * cd - cez * bd + dez * bc;
    double cda = cez * da + dez * ac + aez * cd;
    double dab = dez * ab + aez * bd + bez * da;
    double alift = (aex * aex + aey * aey + aez * aez) - dw[0];
    double blift = (bex * bex + bey * bey + bez * bez) - dw[1];
    double clift = (cex * cex + cey * cey + cez * cez) - dw[2];
    double dlift = (dex * dex + dey * dey + dez * dez) - dw[3];
    double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
    double mx = max4(fabs(aex), fabs(bex), fabs(cex), fabs(dex));
    double my = max4(fabs(aey), fabs(bey), fabs(cey), fabs(dey));
    double mz = max4(fabs(aez), fabs(bez), fabs(cez), fabs(dez));
    double mw = max4(fabs(dw[0]), fabs(dw[1]), fabs(dw[2]), fabs(dw[3]));
    if (in_range(mx, IS_LO, IS_HI) && in_range(my, IS_LO, IS_HI) && in_range(mz, IS_LO, IS_HI) &&
        mw <= IS_HI * IS_HI) {
        double mm = max3(mx, my, mz);
        double eps = IS_C * (mm * mm + mw) * mx * my * mz;
        if (det > eps) return 1;
        if (det < -eps) return -1;
    }
    return 0;
}

int fl_insphere(const double *a, const double *b, const double *c, const double *d, const double *e)
{
    static const double zero[4] = {0, 0, 0, 0};
    int s = insphere_filter(a, b, c, d, e, zero);
    if (s) return s;
    const double *p[5] = {a, b, c, d, e};
    return fl_exact_det_sign(p, 5, 3, 1, 0);
}

int fl_insphere_weighted(const double *a, const double *b, const double *c, const double *d,
                         const double *e)
{
    double dw[4] = {a[3] - e[3], b[3] - e[3], c[3] - e[3], d[3] - e[3]};
    int s = insphere_filter(a, b, c, d, e, dw);
    if (s) return s;
    const double *p[5] = {a, b, c, d, e};
    return fl_exact_det_sign(p, 5, 3, 1, 1);
}
