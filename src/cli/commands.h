/* Entry points of the subcommands, one file each. */
#ifndef FL_CLI_COMMANDS_H
#define FL_CLI_COMMANDS_H

int cmd_version(int argc, char **argv);
int cmd_check(int argc, char **argv);
int cmd_demo(int argc, char **argv);
int cmd_report(int argc, char **argv);
int cmd_delaunay(int argc, char **argv);
int cmd_graph(int argc, char **argv);
int cmd_reconstruct(int argc, char **argv);
int cmd_hal(int argc, char **argv);
int cmd_inside(int argc, char **argv);
int cmd_intersect(int argc, char **argv);
int cmd_closest(int argc, char **argv);
int cmd_hausdorff(int argc, char **argv);
int cmd_render(int argc, char **argv);
int cmd_smooth(int argc, char **argv);
int cmd_skin(int argc, char **argv);
int cmd_balls(int argc, char **argv);

#include "flintstone.h"

/* Writes a 2D Delaunay triangulation of the points p: .svg as a picture of its edges, any mesh
 * format as a flat mesh (z = 0). Shared by `delaunay -o` and the demo. */
fl_status cli_write_dt2(const char *path, const fl_points *p, const fl_dt2 *dt, fl_error *err);

/* The picture of a flintstone approximation: the polygon, the approximation and the
 * flintstones of the polylines it cuts off (by level, or adaptively by max_error as in
 * fl_hal2_approximate_error). Shared by `hal -o .svg` and the demo. */
fl_status cli_write_hal2_svg(const char *path, const fl_hal2 *hal, const fl_polygon *approx,
                             int by_level, uint32_t level, double max_error, fl_error *err);

#endif
