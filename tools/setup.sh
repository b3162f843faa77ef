#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a built candela, then one of:
#   tools/setup.sh render   build and render the default scene (scenes/cornell-box) to EXR + PNG
#   tools/setup.sh test     build and run the whole test suite (what .ci/run calls first; then
#                           tools/ci-sanitizers.sh, with the clang 14 this installs)
#   tools/setup.sh build    only install what is missing and build
#   tools/setup.sh extras   also install the tools' packages (plots, convergence benchmark) and
#                           build the benchmarks
# Installs the missing Debian packages of third_party_config/apt-packages.txt (and, for test and
# extras, apt-packages-extras.txt) with apt-get, without recommends, through sudo when not root.
# BUILD_DIR (default build/), JOBS (default: all cores) and OUT_DIR (render; default out/) can be
# set; CANDELA_SKIP_INSTALL=1 skips the package step (other distributions: install by hand).
set -euo pipefail

mode=${1:-render}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
jobs=${JOBS:-$(nproc)}
config=$root/third_party_config

say() { echo "setup: $*" >&2; }

case "$mode" in
  render|build) lists=("$config/apt-packages.txt") ;;
  test|extras) lists=("$config/apt-packages.txt" "$config/apt-packages-extras.txt") ;;
  *) echo "usage: tools/setup.sh [render|test|build|extras]" >&2; exit 2 ;;
esac

# The package names of the lists: comments (whole-line or trailing) and blank lines dropped.
listed_packages() { sed 's/#.*//' "$@" | tr -s ' \t' '\n\n' | grep -v '^$' || true; }

install_missing() {
  local wanted missing=()
  wanted=$(listed_packages "${lists[@]}")
  if [ "${CANDELA_SKIP_INSTALL:-0}" = 1 ]; then
    say "CANDELA_SKIP_INSTALL=1: not installing packages"
    return 0
  fi
  if ! command -v apt-get >/dev/null || ! command -v dpkg-query >/dev/null; then
    say "this system has no apt-get: tools/setup.sh installs Debian 12 packages."
    say "Install the equivalents of these Debian packages with your system's package manager,"
    say "then run again with CANDELA_SKIP_INSTALL=1:"
    say "  $(echo $wanted)"
    say "(CMake >= 3.25, Ninja, a C++20 compiler, Embree 3.13, oneTBB 2021, OpenImageIO 2.4,"
    say " OpenEXR 3.1, Imath 3.1, OpenColorIO 2.1, OpenSubdiv 3.5, CLI11, fmt, GoogleTest;"
    say " Python 3 with matplotlib for the tools)"
    exit 1
  fi
  for p in $wanted; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    say "all $(echo "$wanted" | wc -w) listed Debian packages are installed"
    return 0
  fi
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || {
      say "installing packages needs root: run as root, or install sudo, or install by hand:"
      say "  apt-get install --no-install-recommends ${missing[*]}"
      exit 1
    }
    sudo=(sudo)
  fi
  say "installing ${#missing[@]} Debian packages and what they depend on (the first time about"
  say "  2-3 minutes): ${missing[*]}"
  "${sudo[@]}" apt-get update -qq
  # apt's per-package lines show progress without the download meter.
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends \
    -o Dpkg::Use-Pty=0 "${missing[@]}" |
    { grep -E '^(Setting up|Need to get|[0-9]+ upgraded)' || true; } | sed 's/^/setup:   /' >&2
  say "packages installed"
}

build_all() {
  local extra=()
  [ "$mode" = extras ] && extra=(-DCANDELA_BUILD_BENCHMARKS=ON)
  say "configuring (CMake, Ninja, Release) in $build"
  mkdir -p "$build"
  if ! cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release "${extra[@]}" \
      >"$build/setup-configure.log" 2>&1; then
    cat "$build/setup-configure.log" >&2
    say "CMake configure failed (above; log in $build/setup-configure.log)"
    exit 1
  fi
  # render needs only the command; the others build everything (tests, and benchmarks for extras).
  local target=()
  [ "$mode" = render ] && target=(--target candela)
  say "building with $jobs jobs (the first build takes a few minutes on 2 cores)"
  cmake --build "$build" -j "$jobs" "${target[@]}"
  say "built $build/candela"
}

install_missing
build_all
case "$mode" in
  build|extras) ;;
  render)
    out=${OUT_DIR:-$root/out}
    mkdir -p "$out"
    say "rendering scenes/cornell-box/cornell-box.pbrt"
    "$build/candela" "$root/scenes/cornell-box/cornell-box.pbrt" \
      --outfile "$out/cornell-box.exr" --preview "$out/cornell-box.png"
    say "wrote $out/cornell-box.exr and $out/cornell-box.png"
    ;;
  test)
    # Long runs carry the label "long" and are left out: `ctest -L long` in the build runs them.
    say "running the test suite (ctest -LE long)"
    cd "$build" && ctest --output-on-failure -j "$jobs" -LE long
    ;;
esac
