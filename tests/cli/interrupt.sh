#!/usr/bin/env bash
# SIGINT and SIGTERM during a render stop it (the time it took is printed, not asserted), leave
# no output, temporary or partial file, and exit 130 and 143.
set -uo pipefail
candela=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail=0
for sig in INT TERM; do
  want=$([ $sig = INT ] && echo 130 || echo 143)
  "$candela" "$src/scenes/cornell-box/cornell-box.pbrt" --spp 100000 -o out.exr -q 2> err.txt &
  pid=$!
  # Until candela has installed its handlers (SigCgt holds SIGINT, bit 1, and SIGTERM, bit 14;
  # loading its libraries can take seconds on a busy machine), then a little into the render.
  for _ in $(seq 300); do
    mask=$(awk '/^SigCgt:/ { print $2 }' /proc/$pid/status 2> /dev/null)
    [ -n "$mask" ] && (( (16#$mask & 16#4002) == 16#4002 )) && break
    sleep 0.1
  done
  sleep 0.5
  start=$(date +%s%N)
  kill -$sig $pid
  # Bounded: an interrupt that is never noticed fails here instead of hanging the suite.
  for _ in $(seq 300); do kill -0 $pid 2> /dev/null || break; sleep 0.1; done
  if kill -0 $pid 2> /dev/null; then
    echo "FAIL $sig: still running 30 s later"; kill -9 $pid; fail=1
  fi
  wait $pid
  rc=$?
  echo "SIG$sig: exit $rc after $(( ($(date +%s%N) - start) / 1000000 )) ms"
  [ $rc -eq $want ] || { echo "FAIL $sig: exit $rc, wanted $want"; cat err.txt; fail=1; }
  grep -q "interrupted by SIG$sig" err.txt || { echo "FAIL $sig: message"; cat err.txt; fail=1; }
  left=$(ls -A | grep -v '^err.txt$')
  [ -z "$left" ] || { echo "FAIL $sig: left $left"; fail=1; }
done
[ $fail -eq 0 ] && echo "interrupt: ok"
exit $fail
