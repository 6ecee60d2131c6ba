# `flintstone skin --balls` against CGAL's Skin_surface_3 mesher (bench/peers/cgal_skin.cpp,
# CGAL::make_skin_surface_mesh_3) on the same ball set and shrink factor t = 0.5, in the same
# run, alternately BENCH_ROUNDS times each. Both sides are timed in-process around the mesher
# call alone, wall and process CPU time (the balls are read before, the mesh written after):
# ours is fl_skin_mesh with its stats (bench/ours_skin.c: regular triangulation, mixed-complex
# index, marching, the vertex-offset check), CGAL's make_skin_surface_mesh_3. The ROW's seconds
# are wall medians, its ratio the CPU-time ratio (steadier on the shared machine); notes give
# both CPU medians. Ball sets (generated, fixed seeds): random balls in a cube ("random N") and a
# chain of balls along a helix ("helix N"). Our mesh is run at the default cell and at a coarser
# cell (SKIN_COARSE_CELL_FACTOR, default 3x) closer to CGAL's mesh size. Notes give both mesh
# sizes and the largest distance from the vertices of each mesh to the other mesh (`flintstone
# closest`, exact point-to-mesh distances; a sampled lower bound of the Hausdorff distance
# between the two meshes) and the certified Hausdorff distance between the two surfaces
# (`flintstone hausdorff --both`, [lower, upper]).
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${FL_BENCH_BUILD:-$root/build-bench}
out=$BENCH_DATA/skin
mkdir -p "$out" "$BENCH_BIN"
cmake --build "$build" -j 2 --target flintstone >/dev/null
fl=$build/flintstone
peer=$BENCH_BIN/cgal_skin
[ "$peer" -nt "$root/bench/peers/cgal_skin.cpp" ] || g++ -O2 -DNDEBUG -o "$peer" "$root/bench/peers/cgal_skin.cpp" -lgmp -lmpfr
ours=$BENCH_BIN/ours_skin
cc -O2 -std=c11 -I"$root/include" -o "$ours" "$root/bench/ours_skin.c" "$build/libflintstone.a" -lm

