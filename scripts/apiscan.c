/* apiscan — reads include/flintstone.h as text and derives what must follow the header:
 *
 *   apiscan symbols HEADER OUT.map   linker version script exporting every declared function
 *   apiscan check HEADER             exit 1 (listing them) if a public function has no doc comment
 *   apiscan markdown HEADER OUTDIR   API reference: OUTDIR/README.md + one page a section
 *
 * It runs at build time (the version script) and from `make api-docs`, so sections added to the
 * header are picked up without touching this tool. It is a small scanner for the header's own
 * conventions, not a C parser:
 *  - top level is a sequence of comments, preprocessor lines and declarations (text up to a ';'
 *    outside braces and parentheses); `extern "C" {` and its closing brace are skipped;
 *  - the doc comment of a declaration is the run of comments directly above it (no blank line in
 *    between); declarations written on consecutive lines form a group sharing the doc comment of
 *    the first one (e.g. fl_read_points / fl_read_mesh / fl_read_polygon);
 *  - a comment starting "==== name" opens section `name`; the comment right after it is the
 *    section's introduction unless a declaration follows it directly;
 *  - a function is a declaration that is not a typedef and whose first '(' follows an
 *    identifier; `#define` lines are documented like declarations but export nothing.
 * Needs only the C standard library (no Python or Doxygen on a fresh machine). */
#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum item_kind { ITEM_COMMENT, ITEM_DECL, ITEM_MACRO, ITEM_OTHER };

typedef struct item {
    enum item_kind kind;
    char *text;      /* verbatim source text */
    int line;        /* 1-based line of its first character */
    int gap_before;  /* a blank line (or nothing) separates it from the previous item */
    int section;     /* index into sections, -1 before the first */
    char name[128];  /* declared name (functions, typedefs, macros) */
    int is_function;
    int is_static;   /* a static (inline) function: documented, not exported */
    int doc;         /* index of the first comment of its doc run, -1 if none */
    int doc_end;     /* one past the last comment of the doc run */
} item;

typedef struct section {
    char name[64];
    int intro;       /* comment item index, -1 if none */
} section;

static item *items;
static size_t item_count, item_cap;
static section sections[256];
static int section_count;

static void die(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("apiscan: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    exit(2);
}

static char *copy_range(const char *s, size_t n)
{
    char *t = malloc(n + 1);
    if (!t) die("out of memory");
    memcpy(t, s, n);
    t[n] = '\0';
    return t;
}

static char *read_file(const char *path)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) die("cannot open %s", path);
    size_t cap = 1 << 16, len = 0;
    char *buf = malloc(cap);
    if (!buf) die("out of memory");
    size_t got;
    while ((got = fread(buf + len, 1, cap - len - 1, fp)) > 0) {
        len += got;
        if (cap - len < 2) {
            cap *= 2;
            char *grown = realloc(buf, cap);
            if (!grown) die("out of memory");
            buf = grown;
        }
    }
    fclose(fp);
    buf[len] = '\0';
    return buf;
}

static item *push_item(enum item_kind kind, const char *start, size_t n, int line, int gap)
{
    if (item_count == item_cap) {
        item_cap = item_cap ? 2 * item_cap : 256;
        item *grown = realloc(items, item_cap * sizeof *items);
        if (!grown) die("out of memory");
        items = grown;
    }
    item *it = &items[item_count++];
    memset(it, 0, sizeof *it);
    it->kind = kind;
    it->text = copy_range(start, n);
    it->line = line;
    it->gap_before = gap;
    it->doc = -1;
    return it;
}

static int count_lines(const char *s, const char *end)
{
    int n = 0;
    for (; s < end; s++) n += *s == '\n';
    return n;
}

/* End of a comment starting at s ("/ *" or "//"). */
static const char *comment_end(const char *s)
{
    if (s[1] == '/') {
        const char *e = strchr(s, '\n');
        return e ? e : s + strlen(s);
    }
    const char *e = strstr(s + 2, "*/");
    if (!e) die("unterminated comment");
    return e + 2;
}

/* End of a declaration: the ';' outside braces/parentheses (comments inside are skipped), or
 * the closing brace of a function body (a static inline function in the header). */
