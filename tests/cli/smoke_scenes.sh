#!/usr/bin/env bash
# The two smoke scenes are what tools/make_smoke_scene.py writes, and both render end to end
# without warnings: the pbrt-v3 one (named medium, volpath) and the pbrt-v2 one (Volume
# "volumegrid", single scattering), the latter also with volpath, which then counts one volume
# region and renders a different image (more scattering orders).
set -euo pipefail
candela=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work/scenes"
python3 "$src/tools/make_smoke_scene.py" "$work/scenes"
for s in smoke smoke-grid; do
  cmp "$work/scenes/$s/$s.pbrt" "$src/scenes/$s/$s.pbrt" ||
    { echo "FAIL: scenes/$s/$s.pbrt differs from what tools/make_smoke_scene.py writes"; exit 1; }
  "$candela" "$src/scenes/$s/$s.pbrt" --quick --spp 2 --stats --outfile "$work/$s.exr" \
    2> "$work/$s.log"
  test -s "$work/$s.exr" || { echo "FAIL: $s: no EXR"; exit 1; }
  grep -q "warning" "$work/$s.log" && { cat "$work/$s.log"; echo "FAIL: $s: warnings"; exit 1; }
done
grep -Eq "named media +1" "$work/smoke.log" || { echo "FAIL: smoke: medium not counted"; exit 1; }
grep -Eq "volume regions +1" "$work/smoke-grid.log" ||
  { echo "FAIL: smoke-grid: region not counted"; exit 1; }
sed -e 's/^SurfaceIntegrator .*/Integrator "volpath" "integer maxdepth" [16]/' \
    -e '/^VolumeIntegrator/d' "$src/scenes/smoke-grid/smoke-grid.pbrt" > "$work/volpath.pbrt"
"$candela" "$work/volpath.pbrt" --quick --spp 2 --stats --outfile "$work/volpath.exr" \
  2> "$work/volpath.log"
grep -q "warning" "$work/volpath.log" && { cat "$work/volpath.log"; echo "FAIL: warnings"; exit 1; }
cmp -s "$work/volpath.exr" "$work/smoke-grid.exr" && { echo "FAIL: volpath = single"; exit 1; }
echo "smoke scenes: ok"
