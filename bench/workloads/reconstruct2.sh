#!/usr/bin/env bash
# 2D boundary construction on real borders (docs/reconstruct2d.md, "Evaluation on country
# borders"): every ring of npm world-atlas countries-50m with >= 20 distinct, non-collinear
# points, its vertices shuffled, is given to constriction (ours), CGAL's optimal alpha shape and
# GEOS's concave hull; each method's boundary is scored against the true ring by the same code
# (bench/recon2_eval.h). Times are sums over the rings of the calls alone, median of
# BENCH_ROUNDS processes; the ratio column is ours / peer of those medians. The last round writes
# every method's boundary edges, and one scorer (bench/tools/recon2_symdiff.c, GEOS overlay) gives
# the median area of the symmetric difference with the true ring, relative to the ring's area.
set -euo pipefail
source "$(dirname "$0")/../lib.sh"

rings=$BENCH_CACHE/real/countries-50m.xy
[ -e "$rings" ] || { echo "ERROR|reconstruct2|$rings missing (bench/get-data.sh)"; exit 0; }

edges=$BENCH_DATA/reconstruct2_edges
rm -rf "$edges"
mkdir -p "$edges"
declare -A secs quality symdiff
runs() { # PROGRAM: collects per-method seconds over BENCH_ROUNDS processes, keeps the last scores
  local out line m dir
  for ((r = 0; r < BENCH_ROUNDS; r++)); do
    dir=-
    ((r == BENCH_ROUNDS - 1)) && dir=$edges
    out=$("$BENCH_BIN/$1" "$rings" 20 "$dir") || { echo "ERROR|reconstruct2|$1 failed"; return 0; }
    while read -r line; do
      m=$(field method "$line")
      secs[$m]+="$(field seconds "$line")"$'\n'
      [ -n "$(field recall "$line")" ] || continue
      quality[$m]="$(field cases "$line") rings: edge recall $(field recall "$line"), precision $(field precision "$line"), points on boundary $(field on_boundary "$line"), simple polygon through all points $(field polygon "$line"), ring recovered exactly $(field exact "$line")"
    done < <(grep '^RESULT' <<<"$out")
  done
}
runs eval_reconstruct2
runs cgal_alpha2
runs geos_concave
while read -r line; do
  symdiff[$(field method "$line")]=", median symmetric difference / ring area $(field median "$line") (holes filled $(field filled_median "$line"); $(field made_valid "$line") repaired by MakeValid, $(field linework "$line") built from linework)"
done < <("$BENCH_BIN/recon2_symdiff" "$rings" 20 "$edges"/*.edges | grep '^SYMDIFF' ||
         echo "ERROR|reconstruct2|recon2_symdiff failed" >&2)
# The Delaunay triangulation's boundary is the convex hull: its scores stand for it.
quality[flintstone-delaunay]="boundary = convex hull, ${quality[convex-hull]:-}"
symdiff[flintstone-delaunay]=${symdiff[convex-hull]:-}

med() { median <<<"${secs[$1]%$'\n'}"; }
row() { # OURS PEER PEERNAME NOTES
  local o p
  o=$(med "$1")
  p=$(med "$2")
  printf 'ROW|reconstruct2_%s|%s|%s|%s|%s|ours (%s): %s%s; %s: %s%s\n' "$4" "$o" "$3" "$p" \
    - "$1" "${quality[$1]}" \
    "${symdiff[$1]:-}" "$2" "${quality[$2]:-}" "${symdiff[$2]:-}"
}
row constriction-gamma cgal-alpha-shape-optimal "CGAL Alpha_shape_2 (optimal alpha)" countries50m
row constriction-gamma geos-concave-hull-0 "GEOS ConcaveHull (ratio 0)" countries50m
row constriction-gamma geos-concave-hull-0.1 "GEOS ConcaveHull (ratio 0.1)" countries50m_geos01
row constriction-area-change constriction-gamma "ours, gamma-indicator criterion" countries50m_area_change
row constriction-voronoi-skeleton constriction-gamma "ours, gamma-indicator criterion" countries50m_voronoi
row constriction-gamma flintstone-delaunay "our own fl_dt2_build (471 small rings, no target: the 1.5 target is for the curve rows)" countries50m_vs_dt
