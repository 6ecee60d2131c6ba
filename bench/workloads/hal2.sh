#!/usr/bin/env bash
# 2D flintstones against GEOS (docs/hal.md, "Against GEOS"): the 20 largest rings of npm
# world-atlas countries-50m (30 320 vertices) for approximation and 1e6 point-inclusion queries,
# the 300 largest for boundary-intersection detection between the 632 pairs whose bounding boxes
# overlap. Ours: bench/eval_hal2.c; GEOS: bench/peers/geos_hal2.c, same rings and queries
# (bench/hal2_eval.h). Both write their answers, which must agree byte for byte; ours are also
# checked (untimed) against the exact brute force: 10 000 queries a ring, every ring pair.
# Times are medians of BENCH_ROUNDS processes; run.sh computes the ratio ours / peer (wall time;
# the CPU-ratio field is "-").
set -euo pipefail
source "$(dirname "$0")/../lib.sh"

rings=$BENCH_CACHE/real/countries-50m.xy
[ -e "$rings" ] || { echo "ERROR|hal2|$rings missing (bench/get-data.sh)"; exit 0; }

declare -A t
collect() { # TAG KEY LINES: appends KEY's value of each line to t[TAG/method]
  local line
  while read -r line; do
    t[$1/$(field method "$line")]+="$(field "$2" "$line")"$'\n'
  done < <(grep "^$1 " <<<"$3")
}
for ((r = 0; r < BENCH_ROUNDS; r++)); do
  ours=$("$BENCH_BIN/eval_hal2" "$rings" "$BENCH_DATA/hal2-ours") || { echo "ERROR|hal2|ours failed"; exit 0; }
  geos=$("$BENCH_BIN/geos_hal2" "$rings" "$BENCH_DATA/hal2-geos") || { echo "ERROR|hal2|GEOS failed"; exit 0; }
  both=$(printf '%s\n%s' "$ours" "$geos")
  for tag in INSIDE INTERSECT BUILD; do collect $tag seconds "$both"; done
done
med() { median <<<"${t[$1]%$'\n'}"; }
ratio() { awk -v o="$1" -v p="$2" 'BEGIN {printf "%.2f", o / p}'; }
agree() { [ "$(cmp -l "$BENCH_DATA/hal2-ours.$1" "$BENCH_DATA/hal2-geos.$1" | wc -l)" = 0 ] &&
  echo "answers identical" || echo "**ANSWERS DIFFER**"; }

o=$(med INSIDE/flintstone); p=$(med INSIDE/geos-prepared-contains); b=$(med BUILD/flintstone)
brute=$(grep '^INSIDE method=brute-force' <<<"$ours")
fi=$(grep '^INSIDE method=flintstone' <<<"$ours"); fx=$(grep '^INTERSECT method=flintstone' <<<"$ours")
printf 'ROW|hal2_inside_1e6|%s|GEOS PreparedContains|%s|-|1e6 queries uniform in the bounding boxes of the 20 largest countries-50m rings (30 320 vertices), %s (%s inside), exact brute force on %s of them: %s differ; brute-force crossing test would take %s s (ours is %sx faster); tree build for all 300 rings %s s, not in the time\n' \
  "$o" "$p" "$(agree inside)" "$(field inside "$fi")" "$(field exact_checked "$fi")" "$(field exact_disagreements "$fi")" \
  "$(field per_query_scaled "$brute")" "$(awk -v b="$(field per_query_scaled "$brute")" -v o="$o" 'BEGIN {printf "%.0f", b / o}')" "$b"
o=$(med INTERSECT/flintstone); p=$(med INTERSECT/geos-prepared-intersects); q=$(med INTERSECT/geos-intersects)
printf 'ROW|hal2_intersect_632_pairs|%s|GEOS PreparedIntersects|%s|-|do the boundaries meet, 632 ring pairs with overlapping bounding boxes among the 300 largest rings (%s meet), %s, exact all-edge-pairs brute force: %s differ; GEOS plain Intersects %s s (ratio %s); GEOS time includes preparing, ours excludes the tree build (%s s for the 300 trees; with it the ratio is %s)\n' \
  "$o" "$p" "$(field meeting "$fx")" \
  "$(agree pairs)" "$(field exact_disagreements "$fx")" "$q" "$(ratio "$o" "$q")" "$b" "$(ratio "$(awk -v o="$o" -v b="$b" 'BEGIN {print o + b}')" "$p")"
# The approximation curve (error against vertices, like thesis Fig. 7.6) goes to
# bench/out/hal2-approx.svg (docs/img/hal2-approx.svg is a copy) and its table to docs/hal.md; the
# lines are printed for the record. The ERROR line goes to stdout, where run.sh collects rows.
grep '^APPROX' <<<"$both" | sed 's/^/NOTE|hal2|/' >&2
here=$(cd "$(dirname "$0")/.." && pwd)
if grep '^APPROX' <<<"$both" | python3 "$here/tools/plot_hal2_approx.py" >"$here/out/hal2-approx.svg"; then
  echo "NOTE|hal2|approximation plot written to $here/out/hal2-approx.svg" >&2
else
  echo "ERROR|hal2|approximation plot failed"
fi
