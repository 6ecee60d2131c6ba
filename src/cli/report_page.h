/* The HTML report of `flintstone demo` and `flintstone report`: one static page, no network and
 * no scripts. Each step of the pipeline becomes a section with its picture, its key numbers
 * (value, unit and what the number means) and the exact command that reproduces it. */
#ifndef FL_CLI_REPORT_PAGE_H
#define FL_CLI_REPORT_PAGE_H

#include "flintstone.h"

typedef struct cli_page cli_page;

/* A new page; NULL when out of memory. */
cli_page *cli_page_new(const char *title, const char *intro);
void cli_page_free(cli_page *page);

/* A heading over the steps that follow (one input's pipeline). */
void cli_page_group(cli_page *page, const char *title, const char *text);

/* Opens a step section. `image` is a path relative to the page (PNG or SVG) or NULL; `text`
 * one paragraph saying what the step does; `command` the command line that reproduces it
 * (NULL: none). Ends the previous section. */
void cli_page_step(cli_page *page, const char *title, const char *image, const char *text,
                   const char *command);
/* One row of the current step's table of numbers. */
void cli_page_number(cli_page *page, const char *name, double value, const char *unit,
                     const char *meaning);
void cli_page_count(cli_page *page, const char *name, unsigned long long value,
                    const char *meaning);
void cli_page_text(cli_page *page, const char *name, const char *value, const char *meaning);
/* A step that could not run: the reason is shown instead of numbers. */
void cli_page_note(cli_page *page, const char *note);

/* Writes the page to `path` atomically. FL_ERR_NOMEM if any earlier append ran out of memory,
 * FL_ERR_IO when the file cannot be written. */
fl_status cli_page_write(cli_page *page, const char *path, fl_error *err);

#endif
