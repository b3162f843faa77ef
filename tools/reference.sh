#!/usr/bin/env bash
# Prints the path of a high-spp reference render of a scene, rendering it only when no cached copy
# exists. The cache key covers the scene file's bytes (and its Include'd files), the spp, the seed
# and the candela binary itself, so a change to any of them renders anew.
#   tools/reference.sh SCENE [SPP=4096] [SEED=1000] [candela options...]   (e.g. --quick)
# CANDELA (default build/candela) and CANDELA_CACHE (default ~/.cache/candela/references) can be set.
set -euo pipefail
scene=${1:?usage: tools/reference.sh SCENE [SPP] [SEED]}
spp=${2:-4096}
seed=${3:-1000}
shift $(( $# < 3 ? $# : 3 ))
extra=("$@")
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
candela=${CANDELA:-$root/build/candela}
cache=${CANDELA_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/candela/references}
[ -x "$candela" ] || { echo "reference.sh: no candela binary at $candela (build first)" >&2; exit 1; }
[ -f "$scene" ] || { echo "reference.sh: $scene: no such scene file" >&2; exit 1; }

# The scene and the files it includes, recursively (Include "path" relative to the includer).
files() {
  local f=$1 dir
  echo "$f"
  dir=$(dirname "$f")
  grep -oE '^\s*Include\s+"[^"]+"' "$f" 2>/dev/null | sed -E 's/.*"([^"]+)"/\1/' |
    while read -r inc; do files "$dir/$inc"; done
}
key=$( { files "$scene" | sort -u | xargs cat; echo "spp=$spp seed=$seed ${extra[*]:-}"; cat "$candela"; } |
       sha256sum | cut -c1-24)
out="$cache/$(basename "${scene%.*}")-$spp-$key.exr"
if [ ! -s "$out" ]; then
  mkdir -p "$cache"
  echo "reference.sh: rendering $scene at $spp spp into $out" >&2
  "$candela" "$scene" --spp "$spp" --seed "$seed" -o "$out" --preview none --quiet "${extra[@]}"
fi
echo "$out"
