#!/usr/bin/env bash
# --subdiv picks the code that refines loopsubdiv shapes; both render (the images are compared
# in-process by SubdivRenders), and anything else is a usage error.
set -euo pipefail
candela=$1 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
cat > subdiv.pbrt <<'S'
Film "image" "integer xresolution" [16] "integer yresolution" [16]
Sampler "random" "integer pixelsamples" [2]
LookAt 0 -4 1  0 0 0  0 0 1
Camera "perspective" "float fov" [40]
WorldBegin
LightSource "point" "point from" [0 -4 4] "rgb I" [20 20 20]
Shape "loopsubdiv" "integer nlevels" [3]
  "point P" [1 1 1  1 -1 -1  -1 1 -1  -1 -1 1]
  "integer indices" [0 1 2  0 2 3  0 3 1  1 3 2]
WorldEnd
S
for producer in book opensubdiv; do
  "$candela" -q --stats subdiv.pbrt --subdiv "$producer" -o "$producer.exr" --preview none \
    2> "$producer.stats"
  test -s "$producer.exr" || { echo "FAIL: --subdiv $producer wrote no image"; exit 1; }
  grep -Eq "triangles +256" "$producer.stats" ||
    { echo "FAIL: --subdiv $producer did not make 256 triangles"; cat "$producer.stats"; exit 1; }
done
status=0
"$candela" -q subdiv.pbrt --subdiv pbrt -o bad.exr 2> bad.err || status=$?
test "$status" -ne 0 || { echo "FAIL: --subdiv pbrt was accepted"; exit 1; }
grep -q "subdiv" bad.err || { echo "FAIL: the error does not name --subdiv"; cat bad.err; exit 1; }
test ! -e bad.exr || { echo "FAIL: an image was written"; exit 1; }
# Bad topology: file:line:col, the shape and the face, with either producer; no image.
sed 's/0 3 1  1 3 2/0 3 1  1 3 3/' subdiv.pbrt > bad.pbrt
for producer in book opensubdiv; do
  status=0
  "$candela" -q bad.pbrt --subdiv "$producer" -o bad.exr 2> bad.err || status=$?
  test "$status" -ne 0 || { echo "FAIL: bad topology accepted by $producer"; exit 1; }
  grep -q "bad.pbrt:[0-9]*:[0-9]*: error: loopsubdiv: face 3 repeats vertex 3" bad.err ||
    { echo "FAIL: $producer's error"; cat bad.err; exit 1; }
  test ! -e bad.exr || { echo "FAIL: an image was written"; exit 1; }
done
echo "subdiv: ok"
