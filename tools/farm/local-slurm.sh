# A private one-node Slurm on this machine, from Debian's packages (munge, slurmctld, slurmd,
# slurm-client), for the farm's tests and benchmarks: configuration, state, sockets and logs all
# in one directory, ports on loopback that nothing else uses, no system service involved.
# Source this file, then:
#   local_slurm_up DIR      writes DIR/slurm.conf, starts munged, slurmctld and slurmd (each in
#                           the foreground of a background job, their PIDs in DIR/pids), waits
#                           (bounded) until the node takes jobs, and exports SLURM_CONF. Returns 1
#                           with the reason in LOCAL_SLURM_WHY when they cannot start; 2 when they
#                           started but did not come up (the logs are in DIR).
#   local_slurm_down DIR    stops every daemon local_slurm_up started (by PID; SIGKILL after 10 s)
# Needs root: slurmd runs jobs as their users, and munged and slurmd check who owns their files.

local_slurm_free_port() {
  # A port in 20000-59999 that no socket of this machine uses (listening or connected).
  local used p i
  used=$(awk 'NR > 1 { split($2, a, ":"); print strtonum("0x" a[2]) }' \
    /proc/net/tcp /proc/net/tcp6 2> /dev/null | sort -u)
  for i in $(seq 200); do
    p=$((20000 + (RANDOM * 32768 + RANDOM) % 40000))
    grep -qx "$p" <<< "$used" || { [ "$p" != "${1:-}" ] && { echo "$p"; return 0; }; }
  done
  return 1
}

local_slurm_wait() { # SECONDS COMMAND...: runs COMMAND every 0.2 s until it succeeds
  local tries=$(($1 * 5))
  shift
  for _ in $(seq "$tries"); do
    "$@" > /dev/null 2>&1 && return 0
    sleep 0.2
  done
  return 1
}

local_slurm_up() {
  local dir=$1 tool
  LOCAL_SLURM_WHY=""
  if [ "$(id -u)" -ne 0 ]; then
    LOCAL_SLURM_WHY="not root: slurmd must run as root to start jobs"
    return 1
  fi
  for tool in munged mungekey slurmctld slurmd sbatch squeue scontrol scancel sinfo; do
    command -v "$tool" > /dev/null || PATH=$PATH:/usr/sbin:/sbin
    command -v "$tool" > /dev/null || {
      LOCAL_SLURM_WHY="$tool is not installed (Debian: munge, slurmctld, slurmd, slurm-client)"
      return 1
    }
  done
  dir=$(mkdir -p "$dir" && cd "$dir" && pwd)
  mkdir -p "$dir/munge" "$dir/state" "$dir/spool"
  chmod 700 "$dir/munge"
  : > "$dir/pids"
  # munged: its own key, socket, PID, log and seed files here; the socket in a short temporary
  # directory when DIR is too deep for a socket path (108 bytes).
  local socket=$dir/munge/munge.socket
  if [ ${#socket} -gt 100 ]; then
    socket=$(mktemp -d /tmp/candela-munge.XXXXXX)/munge.socket
    echo "${socket%/*}" > "$dir/munge/socket-dir"
  fi
  mungekey --create --keyfile="$dir/munge/munge.key" > /dev/null 2>&1 ||
    dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 status=none
  chmod 400 "$dir/munge/munge.key"
  munged --foreground --force --key-file="$dir/munge/munge.key" --socket="$socket" \
    --pid-file="$dir/munge/munged.pid" --log-file="$dir/munge/munged.log" \
    --seed-file="$dir/munge/munged.seed" > "$dir/munge/stdout.log" 2>&1 &
  echo $! >> "$dir/pids"
  if ! local_slurm_wait 20 test -S "$socket"; then
    LOCAL_SLURM_WHY="munged did not start ($dir/munge/munged.log)"
    return 2
  fi
  local ctld_port slurmd_port
  ctld_port=$(local_slurm_free_port) && slurmd_port=$(local_slurm_free_port "$ctld_port") || {
    LOCAL_SLURM_WHY="no free port"
    return 2
  }
  cat > "$dir/slurm.conf" << CONF
# Written by tools/farm/local-slurm.sh: one node, this machine's $(nproc) CPUs, on loopback.
ClusterName=candela
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
# cred_expire: a requeued task waits this long before it runs again (default 120 s).
AuthInfo=socket=$socket,cred_expire=5
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
# First in, first out, looking at the queue every second (default 60 s).
SchedulerType=sched/builtin
SchedulerParameters=sched_interval=1
MpiDefault=none
ReturnToService=2
JobCompType=jobcomp/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MailProg=/bin/true
SlurmdParameters=config_overrides
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=farm Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF=$dir/slurm.conf
  slurmctld -D -c -f "$SLURM_CONF" > "$dir/slurmctld.stdout" 2>&1 &
  echo $! >> "$dir/pids"
  if ! local_slurm_wait 30 scontrol ping; then
    LOCAL_SLURM_WHY="slurmctld did not answer within 30 s ($dir/slurmctld.log)"
    return 2
  fi
  slurmd -D -N localhost -f "$SLURM_CONF" > "$dir/slurmd.stdout" 2>&1 &
  echo $! >> "$dir/pids"
  if ! local_slurm_wait 30 bash -c '[ "$(sinfo -h -N -o %t)" = idle ]'; then
    LOCAL_SLURM_WHY="the node did not become idle within 30 s ($dir/slurmd.log)"
    return 2
  fi
  return 0
}

local_slurm_down() {
  local dir=$1 pid alive
  [ -f "$dir/pids" ] || return 0
  # slurmd first (it ends the jobs' steps), then slurmctld, then munged.
  for pid in $(tac "$dir/pids"); do kill -TERM "$pid" 2> /dev/null || true; done
  for _ in $(seq 50); do
    alive=0
    for pid in $(cat "$dir/pids"); do kill -0 "$pid" 2> /dev/null && alive=1; done
    [ $alive -eq 0 ] && break
    sleep 0.2
  done
  for pid in $(cat "$dir/pids"); do kill -KILL "$pid" 2> /dev/null || true; done
  rm -f "$dir/pids"
  if [ -f "$dir/munge/socket-dir" ]; then
    rm -rf "$(cat "$dir/munge/socket-dir")" "$dir/munge/socket-dir"
  fi
}
