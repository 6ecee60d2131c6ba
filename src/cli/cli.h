/* Shared pieces of the `flintstone` command: the contract every subcommand follows.
 *  - `-o PATH` writes output, format by extension, atomically (the library's writers do that).
 *  - `--json` prints exactly one JSON object to stdout; otherwise a short human summary.
 *  - errors go to stderr as "flintstone: error: <file>:<line>: <what>"; exit codes are the
 *    fl_status values (0 ok, 1 usage, 2 bad input, 3 could not complete, 4 I/O).
 *  - progress bars on a terminal only, never with --quiet. */
#ifndef FL_CLI_H
#define FL_CLI_H

#include <stdio.h>

#include "flintstone.h"

/* Options every subcommand accepts. */
typedef struct cli_common {
    int json;
    int quiet;
    int help;
    const char *output; /* -o PATH, or NULL */
} cli_common;

/* If argv[*i] is a common option, consumes it (and its value) and returns 1; returns -1 on a
 * malformed common option (message printed), 0 when argv[*i] is not a common option. */
int cli_common_option(cli_common *c, int argc, char **argv, int *i);

/* Prints "flintstone: error: ..." for a library error and returns the exit code. */
int cli_report(const fl_error *err);
/* Prints "flintstone: error: <fmt>" and returns `code`. */
int cli_fail(int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* The memory limit (memlimit.c): strips `--max-memory SIZE` / `--max-memory=SIZE` from argv
 * wherever it appears, reads FLINTSTONE_MAX_MEMORY, and sets a soft address-space limit of that
 * size (default: available memory + free swap) so that an input too large for the machine
 * fails with FL_ERR_NOMEM (exit 3) instead of an OOM kill. Returns 0, or an exit code after a
 * printed usage error. */
int cli_memory_limit_setup(int *argc, char **argv);
/* Parses a size like 512M, 4G, 100000 or none (0 = no limit); returns 0 on success. */
int cli_parse_memory_size(const char *s, unsigned long long *out);
/* After an out-of-memory error: one line on stderr saying which limit applied and how to change
 * it (nothing when no limit was set). */
void cli_memory_limit_note(void);

/* Before any work: 0 when `path` is NULL or its extension is one of `formats` (space
 * separated, lower case, e.g. "off obj ply stl"); otherwise prints which formats this command
 * writes and returns the usage exit code, so a wrong -o fails at once rather than after the
 * computation. */
int cli_check_output(const char *path, const char *formats);

/* Exit code for a status (FL_ERR_NOMEM exits 3). */
int cli_exit_code(fl_status status);

/* Wall-clock seconds since an arbitrary origin (monotonic). */
double cli_now(void);

/* Parses a double / a non-negative integer option value; returns 0 on success. */
int cli_parse_double(const char *s, double *out);
int cli_parse_size(const char *s, size_t *out);
/* Parses the --placement value of `balls` and `skin` (alg1 | subdivision); 0 on success. */
int cli_parse_skin_placement(const char *s, fl_skin_placement *out);

/* Progress reporting: an fl_progress_fn that draws a bar on stderr when it is a terminal and
 * quiet is off. `user` must point to a cli_progress. */
typedef struct cli_progress {
    int enabled;
    int last_permille;
    const char *last_stage;
} cli_progress;

void cli_progress_init(cli_progress *p, const cli_common *c);
int cli_progress_fn(void *user, const char *stage, double fraction);
void cli_progress_done(cli_progress *p);

/* A minimal streaming JSON object writer for the --json summaries (one object, flat or with
 * nested arrays/objects). Keys must be snake_case literals. */
typedef struct cli_json {
    FILE *fp;
    int depth;
    int need_comma[16];
    char closer[16]; /* '}' or ']' for each open level */
} cli_json;

void cli_json_begin(cli_json *j, FILE *fp);
void cli_json_end(cli_json *j); /* closes the top object and prints a newline */
void cli_json_key(cli_json *j, const char *key);
void cli_json_int(cli_json *j, const char *key, long long v);
void cli_json_uint(cli_json *j, const char *key, unsigned long long v);
void cli_json_double(cli_json *j, const char *key, double v); /* NaN/Inf become null */
void cli_json_bool(cli_json *j, const char *key, int v);
void cli_json_string(cli_json *j, const char *key, const char *v);
void cli_json_null(cli_json *j, const char *key);
/* key may be NULL inside arrays. */
void cli_json_open_object(cli_json *j, const char *key);
void cli_json_open_array(cli_json *j, const char *key);
void cli_json_close(cli_json *j);

/* Subcommands: argv[0] is the subcommand name. */
typedef struct cli_command {
    const char *name;
    const char *summary;
    int (*run)(int argc, char **argv);
} cli_command;

#endif /* FL_CLI_H */
