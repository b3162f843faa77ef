#!/usr/bin/env bash
# Scene input from several files in order, and from standard input ('-' or no file).
set -euo pipefail
candela=$1 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
cat > options.pbrt <<'S'
Film "image" "integer xresolution" [8] "integer yresolution" [8] "string filename" "split.exr"
Sampler "random" "integer pixelsamples" [2]
S
cat > world.pbrt <<'S'
WorldBegin
LightSource "point" "point from" [0 0 -2] "rgb I" [5 5 5]
Translate 0 0 3
Shape "sphere"
WorldEnd
S
"$candela" -q options.pbrt world.pbrt --preview none
test -s split.exr || { echo "FAIL: two files did not render"; exit 1; }
cat options.pbrt world.pbrt | "$candela" -q - -o stdin.exr --preview none
cat options.pbrt world.pbrt | "$candela" -q -o nofile.exr --preview none
test -s stdin.exr && test -s nofile.exr || { echo "FAIL: stdin"; exit 1; }
# Two frames in one file write two images.
cat options.pbrt world.pbrt world.pbrt > twoframes.pbrt
"$candela" -q twoframes.pbrt -o frame.exr --preview none
test -s frame.exr && test -s frame-1.exr || { echo "FAIL: second frame"; ls; exit 1; }
echo "inputs: ok"
