#!/bin/sh
# scripts/apiscan.c on a synthetic header with the constructs new sections may bring (groups,
# multi-line prototypes, function-pointer typedefs, macros, a static inline function, a missing
# doc comment): the exported names, the doc check and the reference pages come out right.
#   test_apiscan.sh APISCAN
set -eu
apiscan=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
cat >"$tmp/h.h" <<'HDR'
/* A header. */
#ifndef H_H
#define H_H
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif
/* ==== alpha ============================================================================ */
/* (section owned by src/alpha)
 *
 * Alpha introduction. */

/* Documented a (contains a (parenthesis) and fl_fake(x) in prose). */
int fl_alpha_a(int x);

/* Group doc. */
int fl_alpha_b(void);
void fl_alpha_c(double *p,
                size_t n);

typedef int (*fl_alpha_fn)(void *user);

/* A struct with a callback member. */
typedef struct fl_alpha_opts {
    fl_alpha_fn fn; /* called (sometimes) */
    int (*inline_fn)(int);
} fl_alpha_opts;

/* A macro. */
#define FL_ALPHA_MAX 3

/* Inline helper: documented, not exported. */
static inline int fl_alpha_inline(int a) { if (a) { return a + 1; } return 0; }
/* Follows an inline. */
int fl_alpha_after_inline(void);

int fl_alpha_undocumented(int);
/* end of alpha */
#ifdef __cplusplus
}
#endif
#endif
HDR
"$apiscan" symbols "$tmp/h.h" "$tmp/map"
sed -n 's/^ *\(fl_[a-z_]*\);$/\1/p' "$tmp/map" | tr '\n' ' ' >"$tmp/names"
[ "$(cat "$tmp/names")" = "fl_alpha_a fl_alpha_after_inline fl_alpha_b fl_alpha_c fl_alpha_undocumented " ] ||
    fail "exported names: $(cat "$tmp/names")"
grep -q "local:" "$tmp/map" || fail "no local: * in the version script"
if "$apiscan" check "$tmp/h.h" >"$tmp/check.out" 2>&1; then fail "check passed an undocumented function"; fi
grep -q "fl_alpha_undocumented" "$tmp/check.out" || fail "check did not name the undocumented function"
[ "$(grep -c "no doc comment" "$tmp/check.out")" = 1 ] || fail "check flagged more than one: $(cat "$tmp/check.out")"
mkdir "$tmp/md"
"$apiscan" markdown "$tmp/h.h" "$tmp/md"
page=$tmp/md/alpha.md
[ -f "$page" ] || fail "no alpha.md"
grep -q "Alpha introduction" "$page" || fail "section introduction missing"
grep -q "^## fl_alpha_b · fl_alpha_c$" "$page" || fail "group heading missing"
[ "$(grep -c "Group doc" "$page")" = 1 ] || fail "group doc not printed exactly once"
grep -q "^## fl_alpha_inline$" "$page" || fail "inline function missing"
grep -q "^## fl_alpha_after_inline$" "$page" || fail "declaration after the inline function lost"
grep -q "^## FL_ALPHA_MAX$" "$page" || fail "macro missing"
grep -q "^## fl_alpha_fn$" "$page" || fail "function-pointer typedef missing"
grep -q "^## fl_alpha_opts$" "$page" || fail "struct typedef missing"
grep -q '\[`fl_alpha_c`\](alpha.md#fl_alpha_c)' "$tmp/md/README.md" || fail "index entry missing"
echo "ok: apiscan symbols, check and markdown on a synthetic header"