gen_random() { # N SEED: N balls, centres in [0, 2 N^(1/3)]^3, radii in [0.6, 1.2]
  awk -v n="$1" -v seed="$2" 'BEGIN { srand(seed); s = 2 * n ^ (1 / 3);
    for (i = 0; i < n; i++) { r = 0.6 + 0.6 * rand();
      printf "%.9f %.9f %.9f %.9f\n", s * rand(), s * rand(), s * rand(), r * r } }'
}
gen_helix() { # N: N balls of radius 0.5 every 0.6 along a helix of radius 3 and pitch 2
  awk -v n="$1" 'BEGIN { for (i = 0; i < n; i++) { a = i * 0.6 / 3;
    printf "%.9f %.9f %.9f %.9f\n", 3 * cos(a), 3 * sin(a), a / 3.14159265 * 2 / 2, 0.25 } }'
}
off_vertices() { awk 'NR == 1 && $1 == "OFF" { next } !n && NF >= 2 { n = $1; next }
  n && k < n && NF >= 3 { print $1, $2, $3; k++ }' "$1"; }
max_dist() { # MESH POINTS.xyz
  "$fl" closest "$1" "$2" --json | sed -n 's/.*"max_distance":\([^,}]*\).*/\1/p'
}

run_case() { # NAME BALLS CELL (0: the default cell) [GRADE (the graded grid)]
  local name=$1 balls=$2 cell=$3 grade=${4:-0}
  local o_times="" p_times="" o_cpus="" p_cpus="" o_line p_line
  for ((r = 0; r < BENCH_ROUNDS; r++)); do
    o_line=$("$ours" "$balls" 0.5 "$cell" "$out/ours.off" "$grade" | grep '^RESULT') ||
      { echo "ERROR|skin $name|ours failed"; return 0; }
    p_line=$("$peer" "$balls" 0.5 "$out/cgal.off" | grep '^RESULT') ||
      { echo "ERROR|skin $name|cgal failed"; return 0; }
    o_times+="$(field seconds "$o_line")"$'\n'
    p_times+="$(field seconds "$p_line")"$'\n'
    o_cpus+="$(field cpu "$o_line")"$'\n'
    p_cpus+="$(field cpu "$p_line")"$'\n'
  done
  off_vertices "$out/ours.off" >"$out/ours.xyz"
  off_vertices "$out/cgal.off" >"$out/cgal.xyz"
  local d1 d2 hd o_cpu p_cpu
  d1=$(max_dist "$out/cgal.off" "$out/ours.xyz")
  d2=$(max_dist "$out/ours.off" "$out/cgal.xyz")
  # the certified Hausdorff distance between the two meshes' surfaces ([lower, upper])
  hd=$("$fl" hausdorff "$out/ours.off" "$out/cgal.off" --both --relative 1e-3 --budget 60 --json |
    sed -n 's/.*"hausdorff":\[\([^]]*\)\].*/\1/p')
  o_cpu=$(median <<<"${o_cpus%$'\n'}")
  p_cpu=$(median <<<"${p_cpus%$'\n'}")
  printf 'ROW|skin %s|%s|CGAL make_skin_surface_mesh_3|%s|%s|CPU s ours %s, CGAL %s (load %s); ours V=%s F=%s Euler %s (expected %s, %s mesh(es), grade %s, union Euler check %s s CPU) cell %s, CGAL V=%s F=%s; max vertex-to-other-mesh distance ours->CGAL %.3g, CGAL->ours %.3g; Hausdorff [%s]\n' \
    "$name" "$(median <<<"${o_times%$'\n'}")" "$(median <<<"${p_times%$'\n'}")" \
    "$(awk -v o="$o_cpu" -v p="$p_cpu" 'BEGIN { printf "%.2f", o / p }')" "$o_cpu" "$p_cpu" \
    "$(cut -d' ' -f1 /proc/loadavg)" "$(field vertices "$o_line")" "$(field faces "$o_line")" \
    "$(field euler "$o_line")" "$(field expected "$o_line")" "$(field attempts "$o_line")" \
    "$(field grade "$o_line")" "$(field check_cpu "$o_line")" "$(field cell "$o_line")" \
    "$(field vertices "$p_line")" \
    "$(field faces "$p_line")" "$d1" "$d2" "$hd"
}

factor=${SKIN_COARSE_CELL_FACTOR:-3}
# SKIN_CASES: ';'-separated cases, e.g. "random 50 7;helix 120" (issue #12's sets)
IFS=';' read -r -a cases <<<"${SKIN_CASES:-random 50 7;random 200 11}"
for spec in "${cases[@]}"; do
  set -- $spec
  balls=$out/$1_$2.xyzw
  if [ "$1" = random ]; then gen_random "$2" "$3" >"$balls"; else gen_helix "$2" >"$balls"; fi
  # the default of `skin --balls` (fl_skin_mesh_checked: graded 1.5, 0.75, then the uniform
  # default cell, until the Euler characteristic is twice the union's)
  run_case "$1 $2 (default: checked)" "$balls" 0
  # SKIN_UNIFORM=1: also the uniform grid's default cell alone (the default until round 13)
  if [ "${SKIN_UNIFORM:-0}" = 1 ]; then run_case "$1 $2 (uniform default cell)" "$balls" -1; fi
  # sqrt(t) r_min / 4 (the default cell before the neck rule); the coarse one is factor times it
  rmin=$(awk 'NR == 1 || $4 < m { m = $4 } END { printf "%.9g", sqrt(m) }' "$balls")
  run_case "$1 $2 (cell x$factor)" "$balls" "$(awk -v r="$rmin" -v f="$factor" \
    'BEGIN { printf "%.9g", f * sqrt(0.5) * r / 4 }')"
  # the graded grid (octree sized by the local feature size, docs/skin.md); "" skips the row
  for g in ${SKIN_GRADES-1.5}; do run_case "$1 $2 (graded grid, grade $g)" "$balls" 0 "$g"; done
done

# The epsilon mode (issue #12): `flintstone skin MESH --epsilon E --star B*` builds the verified
# approximation (Algorithm 1 balls, B_perp, B*); then both meshers triangulate skin^t(B*) of the
# same B* at t = 0.5 (ours at the grid cell the approximation used). SKIN_EPS_CASES: ';'-separated
# "cube E" or "torus NU NV E" (R = 2, r = 0.75, genus 1); "" skips the mode.
gen_cube() {
  printf 'OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n'
  printf '3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n'
  printf '3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n'
}
gen_torus() { # NU NV
  awk -v nu="$1" -v nv="$2" 'BEGIN { pi = 3.14159265358979; print "OFF"; print nu * nv, 2 * nu * nv, 0
    for (i = 0; i < nu; i++) for (j = 0; j < nv; j++) { u = 2 * pi * i / nu; v = 2 * pi * j / nv
      printf "%.17g %.17g %.17g\n", (2 + 0.75 * cos(v)) * cos(u), (2 + 0.75 * cos(v)) * sin(u), 0.75 * sin(v) }
    for (i = 0; i < nu; i++) for (j = 0; j < nv; j++) { a = i * nv + j; b = ((i + 1) % nu) * nv + j
      c = ((i + 1) % nu) * nv + (j + 1) % nv; d = i * nv + (j + 1) % nv
      print 3, a, b, c; print 3, a, c, d } }'
}
IFS=';' read -r -a eps_cases <<<"${SKIN_EPS_CASES-cube 0.5;torus 8 4 1.0}"
for spec in "${eps_cases[@]}"; do
  set -- $spec
  if [ "$1" = cube ]; then mesh=$out/cube.off; gen_cube >"$mesh"; name="cube eps $2"; eps=$2
  else mesh=$out/torus_$2x$3.off; gen_torus "$2" "$3" >"$mesh"; name="torus $2x$3 eps $4"; eps=$4; fi
  e_json=$("$fl" skin "$mesh" --epsilon "$eps" --star "$out/star.xyzw" --json) ||
    { echo "ERROR|skin $name|approximation not verified"; continue; }
  echo "NOTE|skin $name|approximation: $e_json"
  # B* is full of exact degeneracies (cospherical groups, mirror twins 1e-17 apart on symmetry
  # planes): CGAL's mesher (inexact constructions) then returns a broken surface (cube eps 0.5:
  # 59 components at the bounding octahedron's dummy balls, self-intersections). Both meshers
  # therefore get the same B* with its centres moved by at most SKIN_EPS_PERTURB/2 per coordinate
  # (fixed seed): the skin moves by about as much, far below both meshes' chordal errors.
  awk -v d="${SKIN_EPS_PERTURB:-1e-7}" 'BEGIN { srand(3) } { printf "%.17g %.17g %.17g %.17g\n",
    $1 + d * (rand() - 0.5), $2 + d * (rand() - 0.5), $3 + d * (rand() - 0.5), $4 }' \
    "$out/star.xyzw" >"$out/star_p.xyzw"
  run_case "$name, B* of $(wc -l <"$out/star.xyzw") balls, centres perturbed ${SKIN_EPS_PERTURB:-1e-7}" \
    "$out/star_p.xyzw" "$(sed -n 's/.*"cell":\([^,}]*\).*/\1/p' <<<"$e_json")"
done
