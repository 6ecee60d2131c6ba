/* PNG encoding with Debian's libpng: one IDAT stream of 8-bit RGBA rows. libpng reports errors
 * by longjmp, so everything that must survive the jump is set up before setjmp and no
 * automatic variable changed after it is read afterwards. */
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <string.h>

#include "cli/png_write.h"
#include "core/core.h"

typedef struct png_failure {
    char message[256];
} png_failure;

static void on_error(png_structp png, png_const_charp msg)
{
    png_failure *f = png_get_error_ptr(png);
    snprintf(f->message, sizeof f->message, "%s", msg);
    png_longjmp(png, 1);
}

static void on_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg; /* warnings do not make the file wrong; the CLI stays quiet about them */
}

/* Encodes into an open stream; returns 0 on success, -1 with f->message set on failure. */
static int encode(FILE *fp, const fl_image *image, png_failure *f)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, f, on_error, on_warning);
    if (!png) {
        snprintf(f->message, sizeof f->message, "out of memory");
        return -1;
    }
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, info ? &info : NULL);
        if (!f->message[0]) snprintf(f->message, sizeof f->message, "out of memory");
        return -1;
    }
    png_init_io(png, fp);
    png_set_IHDR(png, info, image->width, image->height, 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (uint32_t y = 0; y < image->height; y++)
        png_write_row(png, image->rgba + (size_t)y * image->width * 4);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return 0;
}

fl_status cli_write_png(const char *path, const fl_image *image, fl_error *err)
{
    if (!image || !image->rgba || !image->width || !image->height)
        return fl_fail(err, FL_ERR_USAGE, path, -1, "no image to write");
    fl_out_file out;
    fl_status st = fl_out_open(&out, path, 1, err);
    if (st) return st;
    png_failure f = {{0}};
    if (encode(out.fp, image, &f)) {
        fl_out_abort(&out);
        return fl_fail(err, FL_ERR_IO, path, -1, "PNG encoding failed: %s", f.message);
    }
    return fl_out_commit(&out, err);
}

fl_status cli_render_png(fl_render *render, const char *path, fl_render_stats *stats, fl_error *err)
{
    fl_image img;
    fl_status st = fl_render_finish(render, &img, stats, err);
    if (st == FL_OK) st = cli_write_png(path, &img, err);
    fl_image_free(&img);
    return st;
}
