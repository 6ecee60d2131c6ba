#!/usr/bin/env bash
# Delaunay triangulation speed (docs/delaunay.md, "Benchmark"): fl_dt2_build / fl_dt3_build /
# fl_rt3_build (bench/ours_delaunay.c) against CGAL's Delaunay_triangulation_2/3 and
# Regular_triangulation_3 (bench/peers/cgal_*.cpp), both timed on points already in memory;
# then against qhull's qdelaunay and TetGen, which are programs reading text files, by the
# compute time they report themselves.
#
# Environment besides lib.sh's: BENCH_ROUNDS_BIG / BENCH_REPS_BIG (default 1 / 1) replace
# BENCH_ROUNDS / BENCH_REPS for the 1e6-point 3D inputs, which take minutes on a loaded machine
# (the 2D one takes a second and gets the full rounds);
# BENCH_SMALL_REPS (default 21) is BENCH_REPS for the real point sets of a few thousand points;
# BENCH_QHULL_BIG=0 skips qhull on the 1e6-point 3D inputs (about 2 GB and a minute of CPU).
set -euo pipefail
source "$(dirname "$0")/../lib.sh"

BIG_ROUNDS=${BENCH_ROUNDS_BIG:-1}
BIG_REPS=${BENCH_REPS_BIG:-1}
SMALL_REPS=${BENCH_SMALL_REPS:-21}
QHULL_BIG=${BENCH_QHULL_BIG:-1}

# points KIND N SEED NAME: prefix of generated points (bench/gen_points.c), made on first use.
points() {
  local p=$BENCH_DATA/$4
  [ -e "$p.bin" ] || "$BENCH_BIN/gen_points" "$1" "$2" "$3" "$p" >&2
  echo "$p"
}

# real FILE NAME: prefix of a real point file converted to the same formats.
real() {
  local p=$BENCH_DATA/$2
  [ -e "$p.bin" ] || "$BENCH_BIN/gen_points" convert "$1" "$p" >&2
  echo "$p"
}

mb() { echo $(($1 / 1024)); }

# compare_cgal WORKLOAD MODE PREFIX ROUNDS REPS NOTES: ours and CGAL alternately, ROUNDS
# processes each of REPS builds; prints the ROW and sets OURS_CPU (median CPU seconds of a
# build of ours) and OURS_CELLS for the qhull/TetGen rows.
compare_cgal() {
  local workload=$1 mode=$2 file=$3.bin rounds=$4 reps=$5 notes=$6
  local o_wall="" p_wall="" o_cpu="" p_cpu="" o p
  for ((r = 0; r < rounds; r++)); do
    o=$("$BENCH_BIN/ours_delaunay" "$mode" "$file" "$reps" | grep '^RESULT') ||
      { echo "ERROR|$workload|ours failed"; return 0; }
    p=$("$BENCH_BIN/cgal_$mode" "$file" "$reps" | grep '^RESULT') ||
      { echo "ERROR|$workload|CGAL failed"; return 0; }
    o_wall+="$(field median_s "$o")"$'\n'
    p_wall+="$(field median_s "$p")"$'\n'
    o_cpu+="$(field cpu_median_s "$o")"$'\n'
    p_cpu+="$(field cpu_median_s "$p")"$'\n'
  done
  OURS_CPU=$(median <<<"${o_cpu%$'\n'}")
  OURS_CELLS=$(field triangles "$o")
  local cgal_cpu cells agree
  cgal_cpu=$(median <<<"${p_cpu%$'\n'}")
  cells=$([ "$mode" = dt2 ] && echo triangles || echo tetrahedra)
  agree=$([ "$(field triangles "$o")" = "$(field triangles "$p")" ] &&
    [ "$(field vertices "$o")" = "$(field vertices "$p")" ] && echo "counts agree" ||
    echo "**COUNTS DIFFER**")
  printf 'ROW|%s|%s|CGAL|%s|%s|%s; wall: median of %d processes x %d builds; CPU %.3f s / %.3f s; %s %s / %s, vertices %s / %s (%s); peak RSS %s MB / %s MB\n' \
    "$workload" "$(median <<<"${o_wall%$'\n'}")" "$(median <<<"${p_wall%$'\n'}")" \
    "$(awk -v o="$OURS_CPU" -v p="$cgal_cpu" 'BEGIN {printf "%.2f", o / p}')" "$notes" \
    "$rounds" "$reps" "$OURS_CPU" "$cgal_cpu" \
    "$cells" "$(field triangles "$o")" "$(field triangles "$p")" \
    "$(field vertices "$o")" "$(field vertices "$p")" "$agree" \
    "$(mb "$(field maxrss_kb "$o")")" "$(mb "$(field maxrss_kb "$p")")"
}

# Runs a peer program ROUNDS times; each run prints the program's output plus
# "TIME wall=<s> maxrss=<kb>" (GNU time). Sets PEER_CPU (median of the figure matched by
# SED_CPU), PEER_CELLS (from the last run), PEER_WALL and PEER_RSS_MB (of the last run).
run_peer() {
  local rounds=$1 sed_cpu=$2 sed_cells=$3
  shift 3
  local cpus="" out
  for ((r = 0; r < rounds; r++)); do
    out=$(/usr/bin/time -f 'TIME wall=%e maxrss=%M' "$@" 2>&1) || return 1
    cpus+="$(sed -n "$sed_cpu" <<<"$out")"$'\n'
  done
  PEER_CPU=$(median <<<"${cpus%$'\n'}")
  PEER_CELLS=$(sed -n "$sed_cells" <<<"$out")
  PEER_WALL=$(sed -n 's/^TIME wall=\([^ ]*\) .*/\1/p' <<<"$out")
  PEER_RSS_MB=$(mb "$(sed -n 's/^TIME .*maxrss=//p' <<<"$out")")
}

