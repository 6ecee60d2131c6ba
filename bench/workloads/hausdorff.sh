#!/usr/bin/env bash
# `flintstone hausdorff` against CGAL (bench/peers/cgal_hausdorff.cpp), in the same run: a
# libcgal-demo mesh against its edge-collapse simplification to ~15% of the triangles (Guéziec
# §6 / Fig. 10: 29,200 vs 4,450 triangles), made by the peer into bench/out/data.
#
#  - ours: `flintstone hausdorff A B --precision P` with P = 1e-4 (HD_RELATIVE) of the bounding-
#    box diagonal: a certified interval of width <= P (whole process: read both files, build
#    both hierarchies, refine).
#  - CGAL bounded: PMP::bounded_error_symmetric_Hausdorff_distance(A, B, P) (read excluded).
#  - CGAL approx: PMP::approximate_symmetric_Hausdorff_distance with HD_DENSITY (default 1e4)
#    random points per unit area (read excluded): a lower estimate without a bound.
# Processes alternate, BENCH_ROUNDS each; wall and CPU (user + sys) from bash's `time`; ROW
# lines with the medians (format in bench/lib.sh).
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${FL_BENCH_BUILD:-$root/build-bench}
out=$root/bench/out/hausdorff
meshes=${HD_MESHES:-camel fandisk_large}
rel=${HD_RELATIVE:-1e-4}
density=${HD_DENSITY:-1e4}
mkdir -p "$out" "$BENCH_BIN"

cmake --build "$build" -j 2 --target flintstone >/dev/null
fl=$build/flintstone
peer=$BENCH_BIN/cgal_hausdorff
# Not in bench/Makefile's list (a CGAL peer takes minutes to compile): built here on first use.
[ -x "$peer" ] || g++ -std=c++17 -O2 -DNDEBUG -Wall -Wextra -Werror -o "$peer" \
  "$root/bench/peers/cgal_hausdorff.cpp" -lgmp -lmpfr

# one_run TIMES OUTPUT CMD...: appends "wall cpu" to TIMES and CMD's stdout to OUTPUT.
one_run() {
  local times=$1 output=$2 t
  shift 2
  t=$({ TIMEFORMAT='%3R %3U %3S'; time "$@" >>"$output" 2>/dev/null; } 2>&1)
  awk '{printf "%s %.3f\n", $1, $2 + $3}' <<<"$t" >>"$times"
}
col_median() { awk -v c="$2" '{print $c}' "$1" | median; }
# json_key FILE KEY: KEY's raw JSON value in the last line of FILE.
json_key() { tail -1 "$1" | sed -n "s/.*\"$2\":\(\[[^]]*\]\|[^,}]*\).*/\1/p"; }
result_key() { tail -1 "$1" | tr ' ' '\n' | sed -n "s/^$2=//p"; }

for name in $meshes; do
  src=$BENCH_CACHE/cgal/data/meshes/$name.off
  [ -e "$src" ] || { echo "ERROR|hausdorff_$name|missing $src"; continue; }
  simp=$BENCH_DATA/${name}_15.off
  [ -e "$simp" ] || "$peer" simplify "$src" "$simp" 0.15 >"$out/simplify_$name.txt"
  # The absolute precision: 1e-4 of the diagonal, as our own run computes it.
  "$fl" hausdorff "$src" "$simp" --relative 1 --json >"$out/probe.json"
  p=$(awk -v p="$(json_key "$out/probe.json" precision)" -v r="$rel" 'BEGIN {printf "%.17g", p * r}')
  rm -f "$out"/t_* "$out"/j_*
  for ((r = 0; r < BENCH_ROUNDS; r++)); do
    one_run "$out/t_ours" "$out/j_ours" "$fl" hausdorff "$src" "$simp" --precision "$p" --json
    one_run "$out/t_bounded" "$out/j_bounded" "$peer" bounded "$src" "$simp" "$p"
    one_run "$out/t_approx" "$out/j_approx" "$peer" approx "$src" "$simp" "$density"
  done
  faces=$(sed -n 's/.*faces=\([0-9]*\).*/\1/p' "$out/simplify_$name.txt" 2>/dev/null || true)
  ours_iv=$(json_key "$out/j_ours" hausdorff)
  samples=$(json_key "$out/j_ours" samples)
  for peer_name in bounded approx; do
    ratio=$(awk -v o="$(col_median "$out/t_ours" 2)" -v q="$(col_median "$out/t_$peer_name" 2)" \
      'BEGIN {printf "%.2f", o / q}')
    printf 'ROW|hausdorff_%s_%s|%s|cgal %s|%s|%s|%s vs %s-face simplification; precision %s (%s of diagonal); ours %s (certified, %s samples, whole process); cgal %s = %s (%s)\n' \
      "$name" "$peer_name" "$(col_median "$out/t_ours" 1)" "$peer_name" \
      "$(col_median "$out/t_$peer_name" 1)" "$ratio" "$name" "${faces:-?}" "$p" "$rel" \
      "$ours_iv" "$samples" "$peer_name" "$(result_key "$out/j_$peer_name" value)" \
      "$([ "$peer_name" = bounded ] && echo "within the precision, read excluded" ||
        echo "$density points per unit area, lower estimate without bound, read excluded")"
  done
done
