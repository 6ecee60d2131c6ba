/* PNG output of the CLI through libpng (the library itself stays libc + libm only). */
#ifndef FL_CLI_PNG_WRITE_H
#define FL_CLI_PNG_WRITE_H

#include "flintstone.h"

/* Writes image as an 8-bit RGBA PNG, atomically (temporary file, then rename). FL_ERR_IO with
 * libpng's message on failure; the target is then untouched. */
fl_status cli_write_png(const char *path, const fl_image *image, fl_error *err);

/* Finishes the scene (fl_render_finish) and writes it as a PNG: the one call the commands need
 * to turn a scene into a picture. stats may be NULL. */
fl_status cli_render_png(fl_render *render, const char *path, fl_render_stats *stats,
                         fl_error *err);

#endif
