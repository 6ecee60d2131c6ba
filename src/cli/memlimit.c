/* The command's memory limit (issue #14: "inputs larger than available memory fail cleanly with
 * an error, not an OOM kill").
 *
 * Linux overcommits: malloc of more than the machine has usually succeeds, and the process is
 * killed later, when the pages are touched, with no message and possibly half an output. A
 * soft address-space limit (RLIMIT_AS) turns that into a failing malloc, which the library
 * reports as FL_ERR_NOMEM and the command as exit code 3 with a message; the atomic writers
 * leave no output behind. The default limit is what the machine can give at start:
 * MemAvailable + SwapFree from /proc/meminfo, on top of the address space the process already
 * uses. `--max-memory SIZE` (any command, before or after the subcommand) or the environment
 * variable FLINTSTONE_MAX_MEMORY override it; `none` removes it.
 *
 * Sanitizer builds reserve terabytes of shadow address space, so there the limit is not set
 * (the option is still accepted). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "cli/cli.h"

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define FL_CLI_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer) || \
    __has_feature(thread_sanitizer)
#define FL_CLI_SANITIZED 1
#endif
#endif
#ifndef FL_CLI_SANITIZED
#define FL_CLI_SANITIZED 0
#endif

static unsigned long long g_limit;   /* bytes on top of the start's address space; 0 = none */
static const char *g_limit_source; /* "available memory", "--max-memory", ... */

/* "123", "512K", "64M", "2G", "1T" (binary multiples, optional trailing B / iB), or
 * none/off/0 for no limit. Returns 0 on success. */
int cli_parse_memory_size(const char *s, unsigned long long *out)
{
    if (strcmp(s, "none") == 0 || strcmp(s, "off") == 0 || strcmp(s, "unlimited") == 0) {
        *out = 0;
        return 0;
    }
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || errno == ERANGE || !(v >= 0) || v > 1e18) return -1;
    double mult = 1;
    switch (*end) {
    case 'k': case 'K': mult = 1024.0, end++; break;
    case 'm': case 'M': mult = 1048576.0, end++; break;
    case 'g': case 'G': mult = 1073741824.0, end++; break;
    case 't': case 'T': mult = 1099511627776.0, end++; break;
    default: break;
    }
    if (mult > 1 && *end == 'i') end++;
    if (*end == 'B' || *end == 'b') end++;
    if (*end) return -1;
    double bytes = v * mult;
    if (bytes > 1e18) return -1;
    *out = (unsigned long long)bytes;
    return 0;
}

/* A "Name:   value kB" line of a /proc file, in bytes; 0 when absent. */
static unsigned long long proc_kb(const char *path, const char *name)
{
    FILE *f = fopen(path, "r");
    if (!f) return 0;
    char line[256];
    size_t len = strlen(name);
    unsigned long long kb = 0;
    while (fgets(line, sizeof line, f))
        if (strncmp(line, name, len) == 0 && line[len] == ':') {
            kb = strtoull(line + len + 1, NULL, 10);
            break;
        }
    fclose(f);
    return kb * 1024ull;
}

/* Removes argv[i] and argv[i + 1 .. i + k - 1] from the argument vector. */
static void drop_args(int *argc, char **argv, int i, int k)
{
    for (int j = i; j + k <= *argc; j++)
        argv[j] = argv[j + k];
    *argc -= k;
}

int cli_memory_limit_setup(int *argc, char **argv)
{
    const char *value = NULL, *source = NULL;
    const char *env = getenv("FLINTSTONE_MAX_MEMORY");
    if (env && *env) value = env, source = "FLINTSTONE_MAX_MEMORY";
    for (int i = 1; i < *argc; i++) {
        if (strcmp(argv[i], "--max-memory") == 0) {
            if (i + 1 >= *argc)
                return cli_fail(1, "--max-memory needs a size (e.g. 4G, 512M, or none)");
            value = argv[i + 1], source = "--max-memory";
            drop_args(argc, argv, i, 2);
            i--;
        } else if (strncmp(argv[i], "--max-memory=", 13) == 0) {
            value = argv[i] + 13, source = "--max-memory";
            drop_args(argc, argv, i, 1);
            i--;
        }
    }
    unsigned long long limit;
    if (value) {
        if (cli_parse_memory_size(value, &limit) != 0)
            return cli_fail(1, "%s: '%s' is not a size (e.g. 4G, 512M, 100000000, or none)",
                            source, value);
        if (limit != 0 && limit < (1ull << 20))
            return cli_fail(1, "%s: %s is below the 1 MiB minimum", source, value);
    } else {
        limit = proc_kb("/proc/meminfo", "MemAvailable") + proc_kb("/proc/meminfo", "SwapFree");
        source = "available memory at start";
    }
    if (limit == 0 || FL_CLI_SANITIZED) return 0;
    unsigned long long used = proc_kb("/proc/self/status", "VmSize");
    struct rlimit rl;
    if (getrlimit(RLIMIT_AS, &rl) != 0) return 0;
    rlim_t want = (rlim_t)(used + limit);
    if (rl.rlim_max != RLIM_INFINITY && want > rl.rlim_max) want = rl.rlim_max;
    if (rl.rlim_cur != RLIM_INFINITY && rl.rlim_cur <= want) return 0; /* already tighter */
    rl.rlim_cur = want;
    if (setrlimit(RLIMIT_AS, &rl) != 0) return 0;
    g_limit = limit;
    g_limit_source = source;
    return 0;
}

void cli_memory_limit_note(void)
{
    if (!g_limit) return;
    fprintf(stderr,
            "flintstone: note: the memory limit was %.0f MiB (%s); set it with --max-memory SIZE "
            "or FLINTSTONE_MAX_MEMORY (none for no limit)\n",
            (double)g_limit / 1048576.0, g_limit_source);
}