cpu_ratio() { awk -v o="$OURS_CPU" -v p="$PEER_CPU" 'BEGIN {printf "%.2f", o / p}'; }

# qhull_row WORKLOAD PREFIX ROUNDS: `qdelaunay Qt s TI PREFIX.qh`; Qt triangulates non-simplicial
# regions, s prints the summary with qhull's own CPU time of the computation after reading.
qhull_row() {
  local workload=$1 file=$2.qh rounds=$3
  [ -n "${OURS_CPU:-}" ] || return 0
  if ! run_peer "$rounds" 's/.*CPU seconds to compute hull (after input): *//p' \
    's/.*Number of Delaunay regions: *//p' qdelaunay Qt s TI "$file"; then
    echo "ERROR|$workload|qdelaunay failed"
    return 0
  fi
  printf 'ROW|%s|%s|qhull|%s|%s|CPU seconds in both time columns (so both ratios are CPU-time ratios): ours = CPU time of one build (median), qhull = its "CPU seconds to compute hull (after input)" (median of %d runs of qdelaunay Qt); qhull whole process incl. reading text: %s s wall, peak RSS %s MB; regions: ours %s, qhull %s\n' \
    "$workload" "$OURS_CPU" "$PEER_CPU" "$(cpu_ratio)" "$rounds" "$PEER_WALL" "$PEER_RSS_MB" "$OURS_CELLS" "$PEER_CELLS"
}

# tetgen WORKLOAD PREFIX ROUNDS [-w]: `tetgen -V -N -E -F PREFIX.node` (no output files);
# -V prints "Delaunay seconds" (CPU time by clock(), its point sort included, reading not).
tetgen_row() {
  local workload=$1 file=$2.node rounds=$3
  shift 3
  [ -n "${OURS_CPU:-}" ] || return 0
  if ! run_peer "$rounds" 's/^Delaunay seconds: *//p' 's/^ *Mesh tetrahedra: *//p' \
    tetgen "$@" -V -N -E -F "$file"; then
    echo "ERROR|$workload|tetgen failed"
    return 0
  fi
  printf 'ROW|%s|%s|TetGen|%s|%s|CPU seconds in both time columns (so both ratios are CPU-time ratios): ours = CPU time of one build (median), TetGen = its "Delaunay seconds" (median of %d runs of tetgen %s-V); TetGen whole process incl. reading text: %s s wall, peak RSS %s MB; tetrahedra: ours %s, TetGen %s\n' \
    "$workload" "$OURS_CPU" "$PEER_CPU" "$(cpu_ratio)" "$rounds" "${*:+$* }" "$PEER_WALL" "$PEER_RSS_MB" "$OURS_CELLS" "$PEER_CELLS"
}

# all_peers WORKLOAD MODE PREFIX ROUNDS REPS NOTES QHULL(1/0) TETGEN(1/0)
all_peers() {
  OURS_CPU=""
  compare_cgal "$1" "$2" "$3" "$4" "$5" "$6"
  [ "$7" = 1 ] && qhull_row "$1" "$3" "$4"
  [ "$8" = 1 ] && tetgen_row "$1" "$3" "$4" $([ "$2" = rt3 ] && echo -w)
  return 0
}

R=$BENCH_ROUNDS
N=$BENCH_REPS
all_peers dt2_uniform_1e5 dt2 "$(points uniform2 100000 1 u2-1e5)" "$R" "$N" \
  "100 000 uniform random points in the unit square" 1 0
all_peers dt2_uniform_1e6 dt2 "$(points uniform2 1000000 2 u2-1e6)" "$R" "$N" \
  "1 000 000 uniform random points in the unit square" 1 0
all_peers dt3_uniform_1e5 dt3 "$(points uniform3 100000 3 u3-1e5)" "$R" "$N" \
  "100 000 uniform random points in the unit cube" 1 1
all_peers dt3_uniform_1e6 dt3 "$(points uniform3 1000000 4 u3-1e6)" "$BIG_ROUNDS" "$BIG_REPS" \
  "1 000 000 uniform random points in the unit cube" "$QHULL_BIG" 1
all_peers dt3_sphere_1e6 dt3 "$(points sphere 1000000 5 s-1e6)" "$BIG_ROUNDS" "$BIG_REPS" \
  "1 000 000 uniform random points on the unit sphere (surface)" 0 1
all_peers dt3_kitten dt3 "$(real "$BENCH_CACHE/cgal/data/points_3/kitten.xyz" kitten)" "$R" \
  "$SMALL_REPS" "libcgal-demo points_3/kitten.xyz (5 210 points of a scanned surface)" 1 1
all_peers dt3_sphere_20k dt3 "$(real "$BENCH_CACHE/cgal/data/points_3/sphere_20k.xyz" sphere20k)" \
  "$R" "$SMALL_REPS" "libcgal-demo points_3/sphere_20k.xyz (20 000 points on a sphere)" 1 1
all_peers dt3_bunny dt3 "$(real "$BENCH_CACHE/real/bunny.xyz" bunny)" "$R" "$SMALL_REPS" \
  "Stanford bunny vertices (npm bunny, 1 839 points)" 1 1
all_peers rt3_weighted_1e5 rt3 "$(points weighted 100000 6 w-1e5)" "$R" "$N" \
  "100 000 uniform random balls in the unit cube, weight (squared radius) uniform in [0, s^2), s = n^(-1/3)" 0 1