static const char *decl_end(const char *s)
{
    int depth = 0, body = 0;
    char last = 0; /* last non-blank code character at depth 0 */
    for (; *s; s++) {
        if (s[0] == '/' && (s[1] == '*' || s[1] == '/')) {
            s = comment_end(s) - 1;
            continue;
        }
        if (*s == '{' && depth == 0) body = last == ')';
        if (*s == '{' || *s == '(') {
            depth++;
        } else if (*s == '}' || *s == ')') {
            depth--;
            if (depth == 0 && *s == '}' && body) return s + 1;
        } else if (*s == ';' && depth == 0) {
            return s + 1;
        }
        if (depth == 0 && !isspace((unsigned char)*s)) last = *s;
        if (*s == ')' && depth == 0) last = ')';
    }
    die("declaration without ';' at end of file");
    return s;
}

static const char *pp_end(const char *s)
{
    for (; *s && *s != '\n'; s++)
        if (*s == '\\' && s[1] == '\n') s++;
    return s;
}

/* The declaration with its comments blanked out, so names are found in code only. */
static char *strip_comments(const char *text)
{
    char *t = copy_range(text, strlen(text));
    for (char *s = t; *s; s++) {
        if (s[0] == '/' && (s[1] == '*' || s[1] == '/')) {
            const char *e = comment_end(s);
            while (s < e) *s++ = ' ';
            s--;
        }
    }
    return t;
}

static int is_ident(int c) { return isalnum(c) || c == '_'; }

/* Copies the identifier ending just before `end` (skipping blanks) into name. */
static int ident_before(const char *start, const char *end, char *name, size_t size)
{
    while (end > start && isspace((unsigned char)end[-1])) end--;
    const char *b = end;
    while (b > start && is_ident((unsigned char)b[-1])) b--;
    if (b == end || (size_t)(end - b) >= size) return 0;
    memcpy(name, b, (size_t)(end - b));
    name[end - b] = '\0';
    return 1;
}

static void name_declaration(item *it)
{
    char *code = strip_comments(it->text);
    char *p = code;
    while (isspace((unsigned char)*p)) p++;
    int is_typedef = strncmp(p, "typedef", 7) == 0 && !is_ident((unsigned char)p[7]);
    char *paren = strchr(p, '(');
    char *brace = strchr(p, '{');
    if (is_typedef) {
        /* typedef int (*name)(...);  or  typedef struct x {...} name; */
        char *fnptr = strstr(p, "(*");
        if (fnptr && (!brace || fnptr < brace)) {
            char *close = strchr(fnptr, ')');
            if (close) ident_before(fnptr, close, it->name, sizeof it->name);
        } else {
            char *semi = strrchr(p, ';');
            if (semi) ident_before(p, semi, it->name, sizeof it->name);
        }
    } else if (paren && (!brace || paren < brace)) {
        /* static (inline) functions are documented but not exported */
        it->is_function = ident_before(p, paren, it->name, sizeof it->name);
        it->is_static = strncmp(p, "static", 6) == 0 && !is_ident((unsigned char)p[6]);
    } else if (brace) {
        /* enum { FIRST = 0, ... };  -> named after its first enumerator */
        char *b = brace + 1;
        while (isspace((unsigned char)*b)) b++;
        size_t n = 0;
        while (is_ident((unsigned char)b[n]) && n + 1 < sizeof it->name) n++;
        memcpy(it->name, b, n);
        it->name[n] = '\0';
    }
    free(code);
}

static int starts_with_word(const char *s, const char *word)
{
    size_t n = strlen(word);
    return strncmp(s, word, n) == 0;
}

/* The text of a comment without its delimiters and leading " * ". */
static char *comment_body(const char *text)
{
    size_t n = strlen(text);
    char *out = malloc(n + 1);
    if (!out) die("out of memory");
    size_t o = 0;
    const char *s = text + 2, *end = text + n;
    if (text[1] == '*') end -= 2;
    int line_start = 1;
    for (; s < end; s++) {
        if (line_start) {
            const char *q = s;
            while (q < end && (*q == ' ' || *q == '\t')) q++;
            if (q < end && *q == '*' && !(q + 1 < end && q[1] == '/')) {
                s = q + 1;
                if (s < end && *s == ' ') s++;
            } else if (s == text + 2 && *s == ' ') {
                s++;
            }
            line_start = 0;
            if (s >= end) break;
        }
        out[o++] = *s;
        if (*s == '\n') line_start = 1;
    }
    while (o > 0 && isspace((unsigned char)out[o - 1])) o--;
    out[o] = '\0';
    size_t lead = 0;
    while (out[lead] == '\n') lead++;
    memmove(out, out + lead, o - lead + 1);
    return out;
}

