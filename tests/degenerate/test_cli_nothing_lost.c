/* Nothing lost (issue #14): a failing flintstone command (bad input, bad option, unwritable
 * output, -o naming its own input) never leaves a file at the -o path, never changes a file
 * already there, never modifies its input and leaves no temporary behind; a command killed
 * with SIGKILL mid-run leaves no file at the -o path (the writers go through a temporary that
 * is renamed only when complete) and, when killed before writing started, no temporary. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "cli/cli_run.h"
#include "fl_test.h"

static char *slurp(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *b = malloc((size_t)n + 1);
    if (b && fread(b, 1, (size_t)n, f) != (size_t)n) n = 0;
    if (b) b[n] = 0;
    fclose(f);
    *size = (size_t)n;
    return b;
}

static int same_content(const char *path, const char *expected, size_t size)
{
    size_t n;
    char *b = slurp(path, &n);
    int same = b && n == size && memcmp(b, expected, n) == 0;
    free(b);
    return same;
}

/* Temporaries of the writers are "<target>.tmp.<pid>": count those of our files. */
static int temporaries(const char *prefix)
{
    DIR *d = opendir(".");
    int count = 0;
    struct dirent *e;
    while (d && (e = readdir(d)))
        if (strncmp(e->d_name, prefix, strlen(prefix)) == 0 && strstr(e->d_name, ".tmp."))
            count++;
    if (d) closedir(d);
    return count;
}

static int exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

static const char SENTINEL[] = "user data that must survive\n";

static void test_failing_commands_leave_nothing(void)
{
    cli_write_file("nl_sq.xy", "0 0\n4 0\n4 4\n0 4\n1 1\n");
    cli_write_file("nl_line.xy", "0 0\n1 1\n2 2\n3 3\n");
    cli_write_file("nl_nan.xyz", "0 0 0\n1 0 0\nnan 1 0\n0 0 1\n");
    cli_write_file("nl_poly.xy", "0 0\n4 0\n4 4\n0 4\n");
    cli_write_file("nl_open.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n"
                                  "3 0 3 2\n");
    cli_write_file("nl_q.xyz", "0 0 0\n");
    cli_write_file("nl_notadir", "x\n");
    struct {
        const char *args, *out; /* command line; its -o target */
        int code;               /* expected exit code */
    } cases[] = {
        {"delaunay nl_line.xy -o nl_out1.off", "nl_out1.off", 3},      /* collinear */
        {"delaunay nl_nan.xyz -o nl_out2.vtk", "nl_out2.vtk", 2},      /* NaN */
        {"delaunay nl_missing.xyz -o nl_out3.vtk", "nl_out3.vtk", 4},  /* no input */
        {"delaunay nl_sq.xy --bogus -o nl_out4.off", "nl_out4.off", 1}, /* bad option */
        {"delaunay nl_sq.xy -o nl_out5.xyz", "nl_out5.xyz", 1},        /* bad output format */
        {"reconstruct nl_line.xy -o nl_out6.xy", "nl_out6.xy", 3},
        {"reconstruct nl_nan.xyz -o nl_out7.off", "nl_out7.off", 2},
        {"graph nl_nan.xyz --gamma 0,0 -o nl_out8.off", "nl_out8.off", 2},
        {"hal nl_poly.xy --level -3 -o nl_out9.xy", "nl_out9.xy", 1},
        {"closest nl_nan.xyz nl_q.xyz -o nl_out10.csv", "nl_out10.csv", 2},
        {"delaunay nl_sq.xy -o nl_notadir/x.off", NULL, 4}, /* parent is a file */
        {"delaunay nl_sq.xy -o /nonexistent-dir-flintstone/x.off", NULL, 4},
        {"hal nl_poly.xy --level 1 -o nl_poly.xy", NULL, 1},  /* -o is the input */
        {"hal ./nl_poly.xy --level 1 -o nl_poly.xy", NULL, 1}, /* same file, other spelling */
    };
    size_t sq_n, poly_n;
    char *sq = slurp("nl_sq.xy", &sq_n), *poly = slurp("nl_poly.xy", &poly_n);
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        for (int pre = 0; pre < 2; pre++) { /* without, then with a file already at -o */
            if (cases[i].out) {
                remove(cases[i].out);
                if (pre) cli_write_file(cases[i].out, SENTINEL);
            } else if (pre) {
                continue;
            }
            cli_result r;
            int code = cli_run(&r, cases[i].args);
            CHECK_MSG(code == cases[i].code, "'%s': exit %d, expected %d (%s)", cases[i].args,
                      code, cases[i].code, r.err);
            CHECK_MSG(strstr(r.err, "error") != NULL, "'%s': no error message", cases[i].args);
            if (cases[i].out && !pre)
                CHECK_MSG(!exists(cases[i].out), "'%s' left %s", cases[i].args, cases[i].out);
            if (cases[i].out && pre)
                CHECK_MSG(same_content(cases[i].out, SENTINEL, strlen(SENTINEL)),
                          "'%s' changed the existing %s", cases[i].args, cases[i].out);
            CHECK_MSG(temporaries("nl_") == 0, "'%s' left a temporary", cases[i].args);
            CHECK_MSG(same_content("nl_sq.xy", sq, sq_n), "'%s' changed its input",
                      cases[i].args);
            CHECK_MSG(same_content("nl_poly.xy", poly, poly_n), "'%s' changed its input",
                      cases[i].args);
            if (cases[i].out) remove(cases[i].out);
        }
    }
    free(sq);
    free(poly);
    static const char *const inputs[] = {"nl_sq.xy", "nl_line.xy", "nl_nan.xyz", "nl_poly.xy",
                                         "nl_open.off", "nl_q.xyz", "nl_notadir"};
    for (size_t i = 0; i < sizeof inputs / sizeof *inputs; i++) remove(inputs[i]);
}

