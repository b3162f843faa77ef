#!/usr/bin/env bash
# Runs one libFuzzer executable for a bounded time on a copy of its seed corpus (the source tree
# is never written), for ctest -L fuzz.
#   run_fuzzer.sh FUZZER SEED_DIR ARTIFACT_DIR SECONDS INPUT_TIMEOUT [DICT]
# Fails (libFuzzer's non-zero exit) on a crash, a sanitizer report, a leak, an input slower than
# INPUT_TIMEOUT seconds or one that needs more than 2 GiB; the input that did it is kept in
# ARTIFACT_DIR and named in the output. The final stats (executions, exec/s, coverage) close it.
set -euo pipefail
fuzzer=$1 seeds=$2 artifacts=$3 seconds=$4 timeout=$5 dict=${6:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -R "$seeds/." "$work/"
mkdir -p "$artifacts"
# Undefined behaviour stops the run like a crash (a report alone would not fail the test).
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
args=(-max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=2048 -print_final_stats=1
      -artifact_prefix="$artifacts/")
[ -n "$dict" ] && args+=(-dict="$dict")
echo "fuzz: $(basename "$fuzzer") for ${seconds} s on $(ls "$work" | wc -l) seed inputs"
"$fuzzer" "${args[@]}" "$work"
