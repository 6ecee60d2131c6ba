/* Recording helpers of the demo/report pipeline (see pipeline.h): every number goes to
 * summary.json under a snake_case key and to report.html with its unit and meaning. */
#include "cli/pipeline.h"

#include "cli/png_write.h"

#include <stdio.h>
#include <string.h>

void pl_path(const pipeline *pl, char *buf, size_t size, const char *name)
{
    snprintf(buf, size, "%s/%s", pl->out_dir, name);
}

void pl_group_begin(pipeline *pl, const char *key, const char *title, const char *text)
{
    cli_json_open_object(pl->json, key);
    cli_page_group(pl->page, title, text);
    if (!pl->quiet) printf("%s\n", title);
}

void pl_group_end(pipeline *pl) { cli_json_close(pl->json); }

void pl_step(pipeline *pl, const char *key, const char *title, const char *image,
             const char *text, const char *command)
{
    cli_json_open_object(pl->json, key);
    if (image) cli_json_string(pl->json, "picture", image);
    cli_page_step(pl->page, title, image, text, command);
    pl->step_start = cli_now();
}

void pl_step_end(pipeline *pl, const char *line)
{
    double s = cli_now() - pl->step_start;
    cli_json_double(pl->json, "seconds", s);
    cli_page_number(pl->page, "time", s, "s", "wall-clock time of this step");
    cli_json_close(pl->json);
    if (!pl->quiet && line) printf("  %s (%.2f s)\n", line, s);
}

void pl_step_failed(pipeline *pl, const char *what, const fl_error *err)
{
    char buf[1200], note[1400];
    fl_error_format(err, buf, sizeof buf);
    snprintf(note, sizeof note, "%s failed: %s", what, buf);
    cli_json_string(pl->json, "error", buf);
    cli_json_close(pl->json);
    cli_page_note(pl->page, note);
    fprintf(stderr, "flintstone: error: %s\n", note);
    if (!pl->failed) pl->failed = cli_exit_code(err->status);
}

void pl_step_skipped(pipeline *pl, const char *key, const char *title, const char *why)
{
    cli_json_open_object(pl->json, key);
    cli_json_string(pl->json, "skipped", why);
    cli_json_close(pl->json);
    cli_page_step(pl->page, title, NULL, why, NULL);
    if (!pl->quiet) printf("  skipped: %s\n", why);
}

void pl_num(pipeline *pl, const char *key, const char *name, double v, const char *unit,
            const char *meaning)
{
    cli_json_double(pl->json, key, v);
    cli_page_number(pl->page, name, v, unit, meaning);
}

void pl_count(pipeline *pl, const char *key, const char *name, unsigned long long v,
              const char *meaning)
{
    cli_json_uint(pl->json, key, v);
    cli_page_count(pl->page, name, v, meaning);
}

void pl_bool(pipeline *pl, const char *key, const char *name, int v, const char *meaning)
{
    cli_json_bool(pl->json, key, v);
    cli_page_text(pl->page, name, v ? "yes" : "no", meaning);
}

void pl_text(pipeline *pl, const char *key, const char *name, const char *v, const char *meaning)
{
    cli_json_string(pl->json, key, v);
    cli_page_text(pl->page, name, v, meaning);
}

fl_render *pl_scene(void)
{
    fl_render_options o = {0};
    o.width = 800;
    o.height = 600;
    o.azimuth = 30;
    o.elevation = 25;
    o.supersample = 2;
    fl_render *r = NULL;
    fl_error err;
    return fl_render_new(&o, &r, &err) == FL_OK ? r : NULL;
}

fl_status pl_scene_write(const pipeline *pl, fl_render *scene, const char *file, fl_error *err)
{
    char path[1024];
    pl_path(pl, path, sizeof path, file);
    fl_status st = cli_render_png(scene, path, NULL, err);
    fl_render_free(scene);
    return st;
}
