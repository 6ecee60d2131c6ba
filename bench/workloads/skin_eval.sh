#!/usr/bin/env bash
# Evaluation of the ε-approximation by balls (issue #12, "Evaluation"; docs/skin.md): for closed
# meshes of Debian libcgal-demo (bench/get-data.sh; the npm bunny is not closed, so the closed
# libcgal-demo bunny00.off stands for it) and several ε, `flintstone balls MESH --epsilon E
# --json`: |B_perp|, |B| (protecting balls on the surface), |B_perp| ε²/A and |B| ε²/A (Cheng &
# Tan predict O(A/ε²) balls, so these should stay bounded as ε shrinks), the certified
# Hausdorff distance of ∂∪B_perp itself (fl_skin_union_hausdorff, precision ε/50) and of the
# verifying skin mesh of B*, the Euler check (skin mesh vs input), CPU and wall seconds. There is
# no peer: the ratio column is "-". A case that runs longer than SKIN_EVAL_TIMEOUT seconds
# (default 300) is reported as not finished.
#
#   SKIN_EVAL_CASES="cube 0.5 0.35 0.25;hole 4 3 2"   mesh name (cgal/data/meshes/NAME.off)
#                                                      and its ε values
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${FL_BENCH_BUILD:-$root/build-bench}
cmake --build "$build" -j 2 --target flintstone >/dev/null
fl=$build/flintstone
meshes=$BENCH_CACHE/cgal/data/meshes
timeout_s=${SKIN_EVAL_TIMEOUT:-300}
cases=${SKIN_EVAL_CASES:-"cube 0.5 0.35 0.25;icosahedron 0.4 0.3 0.2;hole 4 3 2;P 1.0 0.8 0.6"}

key() { sed -n "s/.*\"$1\":\([^,}]*\).*/\1/p" <<<"$2"; }

IFS=';' read -ra list <<<"$cases"
for c in "${list[@]}"; do
  read -ra f <<<"$c"
  name=${f[0]}
  mesh=$meshes/$name.off
  [ -e "$mesh" ] || { echo "ERROR|skin_eval_$name|$mesh missing (run bench/get-data.sh)"; continue; }
  info=$("$fl" check "$mesh" --json)
  area=$(key area "$info")
  genus=$(key genus "$info")
  for eps in "${f[@]:1}"; do
    wl=skin_eval_${name}_$eps
    tfile=$(mktemp)
    set +e
    json=$(timeout "$timeout_s" /usr/bin/time -f "%U %e" -o "$tfile" "$fl" balls "$mesh" \
      --epsilon "$eps" --json 2>/dev/null)
    rc=$?
    set -e
    read -r cpu wall <"$tfile" || true
    rm -f "$tfile"
    load=$(cut -d' ' -f1 /proc/loadavg)
    if [ "$rc" = 124 ]; then
      echo "ROW|$wl|-|-|-|-|not finished in ${timeout_s} s (genus $genus, area $area); load $load"
      continue
    fi
    if [ "$rc" != 0 ]; then
      echo "ROW|$wl|-|-|-|-|failed (exit $rc: not verified) (genus $genus); load $load"
      continue
    fi
    perp=$(key balls "$json")
    surf=$(key boundary_balls "$json")
    notes=$(awk -v p="$perp" -v s="$surf" -v e="$eps" -v a="$area" -v g="$genus" \
      -v hl="$(key hausdorff_lower "$json")" -v hu="$(key hausdorff_upper "$json")" \
      -v hs="$(key skin_hausdorff_upper "$json")" -v eu="$(key euler "$json")" \
      -v ei="$(key euler_input "$json")" -v r="$(key rounds "$json")" \
      -v us="$(key union_seconds "$json")" -v cpu="$cpu" -v ld="$load" 'BEGIN {
        printf "genus %d, A %.4g: B_perp %d (%.2f eps^2/A), B %d (%.2f eps^2/A); " \
               "union Hausdorff [%.4f, %.4f], skin of B* <= %.4f; Euler %d / %d; rounds %d; " \
               "union bound %.1f s wall; CPU %s s; load %s",
               g, a, p, p * e * e / a, s, s * e * e / a, hl, hu, hs, eu, ei, r, us, cpu, ld }')
    echo "ROW|$wl|$wall|-|-|-|$notes"
  done
done
