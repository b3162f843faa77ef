#!/usr/bin/env bash
# --light-sampler overrides the integrator's lightsamplestrategy: each strategy renders, the same
# bits on one thread and two, bvh gives the same image as the scene asking for it by name; an
# unknown name is a usage error that writes nothing; an integrator that chooses no lights by a
# strategy says it ignores the option.
set -euo pipefail
candela=$1 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
scene() {  # $1: extra integrator parameters, $2: integrator
  cat <<S
Film "image" "integer xresolution" [24] "integer yresolution" [16]
Sampler "random" "integer pixelsamples" [4]
LookAt 0 4 6  0 0 0  0 1 0
Camera "perspective" "float fov" [50]
Integrator "${2:-path}" "integer maxdepth" [2] $1
WorldBegin
LightSource "point" "point from" [2 2 0] "rgb I" [3 3 3]
LightSource "spot" "point from" [-2 3 0] "point to" [-2 0 0] "float coneangle" [30] "rgb I" [9 9 9]
AttributeBegin
AreaLightSource "diffuse" "rgb L" [4 4 4]
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point P" [-1 2 -1  -1 2 1  1 2 1  1 2 -1]
AttributeEnd
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point P" [-5 0 -5  5 0 -5  5 0 5  -5 0 5]
WorldEnd
S
}
scene "" > flag.pbrt
scene '"string lightsamplestrategy" "bvh"' > named.pbrt
for s in uniform power spatial bvh; do
  "$candela" -q flag.pbrt --light-sampler "$s" -o "$s.exr" --preview none --nthreads 1
  "$candela" -q flag.pbrt --light-sampler "$s" -o "$s-2.exr" --preview none --nthreads 2 --tile-size 4
  "$candela" compare "$s-2.exr" --reference "$s.exr" | grep -q " mse=0 " ||
    { echo "FAIL: --light-sampler $s differs between thread counts"; exit 1; }
done
"$candela" -q named.pbrt -o named.exr --preview none --nthreads 1
"$candela" compare named.exr --reference bvh.exr | grep -q " mse=0 " ||
  { echo "FAIL: --light-sampler bvh is not the scene's lightsamplestrategy \"bvh\""; exit 1; }
"$candela" compare power.exr --reference bvh.exr | grep -q " mse=0 " &&
  { echo "FAIL: bvh renders the same as power"; exit 1; }
status=0
"$candela" -q flag.pbrt --light-sampler tree -o bad.exr 2> bad.err || status=$?
test "$status" -eq 2 || { echo "FAIL: --light-sampler tree exited $status, not 2"; exit 1; }
grep -q "light-sampler" bad.err || { echo "FAIL: the error does not name the option"; cat bad.err; exit 1; }
test ! -e bad.exr || { echo "FAIL: an image was written"; exit 1; }
scene "" whitted > whitted.pbrt
"$candela" whitted.pbrt --light-sampler bvh -o whitted.exr --preview none 2> whitted.err
grep -q "whitted.pbrt:5:1: warning: --light-sampler is ignored: integrator 'whitted'" whitted.err ||
  { echo "FAIL: no located warning for an integrator without a light strategy"; cat whitted.err; exit 1; }
echo "light_sampler: ok"