/* Starts the CLI on `args` (split on spaces), waits `ms` milliseconds, SIGKILLs it. Returns 1
 * when it was still running when killed. */
static int run_and_kill(char *const *argv, long ms)
{
    fflush(stdout); /* or the child's freopen would flush our buffered lines a second time */
    fflush(stderr);
    pid_t pid = fork();
    if (pid == 0) {
        FILE *null = freopen("/dev/null", "w", stdout);
        null = freopen("/dev/null", "w", stderr);
        (void)null;
        execv(FL_CLI_PATH, argv);
        _exit(127);
    }
    struct timespec ts = {ms / 1000, (ms % 1000) * 1000000L};
    nanosleep(&ts, NULL);
    int status, killed = waitpid(pid, &status, WNOHANG) == 0;
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    return killed;
}

/* n random points in the unit cube, "%.17g" text. */
static void write_cloud(const char *path, int n)
{
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f) return;
    unsigned long long s = 12345;
    for (int i = 0; i < n; i++) {
        double c[3];
        for (int k = 0; k < 3; k++) {
            s = s * 6364136223846793005ULL + 1442695040888963407ULL;
            c[k] = (double)(s >> 11) / 9007199254740992.0;
        }
        fprintf(f, "%.17g %.17g %.17g\n", c[0], c[1], c[2]);
    }
    fclose(f);
}

static void remove_temporaries(const char *prefix)
{
    DIR *d = opendir(".");
    struct dirent *e;
    while (d && (e = readdir(d)))
        if (strncmp(e->d_name, prefix, strlen(prefix)) == 0 && strstr(e->d_name, ".tmp."))
            remove(e->d_name);
    if (d) closedir(d);
}

static void test_killed_command_leaves_no_output(void)
{
    /* 2e5 points: seconds of work even in the release build, so 50 ms is mid-computation. */
    write_cloud("nl_big.xyz", 200000);
    size_t big_n;
    char *big = slurp("nl_big.xyz", &big_n);
    char *argv[] = {"flintstone", "delaunay", "nl_big.xyz", "-o", "nl_big.vtk", NULL};
    remove("nl_big.vtk");
    CHECK_MSG(run_and_kill(argv, 50), "the command finished within 50 ms");
    CHECK_MSG(!exists("nl_big.vtk"), "a killed command left nl_big.vtk");
    CHECK_MSG(temporaries("nl_big") == 0, "a command killed while computing left a temporary");
    CHECK_MSG(same_content("nl_big.xyz", big, big_n), "the killed command changed its input");
    free(big);
    remove("nl_big.xyz");
    /* Kills at later times on a smaller input may land in the writer: the target is then
     * still absent (the temporary is renamed only once complete) or, if the command got to
     * finish, complete. A kill inside the writer leaves its temporary (SIGKILL cannot be
     * caught), which never has the target's name; removed between rounds. */
    write_cloud("nl_mid.xyz", 20000);
    cli_result full;
    CHECK_EQ_INT(cli_run(&full, "delaunay nl_mid.xyz -o nl_full.vtk"), 0);
    size_t full_n;
    char *complete = slurp("nl_full.vtk", &full_n);
    char *mid[] = {"flintstone", "delaunay", "nl_mid.xyz", "-o", "nl_mid.vtk", NULL};
    for (long ms = 10; ms <= 640; ms *= 2) {
        remove("nl_mid.vtk");
        run_and_kill(mid, ms);
        if (exists("nl_mid.vtk"))
            CHECK_MSG(complete && same_content("nl_mid.vtk", complete, full_n),
                      "kill after %ld ms left a partial nl_mid.vtk", ms);
        remove_temporaries("nl_mid.vtk");
    }
    free(complete);
    remove("nl_mid.vtk");
    remove("nl_full.vtk");
    remove("nl_mid.xyz");
}

int main(void)
{
    fl_test_case cases[] = {
        FL_TEST_CASE(test_failing_commands_leave_nothing),
        FL_TEST_CASE(test_killed_command_leaves_no_output),
    };
    return fl_test_run(cases, sizeof cases / sizeof *cases);
}
