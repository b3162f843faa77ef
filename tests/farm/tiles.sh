#!/usr/bin/env bash
# `--tile I/N` pieces merged by `candela merge` are the single render's pixels, bit for bit, for
# N = 1, 2, 3, 7 and 16 on an odd-sized image with every AOV and a Mitchell filter of radius 2, and
# for tiles 3 x 2 pixels under a Gaussian of radius 3 (tile edges through the filter's support).
# Each piece says in its metadata what it is; the merge sums their seconds and rays.
set -euo pipefail
candela=$1 diff=$2 src=$3 work=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work"
box=$src/scenes/cornell-box/cornell-box.pbrt
sed -e 's/"integer xresolution" \[256\] "integer yresolution" \[256\]/"integer xresolution" [61] "integer yresolution" [47]/' \
  -e 's/^PixelFilter .*/PixelFilter "mitchell" "float xwidth" [2] "float ywidth" [2]/' "$box" > odd.pbrt
sed -e 's/"integer xresolution" \[256\] "integer yresolution" \[256\]/"integer xresolution" [12] "integer yresolution" [4]/' \
  -e 's/^PixelFilter .*/PixelFilter "gaussian" "float xwidth" [3] "float ywidth" [3]/' "$box" > strip.pbrt
grep -q 'xresolution" \[61\]' odd.pbrt && grep -q mitchell odd.pbrt && grep -q 'xwidth" \[3\]' strip.pbrt ||
  { echo "FAIL: could not make the test scenes"; exit 1; }
opts=(--spp 4 --seed 7 --preview none -q)
source "$(dirname "${BASH_SOURCE[0]}")/parallel.bash"

check_tiles() { # SCENE N [candela options...]
  local scene=$1 n=$2 name
  shift 2
  name=$(basename "$scene" .pbrt)-$n
  # One single render per scene and options, for every N.
  local single
  single=$(basename "$scene" .pbrt)-single$(echo "$@" | tr -c 'a-zA-Z0-9.\n' _).exr
  [ -e "$single" ] || in_parallel "$candela" "$scene" "${opts[@]}" "$@" -o "$single"
  local pieces=()
  for ((i = 0; i < n; ++i)); do
    in_parallel "$candela" "$scene" "${opts[@]}" "$@" --tile "$i/$n" -o "$name-tile$i.exr"
    pieces+=("$name-tile$i.exr")
  done
  wait_all
  "$candela" merge -q -o "$name-merged.exr" "${pieces[@]}"
  echo -n "$name: "
  "$diff" "$single" "$name-merged.exr" --max-ulps 0 ||
    { echo "FAIL: $n tiles of $scene are not the single render's pixels"; exit 1; }
  [ "$n" = 3 ] || return 0
  # What each piece is, and the merge's sums of their seconds and rays.
  local seconds=0 rays=0
  for ((i = 0; i < n; ++i)); do
    [ "$("$diff" --get "$name-tile$i.exr" candela:tile)" = "$i/$n" ] ||
      { echo "FAIL: $name-tile$i.exr: candela:tile"; exit 1; }
    for key in candela:sceneHash candela:frame candela:spp candela:seed candela:renderSeconds; do
      "$diff" --get "$name-tile$i.exr" $key > /dev/null || { echo "FAIL: no $key"; exit 1; }
    done
    seconds=$(awk -v a="$seconds" -v b="$("$diff" --get "$name-tile$i.exr" candela:renderSeconds)" \
      'BEGIN { printf "%.9g", a + b }')
    rays=$((rays + $("$diff" --get "$name-tile$i.exr" candela:rays)))
  done
  [ "$("$diff" --get "$name-merged.exr" candela:rays)" = "$rays" ] ||
    { echo "FAIL: $name: merged rays $("$diff" --get "$name-merged.exr" candela:rays), pieces $rays"; exit 1; }
  awk -v a="$seconds" -v b="$("$diff" --get "$name-merged.exr" candela:renderSeconds)" \
    'BEGIN { exit !(a > 0 && (a - b) ^ 2 < (1e-5 * a) ^ 2) }' ||
    { echo "FAIL: $name: merged seconds are not the pieces' sum $seconds"; exit 1; }
  [ "$("$diff" --get "$name-merged.exr" candela:sceneHash)" = \
    "$("$diff" --get "$single" candela:sceneHash)" ] || { echo "FAIL: scene hash"; exit 1; }
}

for n in 1 2 3 7 16; do check_tiles odd.pbrt $n "${aovs[@]}"; done
check_tiles strip.pbrt 8
# The grid candela chose for the strip: 4 x 2 tiles of 3 x 2 pixels, narrower than the filter.
[ "$("$diff" --get strip-8-tile5.exr dataWindow)" = "3 2 6 4" ] ||
  { echo "FAIL: strip tile 5: $("$diff" --get strip-8-tile5.exr dataWindow)"; exit 1; }
# A crop window is split too: the tiles cover the crop.
check_tiles odd.pbrt 3 --cropwindow 0.2 0.9 0.1 0.5
echo "tiles: ok"
