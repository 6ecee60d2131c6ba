#!/usr/bin/env bash
# γ-neighbourhood graph, c1 < 0 regime (docs/gamma.md, "Timings"): the non-Delaunay part
# γ([-1,1],[-kappa,0^-]), kappa = 0.5, on uniform random points (bench/gamma_bench.c), built by
# our search (2D: output-sensitive lens search; 3D: shortest-edge candidates, docs/gamma.md),
# by our Theorem 3.1 brute force (the peer: the only other method
# that builds this graph), and our own Delaunay triangulation of the same points for scale.
# Times are CPU seconds of one run (the machine is shared). Where a side cannot run at the
# target size, its time is extrapolated with the exponent b of a least-squares fit of
# log(time) against log(N) over the sizes it did run; the notes say so and give b.
#
# Environment: GAMMA_2D_SIZES, GAMMA_2D_BRUTE, GAMMA_3D_SIZES, GAMMA_3D_BRUTE override the sizes.
set -euo pipefail
source "$(dirname "$0")/../lib.sh"

KAPPA=0.5
SIZES_2D=${GAMMA_2D_SIZES:-"1000 3000 10000 30000 100000"}
BRUTE_2D=${GAMMA_2D_BRUTE:-"250 500 1000"}
SIZES_3D=${GAMMA_3D_SIZES:-"100 200 400 800 1600 3200"}
BRUTE_3D=${GAMMA_3D_BRUTE:-"60 90 120 160"}

# run MODE DIM N: CPU seconds and simplex count of one run ("cpu count").
run() {
  local line
  line=$("$BENCH_BIN/gamma_bench" "$1" "$2" "$3" "$KAPPA" | grep '^RESULT') || return 1
  echo "$(field cpu_s "$line") $(field simplices "$line")"
}

# series MODE DIM SIZES...: "N cpu count" lines.
series() {
  local mode=$1 dim=$2 n r
  shift 2
  for n in "$@"; do
    r=$(run "$mode" "$dim" "$n") || return 1
    echo "$n $r"
  done
}

# fit: reads "N seconds ..." lines, prints "b a" of log(t) = a + b log(N).
fit() {
  awk '{x = log($1); y = log($2); sx += x; sy += y; sxx += x * x; sxy += x * y; k++}
       END {b = (k * sxy - sx * sy) / (k * sxx - sx * sx); printf "%.3f %.6f\n", b, (sy - b * sx) / k}'
}

# at N "b a": the fitted time at N.
at() { awk -v n="$1" -v b="${2% *}" -v a="${2#* }" 'BEGIN {printf "%.4g", exp(a + b * log(n))}'; }

# time_at N SERIES: the measured time at N if the series has it, else empty.
time_at() { awk -v n="$1" '$1 == n {print $2}' <<<"$2"; }
count_at() { awk -v n="$1" '$1 == n {print $3}' <<<"$2"; }

report_dim() {
  local dim=$1 targets=$2 fast=$3 brute=$4 fb bb n t c bt dt note
  fb=$(fit <<<"$fast")
  bb=$(fit <<<"$brute")
  echo "# ${dim}D fast:" $fast | tr '\n' ';' >&2; echo >&2
  echo "# ${dim}D brute:" $brute | tr '\n' ';' >&2; echo >&2
  for n in $targets; do
    t=$(time_at "$n" "$fast")
    note="measured"
    if [ -z "$t" ]; then t=$(at "$n" "$fb"); note="extrapolated"; fi
    c=$(count_at "$n" "$fast")
    bt=$(at "$n" "$bb")
    printf 'ROW|gamma%sd-c1neg-%s|%s|our brute force (Thm 3.1), extrapolated|%s|%s|CPU s, kappa=%s; ours %s (fit N^%s over N=%s), %s simplices; brute force fit N^%s over N=%s\n' \
      "$dim" "$n" "$t" "$bt" "$(awk -v o="$t" -v p="$bt" 'BEGIN {printf "%.2g", o / p}')" \
      "$KAPPA" "$note" "${fb% *}" "$(awk '{print $1}' <<<"$fast" | paste -sd,)" "${c:-?}" \
      "${bb% *}" "$(awk '{print $1}' <<<"$brute" | paste -sd,)"
    dt=$(run dt "$dim" "$n") || { echo "ERROR|gamma${dim}d-dt-$n|Delaunay failed"; continue; }
    printf 'ROW|gamma%sd-c1neg-%s-vs-dt|%s|our Delaunay (fl_dt%s_build)|%s|%s|CPU s, kappa=%s; ours %s; %s Delaunay cells\n' \
      "$dim" "$n" "$t" "$dim" "${dt% *}" "$(awk -v o="$t" -v p="${dt% *}" 'BEGIN {printf "%.3g", o / p}')" \
      "$KAPPA" "$note" "${dt#* }"
  done
}

# shellcheck disable=SC2086
fast2=$(series fast 2 $SIZES_2D) || { echo "ERROR|gamma2d|fast run failed"; exit 0; }
# shellcheck disable=SC2086
brute2=$(series brute 2 $BRUTE_2D) || { echo "ERROR|gamma2d|brute force run failed"; exit 0; }
report_dim 2 "10000 100000" "$fast2" "$brute2"
# shellcheck disable=SC2086
fast3=$(series fast 3 $SIZES_3D) || { echo "ERROR|gamma3d|fast run failed"; exit 0; }
# shellcheck disable=SC2086
brute3=$(series brute 3 $BRUTE_3D) || { echo "ERROR|gamma3d|brute force run failed"; exit 0; }
report_dim 3 "${SIZES_3D##* } 10000" "$fast3" "$brute3"
