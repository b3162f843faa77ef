#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a built candela, then one of:
#   tools/setup.sh render   build and render the default scene (scenes/cornell-box) to EXR + PNG
#   tools/setup.sh test     build and run the whole test suite (what .ci/run calls)
#   tools/setup.sh build    only install what is missing and build
# Installs missing Debian packages (third_party_config/apt-packages.txt) with apt-get, through sudo
# when not root. BUILD_DIR (default build/) and JOBS (default: all cores) can be set.
set -euo pipefail

mode=${1:-render}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
jobs=${JOBS:-$(nproc)}

install_missing() {
  local wanted missing=()
  wanted=$(grep -v '^\s*#' "$root/third_party_config/apt-packages.txt" | grep -v '^\s*$')
  for p in $wanted; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "setup: installing ${missing[*]}" >&2
  local sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
}

build_all() {
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" -j "$jobs"
}

install_missing
build_all
case "$mode" in
  build) ;;
  render)
    out=${OUT_DIR:-$root/out}
    mkdir -p "$out"
    "$build/candela" "$root/scenes/cornell-box/cornell-box.pbrt" \
      --outfile "$out/cornell-box.exr" --preview "$out/cornell-box.png"
    echo "setup: wrote $out/cornell-box.exr and $out/cornell-box.png" >&2
    ;;
  test)
    # Long runs carry the label "long" and are left to tools/run-long-tests.sh.
    cd "$build" && ctest --output-on-failure -j "$jobs" -LE long
    ;;
  *) echo "usage: tools/setup.sh [render|test|build]" >&2; exit 2 ;;
esac
