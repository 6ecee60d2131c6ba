#!/usr/bin/env bash
# 3D boundary construction (`flintstone reconstruct`, docs/reconstruct3d.md) against CGAL's
# Advancing Front surface reconstruction (bench/peers/cgal_afront.cpp) on the same scattered
# points, in the same run: the point sets of libcgal-demo (kitten, blobby, sphere_20k, oneK;
# only x y z kept) and the vertices of npm's bunny (bench/get-data.sh fetches both).
#
# Per input, one ROW line:
#   ours: seconds of `flintstone reconstruct --json` (read + Delaunay + constriction + unlocking),
#         of `flintstone delaunay --json` on the same file (read + Delaunay), their ratio (issue
#         6 target <= 3), points on the boundary, flips, closed / genus / self-intersections of
#         the written mesh by `flintstone check`;
#   CGAL: its reconstruction time (best of 3, in-process; ours is one whole process, so the
#         ratio favours CGAL slightly), the fraction of points its surface uses (points minus
#         check's unreferenced vertices), closed / genus / self-intersections by the same check.
# Then one QUALITY line per surface with a known truth (the demo peanut of data/demo, and the
# vertices of libcgal-demo's genus-0 meshes blobby, cow, bull with the mesh as truth): the
# one-sided Hausdorff distance surface -> truth (`flintstone hausdorff`, upper bound) and the
# area (`flintstone check`) of ours and of CGAL's, the fraction of the truth's triangles each
# recovered (same vertex triple; the libcgal-demo meshes only), and the truth's area.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cache=${BENCH_CACHE:-$root/bench/cache}
build=${FL_BENCH_BUILD:-$root/build-bench}
out=$root/bench/out/reconstruct3
bin=$root/bench/out/bin
mkdir -p "$out" "$bin"

if [ ! -x "$build/flintstone" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" -j 2 --target flintstone >/dev/null
fl=$build/flintstone
peer=$bin/cgal_afront
if [ ! -x "$peer" ] || [ "$root/bench/peers/cgal_afront.cpp" -nt "$peer" ]; then
  echo "building cgal_afront (about a minute)" >&2
  ${CXX:-c++} -std=c++17 -O2 -DNDEBUG -o "$peer" "$root/bench/peers/cgal_afront.cpp" -lgmp -lmpfr
fi

jget() { python3 -c "import json,sys; d=json.load(sys.stdin); print(d.get('$1'))"; }

inputs=(cgal/data/points_3/oneK.xyz cgal/data/points_3/kitten.xyz cgal/data/points_3/blobby.xyz
        cgal/data/points_3/sphere_20k.xyz real/bunny.xyz)
printf '%-12s %7s | %8s %8s %5s %9s %5s %s | %8s %6s %9s %s\n' input points ours_s dt_s ratio \
  on_bnd flips "closed/genus/si" cgal_s ratio used "closed/genus/si"
for rel in "${inputs[@]}"; do
  src=$cache/$rel
  [ -e "$src" ] || { echo "missing $src (run bench/get-data.sh)" >&2; continue; }
  name=$(basename "$rel" .xyz)
  pts=$out/$name.xyz
  awk 'NF >= 3 { print $1, $2, $3 }' "$src" >"$pts"
  n=$(wc -l <"$pts")
  ours=$("$fl" reconstruct "$pts" --json -o "$out/$name.ours.off" 2>/dev/null || true)
  dt=$("$fl" delaunay "$pts" --json 2>/dev/null)
  cg=$("$peer" "$pts" "$out/$name.cgal.off")
  co=$("$fl" check "$out/$name.ours.off" --json || true)
  cc=$("$fl" check "$out/$name.cgal.off" --json || true)
  os=$(jget seconds <<<"$ours"); ds=$(jget seconds <<<"$dt"); cs=$(jget seconds <<<"$cg")
  ob=$(jget boundary_vertices <<<"$ours"); uq=$(jget points <<<"$ours")
  cu=$(jget unreferenced_vertices <<<"$cc")
  printf 'ROW %-12s %7d | %8.3f %8.3f %5.2f %9s %5s %s/%s/%s | %8.3f %6.2f %9s %s/%s/%s\n' \
    "$name" "$n" "$os" "$ds" "$(python3 -c "print($os/$ds)")" "$ob/$uq" \
    "$(jget flips <<<"$ours")" "$(jget closed <<<"$co")" "$(jget genus <<<"$co")" \
    "$(jget self_intersections <<<"$co")" "$cs" "$(python3 -c "print($os/$cs)")" \
    "$((n - cu))/$n" "$(jget closed <<<"$cc")" "$(jget genus <<<"$cc")" \
    "$(jget self_intersections <<<"$cc")"
done

printf '%-12s %7s | %9s %9s %8s | %9s %9s %8s | %9s\n' input points ours_h ours_area ours_rec \
  cgal_h cgal_area cgal_rec truth_area
grep -v '^#' "$root/data/demo/peanut.xyz" >"$out/peanut.xyz"
quality=("$out/peanut.xyz:$root/data/demo/peanut-truth.off")
for m in blobby cow bull; do
  mesh=$cache/cgal/data/meshes/$m.off
  [ -e "$mesh" ] || continue
  awk 'NR == 1 { next } NR == 2 { n = $1; next } n > 0 && NF >= 3 { print $1, $2, $3; n-- }' \
    "$mesh" >"$out/$m.vertices.xyz"
  quality+=("$out/$m.vertices.xyz:$mesh")
done
for pair in "${quality[@]}"; do
  pts=${pair%%:*}; truth=${pair#*:}
  name=$(basename "$pts" .xyz)
  "$fl" reconstruct "$pts" -o "$out/$name.q.ours.off" >/dev/null 2>&1 || true
  "$peer" "$pts" "$out/$name.q.cgal.off" >/dev/null
  hget() { "$fl" hausdorff "$1" "$truth" --json | python3 -c \
    "import json,sys; print('%.4f' % json.load(sys.stdin)['h_ab'][1])"; }
  aget() { "$fl" check "$1" --json | python3 -c \
    "import json,sys; print('%.3f' % json.load(sys.stdin)['area'])"; }
  # Fraction of the truth's triangles (as unordered vertex triples) that the surface has; only
  # where the points are the truth's vertices in order (not the resampled peanut).
  rget() { [ "$name" != peanut ] || { echo -; return; }; python3 - "$1" "$truth" <<'PY'
import sys
def tris(path):
    w = open(path).read().split()
    i = 1 if w[0] == 'OFF' else 0
    nv, nf = int(w[i]), int(w[i + 1])
    j = i + 3 + 3 * nv
    out = set()
    for _ in range(nf):
        k = int(w[j])
        if k == 3:
            out.add(tuple(sorted(int(x) for x in w[j + 1:j + 4])))
        j += k + 1
    return out
got, ref = tris(sys.argv[1]), tris(sys.argv[2])
print('%.3f' % (len(got & ref) / len(ref)))
PY
  }
  printf 'QUALITY %-12s %7d | %9s %9s %8s | %9s %9s %8s | %9s\n' "$name" "$(wc -l <"$pts")" \
    "$(hget "$out/$name.q.ours.off")" "$(aget "$out/$name.q.ours.off")" \
    "$(rget "$out/$name.q.ours.off")" "$(hget "$out/$name.q.cgal.off")" \
    "$(aget "$out/$name.q.cgal.off")" "$(rget "$out/$name.q.cgal.off")" "$(aget "$truth")"
done
