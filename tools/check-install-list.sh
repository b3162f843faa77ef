#!/usr/bin/env bash
# Checks that the install lists name every Debian package the build, the tests and the tools use,
# so that a fresh Debian 12 machine gets them from tools/setup.sh and not from earlier hand work.
#   tools/check-install-list.sh [--manifest FILE] [--build-dir DIR] [--python-modules "m1 m2"]
#                               [--programs "p1 p2"] [LIST...]
# LISTs default to third_party_config/apt-packages.txt and apt-packages-extras.txt.
#
# 1. A probe CMake project (tools/install-check) finds the packages as the build does, with tests
#    and benchmarks on, and writes every file their configs refer to (imported locations, include
#    and link directories, link libraries, the config files, the compiler and build tools). With
#    --manifest FILE an existing manifest is reused, or the probe writes it there.
# 2. The interpreter and Python modules the tools import (--python-modules), the programs the tests
#    run (--programs: Slurm and munge, for tests/farm/slurm.sh), and with --build-dir DIR (a Ninja
#    build) every system header its objects were compiled with join the manifest.
# 3. Each file is mapped to the installed package that owns it (dpkg's file lists, through
#    /usr-merge and symlinks).
# 4. That package must lie in what a fresh machine would have: the base system (Essential and
#    Priority required packages) plus the listed packages, closed over Depends and Pre-Depends
#    (Recommends and Suggests are not installed; of alternatives, the first one installed here).
# Every file whose package falls outside is reported with the package and the target that needs
# it; the exit status is then 1. The dependency data is dpkg's, so no network is needed.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
manifest=""
builddir=""
modules="matplotlib matplotlib.pyplot matplotlib.image PIL xml.etree.ElementTree"
programs="munged mungekey slurmctld slurmd sbatch squeue scancel scontrol sinfo"
lists=()
while [ $# -gt 0 ]; do
  case "$1" in
    --manifest) manifest=$2; shift 2 ;;
    --python-modules) modules=$2; shift 2 ;;
    --programs) programs=$2; shift 2 ;;
    --build-dir) builddir=$2; shift 2 ;;
    -h|--help) sed -n '2,21p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "check-install-list: unknown option $1" >&2; exit 2 ;;
    *) lists+=("$1"); shift ;;
  esac
