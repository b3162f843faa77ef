#!/usr/bin/env bash
# --reference/--error-log write one CSV row per doubling pass; --target-error and --time-budget stop
# the render and say why in the EXR header.
set -euo pipefail
candela=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
scene=$src/scenes/cornell-box/cornell-box.pbrt
"$candela" "$scene" --quick --spp 16 --seed 9 -o ref.exr --preview none -q
"$candela" "$scene" --quick --spp 8 -o run.exr --reference ref.exr --error-log log.csv \
  --preview none -q
head -1 log.csv | grep -qx 'seconds,spp,rays,mse,relmse,rmse,maxerr,relmse_ci95,relmse_predicted,samples' ||
  { echo "FAIL: header"; cat log.csv; exit 1; }
[ "$(tail -n +2 log.csv | cut -d, -f2 | tr '\n' ' ')" = "1 2 4 8 " ] ||
  { echo "FAIL: passes"; cat log.csv; exit 1; }
# A second run appends rows without a second header.
"$candela" "$scene" --quick --spp 2 -o run.exr --reference ref.exr --error-log log.csv \
  --preview none -q
[ "$(grep -c '^seconds' log.csv)" = 1 ] && [ "$(wc -l < log.csv)" = 7 ] ||
  { echo "FAIL: append"; cat log.csv; exit 1; }
# Without a reference the target is checked against the variance estimate.
"$candela" "$scene" --quick --spp 1024 --target-error 0.05 -o t.exr --preview none 2> t.txt
grep -q "estimated from variance" t.txt || { echo "FAIL: no estimate"; cat t.txt; exit 1; }
grep -a -q "target error" t.exr || { echo "FAIL: stop reason not in EXR"; exit 1; }
grep -a -q "candela:targetError" t.exr || { echo "FAIL: target not in EXR"; exit 1; }
# SPPM (a whole-image integrator) logs after 1, 2, 4 iterations and the last; --spp sets the iterations,
# --stats reports them, and the error against a 64-iteration render of another seed falls.
sed 's/^SurfaceIntegrator .*/SurfaceIntegrator "sppm" "float radius" [8]/' "$scene" > sppm.pbrt
"$candela" sppm.pbrt --quick --spp 64 --seed 9 -o sppm-ref.exr --preview none -q
"$candela" sppm.pbrt --quick --spp 5 -o sppm.exr --reference sppm-ref.exr --error-log sppm.csv \
  --stats --preview none -q > sppm-stats.txt 2>&1
[ "$(tail -n +2 sppm.csv | cut -d, -f2 | tr '\n' ' ')" = "1 2 4 5 " ] ||
  { echo "FAIL: sppm passes"; cat sppm.csv; exit 1; }
awk -F, 'NR == 2 { first = $5 } END { exit !($5 < first) }' sppm.csv ||
  { echo "FAIL: sppm error did not fall"; cat sppm.csv; exit 1; }
grep -q "sppm iterations  5" sppm-stats.txt || { echo "FAIL: sppm stats"; cat sppm-stats.txt; exit 1; }
# Renderers and integrators whose pixels do not hold all their light refuse a target error
# that only the variance could check, before rendering, rather than never meeting it.
for integrator in 'SurfaceIntegrator "sppm"' 'Integrator "bdpt"'; do
  sed "s/^SurfaceIntegrator .*/$integrator/" "$scene" > nov.pbrt
  if "$candela" nov.pbrt --quick --spp 4 --target-error 0.05 -o nov.exr --preview none \
      2> nov.txt; then
    echo "FAIL: $integrator accepted --target-error without --reference"; exit 1
  fi
  grep -q "give --reference" nov.txt || { echo "FAIL: $integrator message"; cat nov.txt; exit 1; }
  [ ! -e nov.exr ] || { echo "FAIL: $integrator wrote an image"; exit 1; }
done
# Adaptive sampling: --noise-threshold stops converged pixels early, says so in the EXR, logs the
# samples it took (fewer than spp x pixels), and refuses what it cannot judge.
"$candela" "$scene" --quick --spp 256 --noise-threshold 0.2 --reference ref.exr \
  --error-log adaptive.csv -o a.exr --preview none -q
grep -a -q "candela:noiseThreshold" a.exr || { echo "FAIL: threshold not in EXR"; exit 1; }
awk -F, 'END { exit !($2 == 256 && $10 < 256 * 64 * 64) }' adaptive.csv ||
  { echo "FAIL: adaptive samples"; cat adaptive.csv; exit 1; }
"$candela" "$scene" --quick --spp 4096 --noise-threshold 100 -o h.exr --preview none -q
grep -a -q "noise threshold" h.exr || { echo "FAIL: stop reason noise threshold"; exit 1; }
if "$candela" "$scene" --quick --adaptive-min-samples 8 -o x.exr --preview none -q 2> x.txt; then
  echo "FAIL: --adaptive-min-samples without --noise-threshold"; exit 1
fi
sed 's/^SurfaceIntegrator .*/Integrator "bdpt"/' "$scene" > bd.pbrt
if "$candela" bd.pbrt --quick --spp 4 --noise-threshold 0.1 -o bd.exr --preview none 2> bd.txt; then
  echo "FAIL: bdpt accepted --noise-threshold"; exit 1
fi
grep -q "its own samples" bd.txt || { echo "FAIL: bdpt message"; cat bd.txt; exit 1; }
[ ! -e bd.exr ] || { echo "FAIL: bdpt wrote an image"; exit 1; }
echo "error log: ok"
