#!/usr/bin/env bash
# The default scene renders end to end: EXR and PNG preview written, statistics printed, and no
# Embree user geometry built for a scene without quadrics.
set -euo pipefail
candela=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
"$candela" "$src/scenes/cornell-box/cornell-box.pbrt" --quick --stats --outfile "$work/cb.exr" \
  2> "$work/log.txt"
cat "$work/log.txt"
test -s "$work/cb.exr" || { echo "FAIL: no EXR"; exit 1; }
test -s "$work/cb.png" || { echo "FAIL: no PNG preview"; exit 1; }
grep -Eq "embree user geometries +0" "$work/log.txt" || { echo "FAIL: user geometry built"; exit 1; }
grep -Eq "rays/s" "$work/log.txt" || { echo "FAIL: no statistics"; exit 1; }
ls "$work" | grep -v -E '^(cb\.exr|cb\.png|log\.txt)$' && { echo "FAIL: stray files"; exit 1; }
echo "cornell box: ok"
