#!/usr/bin/env bash
# The layers of docs/architecture.md hold, and both of their guards would notice if they did not:
# the include check (check_layers.py) fails naming the file and line of an include that goes up,
# and the build does not compile it (a library sees only the headers of the layers it links).
#   layers.sh SOURCE_DIR WORK_DIR BUILD_DIR
set -euo pipefail
src=$1 work=$2 build=$3
rm -rf "$work" && mkdir -p "$work"
check=$src/tests/layering/check_layers.py

# The tree as it is: must pass.
python3 "$check" "$src"

# A copy with an include going up (lights including integrators) must fail, naming file and line.
copy=$work/tree
mkdir -p "$copy"
cp -r "$src/src" "$src/docs" "$src/CMakeLists.txt" "$copy/"
printf '#pragma once\n\n#include "integrators/integrator.h"\n' > "$copy/src/lights/planted.h"
if python3 "$check" "$copy" > "$work/up.txt"; then
  cat "$work/up.txt"; echo "FAIL: an upward include passed the check"; exit 1
fi
grep -q '^src/lights/planted.h:3: includes integrators/integrator.h, but lights may include only' \
  "$work/up.txt" || { cat "$work/up.txt"; echo "FAIL: the check did not name file and line"; exit 1; }
rm "$copy/src/lights/planted.h"

# A build whose links differ from the table must fail too (samplers without filters).
sed -i 's/^candela_layer(samplers USES core filters)/candela_layer(samplers USES core)/' \
  "$copy/CMakeLists.txt"
grep -q '^candela_layer(samplers USES core)' "$copy/CMakeLists.txt" ||
  { echo "FAIL: could not change the samplers layer in the copy"; exit 1; }
if python3 "$check" "$copy" > "$work/links.txt"; then
  cat "$work/links.txt"; echo "FAIL: a build unlike the table passed the check"; exit 1
fi
grep -q 'candela_samplers links core; docs/architecture.md says core, filters' "$work/links.txt" ||
  { cat "$work/links.txt"; echo "FAIL: the check did not name the samplers layer"; exit 1; }

# The compiler's side: a lights source compiled as the build compiles lights/light_sampler.cpp
# sees accel's headers (which lights links) and not the integrators' (which it may not include).
commands=$build/compile_commands.json
[ -f "$commands" ] || { echo "FAIL: $commands is missing (CMAKE_EXPORT_COMPILE_COMMANDS)"; exit 1; }
probe() {  # probe FILE INCLUDE: 0 when a lights source including INCLUDE compiles
  python3 - "$commands" "$src/src/lights/light_sampler.cpp" "$1" "$2" <<'PY'
import json, os, shlex, subprocess, sys
commands, model, probe, include = sys.argv[1:]
entry = next((e for e in json.load(open(commands))
              if os.path.realpath(e["file"]) == os.path.realpath(model)), None)
if entry is None:
    sys.exit("no compile command for " + model)
open(probe, "w").write('#include "%s"\n' % include)
args = entry["arguments"] if "arguments" in entry else shlex.split(entry["command"])
out = []
skip = False
for a in args:  # the same flags, this file instead of the model, no object written
    if skip:
        skip = False
        continue
    if a in ("-o", "-MF", "-MT", "-MQ"):
        skip = True
        continue
    if a in ("-MD", "-MMD", "-c") or os.path.realpath(a) == os.path.realpath(model):
        continue
    out.append(a)
r = subprocess.run(out + ["-fsyntax-only", probe], cwd=entry["directory"],
                   capture_output=True, text=True)
sys.stderr.write(r.stderr)
sys.exit(r.returncode)
PY
}
probe "$work/allowed.cpp" "accel/aggregate.h" 2> "$work/allowed.txt" ||
  { cat "$work/allowed.txt"; echo "FAIL: lights could not include accel/aggregate.h"; exit 1; }
if probe "$work/upward.cpp" "integrators/integrator.h" 2> "$work/upward.txt"; then
  echo "FAIL: a lights source compiled with an include of integrators/"; exit 1
fi
grep -q 'integrators/integrator.h' "$work/upward.txt" ||
  { cat "$work/upward.txt"; echo "FAIL: the compiler refused it for another reason"; exit 1; }
echo "layers: ok"
