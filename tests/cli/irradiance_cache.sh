#!/usr/bin/env bash
# "irradiancecache" from the command line: the prepass reports its progress, and --stats prints
# the cache's sample count and memory after the render.
set -euo pipefail
candela=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
sed -e 's/SurfaceIntegrator "path" "integer maxdepth" \[5\]/SurfaceIntegrator "irradiancecache" "integer nsamples" [16]/' \
  "$src/scenes/cornell-box/cornell-box.pbrt" > "$work/ic.pbrt"
grep -q irradiancecache "$work/ic.pbrt" || { echo "FAIL: scene not edited"; exit 1; }
"$candela" "$work/ic.pbrt" --quick --spp 1 --stats --outfile "$work/ic.exr" 2> "$work/log.txt"
cat "$work/log.txt"
test -s "$work/ic.exr" || { echo "FAIL: no EXR"; exit 1; }
grep -q "^Irradiance cache:" "$work/log.txt" || { echo "FAIL: no prepass progress"; exit 1; }
grep -Eq "^  samples  [1-9][0-9]*$" "$work/log.txt" || { echo "FAIL: no sample count"; exit 1; }
grep -Eq "^  memory  [1-9][0-9]* KiB$" "$work/log.txt" || { echo "FAIL: no memory"; exit 1; }
echo "irradiance cache: ok"
