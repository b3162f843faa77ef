#!/usr/bin/env bash
# tools/robustness-report on a small subset: two recorded cases and two scenes at 32 x 32 write a
# Markdown table with their criteria and figures, the renders and a contact sheet PNG; an
# unknown scene is a usage error.
set -uo pipefail
candela=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
build=$(dirname "$candela")
fail=0
is_png() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ]; }

"$src/tools/robustness-report" --build "$build" --out "$work/report" --size 32 \
  --filter 'ExtremeTriangles.Degenerate*:StiffFurnace.AThousand*' \
  --scenes furnace-sphere,huge-plane >out.txt 2>&1
code=$?
[ $code -eq 0 ] || { cat out.txt; echo "FAIL: exit $code"; fail=1; }
table=report/robustness.md
[ -s "$table" ] || { echo "FAIL: no $table"; fail=1; }
# Two rows, both passing, each with a criterion and a measured figure.
rows=$(grep -c '^| [A-Za-z0-9]*\.[A-Za-z0-9]* |' "$table")
[ "$rows" = 2 ] || { cat "$table"; echo "FAIL: $rows rows, wanted 2"; fail=1; }
grep -q '^| StiffFurnace.AThousandBouncesOfAlbedo0999AreExactToRounding | furnace sphere, Kd 0.999.* | worst pixel .* of 632.67 | yes |$' "$table" ||
  { cat "$table"; echo "FAIL: the furnace row"; fail=1; }
grep -q '^| ExtremeTriangles.DegenerateTransformationsAreErrorsAtTheirStatement | .* | 4 of 4 located | yes |$' "$table" ||
  { cat "$table"; echo "FAIL: the degenerate transformations row"; fail=1; }
for f in report/renders/furnace-sphere.exr report/renders/huge-plane.png report/contact-sheet.png; do
  [ -s "$f" ] || { echo "FAIL: no $f"; fail=1; }
done
is_png report/contact-sheet.png || { echo "FAIL: contact-sheet.png is not a PNG"; fail=1; }
# The sheet holds two 32-pixel renders: more than a blank page, less than a poster.
size=$(stat -c %s report/contact-sheet.png 2>/dev/null || echo 0)
[ "$size" -gt 5000 ] && [ "$size" -lt 2000000 ] || { echo "FAIL: contact sheet of $size bytes"; fail=1; }

"$src/tools/robustness-report" --build "$build" --out "$work/bad" --scenes nonesuch >bad.txt 2>&1
code=$?
[ $code -eq 2 ] && grep -q "unknown scene(s) nonesuch" bad.txt ||
  { cat bad.txt; echo "FAIL: unknown scene gave exit $code"; fail=1; }

[ $fail -eq 0 ] && echo "robustness report: ok"
exit $fail
