#!/bin/sh
# include/flintstone.h compiles warning-free as C99, C11 and C++ (-Wall -Wextra -pedantic), and
# a C++ program links against the library through it (the extern "C" block works).
#   test_header.sh CC CXX INCLUDE_DIR LIBFLINTSTONE.a "EXTRA_FLAGS"
set -eu
cc=$1 cxx=$2 inc=$3 archive=$4 extra=${5:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/t.c" <<'SRC'
#include "flintstone.h"
#include "flintstone.h" /* include guard */
int main(void)
{
    fl_error err;
    double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {0, 1};
    fl_error_format(0, err.message, sizeof err.message);
    return !(fl_orient2d(a, b, c) == 1 && fl_version()[0] != '\0');
}
SRC
cp "$tmp/t.c" "$tmp/t.cpp"
for std in c99 c11; do
    # shellcheck disable=SC2086
    $cc -std=$std -Wall -Wextra -pedantic -Werror $extra -I"$inc" -c "$tmp/t.c" -o "$tmp/t_$std.o"
    echo "ok: C $std"
done
for std in c++11 c++17; do
    # shellcheck disable=SC2086
    $cxx -x c++ -std=$std -Wall -Wextra -pedantic -Werror $extra -I"$inc" -c "$tmp/t.cpp" \
        -o "$tmp/t_cpp.o" || { echo "FAIL: the header as $std"; exit 1; }
    echo "ok: $std"
done
# shellcheck disable=SC2086
$cxx $extra "$tmp/t_cpp.o" "$archive" -lm -o "$tmp/t_cpp"
"$tmp/t_cpp"
echo "ok: C++ program linked against $(basename "$archive") and ran"
