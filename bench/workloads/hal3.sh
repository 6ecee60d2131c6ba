#!/usr/bin/env bash
# 3D flintstones (docs/hal.md, "3D"): point inclusion against CGAL's Side_of_triangle_mesh and
# surface intersection against CGAL's Polygon_mesh_processing::do_intersect, on closed genus-0
# meshes (libcgal-demo, the npm bunny). Same binary mesh and query files for both sides
# (bench/eval_hal3.c `prepare`). Inclusion: HAL3_QUERIES (default 1e6) points uniform in the
# bounding box, answers compared query by query (they must agree exactly: both are exact) and
# against a brute force on the first HAL3_BRUTE (default 2000). Times: the median over
# BENCH_ROUNDS alternating processes of each process's median of HAL3_REPS query runs; builds
# (our flintstone tree, CGAL's AABB tree) in the notes, not in the ratio. Intersection: the mesh
# against a copy rotated by 0.2 rad about z and shifted by 10 % (surfaces cross) or 102 % (apart)
# of its x extent; do_intersect's time includes its own box structure, so the notes also give
# ours with both trees' build. Then the approximation error per triangle count against
# meshoptimizer's QEM simplifier (bench/peers/hal3_qem.cpp), measured with fl_hausdorff_meshes.
#
# Last, an INFO line a mesh: every level and the adaptive approximations at R/2 .. R/64 checked
# closed, oriented and manifold with fl_mesh_check (eval_hal3 closed; crack-freeness).
#
# Environment besides lib.sh's: HAL3_QUERIES, HAL3_REPS (default 3), HAL3_BRUTE, HAL3_PARTS
# (default "inside intersect error closed": which parts to run).
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
NQ=${HAL3_QUERIES:-1000000}
REPS=${HAL3_REPS:-3}
NB=${HAL3_BRUTE:-2000}
PARTS=${HAL3_PARTS:-inside intersect error closed}
part() { [[ " $PARTS " == *" $1 "* ]]; }

one_mesh() { # NAME FILE NOTES
  local name=$1 file=$2 notes=$3 prefix=$BENCH_DATA/hal3-$1 o p ob pb line diff brute other
  [ -e "$file" ] || { echo "ERROR|hal3_inside_$name|$file missing (bench/get-data.sh)"; return 0; }
  "$BENCH_BIN/eval_hal3" prepare "$file" "$prefix" "$NQ" >/dev/null ||
    { echo "ERROR|hal3_inside_$name|prepare failed"; return 0; }
  if part closed; then
    line=$("$BENCH_BIN/eval_hal3" closed "$prefix" | grep '^CLOSED') ||
      { echo "ERROR|hal3_closed_$name|eval_hal3 closed failed"; return 0; }
    printf 'INFO|hal3_closed_%s|-|%s; levels closed %s of %s, adaptive approximations (R/2 .. R/64) closed with error <= bound %s of %s, worst unmatched/non-manifold/misoriented edges %s, finest level = input %s\n' \
      "$name" "$notes" "$(field levels_closed "$line")" "$(field levels "$line")" \
      "$(field bounds_closed "$line")" "$(field bounds "$line")" \
      "$(field worst_bad_edges "$line")" "$(field finest_is_input "$line")"
  fi
  part inside || { intersect_rows "$name" "$prefix" "$notes"; return 0; }
  o="" p="" ob="" pb=""
  for ((r = 0; r < BENCH_ROUNDS; r++)); do
    line=$("$BENCH_BIN/eval_hal3" inside "$prefix" "$REPS" | grep '^RESULT') ||
      { echo "ERROR|hal3_inside_$name|ours failed"; return 0; }
    o+="$(field query_s "$line")"$'\n'
    ob+="$(field build_s "$line")"$'\n'
    local nodes inside
    nodes=$(field nodes "$line") inside=$(field inside "$line")
    line=$("$BENCH_BIN/hal3_cgal" inside "$prefix" "$REPS" | grep '^RESULT') ||
      { echo "ERROR|hal3_inside_$name|CGAL failed"; return 0; }
    p+="$(field query_s "$line")"$'\n'
    pb+="$(field build_s "$line")"$'\n'
  done
  diff=$("$BENCH_BIN/eval_hal3" compare "$prefix.random.ours.a" "$prefix.random.cgal.a")
  brute=$("$BENCH_BIN/eval_hal3" brute "$prefix" "$NB" "$prefix.random.ours.a" "$prefix.random.cgal.a")
  o=$(median <<<"${o%$'\n'}") p=$(median <<<"${p%$'\n'}")
  printf 'ROW|hal3_inside_%s|%s|CGAL Side_of_triangle_mesh|%s|-|%s; %s queries uniform in the bounding box, %s inside; answers differ from CGAL on %s; brute force on the first %s: %s (ours) / %s (CGAL) differ; build ours %s s (%s nodes), CGAL AABB tree %s s\n' \
    "$name" "$o" "$p" "$notes" "$NQ" "$inside" "$(field differ "$diff")" \
    "$NB" "$(field diff0 "$brute")" "$(field diff1 "$brute")" "$(median <<<"${ob%$'\n'}")" \
    "$nodes" "$(median <<<"${pb%$'\n'}")"
  intersect_rows "$name" "$prefix" "$notes"
}

