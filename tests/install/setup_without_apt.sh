#!/usr/bin/env bash
# tools/setup.sh on a system without apt-get: it says what to install instead (every listed
# package by name), exits 1 and builds nothing.
#   setup_without_apt.sh SOURCE_DIR WORK_DIR
set -euo pipefail
src=$1 work=$2
rm -rf "$work" && mkdir -p "$work/bin"
# A PATH with the shell tools the script uses but no apt-get or dpkg.
for c in bash sed tr grep dirname id nproc cat echo wc mkdir; do
  ln -s "$(command -v "$c")" "$work/bin/$c"
done
status=0
PATH=$work/bin BUILD_DIR=$work/build bash "$src/tools/setup.sh" build >"$work/out.txt" 2>&1 || status=$?
cat "$work/out.txt"
[ $status -eq 1 ] || { echo "FAIL: exit status $status, expected 1"; exit 1; }
grep -q "has no apt-get" "$work/out.txt" || { echo "FAIL: does not say apt-get is missing"; exit 1; }
for p in $(sed 's/#.*//' "$src/third_party_config/apt-packages.txt"); do
  grep -qw -- "$p" "$work/out.txt" || { echo "FAIL: does not name $p"; exit 1; }
done
grep -q "CANDELA_SKIP_INSTALL=1" "$work/out.txt" || { echo "FAIL: no way forward named"; exit 1; }
[ ! -e "$work/build" ] || { echo "FAIL: it configured or built anyway"; exit 1; }
echo "setup without apt-get: ok"