done
[ ${#lists[@]} -gt 0 ] || lists=("$root/third_party_config/apt-packages.txt"
                                 "$root/third_party_config/apt-packages-extras.txt")
for l in "${lists[@]}"; do
  [ -r "$l" ] || { echo "check-install-list: $l: cannot read the list" >&2; exit 2; }
done
command -v dpkg-query >/dev/null || { echo "check-install-list: needs dpkg (Debian)" >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# 1. The probe.
if [ -z "$manifest" ]; then
  manifest=$work/manifest.tsv
fi
if [ ! -s "$manifest" ]; then
  if ! cmake -S "$root/tools/install-check" -B "$work/probe" -G Ninja \
      -DCANDELA_MANIFEST="$manifest" >"$work/probe.log" 2>&1; then
    cat "$work/probe.log" >&2
    echo "check-install-list: the probe could not configure (above): a package is missing" >&2
    exit 1
  fi
fi
cp "$manifest" "$work/files.tsv"

# 2. Python: the interpreter and the modules the tools import.
if [ -n "$modules" ]; then
  py=/usr/bin/python3 # the tools run Debian's interpreter, with Debian's modules
  [ -x "$py" ] || py=""
  if [ -z "$py" ]; then
    echo "check-install-list: python3 is not installed; the tools need it" >&2
    exit 1
  fi
  printf 'tool python3\t%s\n' "$py" >>"$work/files.tsv"
  for m in $modules; do
    f=$("$py" -c "import $m, sys; sys.stdout.write($m.__file__)" 2>/dev/null) || {
      echo "check-install-list: python3 cannot import $m" >&2
      exit 1
    }
    printf 'python module %s\t%s\n' "$m" "$f" >>"$work/files.tsv"
  done
fi

# The programs the tests run, found as they find them (daemons in /usr/sbin).
for p in $programs; do
  f=$(PATH=$PATH:/usr/sbin:/sbin command -v "$p" 2>/dev/null) || {
    echo "check-install-list: $p is not installed; tests/farm/slurm.sh runs it" >&2
    exit 1
  }
  printf 'program %s\t%s\n' "$p" "$f" >>"$work/files.tsv"
done

# The headers the build really included (Ninja's dependency log), outside the source and build.
if [ -n "$builddir" ]; then
  bd=$(cd "$builddir" && pwd)
  ninja -C "$bd" -t deps 2>/dev/null | sed -n 's/^ \{4\}\(\/.*\)$/\1/p' | sort -u |
    xargs -r -d '\n' realpath -e -- 2>/dev/null | sort -u |
    grep -v -e "^$root/" -e "^$bd/" | sed 's/^/header compiled by the build\t/' >"$work/headers.tsv" || true
  [ -s "$work/headers.tsv" ] || { echo "check-install-list: $bd: no Ninja dependency log" >&2; exit 2; }
  cat "$work/headers.tsv" >>"$work/files.tsv"
fi

# 3. Owners, from dpkg's file lists. dpkg knows a path as packaged: try it as given, resolved,
# and across /usr-merge.
cut -f2 "$work/files.tsv" | sort -u >"$work/paths.txt"
while read -r p; do
  r=$(readlink -f "$p" 2>/dev/null || echo "$p")
  for v in "$p" "${p#/usr}" "/usr$p" "$r" "${r#/usr}" "/usr$r"; do printf '%s\t%s\n' "$p" "$v"; done
done <"$work/paths.txt" >"$work/variants.tsv"
awk -F'\t' '
  FNR == NR { ++nv; vpath[nv] = $1; vname[nv] = $2; want[$2] = 1; next }
  FNR == 1 { pkg = FILENAME; sub(/.*\//, "", pkg); sub(/\.list$/, "", pkg); sub(/:.*/, "", pkg) }
  $0 in want { owner[$0] = (($0 in owner) ? owner[$0] " " : "") pkg }
  END {
    for (i = 1; i <= nv; i++) {
      p = vpath[i]; all[p] = 1
      if (!(p in done) && (vname[i] in owner)) { done[p] = 1; print p "\t" owner[vname[i]] }
    }
    for (p in all) if (!(p in done)) print p "\t-"
  }' "$work/variants.tsv" /var/lib/dpkg/info/*.list >"$work/owners.tsv"

# 4. What a fresh machine would have: the base system and the lists, closed over Depends.
for l in "${lists[@]}"; do sed 's/#.*//' "$l"; done | tr -s ' \t' '\n\n' | grep -v '^$' |
  sort -u >"$work/listed.txt"
dpkg-query -W -f='${Package}\t${Status}\t${Essential}\t${Priority}\t${Provides}\t${Pre-Depends}, ${Depends}\n' \
  >"$work/status.tsv"
awk -F'\t' -v listed="$work/listed.txt" '
  function strip(s) { sub(/^ +/, "", s); sub(/ *\(.*$/, "", s); sub(/:.*$/, "", s); sub(/ +$/, "", s); return s }
  # The installed package that satisfies a name: itself, or one that provides it.
  function resolve(n) { return (n in inst) ? n : ((n in prov) ? prov[n] : "") }
  function want(n) { if (n != "" && !(n in seen)) { seen[n] = 1; queue[++qn] = n } }
  $2 !~ / installed$/ { next }
  {
    inst[$1] = 1; deps[$1] = $6
    np = split($5, ps, ",")
    for (i = 1; i <= np; i++) { v = strip(ps[i]); if (v != "" && !(v in prov)) prov[v] = $1 }
    if ($3 == "yes" || $4 == "required") base[$1] = 1
  }
  END {
    while ((getline line < listed) > 0) {
      if (!(line in inst) && !(line in prov)) { print "NOTINSTALLED\t" line; continue }
      want(resolve(line))
    }
    for (b in base) want(b)
    for (q = 1; q <= qn; q++) {
      nc = split(deps[queue[q]], clauses, ",")
      for (i = 1; i <= nc; i++) {
        na = split(clauses[i], alts, "|")
        for (j = 1; j <= na; j++) { r = resolve(strip(alts[j])); if (r != "") { want(r); break } }
      }
    }
    for (n in seen) print "HAVE\t" n
  }' "$work/status.tsv" >"$work/closure.tsv"

status=0
if grep -q '^NOTINSTALLED' "$work/closure.tsv"; then
  echo "check-install-list: listed but not installed here (run tools/setup.sh first):" \
    "$(grep '^NOTINSTALLED' "$work/closure.tsv" | cut -f2 | tr '\n' ' ')" >&2
  status=1
fi
grep '^HAVE' "$work/closure.tsv" | cut -f2 | sort -u >"$work/have.txt"

missing=0
while IFS=$'\t' read -r path owners; do
  if [ "$owners" = "-" ]; then
    [ -e "$path" ] || continue # a configuration the build does not use (e.g. a Debug location)
    echo "check-install-list: $path (needed by $(awk -F'\t' -v p="$path" '$2==p{print $1}' \
      "$work/files.tsv" | sort -u | paste -sd, -)) belongs to no installed package" >&2
    missing=$((missing + 1))
    continue
  fi
  ok=0
  for o in $owners; do grep -qxF "$o" "$work/have.txt" && { ok=1; break; }; done
  if [ $ok -eq 0 ]; then
    who=$(awk -F'\t' -v p="$path" '$2==p{print $1}' "$work/files.tsv" | sort -u | paste -sd, -)
    echo "check-install-list: the install lists lack ${owners% }, which provides $path" \
      "(needed by $who)" >&2
    missing=$((missing + 1))
  fi
done <"$work/owners.tsv"

nfiles=$(wc -l <"$work/owners.tsv")
if [ $missing -gt 0 ] || [ $status -ne 0 ]; then
  echo "check-install-list: FAILED: $missing of $nfiles files come from packages no list reaches" >&2
  exit 1
fi
echo "check-install-list: ok: $nfiles files, all from the base system or the closure of" \
  "$(wc -l <"$work/listed.txt") listed packages ($(wc -l <"$work/have.txt") packages)"
