#!/usr/bin/env bash
# Reproducers from a mutation fuzz of the command (issue 15), each now a clean error or a correct
# render: nothing non-finite reaches Embree, no crash, no NaN pixel; outputs are checked before
# rendering and written only when every frame has succeeded.
set -uo pipefail
candela=$1 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail=0
outputs() { ls -A | grep -Ev '\.(pbrt|txt|inc)$|^tex\.png$'; }
expect() {  # expect NAME EXIT_CODE PATTERN -- candela args...
  local name=$1 code=$2 pattern=$3; shift 4
  "$candela" "$@" > out.txt 2>&1
  local got=$?
  if [ "$got" -ne "$code" ]; then echo "FAIL $name: exit $got, wanted $code"; cat out.txt; fail=1; fi
  if ! grep -Eq -- "$pattern" out.txt; then echo "FAIL $name: no '$pattern' in:"; cat out.txt; fail=1; fi
  if [ "$code" -ne 0 ] && [ -n "$(outputs)" ]; then
    echo "FAIL $name: left output: $(outputs)"; fail=1
  fi
  outputs | xargs -r rm -f
}
cat > base.inc <<'SCENE'
LookAt 0 0 -5 0 0 0 0 1 0
Camera "perspective" "float fov" [40]
Film "image" "integer xresolution" [16] "integer yresolution" [16]
Sampler "random" "integer pixelsamples" [2]
SCENE
world='WorldBegin
LightSource "point" "rgb I" [10 10 10]'

# Aborted inside Embree (rays with components beyond its range), now located errors.
printf 'LookAt 0 0 -5 0 0 0 0 1 0\nCamera "orthographic" "float screenwindow" [1e38 -1e38 1e38 -1e38]\n%s\nShape "sphere"\nWorldEnd\n' "$world" > ortho.pbrt
expect ortho-screenwindow 1 'ortho.pbrt:2:1: error: camera "orthographic": .*beyond 1.8e18' -- ortho.pbrt -o out.exr
printf 'TransformTimes 0 1\nActiveTransform EndTime\nTranslate 0 0 1e38\nActiveTransform All\nLookAt 0 0 -5 0 0 0 0 1 0\nCamera "perspective"\n%s\nShape "sphere"\nWorldEnd\n' "$world" > moving.pbrt
expect moving-camera 1 'moving.pbrt:6:1: error: camera "perspective": .*time 0.5' -- moving.pbrt -o out.exr

# Crashed (segmentation faults); tests/robustness checks that such scenes render finite.
printf 'Include "base.inc"\n%s\nShape "sphere"\nWorldEnd\n' "$world" > plain.pbrt
expect many-threads 2 'nthreads: Value 99999 not in range 0 to 4096' -- plain.pbrt --nthreads 99999 -o out.exr

# NaN in every pixel with exit 0: the filter's parameters are refused instead.
printf 'Include "base.inc"\nPixelFilter "mitchell" "float B" [1e38] "float C" [-1e38]\n%s\nShape "sphere"\nWorldEnd\n' "$world" > mitchell.pbrt
expect mitchell-overflow 1 'mitchell.pbrt:2:1: error: mitchell filter: .*integral' -- mitchell.pbrt -o out.exr

# Output after failure: a second frame's error, found by the parser or only when the frame is
# built, leaves no image of the first frame; output paths are checked before rendering; an output
# never overwrites a file the scene reads.
printf 'Include "base.inc"\n%s\nShape "sphere"\nWorldEnd\nWorldBegin\nShape "sphere" "float radius" ["x"]\nWorldEnd\n' "$world" > two-frames.pbrt
expect second-frame-syntax 1 'two-frames.pbrt:7:32: error' -- two-frames.pbrt -o out.exr
printf 'Include "base.inc"\n%s\nShape "sphere"\nWorldEnd\nWorldBegin\nTexture "t" "spectrum" "imagemap" "string filename" "missing.png"\nMaterial "matte" "texture Kd" "t"\nShape "sphere"\nWorldEnd\n' "$world" > two-frames-build.pbrt
expect second-frame-build 1 'missing.png' -- two-frames-build.pbrt -o out.exr
expect preview-directory 1 '/nonexistent/p.png: .*does not exist' -- plain.pbrt -o out.exr --preview /nonexistent/p.png
# A PNG texture: candela's own preview of the plain scene.
"$candela" plain.pbrt -o t.exr --preview tex.png -q && rm -f t.exr
printf 'Include "base.inc"\n%s\nTexture "t" "spectrum" "imagemap" "string filename" "tex.png"\nMaterial "matte" "texture Kd" "t"\nShape "sphere"\nWorldEnd\n' "$world" > textured.pbrt
before=$(md5sum tex.png)
expect output-is-texture 1 "tex.png: error: refusing to overwrite 'tex.png'" -- textured.pbrt -o tex.exr
[ "$(md5sum tex.png)" = "$before" ] || { echo "FAIL output-is-texture: tex.png changed"; fail=1; }

[ $fail -eq 0 ] && echo "extreme inputs: ok"
exit $fail
