#!/usr/bin/env bash
# Runs the benchmarks and writes bench/RESULTS.md: every row one workload, our time, a peer's
# time measured in the same run on the same input, and the ratio ours/peer (< 1: we are faster).
#
#   bench/run.sh                 every bench/workloads/*.sh  -> bench/RESULTS.md
#   bench/run.sh read_mesh ...   only those workloads        -> bench/out/RESULTS.md
#
# Environment: FL_BENCH_BUILD (default build-bench), BENCH_REPS (timed reads per process,
# default 5), BENCH_ROUNDS (processes per side, alternating ours/peer, default 3).
# A workload is one script in bench/workloads/ printing ROW lines (format in bench/lib.sh).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bench=$root/bench
build=${FL_BENCH_BUILD:-$root/build-bench}

# Debian packages the bench needs: the build, the peers, node for the data conversion. Node and
# npm are looked for as commands, since some machines have them from another nodejs package
# that bundles npm.
packages=(gcc g++ make cmake libassimp-dev libcgal-dev libgeos-dev qhull-bin tetgen)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
command -v node >/dev/null || missing+=(nodejs)
command -v npm >/dev/null || missing+=(npm)
if [ ${#missing[@]} -gt 0 ]; then
  echo "run: installing ${missing[*]}" >&2
  SUDO=$([ "$(id -u)" -eq 0 ] || echo sudo)
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi

echo "run: release build of flintstone in $build" >&2
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DFL_TESTS=OFF >/dev/null
cmake --build "$build" -j 2 --target flintstone_static >/dev/null
make -s -C "$bench" FL_BUILD="$build" >&2
"$bench/get-data.sh" >&2

export BENCH_BIN=$bench/out/bin BENCH_CACHE=$bench/cache BENCH_DATA=$bench/out/data
export BENCH_REPS=${BENCH_REPS:-5} BENCH_ROUNDS=${BENCH_ROUNDS:-3}
# Inputs are regenerated every run, so they always come from the current writer.
rm -rf "$BENCH_DATA"
mkdir -p "$BENCH_DATA"

if [ $# -gt 0 ]; then
  workloads=()
  for w in "$@"; do workloads+=("$bench/workloads/$w.sh"); done
  results=$bench/out/RESULTS.md
else
  workloads=("$bench"/workloads/*.sh)
  results=$bench/RESULTS.md
fi

load_start=$(cut -d' ' -f1-3 /proc/loadavg)
rows=$bench/out/rows.txt
: >"$rows"
for w in "${workloads[@]}"; do
  echo "run: $(basename "$w" .sh)" >&2
  bash "$w" | tee -a "$rows" >&2 || echo "ERROR|$(basename "$w" .sh)|workload script failed" >>"$rows"
done

commit=$(git -C "$root" rev-parse --short HEAD)
git -C "$root" diff --quiet HEAD -- src include bench ':!bench/RESULTS.md' 2>/dev/null ||
  commit="$commit (+ uncommitted changes)"
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
{
  echo "# Benchmark results"
  echo
  echo "Written by \`bench/run.sh\` (see docs/benchmarks.md). Ours and the peer run alternately in the"
  echo "same run on the same input file, page cache warm; each time is the median over"
  echo "$BENCH_ROUNDS processes per side of the median of $BENCH_REPS timed reads after one warm-up."
  echo "Ratio = ours / peer: below 1 we are faster, above 1 we are slower. The wall-time ratio is"
  echo "what a user waits for; the CPU-time ratio leaves out waiting for a core and is the steadier"
  echo "one when other jobs load the machine (load average below)."
  echo
  echo "- date: $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "- commit: $commit"
  echo "- machine: $cpu, $(nproc) cores, $(free -g | awk '/^Mem:/ {print $2}') GiB, $(uname -sr)"
  echo "- load average (1, 5, 15 min) at start: $load_start; at end: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "- compiler: $(cc --version | head -1); flintstone built CMAKE_BUILD_TYPE=Release"
  echo "- peer: assimp $(dpkg-query -W -f='${Version}' libassimp-dev) (Debian libassimp-dev)"
  echo "- peers (Delaunay): CGAL $(dpkg-query -W -f='${Version}' libcgal-dev) (libcgal-dev, g++ -O2 -DNDEBUG), qhull $(dpkg-query -W -f='${Version}' qhull-bin) (qhull-bin), TetGen $(dpkg-query -W -f='${Version}' tetgen) (tetgen)"
  echo "- peer (check): CGAL $(dpkg-query -W -f='${Version}' libcgal-dev) (Debian libcgal-dev)"
  echo "- peer (closest_deform): CGAL $(dpkg-query -W -f='${Version}' libcgal-dev) AABB_tree rebuilt + accelerate_distance_queries every frame (bench/workloads/closest_deform.sh)"
  echo
  echo "| workload | ours (s) | peer | peer (s) | ratio ours/peer (wall) | ratio (CPU) | notes |"
  echo "|---|---:|---|---:|---:|---:|---|"
  awk -F'|' '
    $1 == "ROW"   { printf "| %s | %.4f | %s | %.4f | **%.2f** | %s | %s |\n", $2, $3, $4, $5, $3 / $5, $6, $7 }
    $1 == "ERROR" { printf "| %s | failed | | | | | %s |\n", $2, $3 }' "$rows"
  echo
  echo "In words (a ratio within 10% of 1 is taken as noise; the verdict needs wall and CPU time to agree):"
  echo
  awk -F'|' '$1 == "ROW" {
    w = $3 / $5; c = ($6 == "-") ? w : $6
    if (w > 1.1 && c > 1.1)        printf "- %s: **ours is %.1fx slower than %s**\n", $2, w, $4
    else if (w < 0.91 && c < 0.91) printf "- %s: ours is %.1fx faster than %s\n", $2, 1 / w, $4
    else printf "- %s: ours and %s are on par (ratio %.2f wall, %s CPU)\n", $2, $4, w, $6
  }' "$rows"
  echo
  echo "Where the time goes when we are slower: see \"Findings\" in docs/benchmarks.md (readers) and"
  echo "\"Benchmark\" in docs/delaunay.md (Delaunay: method, what each figure is, profiles)."
} >"$results"
echo "run: wrote $results" >&2
cat "$results"
