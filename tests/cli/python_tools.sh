#!/usr/bin/env bash
# The Python tools run with what the extras install list brings (python3, python3-matplotlib):
# the convergence benchmark at a tiny sample count on two scenes (references through
# tools/reference.sh, the table and the plots), the scene suite the same way, the accelerator
# scaling plot from a small CSV, and the footprint benchmark.
set -euo pipefail
candela=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
is_png() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ]; }

CANDELA=$candela CANDELA_CACHE=$work/cache /usr/bin/python3 "$src/benchmarks/convergence.py" \
  --out "$work/conv" --spp 4 --ref-spp 8 --scenes cornell-box,caustic \
  --methods path/stratified,path/random,directlighting/stratified,directlighting/random >conv.txt
for f in conv/convergence.csv conv/convergence.md conv/cornell-box.png conv/caustic.png; do
  test -s "$f" || { cat conv.txt; echo "FAIL: convergence.py wrote no $f"; exit 1; }
done
is_png conv/cornell-box.png || { echo "FAIL: cornell-box.png is not a PNG"; exit 1; }
[ "$(tail -n +2 conv/convergence.csv | wc -l)" = 8 ] ||
  { cat conv/convergence.csv; echo "FAIL: expected 8 rows (2 scenes x 4 methods)"; exit 1; }

# The scene suite at a tiny count: every configuration on two scenes (the caustic's reference by
# bdpt), the table, the plots; an unknown scene or configuration is refused by name.
CANDELA=$candela CANDELA_CACHE=$work/cache /usr/bin/python3 "$src/benchmarks/suite.py" \
  --out "$work/suite" --spp 4 --jobs 2 --blender none --scenes cornell-box,caustic \
  --configs uniform,adaptive,bvh,guided,bvh+adaptive,guided+adaptive,guided+bvh >suite.txt
for f in suite/suite.csv suite/suite.md suite/cornell-box.png suite/caustic.png; do
  test -s "$f" || { cat suite.txt; echo "FAIL: suite.py wrote no $f"; exit 1; }
done
[ "$(tail -n +2 suite/suite.csv | wc -l)" = 14 ] ||
  { cat suite/suite.csv; echo "FAIL: expected 14 rows (2 scenes x 7 configurations)"; exit 1; }
# Every row measured: a positive CPU time and relMSE, the count asked for.
awk -F, 'NR > 1 && !($NF > 0 && $(NF-2) > 0 && $(NF-4) == 4) { bad = 1; print } END { exit bad }' \
  suite/suite.csv || { echo "FAIL: a suite row without its measures"; exit 1; }
if /usr/bin/python3 "$src/benchmarks/suite.py" --scenes nowhere --out "$work/x" 2>err.txt; then
  echo "FAIL: suite.py accepted an unknown scene"; exit 1
fi
grep -q "unknown scene nowhere" err.txt || { cat err.txt; echo "FAIL: no word on the scene"; exit 1; }

cat >scaling.csv <<'CSV'
aggregate,triangles,build_cpu_s,camera_ns_per_ray,bounce_ns_per_ray
bvh,1000,0.001,300,400
bvh,10000,0.01,500,700
embree,1000,0.002,200,250
embree,10000,0.02,300,350
CSV
/usr/bin/python3 "$src/tools/plot_accel_scaling.py" scaling.csv -o scaling.png
is_png scaling.png || { echo "FAIL: plot_accel_scaling.py wrote no PNG"; exit 1; }
# The footprint benchmark at toy sizes: every case runs and is reported; an EXR-only run loads
# fewer libraries than one writing a PNG preview (which loads the OpenImageIO plug-in).
/usr/bin/python3 "$src/benchmarks/footprint.py" --candela "$candela" --runs 1 --triangles 200 \
  --instances 3 --accel embree,grid --csv footprint.csv >footprint.txt
[ "$(tail -n +2 footprint.csv | wc -l)" = 8 ] ||
  { cat footprint.csv; echo "FAIL: expected 8 rows (2 empty, 2 accelerators x 3)"; exit 1; }
libs() { awk -F, -v c="$1" '$2 == c { print $NF }' footprint.csv; }
[ "$(libs empty)" -gt 0 ] && [ "$(libs empty)" -lt "$(libs empty+png)" ] ||
  { cat footprint.csv; echo "FAIL: the EXR-only run loaded as many libraries as the preview"; exit 1; }
echo "python tools: ok"
