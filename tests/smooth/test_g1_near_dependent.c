/* The three-split's step 5 on nearly (not exactly) dependent edges (docs/smooth.md, "Auto",
 * round 8). A coarse torus whose coordinates are printed to 6 significant digits (as CGAL's
 * torus_quad.off is: 5 x 5 quads, tube radius half the centre radius) has a ring of macro
 * edges where the 2 x 2 system of eq. 9.4 has |det A| / |A|_F^2 about 3e-8: its mirror
 * symmetry is broken only by the rounding of the coordinates. Cramer's rule there left a
 * residual of about 1e-9 of the right-hand side and normal jumps of 2.6e-7 - 6.5e-7 degrees;
 * the pivoted, refined solve on differences is G1 to < 1e-7 degrees. Checked with the
 * independent edge-pairing oracle of g1_oracle.h at 65 points of every patch edge (without
 * the fix: 1.7e-6 degrees with 6 digits, 9.2e-6 with 7; with it 1.7e-12 and 1.2e-12). */
#include <stdio.h>

#include "g1_meshes.h"
#include "g1_oracle.h"

/* n x n quads on a torus (centre radius R, tube radius r) in the layout of torus_quad.off,
 * each quad split into two triangles, every coordinate rounded to `digits` significant digits
 * (0: not rounded). */
static fl_mesh rounded_torus(int n, double R, double r, int digits)
{
    double xyz[3 * 64];
    uint32_t tri[6 * 64];
    const double pi = 3.14159265358979323846;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            double phi = pi - 2 * pi * j / n, th = pi + pi / n - 2 * pi * i / n;
            double rho = R + r * cos(phi), p[3] = {rho * cos(th), r * sin(phi), rho * sin(th)};
            for (int d = 0; d < 3; d++) {
                char buf[64];
                if (digits) snprintf(buf, sizeof buf, "%.*g", digits, p[d]);
                xyz[3 * (n * j + i) + d] = digits ? strtod(buf, NULL) : p[d];
            }
        }
    size_t nt = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            uint32_t a = (uint32_t)(n * ((j + 1) % n) + i), b = (uint32_t)(n * ((j + 1) % n) +
                                                                           (i + 1) % n),
                     c = (uint32_t)(n * j + (i + 1) % n), d = (uint32_t)(n * j + i);
            uint32_t q[6] = {a, b, c, a, c, d};
            memcpy(tri + 3 * nt, q, sizeof q);
            nt += 2;
        }
    return g1_mesh_from(xyz, (size_t)(n * n), tri, nt);
}

static void test_three_split_g1_on_nearly_dependent_edges(void)
{
    for (int digits = 6; digits <= 7; digits++) {
        fl_mesh m = rounded_torus(5, 0.697, 0.3485, digits);
        fl_g1_surface s;
        fl_error err;
        fl_g1_surface_options o = {.scheme = FL_G1_THREE_SPLIT};
        CHECK_STATUS(fl_g1_surface_build(&m, &o, &s, &err), FL_OK, &err);
        /* the nearly dependent edges took the quadratic boundary curve (surface.c) */
        CHECK_MSG(s.quadratic_edges > 0, "digits %d: no nearly dependent edge, mesh useless",
                  digits);
        size_t flips, unpaired;
        double j = g1_max_edge_jump(&s, 64, &flips, &unpaired);
        CHECK_MSG(j < 1e-7, "digits %d: max normal jump %g degrees", digits, j);
        CHECK_EQ_INT(flips, 0);
        CHECK_EQ_INT(unpaired, 0);
        fl_g1_surface_free(&s);
        fl_mesh_free(&m);
    }
}

FL_TEST_MAIN(FL_TEST_CASE(test_three_split_g1_on_nearly_dependent_edges))
