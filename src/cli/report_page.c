/* HTML report page (see report_page.h). The body is accumulated as escaped HTML in one growing
 * buffer; an allocation failure sets a flag that cli_page_write reports, so callers can append
 * without checking every call. */
#include "cli/report_page.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.h"

struct cli_page {
    char *title;
    fl_vec body; /* chars */
    int in_step, in_table, steps, nomem;
};

static void put(cli_page *p, const char *s, size_t n)
{
    if (!p->nomem && fl_vec_push(&p->body, s, n)) p->nomem = 1;
}

static void puts_raw(cli_page *p, const char *s) { put(p, s, strlen(s)); }

/* Text content and attribute values: the five characters HTML gives meaning to. */
static void puts_escaped(cli_page *p, const char *s)
{
    for (; s && *s; s++) {
        switch (*s) {
        case '&': puts_raw(p, "&amp;"); break;
        case '<': puts_raw(p, "&lt;"); break;
        case '>': puts_raw(p, "&gt;"); break;
        case '"': puts_raw(p, "&quot;"); break;
        case '\'': puts_raw(p, "&#39;"); break;
        default: put(p, s, 1);
        }
    }
}

static char *dup_string(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d) memcpy(d, s, n);
    return d;
}

cli_page *cli_page_new(const char *title, const char *intro)
{
    cli_page *p = calloc(1, sizeof *p);
    if (!p) return NULL;
    p->title = dup_string(title);
    if (!p->title) {
        free(p);
        return NULL;
    }
    fl_vec_init(&p->body, 1);
    puts_raw(p, "<header><h1>");
    puts_escaped(p, title);
    puts_raw(p, "</h1>\n<p>");
    puts_escaped(p, intro);
    puts_raw(p, "</p></header>\n");
    return p;
}

void cli_page_free(cli_page *p)
{
    if (!p) return;
    fl_vec_free(&p->body);
    free(p->title);
    free(p);
}

static void end_table(cli_page *p)
{
    if (p->in_table) puts_raw(p, "</tbody></table>\n");
    p->in_table = 0;
}

static void end_step(cli_page *p)
{
    end_table(p);
    if (p->in_step) puts_raw(p, "</div></section>\n");
    p->in_step = 0;
}

void cli_page_group(cli_page *p, const char *title, const char *text)
{
    end_step(p);
    puts_raw(p, "<h2 class=\"group\">");
    puts_escaped(p, title);
    puts_raw(p, "</h2>\n<p>");
    puts_escaped(p, text);
    puts_raw(p, "</p>\n");
}

void cli_page_step(cli_page *p, const char *title, const char *image, const char *text,
                   const char *command)
{
    end_step(p);
    p->in_step = 1;
    p->steps++;
    char id[32];
    snprintf(id, sizeof id, "step-%d", p->steps);
    puts_raw(p, "<section id=\"");
    puts_raw(p, id);
    puts_raw(p, "\"><h3>");
    puts_escaped(p, title);
    puts_raw(p, "</h3>\n");
    if (image) {
        puts_raw(p, "<figure><img src=\"");
        puts_escaped(p, image);
        puts_raw(p, "\" alt=\"");
        puts_escaped(p, title);
        puts_raw(p, "\"></figure>\n");
    }
    puts_raw(p, "<div class=\"facts\"><p>");
    puts_escaped(p, text);
    puts_raw(p, "</p>\n");
    if (command) {
        puts_raw(p, "<pre><code>$ ");
        puts_escaped(p, command);
        puts_raw(p, "</code></pre>\n");
    }
}

static void row(cli_page *p, const char *name, const char *value, const char *unit,
                const char *meaning)
{
    if (!p->in_table) {
        puts_raw(p, "<table><thead><tr><th>quantity</th><th>value</th><th>meaning</th></tr>"
                    "</thead><tbody>\n");
        p->in_table = 1;
    }
    puts_raw(p, "<tr><td>");
    puts_escaped(p, name);
    puts_raw(p, "</td><td class=\"v\">");
    puts_escaped(p, value);
    if (unit && *unit) {
        puts_raw(p, " ");
        puts_escaped(p, unit);
    }
    puts_raw(p, "</td><td>");
    puts_escaped(p, meaning);
    puts_raw(p, "</td></tr>\n");
}

void cli_page_number(cli_page *p, const char *name, double value, const char *unit,
                     const char *meaning)
{
    char buf[64];
    if (value != value)
        snprintf(buf, sizeof buf, "n/a");
    else
        snprintf(buf, sizeof buf, "%.6g", value);
    row(p, name, buf, unit, meaning);
}

void cli_page_count(cli_page *p, const char *name, unsigned long long value, const char *meaning)
{
    char buf[32];
    snprintf(buf, sizeof buf, "%llu", value);
    row(p, name, buf, NULL, meaning);
}

void cli_page_text(cli_page *p, const char *name, const char *value, const char *meaning)
{
    row(p, name, value, NULL, meaning);
}

void cli_page_note(cli_page *p, const char *note)
{
    end_table(p);
    puts_raw(p, "<p class=\"note\">");
    puts_escaped(p, note);
    puts_raw(p, "</p>\n");
}

static const char *style =
    "body{font:15px/1.45 system-ui,sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;"
    "color:#1d2329}h1{margin-bottom:.2em}section{border-top:1px solid #ccd;padding:1em 0;"
    "display:grid;grid-template-columns:minmax(0,1fr) minmax(0,1fr);gap:1.5em}"
    "section h3{grid-column:1/-1;margin:0}h2.group{margin-top:1.6em}figure{margin:0}img{width:100%;height:auto;"
    "border:1px solid #dde;background:#fff}table{border-collapse:collapse;width:100%}"
    "td,th{border-bottom:1px solid #eef;padding:.25em .4em;text-align:left;vertical-align:top}"
    "td.v{font-family:ui-monospace,monospace;white-space:nowrap}pre{background:#f4f5f7;"
    "padding:.6em;overflow-x:auto;white-space:pre-wrap}.note{color:#8a4b00}"
    "@media(max-width:800px){section{grid-template-columns:1fr}}";

fl_status cli_page_write(cli_page *p, const char *path, fl_error *err)
{
    end_step(p);
    if (p->nomem) return fl_fail(err, FL_ERR_NOMEM, path, -1, "out of memory building the report");
    fl_out_file out;
    fl_status st = fl_out_open(&out, path, 0, err);
    if (st) return st;
    fprintf(out.fp, "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
                    "<meta name=\"viewport\" content=\"width=device-width,initial-scale=1\">\n"
                    "<title>");
    for (const char *s = p->title; *s; s++) {
        if (*s == '<' || *s == '>' || *s == '&')
            fprintf(out.fp, "&#%d;", *s);
        else
            fputc(*s, out.fp);
    }
    fprintf(out.fp, "</title>\n<style>%s</style></head><body>\n", style);
    fwrite(p->body.data, 1, p->body.count, out.fp);
    fprintf(out.fp, "<footer><p>flintstone %s</p></footer>\n</body></html>\n", fl_version());
    return fl_out_commit(&out, err);
}
