#!/usr/bin/env bash
# The install lists are complete (every file the build, tests and tools use comes from a listed
# package or the base system), and the check would notice if they were not: with one package
# taken out of a list, it fails and names that package and a file that needs it.
#   install_list.sh SOURCE_DIR WORK_DIR [BUILD_DIR]   (BUILD_DIR: also the headers it compiled)
set -euo pipefail
src=$1 work=$2 build=${3:-}
rm -rf "$work" && mkdir -p "$work"
check=$src/tools/check-install-list.sh
required=$src/third_party_config/apt-packages.txt
extras=$src/third_party_config/apt-packages-extras.txt
manifest=$work/manifest.tsv

# The real lists: must pass. This run's probe writes the manifest the other cases reuse.
if ! bash "$check" --manifest "$manifest" ${build:+--build-dir "$build"} "$required" "$extras"; then
  echo "FAIL: the install lists are incomplete (above)"
  exit 1
fi
grep -q $'\t/usr/bin/iconvert$' "$manifest" || { echo "FAIL: the probe missed OIIO's tools"; exit 1; }

# A list without PACKAGE must fail, naming PACKAGE and a file matching PATTERN.
expect_missing() {
  local package=$1 pattern=$2 list=$3 name
  name=$(basename "$list")
  sed -E "s/^\s*$package(\s|#|$).*//" "$list" >"$work/$name"
  grep -qE "^\s*$package(\s|#|$)" "$work/$name" && { echo "FAIL: could not remove $package"; exit 1; }
  local lists=("$required" "$extras")
  [ "$list" = "$required" ] && lists[0]=$work/$name || lists[1]=$work/$name
  if bash "$check" --manifest "$manifest" "${lists[@]}" 2>"$work/out-$package.txt"; then
    cat "$work/out-$package.txt"
    echo "FAIL: the check passed without $package"
    exit 1
  fi
  if ! grep -E "lack .*\b$package\b.*provides $pattern" "$work/out-$package.txt" >/dev/null; then
    cat "$work/out-$package.txt"
    echo "FAIL: without $package the check did not name it and a file matching $pattern"
    exit 1
  fi
  echo "without $package: $(grep -c 'lack' "$work/out-$package.txt") files reported, e.g." \
    "$(grep -m1 -E "provides $pattern" "$work/out-$package.txt")"
}
expect_missing openimageio-tools '/usr/bin/iconvert' "$required"
expect_missing libosd-dev '/usr/\S*libosdCPU' "$required"
expect_missing libgmock-dev '/usr/\S*gmock' "$required"
expect_missing libcli11-dev '/usr/\S*CLI11' "$required"
expect_missing python3-matplotlib '/usr/\S*matplotlib' "$extras"
expect_missing slurmctld '/usr/sbin/slurmctld' "$extras"
expect_missing clang '/usr/bin/clang\+\+' "$extras"
expect_missing libclang-rt-14-dev '/usr/\S*libclang_rt\.asan' "$extras"
expect_missing llvm-14 '/usr/\S*llvm-symbolizer' "$extras"
echo "install lists: ok"
