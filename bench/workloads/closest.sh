#!/usr/bin/env bash
# Closest points on meshes against CGAL's AABB tree (docs/sweep.md, "Against CGAL's AABB tree"):
# the same binary mesh and query files for both (bench/closest_eval.h, made by
# `eval_closest prepare`), three query streams per mesh (random in the grown bounding box, near
# the surface in random order, a coherent random walk), exact answers on both sides, compared
# query by query. Times: the median over BENCH_ROUNDS alternating processes of each process's
# median of CLOSEST_REPS runs; the ratio is ours / CGAL for the queries; builds are in the notes.
# Rows *_collapse: the same for the edge-collapse hierarchy (fl_sweep_collapse_*, Guéziec
# §4.2-4.3), run in the same rounds (spatial, collapse, CGAL alternate), with its ratio to the
# spatial hierarchy and its memory (hierarchy + one cursor) in the notes. On the path stream the
# collapse process is followed by a `collapse-static` one (the same hierarchy, every query from
# its start level: the cursor reset before each) whose time goes in the path_collapse row's notes,
# so the §5.1 cursor's gain on the walk is measured in the same rounds.
#
# Environment besides lib.sh's: CLOSEST_QUERIES (default 200000), CLOSEST_REPS (default 1),
# CLOSEST_COLLAPSE (default 1; 0 skips the *_collapse rows: at 200 000 queries the collapse
# hierarchy's random streams alone take about half an hour on a loaded machine),
# CLOSEST_MESHES (default "bunny armadillo bunny00": which meshes to run).
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
NQ=${CLOSEST_QUERIES:-200000}
REPS=${CLOSEST_REPS:-1}
COLLAPSE=${CLOSEST_COLLAPSE:-1}
MESHES=${CLOSEST_MESHES:-bunny armadillo bunny00}

one_mesh() { # NAME FILE NOTES
  local name=$1 file=$2 notes=$3 prefix=$BENCH_DATA/closest-$1 kind o p ob pb line diff prep
  local c cb bytes cs
  [ -e "$file" ] || { echo "ERROR|closest_$name|$file missing (bench/get-data.sh)"; return 0; }
  prep=$("$BENCH_BIN/eval_closest" prepare "$file" "$prefix" "$NQ") ||
    { echo "ERROR|closest_$name|prepare failed"; return 0; }
  for kind in random near path; do
    o="" p="" ob="" pb="" c="" cb="" cs=""
    for ((r = 0; r < BENCH_ROUNDS; r++)); do
      line=$("$BENCH_BIN/eval_closest" run "$prefix" $kind "$REPS" | grep '^RESULT') ||
        { echo "ERROR|closest_${name}_$kind|ours failed"; return 0; }
      o+="$(field query_s "$line")"$'\n'
      ob+="$(field build_s "$line")"$'\n'
      if [ "$COLLAPSE" != 0 ]; then
        line=$("$BENCH_BIN/eval_closest" run "$prefix" $kind "$REPS" collapse | grep '^RESULT') ||
          { echo "ERROR|closest_${name}_${kind}_collapse|ours failed"; return 0; }
        c+="$(field query_s "$line")"$'\n'
        cb+="$(field build_s "$line")"$'\n'
        bytes=$(field bytes_per_triangle "$line")
        if [ $kind = path ]; then
          line=$("$BENCH_BIN/eval_closest" run "$prefix" $kind "$REPS" collapse-static |
            grep '^RESULT') || { echo "ERROR|closest_${name}_path_collapse|static failed"; return 0; }
          cs+="$(field query_s "$line")"$'\n'
        fi
      fi
      line=$("$BENCH_BIN/cgal_aabb" "$prefix" $kind "$REPS" | grep '^RESULT') ||
        { echo "ERROR|closest_${name}_$kind|CGAL failed"; return 0; }
      p+="$(field query_s "$line")"$'\n'
      pb+="$(field build_s "$line")"$'\n'
    done
    diff=$("$BENCH_BIN/eval_closest" compare "$prefix.$kind.ours.d" "$prefix.$kind.cgal.d")
    o=$(median <<<"${o%$'\n'}") p=$(median <<<"${p%$'\n'}")
    printf 'ROW|closest_%s_%s|%s|CGAL AABB_tree|%s|%s|%s; %s %s queries; distances agree to %s (largest distance %s); build ours %s s, CGAL %s s (tree + accelerate_distance_queries)\n' \
      "$name" $kind "$o" "$p" "$(awk -v o="$o" -v p="$p" 'BEGIN {printf "%.2f", o / p}')" "$notes" \
      "$NQ" $kind "$(field max_abs_diff "$diff")" "$(field max_distance "$diff")" \
      "$(median <<<"${ob%$'\n'}")" "$(median <<<"${pb%$'\n'}")"
    [ "$COLLAPSE" != 0 ] || continue
    diff=$("$BENCH_BIN/eval_closest" compare "$prefix.$kind.collapse.d" "$prefix.$kind.cgal.d")
    c=$(median <<<"${c%$'\n'}")
    local static_note=""
    if [ -n "$cs" ]; then
      cs=$(median <<<"${cs%$'\n'}")
      static_note="; every query from the start level (cursor reset before each, no §5.1) $cs s = $(awk -v o="$cs" -v p="$c" 'BEGIN {printf "%.2f", o / p}') x the cursor"
    fi
    printf 'ROW|closest_%s_%s_collapse|%s|CGAL AABB_tree|%s|%s|%s; edge-collapse hierarchy, %s %s queries; %.2f x the spatial hierarchy; distances agree to %s; build collapse %s s, CGAL %s s; %s bytes a triangle (hierarchy + cursor)%s\n' \
      "$name" $kind "$c" "$p" "$(awk -v o="$c" -v p="$p" 'BEGIN {printf "%.2f", o / p}')" "$notes" \
      "$NQ" $kind "$(awk -v o="$c" -v p="$o" 'BEGIN {print o / p}')" "$(field max_abs_diff "$diff")" \
      "$(median <<<"${cb%$'\n'}")" "$(median <<<"${pb%$'\n'}")" "$bytes" "$static_note"
  done
}
for mesh in $MESHES; do
  case $mesh in
    bunny) one_mesh bunny "$BENCH_CACHE/real/bunny.off" "npm bunny (3 674 triangles)" ;;
    armadillo) one_mesh armadillo "$BENCH_CACHE/cgal/data/meshes/armadillo.off" \
      "libcgal-demo armadillo.off (52 000 triangles)" ;;
    bunny00) one_mesh bunny00 "$BENCH_CACHE/cgal/data/meshes/bunny00.off" \
      "libcgal-demo bunny00.off (75 408 triangles)" ;;
    *) echo "ERROR|closest_$mesh|unknown mesh (bunny, armadillo, bunny00)" ;;
  esac
done
