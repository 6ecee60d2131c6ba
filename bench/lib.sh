# Helpers for bench/workloads/*.sh (sourced, not run). bench/run.sh exports:
#   BENCH_BIN    the bench programs (bench/out/bin)
#   BENCH_CACHE  fetched real data (bench/cache)
#   BENCH_DATA   generated inputs (bench/out/data; emptied at the start of every run)
#   BENCH_REPS   timed runs per process (default 5), BENCH_ROUNDS processes per side (default 3)
#
# A workload prints one line per comparison, fields separated by '|':
#   ROW|<workload>|<ours seconds>|<peer name>|<peer seconds>|<CPU-time ratio or ->|<notes>
# (seconds are wall time) or ERROR|<workload>|<why>. run.sh turns the rows into the table of
# bench/RESULTS.md, ratio = ours / peer.

BENCH_REPS=${BENCH_REPS:-5}
BENCH_ROUNDS=${BENCH_ROUNDS:-3}

# field KEY LINE: the value of KEY=value in a RESULT line.
field() { tr ' ' '\n' <<<"$2" | sed -n "s/^$1=//p"; }

# Median of numbers on stdin, one a line.
median() { sort -g | awk '{v[NR]=$1} END {print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }

# compare_readers WORKLOAD NOTES -- OURS_CMD... -- PEER_CMD...
# Runs the two commands alternately, BENCH_ROUNDS times each, so that both see the same machine
# load (the machine is shared); each run is one process printing a RESULT line (bench/timing.h)
# with the median of BENCH_REPS reads. Reports the median of the per-process wall-time medians,
# the same ratio in CPU time (steadier when other jobs share the machine), the counts each reader
# built and the peak RSS of each side.
compare_readers() {
  local workload=$1 notes=$2
  shift 3
  local ours=() peer=()
  while [ "$1" != "--" ]; do ours+=("$1"); shift; done
  shift
  peer=("$@")
  local o_times="" p_times="" o_cpu="" p_cpu="" o_line p_line
  for ((r = 0; r < BENCH_ROUNDS; r++)); do
    o_line=$("${ours[@]}" "$BENCH_REPS" | grep '^RESULT') || { echo "ERROR|$workload|ours failed" ; return 1; }
    p_line=$("${peer[@]}" "$BENCH_REPS" | grep '^RESULT') || { echo "ERROR|$workload|peer failed"; return 1; }
    o_times+="$(field median_s "$o_line")"$'\n'
    p_times+="$(field median_s "$p_line")"$'\n'
    o_cpu+="$(field cpu_median_s "$o_line")"$'\n'
    p_cpu+="$(field cpu_median_s "$p_line")"$'\n'
  done
  local mb_o mb_p cpu_ratio
  mb_o=$(( $(field maxrss_kb "$o_line") / 1024 ))
  mb_p=$(( $(field maxrss_kb "$p_line") / 1024 ))
  cpu_ratio=$(awk -v o="$(median <<<"${o_cpu%$'\n'}")" -v p="$(median <<<"${p_cpu%$'\n'}")" \
    'BEGIN {printf "%.2f", o / p}')
  printf 'ROW|%s|%s|%s|%s|%s|%s; built V=%s T=%s (ours), V=%s T=%s (peer); peak RSS %s MB / %s MB\n' \
    "$workload" "$(median <<<"${o_times%$'\n'}")" "$(field reader "$p_line")" \
    "$(median <<<"${p_times%$'\n'}")" "$cpu_ratio" "$notes" \
    "$(field vertices "$o_line")" "$(field triangles "$o_line")" \
    "$(field vertices "$p_line")" "$(field triangles "$p_line")" "$mb_o" "$mb_p"
}

# generated NAME NU NV: path of a generated torus (bench/gen_mesh.c), made on first use.
generated() {
  local out=$BENCH_DATA/$1
  [ -e "$out" ] || "$BENCH_BIN/gen_mesh" "$out" "$2" "$3" >&2
  echo "$out"
}
