#!/usr/bin/env bash
# Evaluation of the ε-approximation by balls (issue #12, "Evaluation"; docs/skin.md): for closed
# meshes of Debian libcgal-demo (bench/get-data.sh; the npm bunny is not closed, so the closed
# libcgal-demo bunny00.off stands for it) and several ε, `flintstone balls MESH --epsilon E
# --json`: |B_perp|, |B| (protecting balls on the surface), |B_perp| ε²/A and |B| ε²/A (Cheng &
# Tan predict O(A/ε²) balls, so these should stay bounded as ε shrinks), the certified
# Hausdorff distance of ∂∪B_perp itself (fl_skin_union_hausdorff, precision ε/50) and of the
# verifying skin mesh of B*, the Euler check (skin mesh vs input), CPU and wall seconds. There is
# no peer: the ratio column is "-". A case that needs more than SKIN_EVAL_CPU seconds of CPU
# time (default 120; ulimit -t, so the machine's load does not decide) or SKIN_EVAL_TIMEOUT
# seconds of wall time (default 1800) is reported as not finished.
#
#   SKIN_EVAL_CASES="cube 0.5 0.35 0.25;hole 4 3 2"   mesh name (cgal/data/meshes/NAME.off)
#                                                      and its ε values
#   SKIN_EVAL_SLICE="hole 3 0.45 x"  also writes $BENCH_DATA/skin_eval_slice_hole_3.svg: the
#                                  cross-sections of ∪B_perp (blue discs) and of the mesh (black)
#                                  by the plane x = xmin + 0.45 (xmax - xmin)
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${FL_BENCH_BUILD:-$root/build-bench}
cmake --build "$build" -j 2 --target flintstone >/dev/null
fl=$build/flintstone
meshes=$BENCH_CACHE/cgal/data/meshes
timeout_s=${SKIN_EVAL_TIMEOUT:-1800}
cpu_s=${SKIN_EVAL_CPU:-120}
cases=${SKIN_EVAL_CASES:-"cube 0.5 0.35 0.25;icosahedron 0.4 0.3 0.2;hole 4 3 2;P 1.0 0.8 0.6"}

# slice_svg MESH.off BALLS.txt FRACTION AXIS OUT.svg: the cross-sections by a plane normal to
# AXIS (x, y or z) at FRACTION of the mesh's extent along it.
slice_svg() {
  local ax=2
  case $4 in x) ax=0 ;; y) ax=1 ;; esac
  awk -v frac="$3" -v ax=$(( (ax + 1) % 3 )) '
    FNR == 1 { file++ }
    file == 1 && FNR == 1 && $1 == "OFF" { next }
    file == 1 && !nv && NF >= 2 { nv = $1; nf = $2; next }
    file == 1 && k < nv && NF >= 3 { k += 0; x[k] = $(1 + ax % 3); y[k] = $(1 + (ax + 1) % 3);
      z[k] = $(1 + (ax + 2) % 3); k++;
      if (k == 1 || z[k - 1] < z0) z0 = z[k - 1]; if (k == 1 || z[k - 1] > z1) z1 = z[k - 1];
      if (k == 1 || x[k - 1] < x0) x0 = x[k - 1]; if (k == 1 || x[k - 1] > x1) x1 = x[k - 1];
      if (k == 1 || y[k - 1] < y0) y0 = y[k - 1]; if (k == 1 || y[k - 1] > y1) y1 = y[k - 1];
      next }
    file == 1 && k == nv && NF > 3 { face[nfc++] = $0; next }
    file == 2 { bx[nb] = $(1 + ax % 3); by[nb] = $(1 + (ax + 1) % 3); bz[nb] = $(1 + (ax + 2) % 3);
      br[nb] = $4; nb++ }
    END {
      zc = z0 + frac * (z1 - z0); w = x1 - x0; h = y1 - y0; m = 0.05 * (w > h ? w : h);
      s = 800 / (w + 2 * m);
      printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\">\n", \
        (w + 2 * m) * s, (h + 2 * m) * s;
      printf "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n";
      for (i = 0; i < nb; i++) { d = bz[i] - zc; if (d * d >= br[i] * br[i]) continue;
        printf "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"#7fb2e5\"/>\n", \
          (bx[i] - x0 + m) * s, (y1 - by[i] + m) * s, sqrt(br[i] * br[i] - d * d) * s }
      for (f = 0; f < nfc; f++) { n = split(face[f], v, " "); c = 0;
        for (j = 2; j <= v[1] + 1; j++) { a = v[j]; jn = j + 1; if (j == v[1] + 1) jn = 2;
          b = v[jn];
          if ((z[a] - zc) * (z[b] - zc) < 0) { t = (zc - z[a]) / (z[b] - z[a]);
            px[c] = x[a] + t * (x[b] - x[a]); py[c] = y[a] + t * (y[b] - y[a]); c++ } }
        if (c == 2) printf "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" " \
          "stroke=\"black\" stroke-width=\"1.5\"/>\n", (px[0] - x0 + m) * s, \
          (y1 - py[0] + m) * s, (px[1] - x0 + m) * s, (y1 - py[1] + m) * s }
      print "</svg>" }' "$1" "$2" >"$5"
}

key() { sed -n "s/.*\"$1\":\([^,}]*\).*/\1/p" <<<"$2"; }

IFS=';' read -ra list <<<"$cases"
for c in "${list[@]}"; do
  read -ra f <<<"$c"
  name=${f[0]:-}
  [ -n "$name" ] || continue
  mesh=$meshes/$name.off
  [ -e "$mesh" ] || { echo "ERROR|skin_eval_$name|$mesh missing (run bench/get-data.sh)"; continue; }
  info=$("$fl" check "$mesh" --json)
  area=$(key area "$info")
  genus=$(key genus "$info")
  for eps in "${f[@]:1}"; do
    wl=skin_eval_${name}_$eps
    tfile=$(mktemp)
    set +e
    efile=$(mktemp)
    json=$(ulimit -t "$cpu_s"; timeout "$timeout_s" /usr/bin/time -f "%U %e" -o "$tfile" \
      "$fl" balls "$mesh" --epsilon "$eps" --json 2>"$efile")
    rc=$?
    set -e
    read -r cpu wall <"$tfile" || true
    why=$(grep -v "^Command" "$efile" | tail -1 | tr '|' '/' || true)
    rm -f "$tfile" "$efile"
    load=$(cut -d' ' -f1 /proc/loadavg)
    if [ "$rc" = 124 ] || [ "$rc" -gt 128 ]; then
      echo "ROW|$wl|-|-|-|-|not finished in ${cpu_s} s CPU / ${timeout_s} s wall (genus $genus, area $area); load $load"
      continue
    fi
    if [ "$rc" != 0 ]; then
      echo "ROW|$wl|-|-|-|-|failed (exit $rc: $why) (genus $genus); load $load"
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

if [ -n "${SKIN_EVAL_SLICE:-}" ]; then
  read -r name eps frac axis <<<"$SKIN_EVAL_SLICE"
  mkdir -p "$BENCH_DATA"
  balls=$BENCH_DATA/skin_eval_${name}_$eps.txt
  [ -e "$balls" ] || "$fl" balls "$meshes/$name.off" --epsilon "$eps" -o "$balls" --quiet
  slice_svg "$meshes/$name.off" "$balls" "${frac:-0.5}" "${axis:-z}" \
    "$BENCH_DATA/skin_eval_slice_${name}_$eps.svg"
  echo "slice: $BENCH_DATA/skin_eval_slice_${name}_$eps.svg" >&2
fi
