/* Runs the flintstone command built alongside the tests and captures its exit code, stdout and
 * stderr, so CLI tests check the contract a user sees. */
#ifndef FL_TEST_CLI_RUN_H
#define FL_TEST_CLI_RUN_H

#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

typedef struct cli_result {
    int code;
    char out[65536];
    char err[8192];
} cli_result;

static inline void cli_read_file(const char *path, char *buf, size_t size)
{
    buf[0] = '\0';
    FILE *f = fopen(path, "rb");
    if (!f) return;
    size_t n = fread(buf, 1, size - 1, f);
    buf[n] = '\0';
    fclose(f);
}

/* args is appended to the command line as is (quote it yourself). */
static inline int cli_run(cli_result *r, const char *args)
{
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "'%s' %s >cli_test_stdout.txt 2>cli_test_stderr.txt </dev/null",
             FL_CLI_PATH, args);
    int st = system(cmd);
    r->code = (st != -1 && WIFEXITED(st)) ? WEXITSTATUS(st) : -1;
    cli_read_file("cli_test_stdout.txt", r->out, sizeof r->out);
    cli_read_file("cli_test_stderr.txt", r->err, sizeof r->err);
    remove("cli_test_stdout.txt");
    remove("cli_test_stderr.txt");
    return r->code;
}

/* Writes text to a file in the test's working directory. */
static inline void cli_write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    if (!f) return;
    fputs(text, f);
    fclose(f);
}

#endif
