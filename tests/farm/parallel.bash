# Sourced by the farm's test scripts: most of each candela run is starting the process, so the
# renders a test needs run four at a time. in_parallel COMMAND... starts one (waiting for the
# batch when four are running); wait_all waits for them and fails the test if any failed.
pids=()
in_parallel() {
  "$@" &
  pids+=($!)
  if [ ${#pids[@]} -ge 4 ]; then wait_all; fi
}
wait_all() {
  local pid status=0
  for pid in "${pids[@]}"; do wait "$pid" || status=1; done
  pids=()
  [ $status -eq 0 ] || { echo "FAIL: a render failed"; exit 1; }
}