static void scan(const char *src)
{
    const char *s = src;
    int line = 1, cur_section = -1;
    int newlines = 2; /* the file start counts as a gap */
    while (*s) {
        if (*s == '\n') {
            newlines++;
            line++;
            s++;
            continue;
        }
        if (isspace((unsigned char)*s)) {
            s++;
            continue;
        }
        int gap = newlines >= 2;
        const char *end;
        enum item_kind kind;
        if (s[0] == '/' && (s[1] == '*' || s[1] == '/')) {
            end = comment_end(s);
            kind = ITEM_COMMENT;
        } else if (*s == '#') {
            end = pp_end(s);
            const char *d = s + 1;
            while (*d == ' ') d++;
            kind = starts_with_word(d, "define") ? ITEM_MACRO : ITEM_OTHER;
        } else if (starts_with_word(s, "extern \"C\"")) {
            end = strchr(s, '{');
            if (!end) die("line %d: extern \"C\" without '{'", line);
            end++;
            kind = ITEM_OTHER;
        } else if (*s == '}') {
            end = s + 1;
            kind = ITEM_OTHER;
        } else {
            end = decl_end(s);
            kind = ITEM_DECL;
        }
        item *it = push_item(kind, s, (size_t)(end - s), line, gap);
        if (kind == ITEM_COMMENT) {
            char *body = comment_body(it->text);
            if (strncmp(body, "====", 4) == 0) {
                if (section_count == 256) die("too many sections");
                section *sec = &sections[section_count];
                if (sscanf(body, "==== %63[A-Za-z0-9_]", sec->name) != 1)
                    die("line %d: section marker without a name", line);
                sec->intro = -1;
                cur_section = section_count++;
                it->kind = ITEM_OTHER; /* a marker documents nothing */
            } else if (strncmp(body, "end of ", 7) == 0) {
                it->kind = ITEM_OTHER;
                it->section = cur_section;
                cur_section = -1;
                free(body);
                line += count_lines(s, end);
                s = end;
                newlines = 0;
                continue;
            }
            free(body);
        } else if (kind == ITEM_MACRO) {
            const char *d = strstr(it->text, "define") + 6;
            while (*d == ' ') d++;
            size_t n = 0;
            while (is_ident((unsigned char)d[n]) && n + 1 < sizeof it->name) n++;
            memcpy(it->name, d, n);
        } else if (kind == ITEM_DECL) {
            name_declaration(it);
        }
        it->section = cur_section;
        line += count_lines(s, end);
        s = end;
        newlines = 0;
    }
}

/* Attaches doc comments and section introductions (rules in the file comment). */
static void attach_docs(void)
{
    for (size_t i = 0; i < item_count; i++) {
        item *it = &items[i];
        if (it->kind != ITEM_DECL && it->kind != ITEM_MACRO) continue;
        if (it->gap_before || i == 0) continue;
        item *prev = &items[i - 1];
        if (prev->kind == ITEM_COMMENT) {
            size_t first = i - 1;
            while (first > 0 && !items[first].gap_before && items[first - 1].kind == ITEM_COMMENT)
                first--;
            it->doc = (int)first;
            it->doc_end = (int)i;
        } else if (prev->kind == ITEM_DECL || prev->kind == ITEM_MACRO) {
            it->doc = prev->doc; /* same group */
            it->doc_end = prev->doc_end;
        }
    }
    for (size_t i = 1; i < item_count; i++) {
        const item *it = &items[i], *prev = &items[i - 1];
        if (it->kind != ITEM_COMMENT || prev->kind != ITEM_OTHER || it->section < 0) continue;
        if (strstr(prev->text, "====") == NULL || it->gap_before) continue;
        int documents_next = i + 1 < item_count && !items[i + 1].gap_before &&
                             (items[i + 1].kind == ITEM_DECL || items[i + 1].kind == ITEM_MACRO);
        if (!documents_next) sections[it->section].intro = (int)i;
    }
}

