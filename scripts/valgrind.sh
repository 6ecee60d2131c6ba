#!/bin/sh
# Runs valgrind memcheck on a fast subset of the test executables of a debug build (no
# sanitizers: valgrind and ASan do not mix) and fails on any error or leak.
#   scripts/valgrind.sh [BUILD_DIR]        (default build-debug; `make valgrind` builds it)
# Every test runs with --leak-check=full --errors-for-leak-kinds=definite,indirect,possible
# --error-exitcode=99; a summary line per test goes to stdout, full logs to BUILD_DIR/valgrind/.
set -eu
build=${1:-build-debug}
tests="$build/tests"
[ -d "$tests" ] || { echo "valgrind.sh: no $tests (build the debug tree first)" >&2; exit 2; }
command -v valgrind >/dev/null || { echo "valgrind.sh: valgrind not installed" >&2; exit 2; }
# Fast under memcheck (each a few seconds to a minute natively x ~30): one or more per module,
# covering readers/writers, predicates, Delaunay, graphs, reconstruction, HAL, sweep, mesh
# checks and the degenerate-input suite.
subset="core_test_core io_test_off io_test_obj io_test_ply io_test_stl io_test_geojson
io_test_xy_polygon io_test_balls delaunay_test_sort
delaunay_test_dt2_verify mesh_test_halfedge mesh_test_mesh_topology mesh_test_polygon_check
hal_test_hal2_insert graphs_test_gamma_figures reconstruct_test_criteria2
degenerate_test_delaunay_degenerate degenerate_test_mesh_io_degenerate
degenerate_test_hal_sweep_degenerate degenerate_test_reconstruct_degenerate
degenerate_test_surface_degenerate"
mkdir -p "$build/valgrind"
failed=0
for t in $subset; do
    exe="$tests/$t"
    [ -x "$exe" ] || { echo "skip  $t (not built)"; continue; }
    log="$build/valgrind/$t.log"
    start=$(date +%s)
    # Tests run in the tests dir like under ctest (they write scratch files there).
    if (cd "$tests" && valgrind --tool=memcheck --leak-check=full \
            --errors-for-leak-kinds=definite,indirect,possible --error-exitcode=99 \
            --log-file="../valgrind/$t.log" "./$t" >/dev/null 2>&1); then
        status=ok
    else
        status=FAIL
        failed=$((failed + 1))
    fi
    errs=$(grep -o 'ERROR SUMMARY: [0-9]* errors' "$log" | head -1)
    leak=$(grep -o 'definitely lost: [0-9,]* bytes' "$log" | head -1)
    echo "$status  $t  ${errs:-?}  ${leak:-no leaks possible}  $(( $(date +%s) - start ))s"
done
[ "$failed" -eq 0 ] || { echo "valgrind: $failed test(s) failed (see $build/valgrind/)"; exit 1; }
echo "valgrind: all clean"
