#!/usr/bin/env bash
# Path guiding (--guiding) keeps the image a pure function of (scene, spp, seed): the same bits on
# one thread and two with other tile sizes; tiles of a farm merged are the single render's pixels
# (each piece trains on the full image); sample ranges merged are the single render within 1 ulp
# (each piece trains on samples 0-3 of 16 whatever its range); and it does change the image.
# Guiding with adaptive sampling is refused with a message; on an integrator without guiding the
# option is a located warning.
set -euo pipefail
candela=$1 diff=$2 src=$3 work=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work"
sed -e 's/"integer xresolution" \[256\] "integer yresolution" \[256\]/"integer xresolution" [37] "integer yresolution" [29]/' \
  "$src/scenes/indirect-room/indirect-room.pbrt" > room.pbrt
grep -q 'xresolution" \[37\]' room.pbrt || { echo "FAIL: could not make the scene"; exit 1; }
opts=(--spp 16 --seed 5 --guiding --preview none -q)
source "$(dirname "${BASH_SOURCE[0]}")/parallel.bash"
in_parallel "$candela" room.pbrt "${opts[@]}" --nthreads 1 -o single.exr
in_parallel "$candela" room.pbrt "${opts[@]}" --nthreads 2 --tile-size 5 -o threads.exr
in_parallel "$candela" room.pbrt --spp 16 --seed 5 --preview none -q -o unguided.exr
for i in 0 1 2; do
  in_parallel "$candela" room.pbrt "${opts[@]}" --tile "$i/3" -o "tile$i.exr"
done
in_parallel "$candela" room.pbrt "${opts[@]}" --sample-range 0-2 -o range0.exr
in_parallel "$candela" room.pbrt "${opts[@]}" --sample-range 3-9 -o range1.exr
in_parallel "$candela" room.pbrt "${opts[@]}" --sample-range 10-15 -o range2.exr
wait_all
"$diff" single.exr threads.exr --max-ulps 0 || { echo "FAIL: threads or tile size change it"; exit 1; }
"$candela" merge -q -o tiles.exr tile0.exr tile1.exr tile2.exr
"$diff" single.exr tiles.exr --max-ulps 0 || { echo "FAIL: farm tiles differ"; exit 1; }
"$candela" merge -q -o ranges.exr range0.exr range1.exr range2.exr
"$diff" single.exr ranges.exr --max-ulps 1 || { echo "FAIL: sample ranges differ"; exit 1; }
if "$diff" single.exr unguided.exr --max-ulps 0 > /dev/null 2>&1; then
  echo "FAIL: --guiding did not change the image"; exit 1
fi
if "$candela" room.pbrt "${opts[@]}" --noise-threshold 0.1 -o adaptive.exr 2> adaptive.err; then
  echo "FAIL: guiding with adaptive sampling was accepted"; exit 1
fi
grep -q "path guiding does not yet combine with adaptive sampling" adaptive.err ||
  { echo "FAIL: message"; cat adaptive.err; exit 1; }
[ ! -e adaptive.exr ] || { echo "FAIL: an image was written"; exit 1; }
sed 's/^SurfaceIntegrator .*/SurfaceIntegrator "directlighting"/' room.pbrt > direct.pbrt
"$candela" direct.pbrt --spp 1 --guiding -o direct.exr --preview none 2> direct.err
grep -q "direct.pbrt:11:1: warning: --guiding is ignored: integrator 'directlighting'" direct.err ||
  { echo "FAIL: no located warning"; cat direct.err; exit 1; }
echo "guiding: ok"
