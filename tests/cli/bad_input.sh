#!/usr/bin/env bash
# Bad input gets a clear message with file:line:col, a non-zero exit, and no output file.
set -uo pipefail
candela=$1 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail=0
expect() {  # expect NAME EXIT_CODE PATTERN -- candela args...
  local name=$1 code=$2 pattern=$3; shift 4
  "$candela" "$@" > out.txt 2>&1
  local got=$?
  if [ "$got" -ne "$code" ]; then echo "FAIL $name: exit $got, wanted $code"; cat out.txt; fail=1; fi
  if ! grep -Eq -- "$pattern" out.txt; then echo "FAIL $name: no '$pattern' in:"; cat out.txt; fail=1; fi
  if ls out.exr out.png >/dev/null 2>&1; then echo "FAIL $name: output written"; fail=1; fi
  rm -f out.exr out.png
}
header='Film "image" "integer xresolution" [8] "integer yresolution" [8]
Sampler "random" "integer pixelsamples" [1]
WorldBegin'

printf '%s\nShape "sphere" "float radius" [1\nWorldEnd\n' "$header" > unclosed.pbrt
expect unclosed-bracket 1 'unclosed.pbrt:[0-9]+:[0-9]+' -- unclosed.pbrt -o out.exr

printf '%s\nShape "teapot"\nWorldEnd\n' "$header" > unknown.pbrt
expect unknown-shape 1 "unknown.pbrt:4:[0-9]+: .*unknown shape 'teapot' \\(known: .*sphere" -- unknown.pbrt -o out.exr

printf '%s\nShape "sphere" "float radius" ["big"]\nWorldEnd\n' "$header" > badvalue.pbrt
expect bad-value 1 'badvalue.pbrt:4:[0-9]+' -- badvalue.pbrt -o out.exr

# Sizes the machine cannot hold are refused up front, at the statement.
printf 'Film "image" "integer xresolution" [200000] "integer yresolution" [200000]\nWorldBegin\nShape "sphere"\nWorldEnd\n' > hugefilm.pbrt
expect huge-film 1 'hugefilm.pbrt:1:1: error: film: 40000000000 pixels to render' -- hugefilm.pbrt -o out.exr

printf 'WorldBegin\nAttributeEnd\nWorldEnd\n' > unmatched.pbrt
expect unmatched-end 1 'unmatched.pbrt:2:1' -- unmatched.pbrt -o out.exr

expect missing-file 1 'no-such-scene.pbrt' -- no-such-scene.pbrt -o out.exr
expect bad-flag 2 'nthreads|Invalid|Could not' -- --nthreads=-3 unknown.pbrt -o out.exr

printf '%s\nShape "sphere"\nWorldEnd\n' "$header" > good.pbrt
expect unwritable-output 1 'no-such-dir' -- good.pbrt -o no-such-dir/out.exr
expect bad-crop 2 'cropwindow' -- good.pbrt --cropwindow 0.5 0.2 0 1 -o out.exr

# A warning for an unused parameter, naming it and where it was written.
printf '%s\nShape "sphere" "float radius" [1] "float nonsense" [2]\nWorldEnd\n' "$header" > unused.pbrt
"$candela" unused.pbrt -o out.exr > out.txt 2>&1 || { echo "FAIL unused: exit $?"; cat out.txt; fail=1; }
grep -Eq 'unused.pbrt:4:[0-9]+: warning: .*nonsense' out.txt || { echo "FAIL unused warning"; cat out.txt; fail=1; }
rm -f out.exr out.png

[ $fail -eq 0 ] && echo "bad input: ok"
exit $fail
