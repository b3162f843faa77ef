#!/usr/bin/env bash
# The sanitizer stages of CI, each in its own build directory, built with Debian's clang 14:
#   tools/ci-sanitizers.sh address   AddressSanitizer + UndefinedBehaviorSanitizer (and LeakSanitizer)
#                                    in build-asan/: the unit, robustness and cli tests, then the
#                                    fuzz targets (labelled fuzz) when CANDELA_BUILD_FUZZERS exists
#   tools/ci-sanitizers.sh thread    ThreadSanitizer in build-tsan/: the determinism tests (renders
#                                    compared across thread counts), the only ones that race threads
# Run after `tools/setup.sh test`, which installs the packages (clang, its sanitizer runtimes and
# llvm-14's llvm-symbolizer are in third_party_config/apt-packages-extras.txt). BUILD_DIR and JOBS as for
# setup.sh. Any finding stops the test that hit it with a report and fails the stage.
set -euo pipefail

mode=${1:-}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
jobs=${JOBS:-$(nproc)}
cxx=clang++
symbolizer=/usr/lib/llvm-14/bin/llvm-symbolizer
supp=$root/tools/sanitizers

say() { echo "sanitizers: $*" >&2; }

# -O1 without debug information for speed, and with assertions. The thread stage adds line tables:
# its suppressions match the innermost frame, which must be the inlined function, not its caller.
case "$mode" in
  address) build=${BUILD_DIR:-$root/build-asan} sanitize=address,undefined flags="-O1" ;;
  thread) build=${BUILD_DIR:-$root/build-tsan} sanitize=thread flags="-O1 -gline-tables-only" ;;
  *) echo "usage: tools/ci-sanitizers.sh address|thread" >&2; exit 2 ;;
esac
command -v $cxx >/dev/null && [ -x $symbolizer ] || {
  say "needs $cxx and $symbolizer: run tools/setup.sh test first (it installs them)"
  exit 1
}

# Tests take longer under a sanitizer; their ctest time limits are scaled, never dropped.
timeout_scale=4
# The tests that render (or sum) with 1 and 2 threads and compare the bits, most named so, and the
# unit tests that query or fill one structure from several threads.
determinism='Determinism|Deterministic|SameBits|ThreadCount|OneAndTwoThreads|FromTwoThreads'
determinism+='|MediaScenes[.](InsideAGlassSphere|InObjectInstances|UnderMotionBlur)'
determinism+='|AdaptiveRendering|ParallelFor|Concurrent|FlushToZero'
# The fuzz targets join the address stage only: their coverage counters are plain global writes
# from every thread, which ThreadSanitizer would report.
fuzz=()
if grep -q CANDELA_BUILD_FUZZERS "$root/CMakeLists.txt"; then
  [ "$mode" = address ] && fuzz=(-DCANDELA_BUILD_FUZZERS=ON) || fuzz=(-DCANDELA_BUILD_FUZZERS=OFF)
fi

say "configuring ($cxx, -fsanitize=$sanitize, $flags, assertions on) in $build"
mkdir -p "$build"
configure() {
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=$cxx \
    -DCMAKE_CXX_FLAGS_RELEASE="$flags" -DCANDELA_SANITIZE=$sanitize \
    -DCANDELA_TEST_TIMEOUT_SCALE=$timeout_scale "${fuzz[@]}" >"$build/configure.log" 2>&1 &&
    grep -qx "CANDELA_SANITIZE:STRING=$sanitize" "$build/CMakeCache.txt"
}
# A build directory configured for another compiler: CMake then drops its cache, and the values
# given with -D along with it, so the first pass only switches compilers.
if ! configure && ! configure; then
  cat "$build/configure.log" >&2
  say "CMake configure failed (above; log in $build/configure.log)"
  exit 1
fi

# What the tests of LABEL run that the build makes: the arguments of their commands that are
# outputs of this build (the fuzz targets, whatever their names).
built_by_label() {
  local p
  (cd "$build" && ctest -L "$1" --show-only=json-v1) | /usr/bin/python3 -c '
import json, os, sys
build = os.path.realpath(sys.argv[1])
for t in json.load(sys.stdin).get("tests", []):
    for arg in t.get("command", []):
        path = os.path.realpath(arg)
        if path.startswith(build + os.sep):
            print(os.path.relpath(path, build))' "$build" | sort -u |
    while read -r p; do ninja -C "$build" -t query "$p" >/dev/null 2>&1 && echo "$p"; done
}

run_ctest() {
  local what=$1
  shift
  say "running $what under -fsanitize=$sanitize"
  (cd "$build" && ctest --output-on-failure -j "$jobs" --timeout $((1500 * timeout_scale)) "$@")
}

# A finding stops the process with a symbolized stack. LeakSanitizer checks every test process
# and every run of candela at exit (no leak needed a suppression). ThreadSanitizer's suppressions
# cover Debian's uninstrumented oneTBB and Embree only; tools/sanitizers/tsan.supp says why.
export ASAN_SYMBOLIZER_PATH=$symbolizer TSAN_SYMBOLIZER_PATH=$symbolizer
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:external_symbolizer_path=$symbolizer
export ASAN_OPTIONS=halt_on_error=1:detect_leaks=1:detect_stack_use_after_return=1:strict_string_checks=1:check_initialization_order=1:abort_on_error=0
export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:suppressions=$supp/tsan.supp:print_suppressions=0

case "$mode" in
  address)
    say "building candela, the unit and robustness tests with $jobs jobs"
    cmake --build "$build" -j "$jobs" --target candela candela_unit_tests candela_robustness_tests
    run_ctest "the unit, robustness and cli tests" -L 'unit|robustness|cli'
    mapfile -t fuzzers < <(built_by_label fuzz)
    if [ ${#fuzzers[@]} -gt 0 ]; then
      say "building the fuzz targets: ${fuzzers[*]}"
      cmake --build "$build" -j "$jobs" --target "${fuzzers[@]}"
      run_ctest "the fuzz targets" -L fuzz
    else
      say "no tests labelled fuzz in this tree"
    fi
    ;;
  thread)
    say "building the robustness and unit tests with $jobs jobs"
    cmake --build "$build" -j "$jobs" --target candela_robustness_tests candela_unit_tests
    run_ctest "the determinism tests" -L 'unit|robustness' -R "$determinism"
    ;;
esac
say "$mode: ok"
