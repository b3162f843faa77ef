#!/usr/bin/env bash
# Writes the example scenes again with each integrator (and with a material-less sphere that
# paths pass through), so that compare_builds.py can hold a restructuring to the same bits for
# every integrator, not only the ones the example scenes name:
#   benchmarks/integrator_variants.sh DIR
#   benchmarks/compare_builds.py OLD NEW --scene-dir DIR --spp 4 --runs 1
set -euo pipefail
out=${1:?usage: integrator_variants.sh DIR}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
box=$root/scenes/cornell-box/cornell-box.pbrt
mkdir -p "$out"
integrators=(
  'bdpt|Integrator "bdpt" "integer maxdepth" [5]'
  'bidirectional|SurfaceIntegrator "bidirectional"'
  'sppm|Integrator "sppm" "integer numiterations" [4] "float radius" [5]'
  'mlt|Integrator "mlt" "integer mutationsperpixel" [4]'
  'metropolis|SurfaceIntegrator "path"\nRenderer "metropolis" "integer samplesperpixel" [4]'
  'irradiancecache|SurfaceIntegrator "irradiancecache"'
  'igi|SurfaceIntegrator "igi"'
  'photonmap|SurfaceIntegrator "photonmap" "integer causticphotons" [2000] "integer indirectphotons" [2000]'
  'whitted|SurfaceIntegrator "whitted"'
  'ao|Integrator "ao"'
  'directlighting|SurfaceIntegrator "directlighting"'
  'dipolesubsurface|SurfaceIntegrator "dipolesubsurface"'
  'path-v3|Integrator "path" "integer maxdepth" [5]'
  'volpath|Integrator "volpath" "integer maxdepth" [5]'
)
sphere='AttributeBegin\nMaterial "none"\nTranslate 278 200 250\nShape "sphere" "float radius" [120]\nAttributeEnd'
for entry in "${integrators[@]}"; do
  name=${entry%%|*} statement=${entry#*|}
  sed "s|^SurfaceIntegrator .*|$statement|" "$box" > "$out/box-$name.pbrt"
  sed "s|^SurfaceIntegrator .*|$statement|; s|^WorldBegin|WorldBegin\n$sphere|" "$box" \
    > "$out/box-interface-$name.pbrt"
done
# pbrt-v2 Volume regions under integrators that take them three ways.
for entry in 'volpath|Integrator "volpath"' 'path|SurfaceIntegrator "path"' \
  'photonmap|SurfaceIntegrator "photonmap"'; do
  name=${entry%%|*} statement=${entry#*|}
  sed "s|^SurfaceIntegrator .*|$statement|" "$root/scenes/fog/fog.pbrt" > "$out/fog-$name.pbrt"
done
sed 's|^SurfaceIntegrator .*|Integrator "bdpt"|' "$root/scenes/caustic/caustic.pbrt" \
  > "$out/caustic-bdpt.pbrt"
echo "integrator_variants: $(ls "$out" | wc -l) scenes in $out"
