#!/usr/bin/env bash
# `candela compare`: the relMSE of finished images as --error-log defines it, the references' own
# noise taken off with two of them, the outlier share, and clear errors for bad input.
set -euo pipefail
candela=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
scene=$src/scenes/cornell-box/cornell-box.pbrt
"$candela" "$scene" --quick --spp 32 --seed 7 -o refa.exr --preview none -q
"$candela" "$scene" --quick --spp 32 --seed 8 -o refb.exr --preview none -q
"$candela" "$scene" --quick --spp 4 -o run.exr --reference refa.exr --error-log log.csv \
  --preview none -q
field() { tr ' ' '\n' | sed -n "s/^$1=//p"; }
one=$("$candela" compare run.exr --reference refa.exr)
# Against one reference: the error log's last relMSE, to its printed digits.
logged=$(tail -1 log.csv | cut -d, -f5)
awk -v a="$(echo "$one" | field relmse)" -v b="$logged" \
  'BEGIN { exit !(a > 0 && (a - b) * (a - b) <= 1e-10 * b * b) }' ||
  { echo "FAIL: compare $one against the log's $logged"; exit 1; }
[ "$(echo "$one" | field reference_noise)" = 0 ] || { echo "FAIL: noise of one: $one"; exit 1; }
# An image against itself: no error.
self=$("$candela" compare refa.exr --reference refa.exr)
[ "$(echo "$self" | field relmse)" = 0 ] || { echo "FAIL: self $self"; exit 1; }
# Two references: noise > 0 and relmse = relmse_raw - reference_noise.
two=$("$candela" compare run.exr --reference refa.exr --reference refb.exr --worst 10)
awk -v r="$(echo "$two" | field relmse)" -v w="$(echo "$two" | field relmse_raw)" \
  -v n="$(echo "$two" | field reference_noise)" -v s="$(echo "$two" | field outlier_share)" \
  'BEGIN { exit !(n > 0 && r < w && (w - n - r) * (w - n - r) < 1e-12 && s > 0 && s < 1) }' ||
  { echo "FAIL: two references: $two"; exit 1; }
[ "$(echo "$two" | field worst)" = 10 ] || { echo "FAIL: worst: $two"; exit 1; }
# Bad input: a missing file names its path (exit 1), a size mismatch says so (exit 1), no
# reference is a usage error (exit 2).
set +e
"$candela" compare nothere.exr --reference refa.exr 2> missing.txt; code=$?
[ $code = 1 ] && grep -q "nothere.exr" missing.txt || { echo "FAIL: missing ($code)"; cat missing.txt; exit 1; }
"$candela" "$scene" --quick --spp 1 --cropwindow 0 0.5 0 0.5 -o crop.exr --preview none -q
"$candela" compare run.exr --reference crop.exr 2> size.txt; code=$?
[ $code = 1 ] && grep -q "run.exr" size.txt || { echo "FAIL: size ($code)"; cat size.txt; exit 1; }
"$candela" compare run.exr 2> usage.txt; code=$?
[ $code = 2 ] || { echo "FAIL: usage ($code)"; cat usage.txt; exit 1; }
set -e
echo "compare: ok"
