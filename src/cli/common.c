#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cli/cli.h"
#include "core/core.h"

int cli_common_option(cli_common *c, int argc, char **argv, int *i)
{
    const char *a = argv[*i];
    if (strcmp(a, "--json") == 0) {
        c->json = 1;
        return 1;
    }
    if (strcmp(a, "--quiet") == 0 || strcmp(a, "-q") == 0) {
        c->quiet = 1;
        return 1;
    }
    if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
        c->help = 1;
        return 1;
    }
    if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0) {
        if (*i + 1 >= argc) {
            cli_fail(1, "%s needs a file name (the format follows its extension)", a);
            return -1;
        }
        c->output = argv[++*i];
        return 1;
    }
    return 0;
}

int cli_exit_code(fl_status status)
{
    return status == FL_ERR_NOMEM ? 3 : (int)status;
}

int cli_report(const fl_error *err)
{
    char buf[1200];
    fl_error_format(err, buf, sizeof buf);
    fprintf(stderr, "flintstone: error: %s\n", buf);
    if (err->status == FL_ERR_NOMEM) cli_memory_limit_note();
    return cli_exit_code(err->status == FL_OK ? FL_ERR_ALGORITHM : err->status);
}

int cli_fail(int code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("flintstone: error: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    return code;
}

int cli_check_output(const char *path, const char *formats)
{
    if (!path) return 0;
    char ext[16];
    fl_path_extension(path, ext, sizeof ext);
    size_t n = strlen(ext);
    for (const char *f = formats; n && *f;) {
        size_t len = strcspn(f, " ");
        if (len == n && strncmp(f, ext, n) == 0) return 0;
        f += len;
        f += strspn(f, " ");
    }
    if (!n)
        return cli_fail(cli_exit_code(FL_ERR_USAGE),
                        "%s: no file extension to tell the output format (this command writes: %s)",
                        path, formats);
    return cli_fail(cli_exit_code(FL_ERR_USAGE),
                    "%s: this command does not write '.%s' files (it writes: %s)", path, ext,
                    formats);
}

double cli_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int cli_parse_double(const char *s, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end || errno == ERANGE || !isfinite(v)) return -1;
    *out = v;
    return 0;
}

int cli_parse_skin_placement(const char *s, fl_skin_placement *out)
{
    if (!strcmp(s, "alg1"))
        *out = FL_SKIN_PLACE_ALGORITHM1;
    else if (!strcmp(s, "subdivision"))
        *out = FL_SKIN_PLACE_SUBDIVISION;
    else
        return -1;
    return 0;
}

int cli_parse_size(const char *s, size_t *out)
{
    char *end;
    if (*s == '-') return -1;
    errno = 0;
    unsigned long long v = strtoull(s, &end, 10);
    if (end == s || *end || errno == ERANGE || v > SIZE_MAX) return -1;
    *out = (size_t)v;
    return 0;
}

void cli_progress_init(cli_progress *p, const cli_common *c)
{
    p->enabled = !c->quiet && isatty(STDERR_FILENO);
    p->last_permille = -1;
    p->last_stage = NULL;
}

int cli_progress_fn(void *user, const char *stage, double fraction)
{
    cli_progress *p = user;
    if (!p->enabled) return 0;
    if (fraction < 0) fraction = 0;
    if (fraction > 1) fraction = 1;
    int permille = (int)(fraction * 1000);
    if (permille == p->last_permille && stage == p->last_stage) return 0;
    p->last_permille = permille;
    p->last_stage = stage;
    enum { WIDTH = 30 };
    int filled = (int)(fraction * WIDTH);
    char bar[WIDTH + 1];
    for (int i = 0; i < WIDTH; i++)
        bar[i] = i < filled ? '#' : '.';
    bar[WIDTH] = '\0';
    fprintf(stderr, "\r%-24.24s [%s] %5.1f%%", stage ? stage : "", bar, fraction * 100.0);
    fflush(stderr);
    return 0;
}

void cli_progress_done(cli_progress *p)
{
    if (p->enabled && p->last_permille >= 0) fputs("\r\033[K", stderr);
    p->last_permille = -1;
}

/* ---- JSON ---------------------------------------------------------------------------------- */

static void json_prefix(cli_json *j, const char *key)
{
    if (j->need_comma[j->depth]) fputc(',', j->fp);
    j->need_comma[j->depth] = 1;
    if (key) fprintf(j->fp, "\"%s\":", key);
}

/* Summaries nest a few levels at most; deeper nesting is a programming error caught here. */
static void json_push(cli_json *j, char closer)
{
    if (j->depth + 1 >= (int)(sizeof j->closer)) abort();
    j->depth++;
    j->need_comma[j->depth] = 0;
    j->closer[j->depth] = closer;
}

void cli_json_begin(cli_json *j, FILE *fp)
{
    memset(j, 0, sizeof *j);
    j->fp = fp;
    fputc('{', fp);
    j->depth = 1;
}

void cli_json_end(cli_json *j)
{
    while (j->depth > 1)
        cli_json_close(j);
    fputs("}\n", j->fp);
    j->depth = 0;
}

void cli_json_key(cli_json *j, const char *key)
{
    json_prefix(j, key);
}

void cli_json_int(cli_json *j, const char *key, long long v)
{
    json_prefix(j, key);
    fprintf(j->fp, "%lld", v);
}

void cli_json_uint(cli_json *j, const char *key, unsigned long long v)
{
    json_prefix(j, key);
    fprintf(j->fp, "%llu", v);
}

void cli_json_double(cli_json *j, const char *key, double v)
{
    json_prefix(j, key);
    if (isfinite(v))
        fprintf(j->fp, "%.17g", v);
    else
        fputs("null", j->fp);
}

void cli_json_bool(cli_json *j, const char *key, int v)
{
    json_prefix(j, key);
    fputs(v ? "true" : "false", j->fp);
}

void cli_json_null(cli_json *j, const char *key)
{
    json_prefix(j, key);
    fputs("null", j->fp);
}

void cli_json_string(cli_json *j, const char *key, const char *v)
{
    json_prefix(j, key);
    fputc('"', j->fp);
    for (const unsigned char *p = (const unsigned char *)v; *p; p++) {
        if (*p == '"' || *p == '\\')
            fprintf(j->fp, "\\%c", *p);
        else if (*p < 0x20)
            fprintf(j->fp, "\\u%04x", *p);
        else
            fputc(*p, j->fp);
    }
    fputc('"', j->fp);
}

void cli_json_open_object(cli_json *j, const char *key)
{
    json_prefix(j, key);
    fputc('{', j->fp);
    json_push(j, '}');
}

void cli_json_open_array(cli_json *j, const char *key)
{
    json_prefix(j, key);
    fputc('[', j->fp);
    json_push(j, ']');
}

void cli_json_close(cli_json *j)
{
    if (j->depth <= 1) return;
    fputc(j->closer[j->depth], j->fp);
    j->depth--;
}
