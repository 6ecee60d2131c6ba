/* The pipeline behind `flintstone demo` and `flintstone report`: each step runs one capability
 * through the library, writes its outputs and picture into the output directory, and records
 * its key numbers twice, in summary.json (machine-readable) and in report.html (with units,
 * meaning and the command that reproduces the step). A failing step is recorded as such and
 * the steps that do not depend on it still run. */
#ifndef FL_CLI_PIPELINE_H
#define FL_CLI_PIPELINE_H

#include "cli/cli.h"
#include "cli/report_page.h"

typedef struct pipeline {
    const char *out_dir;
    cli_json *json;
    cli_page *page;
    int quiet;
    int failed;       /* exit code of the first failed step, 0 if none */
    double step_start;
} pipeline;

/* "<out_dir>/<name>" into buf. */
void pl_path(const pipeline *pl, char *buf, size_t size, const char *name);

/* Opens a step: a JSON object `key` and a report section. image: file name inside out_dir or
 * NULL; command: the reproducing command line or NULL. Starts the step's clock. */
void pl_step(pipeline *pl, const char *key, const char *title, const char *image,
             const char *text, const char *command);
/* Closes the step: records its seconds and prints `line` (unless quiet). */
void pl_step_end(pipeline *pl, const char *line);
/* Records a failed step (JSON "error", a note on the page, stderr) and closes it. */
void pl_step_failed(pipeline *pl, const char *what, const fl_error *err);
/* Records a step that does not apply to this input (JSON "skipped", a note on the page). */
void pl_step_skipped(pipeline *pl, const char *key, const char *title, const char *why);

/* Numbers of the open step: JSON key, then the report's name, unit and meaning. */
void pl_num(pipeline *pl, const char *key, const char *name, double v, const char *unit,
            const char *meaning);
void pl_count(pipeline *pl, const char *key, const char *name, unsigned long long v,
              const char *meaning);
void pl_bool(pipeline *pl, const char *key, const char *name, int v, const char *meaning);
void pl_text(pipeline *pl, const char *key, const char *name, const char *v, const char *meaning);

/* Pictures: a scene with the report's size and view (800 x 600, from azimuth 30, elevation
 * 25, 2x2 supersampled), NULL when out of memory; written to out_dir/file as PNG (and freed). */
fl_render *pl_scene(void);
fl_status pl_scene_write(const pipeline *pl, fl_render *scene, const char *file, fl_error *err);

/* Groups the steps of one input under a JSON object `key` and a report heading. */
void pl_group_begin(pipeline *pl, const char *key, const char *title, const char *text);
void pl_group_end(pipeline *pl);

/* The 2D pipeline on scattered points (path), measured against `truth` (an ordered closed
 * polyline file, or NULL). The 3D pipeline on scattered points or a closed mesh, measured
 * against `truth` (a mesh file, or NULL). `name` prefixes every output file. */
void pl_run_2d(pipeline *pl, const char *name, const char *path, const char *truth);
void pl_run_3d(pipeline *pl, const char *name, const char *path, const char *truth);

#endif
