/* PNG output of the CLI through libpng (the library itself stays libc + libm only). */
#ifndef FL_CLI_PNG_WRITE_H
#define FL_CLI_PNG_WRITE_H

#include "flintstone.h"

/* Writes image as an 8-bit RGBA PNG, atomically (temporary file, then rename). FL_ERR_IO with
 * libpng's message on failure; the target is then untouched. */
fl_status cli_write_png(const char *path, const fl_image *image, fl_error *err);

#endif
