#!/usr/bin/env bash
# What rendering through Slurm costs on this machine: the Cornell box (scenes/cornell-box, its own
# 64 spp) as 1, 2, 4 and 8 tiles through tools/candela-submit on a private one-node Slurm
# (tools/farm/local-slurm.sh; needs root and Debian's munge, slurmctld, slurmd, slurm-client),
# against one candela process on every core. Each task gets max(1, cores / tiles) CPUs, so the
# machine is always full. Prints a Markdown table (medians of REPEATS runs) and checks that every
# merged image is the single render's, bit for bit.
#   benchmarks/farm_tiles.sh [BUILD_DIR (default build)] [REPEATS (default 3)]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
repeats=${2:-3}
candela=$build/candela
diff=$build/tests/farm/candela_image_diff
scene=$root/scenes/cornell-box/cornell-box.pbrt
[ -x "$candela" ] && [ -x "$diff" ] || { echo "farm_tiles: build candela and the tests first" >&2; exit 2; }
work=$(mktemp -d /tmp/candela-farm-bench.XXXXXX)
source "$root/tools/farm/local-slurm.sh"
trap 'local_slurm_down "$work/slurm"; rm -rf "$work"' EXIT
local_slurm_up "$work/slurm" || { echo "farm_tiles: $LOCAL_SLURM_WHY" >&2; exit 1; }
cores=$(nproc)
now() { date +%s.%N; }
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# Rounds of every configuration in turn, so that a change in the machine's load reaches them alike.
declare -A wall render
render_single() {
  local t0
  t0=$(now)
  "$candela" "$scene" -o "$work/single.exr" --preview none -q
  wall[single]+="$(awk -v a="$t0" -v b="$(now)" 'BEGIN { print b - a }') "
  render[single]+="$("$diff" --get "$work/single.exr" candela:renderSeconds) "
}
render_farm() { # TILES ROUND
  local tiles=$1 out=$work/farm-$1-$2.exr t0 merge
  local cpus=$((cores / tiles > 0 ? cores / tiles : 1))
  t0=$(now)
  bash "$root/tools/candela-submit" -o "$out" --tiles "$tiles" --cpus-per-task "$cpus" \
    --candela "$candela" "$scene" > "$work/submit.txt"
  merge=$(awk '/^merge job/ { sub(":", "", $3); print $3 }' "$work/submit.txt")
  for _ in $(seq 3000); do [ -e "$out" ] && break; sleep 0.1; done
  [ -e "$out" ] || { echo "farm_tiles: no image after 300 s (job $merge)" >&2; exit 1; }
  wall[$tiles]+="$(awk -v a="$t0" -v b="$(now)" 'BEGIN { print b - a }') "
  render[$tiles]+="$("$diff" --get "$out" candela:renderSeconds) "
  "$diff" "$work/single.exr" "$out" > /dev/null || { echo "farm_tiles: $out differs" >&2; exit 1; }
  for _ in $(seq 100); do [ -z "$(squeue -h)" ] && break; sleep 0.1; done
}
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
for r in $(seq "$repeats"); do
  render_single
  for tiles in 1 2 4 8; do render_farm "$tiles" "$r"; done
done
of() { tr ' ' '\n' <<< "$1" | grep . | median; }
sw=$(of "${wall[single]}")
echo "| tiles | tasks at once x CPUs each | wall time, submit to merged image (s) | render time summed over the tasks (s) | wall / single process |"
echo "|---|---|---|---|---|"
for tiles in 1 2 4 8; do
  cpus=$((cores / tiles > 0 ? cores / tiles : 1))
  at_once=$((tiles < cores / cpus ? tiles : cores / cpus))
  w=$(of "${wall[$tiles]}")
  printf '| %d | %d x %d | %.2f | %.2f | %.2f |\n' "$tiles" "$at_once" "$cpus" "$w" \
    "$(of "${render[$tiles]}")" "$(awk -v a="$w" -v b="$sw" 'BEGIN { print a / b }')"
done
printf '| single process | 1 x %d | %.2f | %.2f | 1 |\n' "$cores" "$sw" "$(of "${render[single]}")"
echo
echo "$repeats rounds; load average (1, 5, 15 min) before: $load_before, after: $(cut -d' ' -f1-3 /proc/loadavg)"
