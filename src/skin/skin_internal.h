/* Internals of src/skin shared by the skin function (skin_function.c) and the mesher
 * (skin_mesh.c). */
#ifndef FL_SKIN_INTERNAL_H
#define FL_SKIN_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "flintstone.h"

/* One simplex X of the regular triangulation of the balls (a vertex, edge, triangle or
 * tetrahedron, k = dim) with what the skin needs in its mixed cell (derivation in
 * docs/skin.md, "The skin function"):
 *  - its focus f, the point of aff(X) with equal power to every ball of X, and the weight w of
 *    the ball (f, w) orthogonal to the balls of X (Cheng & Tan §6.2, b_X^perp);
 *  - a frame to project onto aff(X): origin a (first centre), edge vectors e_j = z_j - a and
 *    the inverse Gram matrix, plus the coordinates mu_f of f in that frame. */
typedef struct skin_simplex {
    int k;
    double a[3];
    double e[3][3];
    double ginv[3][3];
    double mu_f[3];
    double f[3];
    double w;
} skin_simplex;

struct fl_skin_function {
    double t;
    double wmax; /* largest ball weight (> 0) */
    size_t simplex_count;
    skin_simplex *simplex;
    /* Uniform grid index: cell c lists the simplices whose bounding box grown by `reach` meets
     * it (CSR arrays cell_start[cells+1], cell_item[]). */
    double origin[3], cell, reach;
    size_t dims[3];
    size_t *cell_start;
    uint32_t *cell_item;
};

#endif
