#!/usr/bin/env bash
# Path guiding (--guiding) keeps the image a pure function of (scene, spp, seed): the same bits on
# one thread and two with other tile sizes; tiles of a farm merged are the single render's pixels
# (each piece trains on the full image); sample ranges merged are the single render within 1 ulp
# (each piece trains on samples 0-3 of 16 whatever its range); and it does change the image.
# The same holds with adaptive sampling (--noise-threshold: every pixel takes the training passes,
# then pixels stop by their noise) and for volpath (the smoke scene); on an integrator without
# guiding the option is a located warning.
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
# Adaptive: 64 spp, minimum 8, pixels judged from 16 on (where training ends).
aopts=(--spp 64 --seed 5 --guiding --noise-threshold 0.2 --adaptive-min-samples 8 --preview none -q)
in_parallel "$candela" room.pbrt "${aopts[@]}" --nthreads 1 -o adaptive.exr
in_parallel "$candela" room.pbrt "${aopts[@]}" --nthreads 2 --tile-size 7 -o adaptive-threads.exr
for i in 0 1; do
  in_parallel "$candela" room.pbrt "${aopts[@]}" --tile "$i/2" -o "atile$i.exr"
done
in_parallel "$candela" room.pbrt --spp 64 --seed 5 --guiding --preview none -q -o guided64.exr
# volpath through the smoke, small.
sed -e 's/"integer xresolution" \[240\] "integer yresolution" \[240\]/"integer xresolution" [31] "integer yresolution" [23]/' \
  "$src/scenes/smoke/smoke.pbrt" > smoke.pbrt
grep -q 'xresolution" \[31\]' smoke.pbrt || { echo "FAIL: could not make the smoke scene"; exit 1; }
vopts=(--spp 8 --seed 3 --guiding --preview none -q)
in_parallel "$candela" smoke.pbrt "${vopts[@]}" --nthreads 1 -o vsingle.exr
in_parallel "$candela" smoke.pbrt "${vopts[@]}" --nthreads 2 --tile-size 6 -o vthreads.exr
for i in 0 1; do
  in_parallel "$candela" smoke.pbrt "${vopts[@]}" --tile "$i/2" -o "vtile$i.exr"
done
in_parallel "$candela" smoke.pbrt --spp 8 --seed 3 --preview none -q -o vplain.exr
wait_all
"$diff" adaptive.exr adaptive-threads.exr --max-ulps 0 ||
  { echo "FAIL: adaptive guided: threads or tile size change it"; exit 1; }
"$candela" merge -q -o atiles.exr atile0.exr atile1.exr
"$diff" adaptive.exr atiles.exr --max-ulps 0 || { echo "FAIL: adaptive guided farm tiles differ"; exit 1; }
if "$diff" adaptive.exr guided64.exr --max-ulps 0 > /dev/null 2>&1; then
  echo "FAIL: --noise-threshold did not change the guided image"; exit 1
fi
"$diff" vsingle.exr vthreads.exr --max-ulps 0 ||
  { echo "FAIL: volpath guided: threads or tile size change it"; exit 1; }
"$candela" merge -q -o vtiles.exr vtile0.exr vtile1.exr
"$diff" vsingle.exr vtiles.exr --max-ulps 0 || { echo "FAIL: volpath guided farm tiles differ"; exit 1; }
if "$diff" vsingle.exr vplain.exr --max-ulps 0 > /dev/null 2>&1; then
  echo "FAIL: --guiding did not change volpath's image"; exit 1
fi
sed 's/^SurfaceIntegrator .*/SurfaceIntegrator "directlighting"/' room.pbrt > direct.pbrt
"$candela" direct.pbrt --spp 1 --guiding -o direct.exr --preview none 2> direct.err
grep -q "direct.pbrt:11:1: warning: --guiding is ignored: integrator 'directlighting'" direct.err ||
  { echo "FAIL: no located warning"; cat direct.err; exit 1; }
echo "guiding: ok"
