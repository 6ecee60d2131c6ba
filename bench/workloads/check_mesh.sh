#!/usr/bin/env bash
# `flintstone check` on real meshes against CGAL (bench/peers/cgal_check.cpp), in the same run:
#
#  1. validation: every mesh of bench/cache/manifest.txt with 1 to CHECK_MAX_TRIANGLES (default
#     200000) triangles, or that our reader rejects, goes through `flintstone check FILE --json`
#     and `cgal_check FILE`; bench/mesh_check_compare.js compares the answers and writes
#     bench/out/check_validation.md (the table in docs/mesh.md, "Validation on real meshes")
#     plus the summary on stderr. Raw answers: bench/out/check/{ours,cgal}.jsonl.
#  2. timing: on the largest meshes (CHECK_TIMED, default "refined_elephant bunny00 armadillo
#     diplodocus"; empty to skip), whole processes alternately, CHECK_RUNS (default 7) each,
#     wall and CPU (user + sys) time from bash's `time`; ROW lines with the medians.
#     Ours: read + every check of fl_mesh_check (topology, components, genus, degenerate and
#     duplicate vertices, exact self-intersections, bbox, area, volume) + JSON. CGAL
#     (`cgal_check --timing`): CGAL::IO::read_polygon_mesh into a Surface_mesh + is_closed +
#     connected_components + Euler per component + is_degenerate_triangle_face + area +
#     volume + self_intersections + JSON. A second row per mesh times the self-intersection
#     search alone, in-process (bench/ours_check.c against `cgal_check --si`).
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${FL_BENCH_BUILD:-$root/build-bench}
out=$root/bench/out/check
max_tri=${CHECK_MAX_TRIANGLES:-200000}
runs=${CHECK_RUNS:-7}
mkdir -p "$out"

# run.sh builds only the library; the command is what a user runs, so it is what we time.
cmake --build "$build" -j 2 --target flintstone >/dev/null
fl=$build/flintstone
peer=$BENCH_BIN/cgal_check

