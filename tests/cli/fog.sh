#!/usr/bin/env bash
# A pbrt-v2 scene with a Volume region and VolumeIntegrator "single" renders end to end; the
# statistics count one volume region, and the fog makes the image differ from the same scene
# without its Volume statement.
set -euo pipefail
candela=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
"$candela" "$src/scenes/fog/fog.pbrt" --quick --stats --outfile "$work/fog.exr" 2> "$work/log.txt"
cat "$work/log.txt"
test -s "$work/fog.exr" || { echo "FAIL: no EXR"; exit 1; }
grep -Eq "volume regions +1" "$work/log.txt" || { echo "FAIL: volume region not counted"; exit 1; }
grep -Eq "warning" "$work/log.txt" && { echo "FAIL: warnings"; exit 1; }
grep -v '^Volume\|^    "float g"' "$src/scenes/fog/fog.pbrt" > "$work/clear.pbrt"
"$candela" "$work/clear.pbrt" --quick --stats --outfile "$work/clear.exr" 2> "$work/log2.txt"
grep -Eq "volume regions +0" "$work/log2.txt" || { echo "FAIL: a volume without Volume"; exit 1; }
cmp -s "$work/fog.exr" "$work/clear.exr" && { echo "FAIL: the fog changed nothing"; exit 1; }
echo "fog: ok"
