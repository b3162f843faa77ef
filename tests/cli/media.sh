#!/usr/bin/env bash
# pbrt-v3 media from the command line: "path" given a scene with a named medium renders but warns
# on standard error, at the MakeNamedMedium's file:line, that it ignores media; "volpath" renders
# the same scene without that warning; an unknown medium name is a located error.
set -uo pipefail
candela=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail=0
scene() {  # scene INTEGRATOR MEDIUM_NAME
  printf 'LookAt 0 0 -3  0 0 0  0 1 0\nCamera "perspective"\n'
  printf 'Film "image" "integer xresolution" [8] "integer yresolution" [8]\n'
  printf 'Sampler "random" "integer pixelsamples" [4]\n%s\nWorldBegin\n' "$1"
  printf 'LightSource "infinite"\n'
  printf 'MakeNamedMedium "fog" "string type" "homogeneous" "rgb sigma_s" [1 1 1]\n'  # line 8
  printf 'MediumInterface "%s" ""\n' "$2"                                             # line 9
  printf 'Material "none"\nShape "sphere"\nWorldEnd\n'
}
scene 'SurfaceIntegrator "path"' fog > path.pbrt
"$candela" path.pbrt -o path.exr > out.txt 2> err.txt
if [ $? -ne 0 ]; then echo "FAIL path: non-zero exit"; cat out.txt err.txt; fail=1; fi
if ! grep -Eq "path.pbrt:8:[0-9]+: .*integrator 'path' ignores participating media.*path.pbrt:9" err.txt; then
  echo "FAIL path: no located ignore-media warning on stderr:"; cat err.txt; fail=1
fi
if [ "$(grep -c 'ignores participating media' err.txt)" -ne 1 ]; then
  echo "FAIL path: the warning is not given exactly once"; cat err.txt; fail=1
fi
[ -f path.exr ] || { echo "FAIL path: no image"; fail=1; }

scene 'Integrator "volpath"' fog > volpath.pbrt
"$candela" volpath.pbrt -o volpath.exr > out.txt 2> err.txt
if [ $? -ne 0 ]; then echo "FAIL volpath: non-zero exit"; cat out.txt err.txt; fail=1; fi
if grep -q 'ignores participating media' err.txt; then echo "FAIL volpath warned:"; cat err.txt; fail=1; fi
[ -f volpath.exr ] || { echo "FAIL volpath: no image"; fail=1; }

scene 'Integrator "volpath"' nonesuch > unknown.pbrt
"$candela" unknown.pbrt -o unknown.exr > out.txt 2>&1
if [ $? -ne 1 ]; then echo "FAIL unknown medium: exit not 1"; cat out.txt; fail=1; fi
if ! grep -Eq "unknown.pbrt:9:[0-9]+: .*unknown medium 'nonesuch'" out.txt; then
  echo "FAIL unknown medium: message:"; cat out.txt; fail=1
fi
[ -f unknown.exr ] && { echo "FAIL unknown medium: output written"; fail=1; }

# The example smoke scene renders with volpath, without warnings, at its --quick settings.
"$candela" --quick "$src/scenes/smoke/smoke.pbrt" -o smoke.exr > out.txt 2> err.txt
if [ $? -ne 0 ]; then echo "FAIL smoke: non-zero exit"; cat out.txt err.txt; fail=1; fi
if grep -qi 'warning' err.txt; then echo "FAIL smoke warned:"; cat err.txt; fail=1; fi
exit $fail
