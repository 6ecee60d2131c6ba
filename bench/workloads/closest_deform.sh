#!/usr/bin/env bash
# Closest points on a deforming mesh re-queried every frame, against CGAL's AABB tree (issue #9's
# third workload; docs/sweep.md "Deforming mesh against CGAL"). Frames and queries come from
# bench/deform_eval.h, bit-identical on both sides: a sine wave along x travelling along y
# (amplitude 1% of the diagonal), and per frame a stretch of one random walk (steps 0.1% of the
# diagonal) continuing across frames. Ours three times: `update` (one build, then
# fl_sweep_update_vertices every frame, one cursor throughout), `rebuild` (fl_sweep_build and
# a new cursor every frame) and `collapse_update` (the edge-collapse hierarchy: one
# fl_sweep_collapse_build, then fl_sweep_collapse_update_vertices every frame, §5.3's
# displacement inflation, one collapse cursor throughout); CGAL rebuilds its tree +
# accelerate_distance_queries every frame.
# Times cover the build/update and the queries of all frames; the median over BENCH_ROUNDS
# alternating processes (update, rebuild, CGAL). Brute force (every triangle) runs once on frame
# 0's first 200 queries for its queries per second and as a third check. All distances are
# compared query by query with CGAL's; a difference above 1e-12 of the largest distance is an
# ERROR row.
#
# Environment besides lib.sh's: DEFORM_FRAMES (default 20), DEFORM_QUERIES (queries a frame,
# default 10000), DEFORM_MESHES (default "bunny armadillo").
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
NF=${DEFORM_FRAMES:-20}
NQ=${DEFORM_QUERIES:-10000}
MESHES=${DEFORM_MESHES:-bunny armadillo}

# agree NAME A.d B.d: prints the largest difference, or fails when it is above 1e-12 relative.
agree() {
  local diff d m
  diff=$("$BENCH_BIN/eval_closest" compare "$2" "$3")
  d=$(field max_abs_diff "$diff") m=$(field max_distance "$diff")
  awk -v d="$d" -v m="$m" 'BEGIN {exit !(d <= 1e-12 * m)}' ||
    { echo "ERROR|$1|distances differ from CGAL's by $d (largest distance $m)"; return 1; }
  echo "$d"
}

one_mesh() { # NAME FILE NOTES
  local name=$1 file=$2 notes=$3 prefix=$BENCH_DATA/deform-$1 mode line r k
  local -A wall cpu qps
  [ -e "$file" ] || { echo "ERROR|closest_deform_$name|$file missing (bench/get-data.sh)"; return 0; }
  "$BENCH_BIN/eval_closest" prepare "$file" "$prefix" 1 >/dev/null ||
    { echo "ERROR|closest_deform_$name|prepare failed"; return 0; }
  for ((r = 0; r < BENCH_ROUNDS; r++)); do
    for mode in update rebuild collapse_update cgal; do
      if [ $mode = cgal ]; then
        line=$("$BENCH_BIN/cgal_closest_deform" "$prefix" "$NF" "$NQ" | grep '^RESULT')
      else
        line=$("$BENCH_BIN/closest_deform" "$prefix" $mode "$NF" "$NQ" | grep '^RESULT')
      fi || { echo "ERROR|closest_deform_${name}_$mode|run failed"; return 0; }
      wall[$mode]+="$(field total_s "$line")"$'\n'
      cpu[$mode]+="$(field cpu_s "$line")"$'\n'
      qps[$mode]+="$(field qps "$line")"$'\n'
      wall[${mode}_move]+="$(field move_s "$line")"$'\n'
    done
  done
  line=$("$BENCH_BIN/closest_deform" "$prefix" brute "$NF" "$NQ" | grep '^RESULT') ||
    { echo "ERROR|closest_deform_${name}_brute|run failed"; return 0; }
  local brute_qps bdiff
  brute_qps=$(field qps "$line")
  bdiff=$(agree "closest_deform_${name}_brute" "$prefix.deform.brute.d" "$prefix.deform.cgal.d") ||
    { echo "$bdiff"; return 0; }
  for k in "${!wall[@]}"; do wall[$k]=$(median <<<"${wall[$k]%$'\n'}"); done
  for k in "${!cpu[@]}"; do cpu[$k]=$(median <<<"${cpu[$k]%$'\n'}"); done
  for k in "${!qps[@]}"; do qps[$k]=$(median <<<"${qps[$k]%$'\n'}"); done
  local load diff
  load=$(cut -d' ' -f1-3 /proc/loadavg)
  for mode in update rebuild collapse_update; do
    diff=$(agree "closest_deform_${name}_$mode" "$prefix.deform.$mode.d" "$prefix.deform.cgal.d") ||
      { echo "$diff"; continue; }
    printf 'ROW|closest_deform_%s_%s|%s|CGAL AABB_tree (rebuilt every frame)|%s|%s|%s; %s frames x %s walk queries; queries/s (wall) ours %.0f, CGAL %.0f, brute force %.0f (frame 0, first 200 queries; ours %.0fx brute); %s %s s of ours, CGAL rebuilds %s s (of the totals); CPU ours %s s, CGAL %s s; distances agree with CGAL to %s (brute force to %s); %s UTC, load %s\n' \
      "$name" $mode "${wall[$mode]}" "${wall[cgal]}" \
      "$(awk -v o="${cpu[$mode]}" -v p="${cpu[cgal]}" 'BEGIN {printf "%.2f", o / p}')" "$notes" \
      "$NF" "$NQ" "${qps[$mode]}" "${qps[cgal]}" "$brute_qps" \
      "$(awk -v o="${qps[$mode]}" -v b="$brute_qps" 'BEGIN {print o / b}')" \
      "$([ $mode = rebuild ] && echo "builds" || echo "build + updates")" "${wall[${mode}_move]}" \
      "${wall[cgal_move]}" "${cpu[$mode]}" "${cpu[cgal]}" "$diff" "$bdiff" \
      "$(date -u '+%Y-%m-%d %H:%M')" "$load"
  done
}
for mesh in $MESHES; do
  case $mesh in
    bunny) one_mesh bunny "$BENCH_CACHE/real/bunny.off" "npm bunny (3 674 triangles)" ;;
    armadillo) one_mesh armadillo "$BENCH_CACHE/cgal/data/meshes/armadillo.off" \
      "libcgal-demo armadillo.off (52 000 triangles)" ;;
    *) echo "ERROR|closest_deform_$mesh|unknown mesh (bunny, armadillo)" ;;
  esac
done
