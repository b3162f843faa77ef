#!/usr/bin/env bash
# `candela merge` refuses, with exit 1, a message naming the file and no output (nor a hidden
# temporary file), pieces that do not make one image: another scene, seed, sample count or
# resolution; a missing or repeated tile; overlapping or missing sample ranges; a truncated file;
# an image that is not a candela piece; and an output that is one of the pieces.
set -euo pipefail
candela=$1 diff=$2 src=$3 work=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work"
box=$src/scenes/cornell-box/cornell-box.pbrt
sed 's/"integer xresolution" \[256\] "integer yresolution" \[256\]/"integer xresolution" [32] "integer yresolution" [24]/' \
  "$box" > a.pbrt
sed 's/"rgb L" \[17 12 4\]/"rgb L" [4 12 17]/' a.pbrt > b.pbrt
cmp -s a.pbrt b.pbrt && { echo "FAIL: could not make the scenes"; exit 1; }
source "$(dirname "${BASH_SOURCE[0]}")/parallel.bash"
render() { in_parallel "$candela" "$@" --preview none -q; }
render a.pbrt --spp 4 --tile 0/2 -o t0.exr
render a.pbrt --spp 4 --tile 1/2 -o t1.exr
render b.pbrt --spp 4 --tile 1/2 -o other-scene.exr
render a.pbrt --spp 4 --seed 5 --tile 1/2 -o other-seed.exr
render a.pbrt --spp 8 --tile 1/2 -o other-spp.exr
render a.pbrt --spp 4 --quick --tile 1/2 -o other-resolution.exr
render a.pbrt --spp 4 --tile 1/3 -o other-grid.exr
render a.pbrt --spp 8 --sample-range 0-3 -o s0-3.exr
render a.pbrt --spp 8 --sample-range 2-7 -o s2-7.exr
in_parallel "$candela" a.pbrt --spp 4 -q -o whole.exr --preview whole.png
wait_all
cp t1.exr copy-of-t1.exr
head -c $(($(stat -c %s t1.exr) / 2)) t1.exr > truncated.exr

refused() { # WHAT PATTERN PIECES...
  local what=$1 pattern=$2
  shift 2
  local rc=0
  "$candela" merge -o out.exr "$@" 2> msg.txt || rc=$?
  [ $rc -eq 1 ] || { echo "FAIL: $what: exit $rc"; cat msg.txt; exit 1; }
  grep -q -- "$pattern" msg.txt || { echo "FAIL: $what: message"; cat msg.txt; exit 1; }
  [ ! -e out.exr ] && [ -z "$(ls -A | grep '^\.')" ] ||
    { echo "FAIL: $what: left $(ls -A | grep -e out.exr -e '^\.')"; exit 1; }
  echo "$what: $(head -1 msg.txt)"
}
refused "another scene" "other-scene.exr: error: is from another scene" t0.exr other-scene.exr
refused "another seed" "other-seed.exr: error: has another seed: 5 (t0.exr: 0)" t0.exr other-seed.exr
refused "another sample count" "other-spp.exr: error: has another sample count" t0.exr other-spp.exr
refused "another resolution" "other-resolution.exr: error: has another resolution: 8x6" \
  t0.exr other-resolution.exr
refused "another grid" "other-grid.exr: error: is from another tile grid" t0.exr other-grid.exr
refused "a missing tile" "frame 0 tile 1/2" t0.exr
refused "a repeated tile" "copy-of-t1.exr: error: frame 0 tile 1/2 again (t1.exr has it)" \
  t0.exr t1.exr copy-of-t1.exr
refused "overlapping samples" "s2-7.exr: error: frame 0 samples 2-7 overlaps s0-3.exr" \
  s0-3.exr s2-7.exr
refused "missing samples" "frame 0 samples 4-7" s0-3.exr
refused "a truncated file" "truncated.exr: error: cannot read image" t0.exr truncated.exr
refused "a foreign image" "whole.png: error: not a candela render piece" whole.png
refused "no piece" "no pieces to merge"
cp t1.exr out.exr
rc=0
"$candela" merge -o out.exr t0.exr out.exr 2> msg.txt || rc=$?
[ $rc -eq 1 ] && grep -q "refusing to overwrite" msg.txt && cmp -s out.exr t1.exr ||
  { echo "FAIL: merged onto a piece"; cat msg.txt; exit 1; }
rm out.exr
# Usage errors: exit 2.
rc=0
"$candela" merge -o out.exr --frames 3-1 t0.exr t1.exr 2> /dev/null || rc=$?
[ $rc -eq 2 ] || { echo "FAIL: --frames 3-1: exit $rc"; exit 1; }
rc=0
"$candela" a.pbrt --tile 2/2 -o out.exr 2> /dev/null || rc=$?
[ $rc -eq 2 ] || { echo "FAIL: --tile 2/2: exit $rc"; exit 1; }
rc=0
"$candela" a.pbrt --tile 0/999 --preview none -o out.exr 2> msg.txt || rc=$?
[ $rc -eq 1 ] && grep -q "cannot be cut into 999 tiles" msg.txt && [ ! -e out.exr ] ||
  { echo "FAIL: 999 tiles of 32x24: exit $rc"; cat msg.txt; exit 1; }
# And the right pieces merge.
"$candela" merge -q -o out.exr t1.exr t0.exr
echo "refusals: ok"
