#!/usr/bin/env bash
# 3D boundary construction at scale (docs/reconstruct3d.md, "Speed at 1e5 and 1e6 points"):
# N points on a smooth closed genus-0 surface (bench/recon3_scale.c: a radially perturbed
# sphere). One process times fl_dt3_build and fl_reconstruct3 (its Delaunay build included) on the
# same points alternately, median of 3 each (issue 6's target: ratio <= 3), and checks the
# result (all points on the boundary, closed, manifold, genus). CGAL's Advancing Front
# (bench/peers/cgal_afront.cpp, best of 3 in its process) reconstructs the same points up to
# RECON3_CGAL_MAX points (default 1e5; it needs minutes at 1e6), and its surface is checked by
# `flintstone check` (closed, genus, points left unused).
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
sizes=${RECON3_SCALE_SIZES:-100000 1000000}
cgal_max=${RECON3_CGAL_MAX:-100000}
fl=${FL_BENCH_BUILD:-$(cd "$(dirname "$0")/../.." && pwd)/build-bench}/flintstone
jget() { python3 -c "import json,sys; d=json.load(sys.stdin); print(d.get('$1'))"; }
for n in $sizes; do
  label=$(awk -v n="$n" 'BEGIN {e = int(log(n) / log(10) + 1e-9)
                                if (n == 10 ^ e) printf "1e%d", e; else printf "%d", n}')
  pts=$BENCH_DATA/blob_$n.xyz
  line=$("$BENCH_BIN/recon3_scale" "$n" 1 "$pts" | grep '^RESULT') ||
    { echo "ERROR|reconstruct3_scale_$label|recon3_scale failed"; continue; }
  rec=$(field rec "$line"); dt=$(field dt "$line")
  notes="on boundary $(field on_boundary "$line"), closed $(field closed "$line"), manifold $(field manifold "$line"), genus $(field genus "$line"), flips $(field flips "$line"), augmented_c0 $(field augmented_c0 "$line")"
  echo "ROW|reconstruct3_scale_${label}_vs_dt|$rec|our own fl_dt3_build (target ratio <= 3)|$dt|$(field cpu_ratio "$line")|$notes"
  if ((n <= cgal_max)) && [ -x "$BENCH_BIN/cgal_afront" ]; then
    cg=$("$BENCH_BIN/cgal_afront" "$pts" "$BENCH_DATA/blob_$n.cgal.off")
    cc=$("$fl" check "$BENCH_DATA/blob_$n.cgal.off" --json --no-self-intersections 2>/dev/null || true)
    cs=$(jget seconds <<<"$cg")
    cu=$(jget unreferenced_vertices <<<"$cc")
    echo "ROW|reconstruct3_scale_${label}_cgal|$rec|CGAL advancing_front_surface_reconstruction|$cs|-|ours: $notes; CGAL: points used $((n - cu))/$n, closed $(jget closed <<<"$cc"), genus $(jget genus <<<"$cc")"
  fi
  rm -f "$pts" "$BENCH_DATA/blob_$n.cgal.off"
done
