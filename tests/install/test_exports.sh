#!/bin/sh
# The shared library exports exactly the functions declared in include/flintstone.h (the version
# script generated from the header), and no internal helper (fl_uf_* are static inline).
#   test_exports.sh LIBFLINTSTONE.so EXPORT.map LIBFLINTSTONE.a
set -eu
so=$1 map=$2 archive=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# Defined dynamic symbols; ASan/UBSan builds add no defined symbols of their own to the .so.
nm -D --defined-only "$so" | awk 'NF == 3 { print $3 }' | sed 's/@.*//' | sort -u >"$tmp/have"
sed -n 's/^ *\(fl_[A-Za-z0-9_]*\);$/\1/p' "$map" | sort -u >"$tmp/want"
[ -s "$tmp/want" ] || { echo "FAIL: no names in $map"; exit 1; }
if ! diff -u "$tmp/want" "$tmp/have"; then
    echo "FAIL: exported symbols differ from the public header's functions (- missing, + extra)"
    exit 1
fi
# The internal helpers exist in the objects (so this check can fail) but are not exported.
for internal in fl_fail fl_fail_at_offset fl_alloc_array; do
    nm --defined-only "$archive" 2>/dev/null | grep -q " T $internal\$" ||
        { echo "FAIL: $internal not found in $archive (test out of date?)"; exit 1; }
    if grep -qx "$internal" "$tmp/have"; then echo "FAIL: $internal is exported"; exit 1; fi
done
echo "ok: $(wc -l <"$tmp/have") symbols exported, all declared in flintstone.h"
