#!/usr/bin/env bash
# Fetches the real benchmark data into bench/cache/ (git-ignored; never commit it) and converts
# it to our formats with our own code (bench/tools/*.js). Idempotent: a step whose output is
# there is skipped; delete bench/cache/ to start over.
#
#   Debian libcgal-demo  -> cache/cgal/data/{meshes,points_3,images}  (CGAL's demo data)
#   npm bunny            -> cache/real/bunny.{off,ply,xyz}
#   npm world-atlas      -> cache/real/countries-{110m,50m}.{geojson,xy}
#   cache/inventory.txt     every data file with its size, by kind
#   cache/manifest.txt      each mesh: vertices, triangles, closed or not (needs the census
#                           program: bench/out/bin/mesh_census or $FL_CENSUS; bench/run.sh
#                           builds it first)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
cache=$here/cache
mkdir -p "$cache/debian" "$cache/npm" "$cache/real"

need() { command -v "$1" >/dev/null || { echo "get-data: $1 is required ($2)" >&2; exit 1; }; }
need node "apt-get install nodejs"
need npm "apt-get install npm"

# --- Debian: libcgal-demo ships CGAL's data/ folder as data.tar.gz inside the package.
if [ ! -e "$cache/cgal/.done" ]; then
  if ! ls "$cache"/debian/libcgal-demo_*.deb >/dev/null 2>&1; then
    if ! apt-cache show libcgal-demo >/dev/null 2>&1; then apt-get update -qq; fi
    # _apt must be able to write the target folder, or apt falls back to an unsandboxed fetch.
    chmod 777 "$cache/debian"
    (cd "$cache/debian" && apt-get download -q libcgal-demo)
  fi
  rm -rf "$cache/cgal" "$cache/debian/pkg"
  dpkg-deb -x "$cache"/debian/libcgal-demo_*.deb "$cache/debian/pkg"
  mkdir -p "$cache/cgal"
  tar -xzf "$cache"/debian/pkg/usr/share/doc/libcgal-dev/data.tar.gz -C "$cache/cgal"
  rm -rf "$cache/debian/pkg"
  touch "$cache/cgal/.done"
fi

# --- npm: fetched as package tarballs only (no install scripts run), versions pinned.
for spec in bunny@1.0.1 world-atlas@2.0.2; do
  name=${spec%@*}
  if [ ! -e "$cache/npm/$name/package/package.json" ]; then
    tgz=$(cd "$cache/npm" && npm pack --silent "$spec" | tail -1)
    mkdir -p "$cache/npm/$name"
    tar -xzf "$cache/npm/$tgz" -C "$cache/npm/$name"
  fi
done

# --- conversions with our own code
if [ ! -e "$cache/real/bunny.ply" ]; then
  node "$here/tools/bunny_convert.js" "$cache/npm/bunny/package" "$cache/real/bunny"
fi
for res in 110m 50m; do
  if [ ! -e "$cache/real/countries-$res.xy" ]; then
    node "$here/tools/topojson_decode.js" "$cache/npm/world-atlas/package/countries-$res.json" \
      countries "$cache/real/countries-$res"
  fi
done

# --- what is there
(
  cd "$cache"
  echo "# bench data inventory: size in bytes, path (relative to bench/cache/)"
  echo "# libcgal-demo $(dpkg-deb -f debian/libcgal-demo_*.deb Version)"
  for kind in meshes points_3 images; do
    echo "## cgal/data/$kind"
    find "cgal/data/$kind" -type f -printf '%s %p\n' | sort -k2
  done
  echo "## real (converted from npm packages)"
  find real -type f -printf '%s %p\n' | sort -k2
) >"$cache/inventory.txt"
echo "get-data: $(grep -vc '^#' "$cache/inventory.txt") files listed in bench/cache/inventory.txt"

census=${FL_CENSUS:-$here/out/bin/mesh_census}
if [ -x "$census" ]; then
  {
    echo "# meshes of libcgal-demo and npm bunny, read with fl_read_mesh (bench/mesh_census.c)"
    (cd "$cache" && "$census" cgal/data/meshes/* cgal/data/points_3/*.off real/bunny.off)
  } >"$cache/manifest.txt"
  echo "get-data: $(grep -c 'closed=yes' "$cache/manifest.txt") closed meshes, see bench/cache/manifest.txt"
else
  echo "get-data: no census program ($census); skipped bench/cache/manifest.txt" >&2
fi
