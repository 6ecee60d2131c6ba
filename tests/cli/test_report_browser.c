/* The demo's report.html opened in a real browser (headless Chromium): every picture loads
 * (natural width > 0), the page logs nothing to the console, and a screenshot is saved next to
 * the report (build dir: report_browser_out/report-screenshot.png). Chromium comes from
 * scripts/install-deps.sh; where it is missing the test says so and passes without checking. */
#include <sys/stat.h>

#include "cli_run.h"
#include "fl_test.h"

#define OUT_DIR "report_browser_out"
#define CHROMIUM "/usr/bin/chromium"
#define CHROMIUM_FLAGS                                                                             \
    "--headless --no-sandbox --disable-gpu --disable-background-networking "                       \
    "--disable-component-update --disable-sync --enable-logging=stderr --v=0 "                     \
    "--virtual-time-budget=2000"

static cli_result r;
static char html[1 << 20];

/* Appended to a copy of the page: after load, lists the images that did not decode. */
static const char *probe =
    "<script>window.addEventListener('load',function(){var b=[],im=document.images;"
    "for(var i=0;i<im.length;i++)if(!im[i].complete||im[i].naturalWidth===0)"
    "b.push(im[i].getAttribute('src'));var d=document.createElement('pre');"
    "d.id='fl-probe';d.textContent='FL'+'PROBE images='+im.length+' broken='+b.length+' '+"
    "b.join(' ');document.body.appendChild(d);});</script>";

static size_t count_occurrences(const char *s, const char *what)
{
    size_t n = 0;
    for (const char *p = strstr(s, what); p; p = strstr(p + 1, what)) n++;
    return n;
}

static int run_chromium(const char *args, const char *out, const char *log)
{
    char cmd[8192];
    int len = snprintf(cmd, sizeof cmd,
                       "timeout 120 " CHROMIUM " " CHROMIUM_FLAGS
                       " --user-data-dir=%s/profile-%ld %s >%s 2>%s",
                       OUT_DIR, (long)getpid(), args, out, log);
    if (len < 0 || (size_t)len >= sizeof cmd) return -1; /* a cut command line must not run */
    return system(cmd);
}

static void test_report_images_load_and_console_is_clean(void)
{
    struct stat st;
    if (stat(CHROMIUM, &st) != 0) {
        printf("SKIPPED: %s not installed (scripts/install-deps.sh installs Debian's chromium); "
               "the browser test did not run\n",
               CHROMIUM);
        return;
    }
    CHECK_EQ_INT(cli_run(&r, "demo --out " OUT_DIR " --quiet"), 0);
    cli_read_file(OUT_DIR "/report.html", html, sizeof html);
    size_t images = count_occurrences(html, "<img ");
    CHECK(images >= 3);
    char *end = strstr(html, "</body>");
    CHECK(end != NULL);
    if (!end) return;

    /* 1. Images: a copy of the page with the probe, in the same directory. */
    char copy[sizeof html + 1024];
    snprintf(copy, sizeof copy, "%.*s%s%s", (int)(end - html), html, probe, end);
    cli_write_file(OUT_DIR "/report-probe.html", copy);
    char cwd[1024], args[4096];
    CHECK(getcwd(cwd, sizeof cwd) != NULL);
    snprintf(args, sizeof args, "--dump-dom file://%s/" OUT_DIR "/report-probe.html", cwd);
    CHECK_EQ_INT(run_chromium(args, OUT_DIR "/dom.txt", OUT_DIR "/dom-log.txt"), 0);
    static char dom[1 << 20];
    cli_read_file(OUT_DIR "/dom.txt", dom, sizeof dom);
    const char *line = strstr(dom, "FLPROBE images=");
    CHECK_MSG(line != NULL, "the probe did not run; chromium output in " OUT_DIR "/dom-log.txt");
    if (line) {
        size_t seen = 0, broken = 0;
        CHECK_EQ_INT(sscanf(line, "FLPROBE images=%zu broken=%zu", &seen, &broken), 2);
        CHECK_EQ_INT(seen, images);
        CHECK_MSG(broken == 0, "%.300s", line);
    }

    /* 2. The page itself: no console messages (it has no scripts, so any is an error), and a
     * screenshot for people to look at. */
    snprintf(args, sizeof args,
             "--window-size=1200,2400 --screenshot=%s/" OUT_DIR "/report-screenshot.png "
             "file://%s/" OUT_DIR "/report.html",
             cwd, cwd);
    CHECK_EQ_INT(run_chromium(args, OUT_DIR "/shot.txt", OUT_DIR "/shot-log.txt"), 0);
    static char log[1 << 16];
    cli_read_file(OUT_DIR "/shot-log.txt", log, sizeof log);
    const char *console = strstr(log, ":CONSOLE");
    CHECK_MSG(console == NULL, "console message: %.300s", console);
    CHECK(stat(OUT_DIR "/report-screenshot.png", &st) == 0 && st.st_size > 1000);
    remove(OUT_DIR "/report-probe.html");
    char rm[256];
    snprintf(rm, sizeof rm, "rm -rf %s/profile-%ld", OUT_DIR, (long)getpid());
    CHECK_EQ_INT(system(rm), 0);
}

FL_TEST_MAIN(FL_TEST_CASE(test_report_images_load_and_console_is_clean))