intersect_rows() { # NAME PREFIX NOTES
  local name=$1 prefix=$2 notes=$3 o p ob line other
  part intersect || return 0
  for other in near far; do
    o="" p="" ob=""
    local io ip all
    for ((r = 0; r < BENCH_ROUNDS; r++)); do
      line=$("$BENCH_BIN/eval_hal3" intersect "$prefix" $other "$REPS" | grep '^RESULT') ||
        { echo "ERROR|hal3_intersect_${name}_$other|ours failed"; return 0; }
      o+="$(field query_s "$line")"$'\n'
      ob+="$(field build_s "$line")"$'\n'
      io=$(field intersect "$line") all=$(field pairs "$line")
      line=$("$BENCH_BIN/hal3_cgal" intersect "$prefix" $other "$REPS" | grep '^RESULT') ||
        { echo "ERROR|hal3_intersect_${name}_$other|CGAL failed"; return 0; }
      p+="$(field query_s "$line")"$'\n'
      ip=$(field intersect "$line")
    done
    o=$(median <<<"${o%$'\n'}") p=$(median <<<"${p%$'\n'}") ob=$(median <<<"${ob%$'\n'}")
    printf 'ROW|hal3_intersect_%s_%s|%s|CGAL PMP::do_intersect|%s|-|%s and its moved copy (%s); answer ours %s, CGAL %s (%s crossing triangle pairs); ours without the two trees'"'"' build (%s s; with it the ratio is %s), CGAL'"'"'s time includes its boxes\n' \
      "$name" $other "$o" "$p" "$notes" $other "$io" "$ip" "$all" "$ob" \
      "$(awk -v o="$o" -v b="$ob" -v p="$p" 'BEGIN {printf "%.0f", (o + b) / p}')"
  done
}

# Approximation error at equal triangle counts: INFO lines (not ROW: no times, so run.sh leaves
# them out of the table; docs/hal.md has them as a table).
qem() { # NAME FILE
  local name=$1 file=$2 line
  [ -e "$file" ] || return 0
  "$BENCH_BIN/hal3_qem" "$file" | grep '^QEM' | while read -r line; do
    printf 'INFO|hal3_error_%s_%s|meshoptimizer simplify|%s; at %s triangles (flintstone bound %s R), Hausdorff distance to the input / R (fl_hausdorff_meshes, certified upper ends): flintstone %s (input to approximation %s), QEM %s (%s; %s triangles)\n' \
      "$name" "$(field target "$line")" "$name" "$(field ours_tris "$line")" \
      "$(field ours_bound "$line")" "$(field ours_h "$line")" "$(field ours_h_in "$line")" \
      "$(field qem_h "$line")" "$(field qem_h_in "$line")" "$(field qem_tris "$line")"
  done
}

one_mesh bunny "$BENCH_CACHE/real/bunny.off" "npm bunny (3 674 triangles)"
one_mesh cow "$BENCH_CACHE/cgal/data/meshes/cow.off" "libcgal-demo cow.off (5 804 triangles)"
one_mesh bull "$BENCH_CACHE/cgal/data/meshes/bull.off" "libcgal-demo bull.off (12 396 triangles)"
one_mesh camel "$BENCH_CACHE/cgal/data/meshes/camel.off" "libcgal-demo camel.off (19 536 triangles)"
if part error && [ -x "$BENCH_BIN/hal3_qem" ]; then
  qem bunny "$BENCH_CACHE/real/bunny.off"
  qem cow "$BENCH_CACHE/cgal/data/meshes/cow.off"
fi
