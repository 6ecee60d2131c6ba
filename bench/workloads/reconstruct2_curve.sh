#!/usr/bin/env bash
# 2D boundary construction, speed on a closed curve (docs/reconstruct2d.md, "Speed"): 1e5 and
# 1e6 points on r(t) = 1 + 0.3 sin(5t), uniform in arc length with a radial jitter of 1% of the
# spacing (bench/tools/recon2_curve.c), shuffled by bench/recon2_eval.h. Times fl_reconstruct2
# (γ-indicator, the Delaunay build included) against our own fl_dt2_build on the same points (the
# issue's target: ratio <= 1.5), CGAL's optimal alpha shape and GEOS's concave hull (ratio 0).
# Each result is scored against the curve order: the fraction of its edges joining consecutive
# curve samples (precision), points on the boundary, one simple polygon through all points.
# Ours: median of BENCH_ROUNDS processes. The peers are slow at these sizes, so CGAL runs
# BENCH_ROUNDS processes at 1e5 and one at 1e6, GEOS one process at 1e5 only (RECON2_GEOS_MAX;
# it takes ~20 s at 1e5 and grows faster than linearly). At 1e5 every method's edges also go
# through the area scorer (bench/tools/recon2_symdiff.c: validity, area against the curve).
set -euo pipefail
source "$(dirname "$0")/../lib.sh"

sizes=${RECON2_CURVE_SIZES:-100000 1000000}
geos_max=${RECON2_GEOS_MAX:-100000}

declare -A secs quality simple symdiff
runs() { # KEY ROUNDS EDGES_DIR PROGRAM ARGS...: per-method seconds, scores of the last round
  local key=$1 rounds=$2 dir=$3 prog=$4 out line m r d
  shift 4
  for ((r = 0; r < rounds; r++)); do
    d=-
    ((r == rounds - 1)) && d=$dir
    out=$("$BENCH_BIN/$prog" "$file" 3 "$d" "$@") ||
      { echo "ERROR|reconstruct2_curve|$prog failed"; return 0; }
    while read -r line; do
      m=$(field method "$line")
      secs[$key/$m]+="$(field seconds "$line")"$'\n'
      [ -n "$(field recall "$line")" ] || continue
      quality[$key/$m]="edges between consecutive curve samples $(field precision "$line"), points on boundary $(field on_boundary "$line"), one polygon through all points $(field polygon "$line"), curve order exact $(field exact "$line")"
    done < <(grep '^RESULT' <<<"$out")
    while read -r line; do
      simple[$key/$(field method "$line")]=", simple (exact check) $(field simple "$line")"
    done < <(grep '^SIMPLE' <<<"$out")
  done
}
med() { median <<<"${secs[$1]%$'\n'}"; }
row() { # NAME OURS PEER PEERNAME EXTRA
  local o p
  o=$(med "$2")
  p=$(med "$3")
  local peer=""
  [ -z "${quality[$3]:-}" ] || peer="; peer: ${quality[$3]}${symdiff[$3]:-}"
  printf 'ROW|%s|%s|%s|%s|-|ours: %s%s%s%s%s\n' "$1" "$o" "$4" "$p" \
    "${quality[$2]:-}" "${simple[$2]:-}" "${symdiff[$2]:-}" "$peer" "${5:-}"
}

for n in $sizes; do
  label=$(awk -v n="$n" 'BEGIN {e = int(log(n) / log(10) + 1e-9)
                                if (n == 10 ^ e) printf "1e%d", e; else printf "%d", n}')
  file=$BENCH_DATA/curve_$n.xy
  dir=$BENCH_DATA/curve_${n}_edges
  rm -rf "$dir"
  mkdir -p "$dir"
  "$BENCH_BIN/recon2_curve" "$n" "$file"
  runs "$label" "$BENCH_ROUNDS" "$dir" eval_reconstruct2 gamma
  if ((n <= 100000)); then cgal_rounds=$BENCH_ROUNDS; else cgal_rounds=1; fi
  runs "$label" "$cgal_rounds" "$dir" cgal_alpha2
  note=""
  if ((n <= geos_max)); then
    runs "$label" 1 "$dir" geos_concave 0
  else
    note=" (GEOS ConcaveHull not timed at $label: RECON2_GEOS_MAX=$geos_max)"
  fi
  if ((n <= 100000)); then
    while read -r line; do
      symdiff[$label/$(field method "$line")]=", symmetric difference / curve area $(field median "$line") (holes filled $(field filled_median "$line"); $(field made_valid "$line") repaired by MakeValid, $(field linework "$line") built from linework)"
    done < <("$BENCH_BIN/recon2_symdiff" "$file" 3 "$dir"/*.edges | grep '^SYMDIFF')
  fi
  row "reconstruct2_curve_${label}_vs_dt" "$label/constriction-gamma" "$label/flintstone-delaunay" \
    "our own fl_dt2_build (target ratio <= 1.5)"
  row "reconstruct2_curve_${label}_cgal" "$label/constriction-gamma" \
    "$label/cgal-alpha-shape-optimal" "CGAL Alpha_shape_2 (optimal alpha)" "$note"
  if ((n <= geos_max)); then
    row "reconstruct2_curve_${label}_geos" "$label/constriction-gamma" \
      "$label/geos-concave-hull-0" "GEOS ConcaveHull (ratio 0)"
  fi
done
