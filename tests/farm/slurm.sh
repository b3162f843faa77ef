#!/usr/bin/env bash
# Through a real Slurm (Debian's munge, slurmctld and slurmd, started here on loopback with their
# configuration and state in the work directory; tools/farm/local-slurm.sh): tools/candela-submit
# sends the Cornell box as 4 tiles and a merge job. Task 1 fails on its first try (a stand-in for a
# lost node) and Slurm runs it again; task 3 is cancelled with scancel mid-render and leaves no
# piece, so the merge job never runs and candela merge names the missing tile; --resume sends
# task 3 again with a new merge, whose image is a local render's, bit for bit. Every daemon is
# stopped on exit, also when the test fails. Skipped (exit 77), saying why, where the daemons
# cannot start (not root, packages missing) unless CI is set: there it must run.
set -euo pipefail
candela=$1 diff=$2 src=$3 work=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$src/tools/farm/local-slurm.sh"
trap 'local_slurm_down "$work/slurm"' EXIT
fail() {
  echo "FAIL: $*"
  for f in slurm/slurmctld.log farm.farm/logs/*.log; do
    [ -f "$f" ] && { echo "--- $f"; tail -20 "$f"; }
  done
  exit 1
}
# Polls CONDITION (a command) every 0.2 s for at most SECONDS.
within() {
  local seconds=$1
  shift
  for _ in $(seq $((seconds * 5))); do "$@" && return 0; sleep 0.2; done
  return 1
}

status=0
local_slurm_up "$work/slurm" || status=$?
if [ $status -eq 1 ]; then
  [ "${CI:-}" = true ] && fail "Slurm cannot start in CI: $LOCAL_SLURM_WHY"
  echo "SKIPPED: Slurm cannot start here: $LOCAL_SLURM_WHY"
  exit 77
fi
[ $status -eq 0 ] || fail "$LOCAL_SLURM_WHY"
echo "slurm: $(sinfo -h -o '%P %D node, %c CPUs, %t') (SLURM_CONF=$SLURM_CONF)"

scene=$src/scenes/cornell-box/cornell-box.pbrt
opts=(--spp 64 --seed 5)
"$candela" "$scene" "${opts[@]}" -o local.exr --preview none -q &
local_render=$!
# Task 3 renders many more samples until slow-task-3 is removed, so that the scancel below finds it
# mid-render however fast the machine is (at 64 spp it could finish before the cancel arrived).
touch slow-task-3
cat > flaky-candela << FLAKY
#!/bin/bash
# Fails the first try of task 1, as a node lost mid-task would.
if [ "\${SLURM_ARRAY_TASK_ID:-}" = 1 ] && [ "\${SLURM_RESTART_COUNT:-0}" = 0 ]; then
  echo "flaky-candela: failing on purpose" >&2
  exit 1
fi
args=("\$@")
if [ "\${SLURM_ARRAY_TASK_ID:-}" = 3 ] && [ -e $(printf %q "$work/slow-task-3") ]; then
  for i in "\${!args[@]}"; do [ "\${args[i]}" = --spp ] && args[i+1]=1000000; done
fi
exec $(printf %q "$candela") "\${args[@]}"
FLAKY
chmod +x flaky-candela
submit=(bash "$src/tools/candela-submit" -o "$work/farm.exr" --tiles 4 --candela "$work/flaky-candela")

# --dry-run prints the batch scripts and submits nothing.
"${submit[@]}" --dry-run "$scene" -- "${opts[@]}" > dry.txt
for want in "#SBATCH --requeue" "--tile \"\$tile/4\"" "scontrol requeue" "candela-submit" \
  "--array=0-3" "--dependency=afterok:RENDER_JOB" "merge --tiles 4 --frames 0-0"; do
  grep -qF -- "$want" dry.txt || fail "--dry-run does not show $want"
done
[ -z "$(squeue -h)" ] && [ ! -e farm.farm ] || fail "--dry-run submitted or wrote something"

"${submit[@]}" "$scene" -- "${opts[@]}" > submit.txt
cat submit.txt
render=$(awk '/^render job/ { sub(":", "", $3); print $3 }' submit.txt)
merge=$(awk '/^merge job/ { sub(":", "", $3); print $3 }' submit.txt)
[ -n "$render" ] && [ -n "$merge" ] || fail "no job ids printed"

# The candela process of task 3, once it has installed its signal handlers (SigCgt has SIGTERM).
task3_rendering() {
  local p
  for p in /proc/[0-9]*; do
    [ "$(cat "$p/comm" 2> /dev/null)" = candela ] || continue
    tr '\0' '\n' 2> /dev/null < "$p/environ" | grep -qx "SLURM_ARRAY_JOB_ID=$render" || continue
    tr '\0' '\n' 2> /dev/null < "$p/environ" | grep -qx "SLURM_ARRAY_TASK_ID=3" || continue
    local mask
    mask=$(awk '/^SigCgt:/ { print $2 }' "$p/status" 2> /dev/null)
    [ -n "$mask" ] && (((16#$mask & 16#4000) != 0)) && return 0
  done
  return 1
}
within 120 task3_rendering || fail "task 3 never started rendering"
sleep 0.5
scancel "${render}_3"
echo "cancelled task ${render}_3"
gone() { [ -z "$(squeue -h -j "$1" 2> /dev/null)" ]; }
within 120 gone "$render" || fail "the render tasks did not end within 120 s"
within 30 gone "$merge" || fail "the merge job is still queued after a task was cancelled"
scontrol show job "$merge" | grep -q "JobState=CANCELLED" || fail "merge job: $(scontrol show job "$merge" | grep JobState)"

logs=farm.farm/logs
grep -q "failing on purpose" $logs/render-1.log && grep -q "try 2" $logs/render-1.log ||
  fail "task 1 was not run again after failing"
grep -q "interrupted by SIGTERM" $logs/render-3.log || fail "task 3 was not stopped mid-render"
ls farm.farm/pieces/tile-{0,1,2}.exr > /dev/null || fail "pieces 0-2 missing"
[ ! -e farm.farm/pieces/tile-3.exr ] && [ -z "$(ls -A farm.farm/pieces | grep '^\.')" ] ||
  fail "the cancelled task left $(ls -A farm.farm/pieces)"
[ ! -e farm.exr ] || fail "a merged image without tile 3"
# The merge, run by hand, names what is missing and writes nothing.
if "$candela" merge --tiles 4 -o by-hand.exr farm.farm/pieces/*.exr 2> by-hand.txt; then
  fail "merged without tile 3"
fi
grep -q "frame 0 tile 3/4" by-hand.txt && [ ! -e by-hand.exr ] || fail "$(cat by-hand.txt)"

rm slow-task-3
bash "$src/tools/candela-submit" --resume "$work/farm.farm" > resume.txt
cat resume.txt
grep -q "tasks 3 again" resume.txt || fail "--resume did not send task 3 alone"
merge=$(awk '/^merge job/ { sub(":", "", $3); print $3 }' resume.txt)
within 120 gone "$merge" || fail "the resumed merge did not end within 120 s"
[ -e farm.exr ] || fail "no merged image after --resume"
wait $local_render || fail "the local render failed"
echo -n "farm.exr against local.exr: "
"$diff" local.exr farm.exr --max-ulps 0 || fail "the farm's image is not the local render's"
[ "$("$diff" --get farm.exr candela:pieces)" = 4 ] || fail "candela:pieces"

# Every daemon stops.
pids=$(cat slurm/pids)
local_slurm_down "$work/slurm"
for pid in $pids; do ! kill -0 "$pid" 2> /dev/null || fail "daemon $pid still running"; done
echo "slurm: ok"
