#!/usr/bin/env bash
# `--sample-range A-B` pieces take samples A to B of every pixel and keep the pixels' sums; merged,
# they give the single render within the stated bound: each value within 1 ulp of 32-bit float
# (each piece's double sums are stored to 2^-48; the merge adds them in double and divides once, as
# the film does). Checked with a Mitchell filter (negative weights), the variance and samples AOVs,
# uneven splits, and tiles split by sample. The merged error log has a row per range, with the
# seconds and rays summed over the pieces so far.
set -euo pipefail
candela=$1 diff=$2 src=$3 work=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work"
sed -e 's/"integer xresolution" \[256\] "integer yresolution" \[256\]/"integer xresolution" [61] "integer yresolution" [47]/' \
  -e 's/^PixelFilter .*/PixelFilter "mitchell" "float xwidth" [2] "float ywidth" [2]/' \
  "$src/scenes/cornell-box/cornell-box.pbrt" > odd.pbrt
grep -q mitchell odd.pbrt || { echo "FAIL: could not make the scene"; exit 1; }
opts=(--spp 16 --seed 3 --aov variance,samples --preview none -q)
source "$(dirname "${BASH_SOURCE[0]}")/parallel.bash"
in_parallel "$candela" odd.pbrt "${opts[@]}" -o single.exr
in_parallel "$candela" odd.pbrt --spp 64 --seed 99 --preview none -q -o ref.exr

check_split() { # NAME RANGE... (each "A-B" or "A-B/tile I/N")
  local name=$1 pieces=() i=0
  shift
  for spec in "$@"; do
    local range=${spec%%/*} tile=()
    [ "$spec" = "$range" ] || tile=(--tile "${spec#*/}")
    in_parallel "$candela" odd.pbrt "${opts[@]}" --sample-range "$range" "${tile[@]}" \
      -o "$name-$i.exr"
    pieces+=("$name-$i.exr")
    i=$((i + 1))
  done
  wait_all
  "$candela" merge -q -o "$name.exr" "${pieces[@]}"
  echo -n "$name: "
  "$diff" single.exr "$name.exr" --max-ulps 1 ||
    { echo "FAIL: $name is not the single render within 1 ulp"; exit 1; }
}
check_split halves 0-4 5-15
check_split uneven 10-15 0-0 1-9
check_split tiles 0-7/0/2 8-15/0/2 0-7/1/2 8-15/1/2
[ "$("$diff" --get halves-1.exr candela:sampleRange)" = 5-15 ] || { echo "FAIL: range"; exit 1; }

# The error log: a row after each range, against a reference or the pixels' own variance.
"$candela" merge -q -o logged.exr --error-log log.csv --reference ref.exr uneven-0.exr uneven-1.exr \
  uneven-2.exr
"$candela" merge -q -o estimated.exr --error-log estimated.csv halves-0.exr halves-1.exr
cat log.csv
[ "$(tail -n +2 log.csv | cut -d, -f2 | tr '\n' ' ')" = "1 10 16 " ] ||
  { echo "FAIL: log rows"; exit 1; }
[ "$(tail -n +2 estimated.csv | cut -d, -f2 | tr '\n' ' ')" = "5 16 " ] ||
  { echo "FAIL: estimated log rows"; cat estimated.csv; exit 1; }
seconds=0 rays=0
for p in uneven-1 uneven-2 uneven-0; do # in the order of their ranges: 0-0, 1-9, 10-15
  seconds=$(awk -v a="$seconds" -v b="$("$diff" --get $p.exr candela:renderSeconds)" \
    'BEGIN { printf "%.9g", a + b }')
  rays=$((rays + $("$diff" --get $p.exr candela:rays)))
done
awk -F, -v s="$seconds" -v r="$rays" 'END { exit !(($1 - s) ^ 2 < (1e-5 * s) ^ 2 && $3 == r) }' \
  log.csv || { echo "FAIL: the last row is not $seconds s, $rays rays"; exit 1; }
awk -F, 'NR > 1 && !($5 > 0) { exit 1 }' log.csv || { echo "FAIL: relmse"; exit 1; }

# What a sample range cannot reproduce is refused before rendering.
refused() { # WHAT GREP candela-args...
  local what=$1 pattern=$2
  shift 2
  if "$candela" "$@" --preview none -q -o refused.exr 2> refused.txt; then
    echo "FAIL: $what accepted"; exit 1
  fi
  grep -q -- "$pattern" refused.txt || { echo "FAIL: $what: message"; cat refused.txt; exit 1; }
  [ ! -e refused.exr ] || { echo "FAIL: $what wrote an image"; exit 1; }
}
refused "a range past spp" "takes 16 samples per pixel" odd.pbrt --spp 16 --sample-range 8-16
sed 's/^SurfaceIntegrator .*/Integrator "bdpt"/' odd.pbrt > bdpt.pbrt
refused "a splatting integrator" "adds light to other pixels" bdpt.pbrt --spp 4 --sample-range 0-1
sed 's/^Sampler .*/Sampler "adaptive"/' odd.pbrt > adaptive.pbrt
refused "the adaptive sampler" "adaptive sampler" adaptive.pbrt --sample-range 0-1
refused "first-hit AOVs" "albedo" odd.pbrt --spp 4 --aov albedo --sample-range 0-1
refused "a stop condition" "cannot be combined" odd.pbrt --spp 4 --time-budget 1 --sample-range 0-1
echo "samples: ok"
