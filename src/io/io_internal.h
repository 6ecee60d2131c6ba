/* Internal interface between the format modules of src/io and the dispatch by extension.
 * Readers parse a whole buffer (files are read whole, in one pass); writers write to an open
 * stream (the dispatch owns the atomic temporary file). */
#ifndef FL_IO_INTERNAL_H
#define FL_IO_INTERNAL_H

#include <stdio.h>

#include "core/core.h"

/* Reads a whole file into a malloc'ed buffer with a terminating NUL (not counted in *size). */
fl_status fl_io_slurp(const char *path, char **data, size_t *size, fl_error *err);

/* Mesh formats (src/io/ply.c, stl.c, off.c, obj.c). A file with vertices and no faces gives a
 * mesh with triangle_count 0, which fl_read_points uses for .ply/.off/.obj point sets. */
fl_status fl_ply_parse(const char *name, const char *data, size_t size, fl_mesh *out,
                       fl_error *err);
fl_status fl_stl_parse(const char *name, const char *data, size_t size, fl_mesh *out,
                       fl_error *err);
fl_status fl_off_parse(const char *name, const char *data, size_t size, fl_mesh *out,
                       fl_error *err);
fl_status fl_obj_parse(const char *name, const char *data, size_t size, fl_mesh *out,
                       fl_error *err);
fl_status fl_ply_write(FILE *fp, const fl_mesh *mesh);
fl_status fl_stl_write(FILE *fp, const fl_mesh *mesh);
fl_status fl_off_write(FILE *fp, const fl_mesh *mesh);
fl_status fl_obj_write(FILE *fp, const fl_mesh *mesh);

/* Text points and polygons (src/io/text_points.c, xy_polygon.c, geojson.c, svg.c). */
/* The text point reader with a choice of how many numbers a line may hold (all lines the same;
 * min_cols..max_cols, at most FL_TEXT_MAX_COLUMNS); out->dim is the count found. */
#define FL_TEXT_MAX_COLUMNS 4
fl_status fl_text_columns_parse(const char *name, const char *data, size_t size, int min_cols,
                                int max_cols, fl_points *out, fl_error *err);
fl_status fl_text_points_parse(const char *name, const char *data, size_t size, fl_points *out,
                               fl_error *err);
fl_status fl_xy_polygon_parse(const char *name, const char *data, size_t size, fl_polygon *out,
                              fl_error *err);
fl_status fl_geojson_parse(const char *name, const char *data, size_t size, fl_polygon *out,
                           fl_error *err);
fl_status fl_text_points_write(FILE *fp, const fl_points *points);
fl_status fl_xy_polygon_write(FILE *fp, const fl_polygon *polygon);
fl_status fl_geojson_write(FILE *fp, const fl_polygon *polygon);
fl_status fl_svg_polygon_write(FILE *fp, const fl_polygon *polygon);

#endif /* FL_IO_INTERNAL_H */
