#!/bin/sh
# man/flintstone.1 is consistent with the --help texts: every command `flintstone --help` lists
# has a ".SS <command>" block, and every option (--name, -o) a command's --help prints appears in
# that block (or in COMMON OPTIONS). If groff is installed, the page renders without warnings.
#   test_manpage.sh FLINTSTONE MANPAGE
set -eu
cli=$1 man=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
status=0
sed 's/\\-/-/g; s/\\(\*g/γ/g' "$man" >"$tmp/man"
"$cli" --help | sed -n '/^commands:/,/^$/p' | awk 'NF >= 2 { print $1 }' >"$tmp/commands"
[ -s "$tmp/commands" ] || { echo "FAIL: no commands in flintstone --help"; exit 1; }
sed -n '/^\.SH COMMON OPTIONS/,/^\.SH COMMANDS/p' "$tmp/man" >"$tmp/common"
while read -r cmd; do
    awk -v c="$cmd" '/^\.S[SH] / { on = ($0 == ".SS " c) } on' "$tmp/man" >"$tmp/section"
    if [ ! -s "$tmp/section" ]; then
        echo "FAIL: command '$cmd' has no '.SS $cmd' block in $man"
        status=1
        continue
    fi
    "$cli" "$cmd" --help >"$tmp/help" 2>&1 || true
    for opt in $(grep -o -- '-\{1,2\}[a-z][a-z-]*' "$tmp/help" | grep -v -- '-$' | sort -u); do
        case $opt in --*|-o) ;; *) continue ;; esac
        grep -q -- "$opt\b" "$tmp/section" "$tmp/common" ||
            { echo "FAIL: '$cmd' option $opt (from --help) is not in $man"; status=1; }
    done
done <"$tmp/commands"
if command -v groff >/dev/null; then
    groff -man -Tutf8 -ww -z "$man" 2>"$tmp/groff" || true
    if [ -s "$tmp/groff" ]; then cat "$tmp/groff"; echo "FAIL: groff warnings"; status=1; fi
fi
[ $status -eq 0 ] && echo "ok: $(wc -l <"$tmp/commands") commands and their options documented"
exit $status
