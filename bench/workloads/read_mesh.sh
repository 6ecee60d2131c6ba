#!/usr/bin/env bash
# Mesh reading speed: fl_read_mesh (bench/ours_read.c) against assimp's aiImportFile
# (bench/peers/assimp_read.c) on the same files, page cache warm for both.
set -euo pipefail
source "$(dirname "$0")/../lib.sh"

ply=$(generated torus-1Mv.ply 1000 1000)
compare_readers read_ply_1Mv "binary LE PLY, 1M vertices, 2M triangles; assimp: no post-processing" \
  -- "$BENCH_BIN/ours_read" "$ply" -- "$BENCH_BIN/assimp_read" "$ply"

# fl_read_mesh welds coincident STL vertices; assimp does not unless asked, so both variants.
stl=$(generated torus-1Mt.stl 1000 500)
compare_readers read_stl_1Mt "binary STL, 1M triangles; ours welds, assimp does not (flags 0)" \
  -- "$BENCH_BIN/ours_read" "$stl" -- "$BENCH_BIN/assimp_read" "$stl"
compare_readers read_stl_1Mt_weld "binary STL, 1M triangles; both weld (assimp: JoinIdenticalVertices+DropNormals)" \
  -- "$BENCH_BIN/ours_read" "$stl" -- "$BENCH_BIN/assimp_read" --weld "$stl"

# Real data: the largest mesh CGAL ships (ASCII OFF).
off=$BENCH_CACHE/cgal/data/meshes/refined_elephant.off
compare_readers read_off_elephant "ASCII OFF from libcgal-demo (refined_elephant.off, 4 MB); assimp: no post-processing" \
  -- "$BENCH_BIN/ours_read" "$off" -- "$BENCH_BIN/assimp_read" "$off"