# Candidates: "<path> vertices=V triangles=T ..." with 0 < T <= max, or "<path> error: ...".
mapfile -t files < <(awk -v max="$max_tri" '
  /^#/ { next }
  $2 == "error:" { print $1; next }
  { t = $3; sub(/^triangles=/, "", t); if (t + 0 > 0 && t + 0 <= max) print $1 }' \
  "$BENCH_CACHE/manifest.txt")

: >"$out/ours.jsonl"
: >"$out/cgal.jsonl"
for f in "${files[@]}"; do
  # Run from the cache so that messages name the file as the manifest does.
  if ours=$(cd "$BENCH_CACHE" && "$fl" check "$f" --json 2>"$out/err.txt"); then
    printf '%s\t%s\n' "$f" "$ours" >>"$out/ours.jsonl"
  else
    printf '%s\tERROR\t%s\n' "$f" "$(tr '\n\t' '  ' <"$out/err.txt")" >>"$out/ours.jsonl"
  fi
  # The peer prints its own error line; a crash leaves no line, which the comparison reports.
  printf '%s\t%s\n' "$f" "$(cd "$BENCH_CACHE" && "$peer" "$f" 2>/dev/null || true)" >>"$out/cgal.jsonl"
done
node "$root/bench/mesh_check_compare.js" "$out/ours.jsonl" "$out/cgal.jsonl" \
  >"$root/bench/out/check_validation.md"
echo "check_mesh: ${#files[@]} files compared, table in bench/out/check_validation.md" >&2

# time_process TIMES_FILE OUTPUT_FILE CMD...: one run of CMD; appends "wall cpu" (bash's `time`:
# real, and user + sys) to TIMES_FILE and CMD's output to OUTPUT_FILE.
time_process() {
  local times=$1 output=$2 t
  shift 2
  t=$({ TIMEFORMAT='%3R %3U %3S'; time "$@" >>"$output" 2>/dev/null; } 2>&1)
  awk '{printf "%s %.3f\n", $1, $2 + $3}' <<<"$t" >>"$times"
}
# json_values FILE KEY: the value of KEY in each JSON line of FILE, one a line.
json_values() {
  node -e '
    const [file, key] = process.argv.slice(1);
    for (const l of require("fs").readFileSync(file, "utf8").trim().split("\n")) console.log(JSON.parse(l)[key]);
  ' "$1" "$2"
}
json_median() { json_values "$1" "$2" | median; }

# The largest meshes that CGAL holds as a Surface_mesh (its self-intersection search needs one).
for name in ${CHECK_TIMED-refined_elephant bunny00 armadillo diplodocus}; do
  path=$BENCH_CACHE/cgal/data/meshes/$name.off
  [ -e "$path" ] || { echo "ERROR|check_$name|missing $path"; continue; }
  rm -f "$out"/t_* "$out"/j_*
  for ((r = 0; r < runs; r++)); do
    time_process "$out/t_ours" "$out/j_ours" "$fl" check "$path" --json
    time_process "$out/t_cgal" "$out/j_cgal" "$peer" --timing "$path"
    time_process "$out/t_nosi" "$out/j_nosi" "$fl" check "$path" --json --no-self-intersections
  done
  o_wall=$(cut -d' ' -f1 "$out/t_ours" | median)
  p_wall=$(cut -d' ' -f1 "$out/t_cgal" | median)
  cpu_ratio=$(awk -v o="$(cut -d' ' -f2 "$out/t_ours" | median)" -v p="$(cut -d' ' -f2 "$out/t_cgal" | median)" \
    'BEGIN {printf "%.2f", (p > 0) ? o / p : 0}')
  tri=$(grep -F "cgal/data/meshes/$name.off " "$BENCH_CACHE/manifest.txt" | tr ' ' '\n' | sed -n 's/^triangles=//p')
  ms() { awk '{printf "%d", $1 * 1000 + 0.5}'; }
  o_in=$(json_median "$out/j_ours" seconds | ms)
  n_in=$(json_median "$out/j_nosi" seconds | ms)
  p_parts="read_polygon_mesh $(json_median "$out/j_cgal" read_s | ms), checks $(json_median "$out/j_cgal" check_s | ms), self_intersections $(json_median "$out/j_cgal" self_intersections_s | ms)"
  echo "ROW|check_$name|$o_wall|CGAL PMP|$p_wall|$cpu_ratio|whole process, median of $runs alternating runs: \`flintstone check --json\` (read + fl_mesh_check, every check) vs \`cgal_check --timing\` (read_polygon_mesh into a Surface_mesh, is_closed, connected_components, Euler, is_degenerate_triangle_face, area, volume, self_intersections) on $name.off ($tri triangles); in-process medians: ours $o_in ms ($n_in ms with --no-self-intersections), CGAL $p_parts ms"
  # The search alone, in-process on a mesh read once (bench/ours_check.c, cgal_check --si):
  # BENCH_ROUNDS processes a side, alternating, each the median of $runs runs; ours is
  # fl_mesh_check with the search minus fl_mesh_check without it.
  : >"$out/si_ours"
  : >"$out/si_cgal"
  for ((r = 0; r < BENCH_ROUNDS; r++)); do
    line=$("$BENCH_BIN/ours_check" "$path" "$runs")
    echo "$(field wall_full_s "$line") $(field wall_skip_s "$line") $(field cpu_full_s "$line") $(field cpu_skip_s "$line")" |
      awk '{printf "%.6f %.6f\n", $1 - $2, $3 - $4}' >>"$out/si_ours"
    "$peer" --si "$runs" "$path" | node -e '
      const j = JSON.parse(require("fs").readFileSync(0, "utf8"));
      console.log(j.si_wall_s, j.si_cpu_s);' >>"$out/si_cgal"
  done
  o_si=$(cut -d' ' -f1 "$out/si_ours" | median)
  p_si=$(cut -d' ' -f1 "$out/si_cgal" | median)
  si_cpu=$(awk -v o="$(cut -d' ' -f2 "$out/si_ours" | median)" -v p="$(cut -d' ' -f2 "$out/si_cgal" | median)" \
    'BEGIN {printf "%.2f", (p > 0) ? o / p : 0}')
  echo "ROW|self_intersections_$name|$o_si|CGAL PMP::self_intersections|$p_si|$si_cpu|the search alone on a mesh read once, in-process, median over $BENCH_ROUNDS processes of the median of $runs runs: ours = fl_mesh_check minus fl_mesh_check with skip_self_intersections (bench/ours_check.c), CGAL = PMP::self_intersections on the Surface_mesh (cgal_check --si); $name.off ($tri triangles); both exact, pairs found $(field pairs "$line") / $(json_median "$out/j_cgal" self_intersections)"
done
