#!/bin/sh
# Peak memory per point of Delaunay 2D/3D, 3D reconstruction and the sweep hierarchy at the
# given sizes (default 1e5 1e6), one process a measurement (scripts/rss_probe.c against the
# release library in build/; `make build` first). Output lines are copied into
# docs/reliability.md.   [RSS_KINDS="dt3 rec3s"] scripts/measure-rss.sh [SIZES...]
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
lib="$root/build/libflintstone.a"
[ -f "$lib" ] || { echo "measure-rss.sh: build the release library first (make build)" >&2; exit 2; }
probe="$root/build/rss_probe"
cc -O2 -std=c11 -I"$root/include" "$root/scripts/rss_probe.c" "$lib" -lm -o "$probe"
sizes=${*:-100000 1000000}
for n in $sizes; do
    for kind in ${RSS_KINDS:-dt2 dt3 rec2 rec3 rec3s sweep}; do
        "$probe" "$kind" "$n" || echo "$kind n=$n failed"
    done
done
