#!/usr/bin/env bash
# G1 cubic Bézier surfaces (docs/smooth.md) on real closed meshes from bench/get-data.sh
# (Debian libcgal-demo). No peer builds G1 Bézier surfaces, so the baseline in the same run is
# PN triangles (Vlachos et al. 2001) = our macro patches of steps 1-3 (`--scheme pn`, C0 only).
#
# Per mesh (SMOOTH_MESHES, names in bench/cache/cgal/data/meshes), BENCH_ROUNDS processes a
# side, alternating: bench/tools/smooth_osc MESH auto / pn; the time is the CPU time of
# fl_g1_surface_build alone (CLOCK_PROCESS_CPUTIME_ID; auto includes building both schemes,
# its own G1 measurement at 33 points an edge and, where both are G1, their deviations), median
# over the processes; CPU seconds in both time columns. The notes carry what the surfaces
# measure: max normal jump across patch edges (33 points an edge), folds, max deviation from
# the mesh and control-point displacement from the PN patches (mean edge lengths).
# SMOOTH_OSC=1 also prints OSC lines with the three-split and six-split alone (the oscillation
# table of docs/smooth.md).
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${FL_BENCH_BUILD:-$root/build-bench}
meshes=${SMOOTH_MESHES:-"sphere blob-closed cube-meshed 3torus hand elephant"}

# run.sh builds only the static library; the tool links it.
cc -O2 -I"$root/include" -o "$BENCH_BIN/smooth_osc" "$root/bench/tools/smooth_osc.c" \
  "$build/libflintstone.a" -lm

for name in $meshes; do
  path=$BENCH_CACHE/cgal/data/meshes/$name.off
  [ -e "$path" ] || { echo "ERROR|smooth_$name|missing $path"; continue; }
  ours="" peer="" o_line="" p_line=""
  for ((r = 0; r < BENCH_ROUNDS; r++)); do
    o_line=$("$BENCH_BIN/smooth_osc" "$path" auto) || { echo "ERROR|smooth_$name|auto failed"; continue 2; }
    p_line=$("$BENCH_BIN/smooth_osc" "$path" pn) || { echo "ERROR|smooth_$name|pn failed"; continue 2; }
    ours+="$(field cpu_s "$o_line")"$'\n'
    peer+="$(field cpu_s "$p_line")"$'\n'
  done
  o=$(median <<<"${ours%$'\n'}")
  p=$(median <<<"${peer%$'\n'}")
  ratio=$(awk -v o="$o" -v p="$p" 'BEGIN {printf "%.1f", (p > 0) ? o / p : 0}')
  six=$(field six_split_triangles "$o_line")
  tri=$(field triangles "$o_line")
  echo "ROW|smooth_$name|$o|PN triangles (ours, --scheme pn)|$p|$ratio|CPU seconds of the surface build, median of $BENCH_ROUNDS alternating processes; $name.off ($tri triangles): auto $(field patches "$o_line") patches ($six triangles six-split, $((tri - six)) three-split), max normal jump $(field max_jump_deg "$o_line") deg, $(field flips "$o_line") folds, max deviation $(field max_deviation "$o_line"), control points moved max $(field disp_max "$o_line") / mean $(field disp_mean "$o_line"); PN $(field patches "$p_line") patches, max jump $(field max_jump_deg "$p_line") deg, $(field flips "$p_line") folds, deviation $(field max_deviation "$p_line") (lengths in mean edge lengths)"
  if [ "${SMOOTH_OSC:-0}" = 1 ]; then
    for s in three-split six-split; do
      echo "OSC|$name|$("$BENCH_BIN/smooth_osc" "$path" "$s" || echo "RESULT scheme=$s failed")"
    done
  fi
done