static int cmp_names(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* Public function names, sorted, each once. */
static const char **function_names(size_t *count)
{
    const char **names = malloc((item_count + 1) * sizeof *names);
    if (!names) die("out of memory");
    size_t n = 0;
    for (size_t i = 0; i < item_count; i++)
        if (items[i].kind == ITEM_DECL && items[i].is_function && !items[i].is_static)
            names[n++] = items[i].name;
    qsort(names, n, sizeof *names, cmp_names);
    size_t u = 0;
    for (size_t i = 0; i < n; i++)
        if (u == 0 || strcmp(names[u - 1], names[i]) != 0) names[u++] = names[i];
    *count = u;
    return names;
}

/* dir + "/" + name + ext, checked (the paths come from the command line). */
static void join_path(char *buf, size_t size, const char *dir, const char *name, const char *ext)
{
    size_t a = strlen(dir), b = strlen(name), c = strlen(ext);
    if (a + b + c + 2 > size) die("path too long: %s/%s%s", dir, name, ext);
    memcpy(buf, dir, a);
    buf[a] = '/';
    memcpy(buf + a + 1, name, b);
    memcpy(buf + a + 1 + b, ext, c + 1);
}

static FILE *open_out(const char *path)
{
    FILE *fp = fopen(path, "w");
    if (!fp) die("cannot write %s", path);
    return fp;
}

static void close_out(FILE *fp, const char *path)
{
    if (ferror(fp) || fclose(fp) != 0) die("write error on %s", path);
}

static int cmd_symbols(const char *out)
{
    size_t n;
    const char **names = function_names(&n);
    if (n == 0) die("no functions found in the header");
    FILE *fp = open_out(out);
    fprintf(fp, "/* Generated by scripts/apiscan.c from include/flintstone.h: the shared library\n"
                " * exports exactly the functions declared in the public header. */\n{\n"
                "  global:\n");
    for (size_t i = 0; i < n; i++) fprintf(fp, "    %s;\n", names[i]);
    fprintf(fp, "  local:\n    *;\n};\n");
    close_out(fp, out);
    free(names);
    return 0;
}

static int cmd_check(const char *header)
{
    int missing = 0, functions = 0;
    for (size_t i = 0; i < item_count; i++) {
        const item *it = &items[i];
        if (it->kind != ITEM_DECL || !it->is_function) continue;
        functions++;
        if (it->doc < 0) {
            fprintf(stderr, "%s:%d: public function %s has no doc comment directly above it\n",
                    header, it->line, it->name);
            missing++;
        }
    }
    if (functions == 0) die("no functions found in %s", header);
    printf("%d public functions, %d without a doc comment\n", functions, missing);
    return missing ? 1 : 0;
}

/* The first sentence of a doc comment, on one line, for the index. */
static void summary(const item *it, char *buf, size_t size)
{
    buf[0] = '\0';
    if (it->doc < 0) return;
    char *body = comment_body(items[it->doc].text);
    size_t o = 0;
    for (const char *s = body; *s && o + 1 < size; s++) {
        char c = *s == '\n' ? ' ' : *s;
        if (c == '|') c = '/';
        if (c == ' ' && o > 0 && buf[o - 1] == ' ') continue;
        buf[o++] = c;
        if (c == '.' && (s[1] == ' ' || s[1] == '\n' || s[1] == '\0')) break;
    }
    buf[o] = '\0';
    free(body);
}

static void write_doc_block(FILE *fp, int first, int end)
{
    fprintf(fp, "```text\n");
    for (int d = first; d < end; d++) {
        char *body = comment_body(items[d].text);
        fprintf(fp, "%s\n", body);
        free(body);
    }
    fprintf(fp, "```\n\n");
}

static const char *kind_label(const item *it)
{
    if (it->kind == ITEM_MACRO) return "macro";
    if (it->is_function) return "function";
    if (strncmp(it->text, "typedef", 7) == 0) return "type";
    return "constants";
}

static int is_entry(const item *it, int s)
{
    return it->section == s && (it->kind == ITEM_DECL || it->kind == ITEM_MACRO);
}

/* The section's introduction without the "(section owned by ...)" bookkeeping line. */
static void write_intro(FILE *fp, int s)
{
    if (sections[s].intro < 0) return;
    char *body = comment_body(items[sections[s].intro].text);
    const char *text = body;
    if (strncmp(text, "(section owned by", 17) == 0) {
        const char *nl = strchr(text, '\n');
        text = nl ? nl : "";
    }
    while (*text == '\n' || *text == ' ') text++;
    if (*text) fprintf(fp, "```text\n%s\n```\n\n", text);
    free(body);
}

/* One entry a group: declarations on consecutive lines share the doc comment above the first. */
static void write_section_page(const char *dir, int s)
{
    char path[4096];
    join_path(path, sizeof path, dir, sections[s].name, ".md");
    FILE *fp = open_out(path);
    fprintf(fp, "# %s\n\n<!-- generated by `make api-docs` (scripts/apiscan.c) from "
                "include/flintstone.h; do not edit -->\n\n[API index](README.md)\n\n",
            sections[s].name);
    write_intro(fp, s);
    for (size_t i = 0; i < item_count;) {
        if (!is_entry(&items[i], s)) {
            i++;
            continue;
        }
        size_t end = i + 1;
        while (end < item_count && is_entry(&items[end], s) && !items[end].gap_before) end++;
        if (end - i > 1)
            for (size_t k = i; k < end; k++)
                if (items[k].name[0]) fprintf(fp, "<a id=\"%s\"></a>", items[k].name);
        fprintf(fp, "%s## ", end - i > 1 ? "\n" : "");
        const char *sep = "";
        for (size_t k = i; k < end; k++) {
            if (!items[k].name[0]) continue;
            fprintf(fp, "%s%s", sep, items[k].name);
            sep = " · ";
        }
        fprintf(fp, "\n\n*%s*\n\n```c\n", kind_label(&items[i]));
        for (size_t k = i; k < end; k++) fprintf(fp, "%s\n", items[k].text);
        fprintf(fp, "```\n\n");
        if (items[i].doc >= 0)
            write_doc_block(fp, items[i].doc, items[i].doc_end);
        else
            fprintf(fp, "(no doc comment)\n\n");
        i = end;
    }
    close_out(fp, path);
}

static int cmd_markdown(const char *dir)
{
    char path[4096];
    join_path(path, sizeof path, dir, "README", ".md");
    FILE *fp = open_out(path);
    fprintf(fp, "# flintstone API reference\n\n<!-- generated by `make api-docs` "
                "(scripts/apiscan.c) from include/flintstone.h; do not edit -->\n\n");
    fprintf(fp, "Generated from the doc comments of `include/flintstone.h`, the one public "
                "header: each entry shows the declaration and the comment directly above it.\n"
                "Link with `pkg-config --cflags --libs flintstone` or CMake's "
                "`find_package(flintstone)` + `flintstone::flintstone` (see "
                "[docs/install.md](../install.md)).\n\n");
    if (item_count > 0 && items[0].kind == ITEM_COMMENT) write_doc_block(fp, 0, 1);
    fprintf(fp, "## Sections\n\n| section | functions |\n|---|---|\n");
    for (int s = 0; s < section_count; s++) {
        int n = 0;
        for (size_t i = 0; i < item_count; i++)
            n += items[i].section == s && items[i].kind == ITEM_DECL && items[i].is_function;
        fprintf(fp, "| [%s](%s.md) | %d |\n", sections[s].name, sections[s].name, n);
    }
    fprintf(fp, "\n## Functions\n\n| function | section | summary |\n|---|---|---|\n");
    size_t n;
    const char **names = function_names(&n);
    for (size_t k = 0; k < n; k++) {
        for (size_t i = 0; i < item_count; i++) {
            const item *it = &items[i];
            if (it->kind != ITEM_DECL || !it->is_function || strcmp(it->name, names[k]) != 0)
                continue;
            char sum[400];
            summary(it, sum, sizeof sum);
            const char *sec = it->section >= 0 ? sections[it->section].name : "";
            fprintf(fp, "| [`%s`](%s.md#%s) | %s | %s |\n", it->name, sec, it->name, sec, sum);
            break;
        }
    }
    close_out(fp, path);
    free(names);
    for (int s = 0; s < section_count; s++) write_section_page(dir, s);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 3) die("usage: apiscan symbols HEADER OUT | check HEADER | markdown HEADER DIR");
    char *src = read_file(argv[2]);
    scan(src);
    attach_docs();
    int rc;
    if (strcmp(argv[1], "symbols") == 0 && argc == 4) {
        rc = cmd_symbols(argv[3]);
    } else if (strcmp(argv[1], "check") == 0 && argc == 3) {
        rc = cmd_check(argv[2]);
    } else if (strcmp(argv[1], "markdown") == 0 && argc == 4) {
        rc = cmd_markdown(argv[3]);
    } else {
        die("unknown command or wrong arguments: %s", argv[1]);
        rc = 2;
    }
    for (size_t i = 0; i < item_count; i++) free(items[i].text);
    free(items);
    free(src);
    return rc;
}
