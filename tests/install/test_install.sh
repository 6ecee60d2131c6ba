#!/bin/sh
# Installs the build into a temporary prefix, then builds every example against the INSTALLED
# library twice -- with pkg-config and with a CMake project using find_package(flintstone) --
# and runs each one, checking its output.
#   test_install.sh BUILD_DIR SOURCE_DIR CC "EXTRA_FLAGS"
# EXTRA_FLAGS carries the sanitizer flags of a sanitized build (the installed library then needs
# the sanitizer runtime at link time).
set -eu
build=$1 src=$2 cc=$3 extra=${4:-}
version=$(sed -n 's/^project(flintstone VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")
major=${version%%.*}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix
fail() { echo "FAIL: $*"; exit 1; }

cmake --install "$build" --prefix "$prefix" >"$tmp/install.log" || { cat "$tmp/install.log"; fail "cmake --install"; }

# --- the installed layout (GNUInstallDirs) ---
libdir=$(dirname "$(find "$prefix" -name libflintstone.a | head -n 1)")
[ -d "$libdir" ] || fail "libflintstone.a not installed"
for f in include/flintstone.h bin/flintstone share/man/man1/flintstone.1; do
    [ -f "$prefix/$f" ] || fail "$f not installed"
done
for f in "libflintstone.so.$version" pkgconfig/flintstone.pc cmake/flintstone/flintstoneConfig.cmake \
         cmake/flintstone/flintstoneConfigVersion.cmake cmake/flintstone/flintstoneTargets.cmake; do
    [ -f "$libdir/$f" ] || fail "$libdir/$f not installed"
done
[ "$(readlink "$libdir/libflintstone.so.$major")" = "libflintstone.so.$version" ] || fail "SONAME link"
[ "$(readlink "$libdir/libflintstone.so")" = "libflintstone.so.$major" ] || fail "dev link"
soname=$(readelf -d "$libdir/libflintstone.so.$version" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
[ "$soname" = "libflintstone.so.$major" ] || fail "SONAME is '$soname'"
[ "$("$prefix/bin/flintstone" --version)" = "flintstone $version" ] || fail "installed flintstone --version"
echo "ok: installed layout under $prefix (libdir ${libdir#"$prefix"/}, SONAME $soname)"

# --- inputs with known answers ---
cat >"$tmp/frame.geojson" <<'JSON'
{"type": "Polygon", "coordinates": [[[0,0],[4,0],[4,4],[0,4],[0,0]], [[1,1],[3,1],[3,3],[1,3],[1,1]]]}
JSON
printf '0.5 0.5\n2 2\n5 5\n0 2\n' >"$tmp/queries.xy"
printf '0 0 0\n0 0 5\n' >"$tmp/queries.xyz"
mkdir "$tmp/run" && ln -s "$src/data" "$tmp/run/data" # the examples' default inputs

# run_examples DIR LABEL: runs each example built into DIR and checks what it prints.
run_examples() {
    dir=$1 label=$2
    out=$("$dir/point_in_polygon" "$tmp/frame.geojson" "$tmp/queries.xy" 2>/dev/null)
    [ "$(echo "$out" | awk '{print $3}' | tr '\n' ' ')" = "inside outside outside boundary " ] ||
        fail "$label point_in_polygon on the framed square: $out"
    if [ "$label" = pkg-config ]; then # the no-argument demos once: they test the examples
        (cd "$tmp/run" && "$dir/point_in_polygon" 2>/dev/null) | grep -q "polygon area" ||
            fail "$label point_in_polygon demo"
        (cd "$tmp/run" && "$dir/closest_points") | grep -q "helix queries" ||
            fail "$label closest_points demo"
        (cd "$tmp/run" && "$dir/reconstruct_surface" >/dev/null && [ -s surface.off ]) ||
            fail "$label reconstruct_surface demo"
    fi
    # the torus (R = 2, r = 0.75, axis z) is 1.25 from its centre, up to the faceting (< 2%)
    out=$("$dir/closest_points" "$src/data/demo/torus.off" "$tmp/queries.xyz")
    echo "$out" | awk 'NR == 1 && ($1 < 1.225 || $1 > 1.25) { exit 1 }' ||
        fail "$label closest_points: distance from the torus centre: $out"
    "$dir/reconstruct_surface" "$src/data/demo/peanut.xyz" "$tmp/$label.off" >/dev/null ||
        fail "$label reconstruct_surface"
    "$prefix/bin/flintstone" check "$tmp/$label.off" | grep -q "closed, manifold, oriented" ||
        fail "$label reconstruct_surface wrote a surface that is not closed"
    "$dir/delaunay_points" "$src/data/demo/leaf.xy" | grep -q triangles || fail "$label delaunay_points"
    # a mesh against itself: the certified interval starts at 0 and is narrower than asked
    out=$("$dir/hausdorff_meshes" "$src/data/demo/torus.off" "$src/data/demo/torus.off" 1e-4)
    echo "$out" | awk '/^Hausdorff/ { gsub(/[\[\],]/, " "); if ($3 != 0 || $4 > 1e-3) exit 1; ok = 1 }
        END { exit !ok }' || fail "$label hausdorff_meshes of a mesh against itself: $out"
    "$dir/smooth_mesh" "$src/data/demo/torus.off" "$tmp/$label-smooth.off" 3 |
        grep -q "normal jump" || fail "$label smooth_mesh"
    "$prefix/bin/flintstone" check "$tmp/$label-smooth.off" | grep -q "closed, manifold, oriented" ||
        fail "$label smooth_mesh wrote a surface that is not closed"
    if [ "$label" = pkg-config ] && command -v ldd >/dev/null; then
        ldd "$dir/closest_points" | grep -q "$libdir/libflintstone.so.$major" ||
            fail "closest_points does not load the installed libflintstone.so.$major"
    fi
    echo "ok: $label: every example built against the installed library and ran correctly"
}

# --- pkg-config ---
export PKG_CONFIG_PATH="$libdir/pkgconfig"
[ "$(pkg-config --modversion flintstone)" = "$version" ] || fail "pkg-config --modversion"
pkg-config --libs --static flintstone | grep -q -- "-lm" || fail "Libs.private -lm missing"
mkdir "$tmp/pc"
for ex in "$src"/examples/*.c; do
    name=$(basename "$ex" .c)
    # shellcheck disable=SC2046,SC2086
    $cc -std=c11 -Wall -Wextra -Werror $extra "$ex" $(pkg-config --cflags --libs flintstone) -lm \
        -Wl,-rpath,"$libdir" -o "$tmp/pc/$name" || fail "pkg-config build of $name"
done
run_examples "$tmp/pc" pkg-config

# --- CMake find_package ---
mkdir "$tmp/cm"
{
    echo "cmake_minimum_required(VERSION 3.16)"
    echo "project(flintstone_examples C)"
    echo "find_package(flintstone $version REQUIRED)"
    for ex in "$src"/examples/*.c; do
        name=$(basename "$ex" .c)
        echo "add_executable($name \"$ex\")"
        echo "target_link_libraries($name PRIVATE flintstone::flintstone m)"
    done
    echo "add_executable(closest_points_static \"$src/examples/closest_points.c\")"
    echo "target_link_libraries(closest_points_static PRIVATE flintstone::flintstone_static)"
} >"$tmp/cm/CMakeLists.txt"
cmake -S "$tmp/cm" -B "$tmp/cm/build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_C_FLAGS="$extra" >"$tmp/cm.log" 2>&1 || { cat "$tmp/cm.log"; fail "cmake configure"; }
cmake --build "$tmp/cm/build" >>"$tmp/cm.log" 2>&1 || { cat "$tmp/cm.log"; fail "cmake build"; }
run_examples "$tmp/cm/build" cmake
"$tmp/cm/build/closest_points_static" "$src/data/demo/torus.off" "$tmp/queries.xyz" >/dev/null ||
    fail "static-linked closest_points"
echo "ok: cmake: flintstone::flintstone_static links too"
