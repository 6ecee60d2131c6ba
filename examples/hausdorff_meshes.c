/* Example: how far apart are two meshes? The certified Hausdorff distance (Guéziec 2001, §6).
 *
 *   hausdorff_meshes A B [RELATIVE]   prints the directed distances and the Hausdorff distance
 *                                     as intervals [lower, upper] that contain the true value,
 *                                     refined until upper - lower <= RELATIVE x the bounding
 *                                     box diagonal (default 1e-4)
 *
 * A and B are mesh files (.off .obj .ply .stl). `lower` is a distance measured at a sample
 * point (printed as "where"); `upper` is proven for every point of the surfaces, not only the
 * vertices. Typical use: a simplified or reconstructed mesh against its reference.
 *
 *   cc hausdorff_meshes.c $(pkg-config --cflags --libs flintstone) -o hausdorff_meshes
 */
#include <stdio.h>
#include <stdlib.h>

#include "flintstone.h"

static int report(const fl_error *err)
{
    char msg[1200];
    fl_error_format(err, msg, sizeof msg);
    fprintf(stderr, "error: %s\n", msg);
    return (int)err->status;
}

int main(int argc, char **argv)
{
    if (argc < 3 || argc > 4) {
        fprintf(stderr, "usage: %s A B [RELATIVE]\n", argv[0]);
        return 1;
    }
    fl_error err;
    fl_mesh a, b;
    if (fl_read_mesh(argv[1], &a, &err)) return report(&err);
    if (fl_read_mesh(argv[2], &b, &err)) {
        fl_mesh_free(&a);
        return report(&err);
    }
    fl_hausdorff_options opt = {0};
    opt.relative = argc > 3 ? atof(argv[3]) : 1e-4;
    opt.both_directions = 1; /* refine both directed distances, not only the larger */
    fl_hausdorff_result r;
    fl_status st = fl_hausdorff_meshes(&a, &b, &opt, &r, &err);
    fl_mesh_free(&a);
    fl_mesh_free(&b);
    if (st) return report(&err);
    printf("h(A,B)    in [%.9g, %.9g]\n", r.h_ab[0], r.h_ab[1]);
    printf("h(B,A)    in [%.9g, %.9g]\n", r.h_ba[0], r.h_ba[1]);
    printf("Hausdorff in [%.9g, %.9g] after %zu samples\n", r.hausdorff[0], r.hausdorff[1],
           r.samples);
    printf("where: (%g, %g, %g) on %s is %.9g from (%g, %g, %g) on %s\n", r.where[0][0],
           r.where[0][1], r.where[0][2], r.where_on_b ? "B" : "A", r.hausdorff[0], r.where[1][0],
           r.where[1][1], r.where[1][2], r.where_on_b ? "A" : "B");
    fl_hausdorff_result_free(&r);
    return 0;
}
