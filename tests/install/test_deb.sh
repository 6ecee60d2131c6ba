#!/bin/sh
# Builds the Debian packages from a copy of the source tree (dpkg-buildpackage -b, tests off)
# and checks them: the three .deb files, what each holds, the -dev -> lib dependency, and that
# the unpacked packages work: flintstone --version runs and an example links through the
# packaged flintstone.pc (relocatable, so it works from the unpacked tree).
# Needs dpkg-dev and debhelper (apt-get install debhelper). Run by `make deb-test`; not a ctest
# (a full release build takes minutes).
#   test_deb.sh SOURCE_DIR
set -eu
src=$(cd "$1" && pwd)
version=$(sed -n 's/^project(flintstone VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
command -v dpkg-buildpackage >/dev/null && command -v dh >/dev/null ||
    fail "needs dpkg-dev and debhelper"
tree=$tmp/flintstone-$version
mkdir "$tree"
(cd "$src" && git ls-files -co --exclude-standard | tar -cf - -T -) | tar -xf - -C "$tree"
(cd "$tree" && DEB_BUILD_OPTIONS="nocheck parallel=2" dpkg-buildpackage -us -uc -b) \
    >"$tmp/build.log" 2>&1 || { tail -40 "$tmp/build.log"; fail "dpkg-buildpackage"; }
arch=$(dpkg --print-architecture)
multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH)
for p in libflintstone0 libflintstone-dev flintstone; do
    deb=$tmp/${p}_${version}_$arch.deb
    [ -f "$deb" ] || fail "$p package missing"
    dpkg-deb -c "$deb" | awk '{ print $6 }' >"$tmp/$p.list"
    dpkg-deb -x "$deb" "$tmp/root"
done
has() { grep -q "$2" "$tmp/$1.list" || fail "$1 lacks $2"; }
has libflintstone0 "usr/lib/$multiarch/libflintstone.so.$version"
has libflintstone0 "usr/lib/$multiarch/libflintstone.so.0"
has libflintstone-dev "usr/include/flintstone.h"
has libflintstone-dev "usr/lib/$multiarch/libflintstone.a"
has libflintstone-dev "usr/lib/$multiarch/pkgconfig/flintstone.pc"
has libflintstone-dev "usr/lib/$multiarch/cmake/flintstone/flintstoneConfig.cmake"
has flintstone "usr/bin/flintstone"
has flintstone "usr/share/man/man1/flintstone.1"
dpkg-deb -f "$tmp/libflintstone-dev_${version}_$arch.deb" Depends | grep -q "libflintstone0 (= $version)" ||
    fail "libflintstone-dev does not depend on libflintstone0 (= $version)"
root=$tmp/root
[ "$("$root/usr/bin/flintstone" --version)" = "flintstone $version" ] || fail "packaged flintstone"
libdir=$root/usr/lib/$multiarch
# shellcheck disable=SC2046
cc -std=c11 "$src/examples/closest_points.c" \
    $(PKG_CONFIG_PATH="$libdir/pkgconfig" pkg-config --cflags --libs flintstone) -lm \
    -Wl,-rpath,"$libdir" -o "$tmp/closest_points"
"$tmp/closest_points" "$src/data/demo/torus.off" | grep -q "helix queries" || fail "packaged example"
echo "ok: libflintstone0, libflintstone-dev, flintstone $version built, complete and working"
