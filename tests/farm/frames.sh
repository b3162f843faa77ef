#!/usr/bin/env bash
# `--frames A-B` renders only those frames of a scene with several WorldEnds, named as the whole
# render names them (out.exr, out-1.exr, ...); tiles of each frame merge, frame by frame, to the
# single render's pixels; a frame past the last, or one missing from the merge, is refused.
set -euo pipefail
candela=$1 diff=$2 src=$3 work=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work"
box=$src/scenes/cornell-box/cornell-box.pbrt
small() { sed -e 's/"integer xresolution" \[256\] "integer yresolution" \[256\]/"integer xresolution" [40] "integer yresolution" [30]/' \
  -e "s/\"rgb L\" \[17 12 4\]/\"rgb L\" [$1]/" "$box"; }
{ small "17 12 4"; small "4 12 17"; small "12 17 4"; } > three.pbrt
[ "$(grep -c WorldEnd three.pbrt)" = 3 ] || { echo "FAIL: could not make the scene"; exit 1; }
opts=(--spp 4 --preview none -q)

"$candela" three.pbrt "${opts[@]}" -o all.exr
ls all.exr all-1.exr all-2.exr > /dev/null
"$candela" three.pbrt "${opts[@]}" --frames 1-2 -o some.exr
[ ! -e some.exr ] && [ -e some-1.exr ] && [ -e some-2.exr ] ||
  { echo "FAIL: --frames 1-2 wrote $(ls some*)"; exit 1; }
"$diff" some-2.exr all-2.exr > /dev/null || { echo "FAIL: frame 2 alone differs"; exit 1; }
[ "$("$diff" --get some-2.exr candela:frame)" = 2 ] || { echo "FAIL: candela:frame"; exit 1; }

# As a farm runs them: one piece per frame and tile.
pieces=()
for f in 0 1 2; do
  for t in 0 1; do
    "$candela" three.pbrt "${opts[@]}" --frames $f --tile $t/2 -o piece-t$t.exr
    pieces+=("piece-t$t$([ $f -eq 0 ] || echo "-$f").exr")
  done
done
"$candela" merge -q --tiles 2 --frames 0-2 -o merged.exr "${pieces[@]}"
for f in 0 1 2; do
  suffix=$([ $f -eq 0 ] || echo "-$f")
  echo -n "frame $f: "
  "$diff" "all$suffix.exr" "merged$suffix.exr" || { echo "FAIL: merged frame $f"; exit 1; }
done

# Past the last frame: an error before anything renders.
if "$candela" three.pbrt "${opts[@]}" --frames 2-3 -o past.exr 2> past.txt; then
  echo "FAIL: --frames 2-3 of 3 frames succeeded"; exit 1
fi
grep -q "the scene has 3 frames" past.txt || { echo "FAIL: message"; cat past.txt; exit 1; }
ls past*.exr 2> /dev/null && { echo "FAIL: wrote an image"; exit 1; }
# A frame the merge expects but has no piece of: named, and nothing written.
if "$candela" merge --frames 0-2 -o partial.exr "${pieces[@]:0:4}" 2> partial.txt; then
  echo "FAIL: merged without frame 2"; exit 1
fi
grep -q "frame 2 tile 0/2" partial.txt && grep -q "frame 2 tile 1/2" partial.txt ||
  { echo "FAIL: missing frame not named"; cat partial.txt; exit 1; }
[ -z "$(ls -A | grep partial | grep -v partial.txt)" ] || { echo "FAIL: wrote $(ls -A | grep partial)"; exit 1; }
echo "frames: ok"
