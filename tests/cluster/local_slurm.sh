# A single-node Slurm cluster on localhost for tests and measurements, sourced by
# tests/cluster/slurm_array_test.sh and scripts/measure-farm-scaling.sh: slurmctld, slurmd and
# munged from Debian's slurm-wlm and munge, started in a scratch directory ($work) with their
# own munge key and a generated slurm.conf (proctrack/linuxproc, task/none, no systemd, no
# cgroups, random ports), stopped with their jobs and the directory removed on every way out
# (an EXIT trap). Every wait is bounded by $deadline (in bash's SECONDS).
# The caller sets `set -euo pipefail` and `deadline`, then calls local_slurm_require (exit 77,
# CTest's "skipped", only when the packages are missing and cannot be installed) and
# local_slurm_start; queue_empty and wait_for then wait for the jobs.

export PATH=$PATH:/usr/sbin
pids=()
work=

fail() { echo "local slurm: FAILED: $*" >&2; exit 1; }

# wait_for WHAT COMMAND...: polls COMMAND until it succeeds or the deadline passes.
wait_for() {
  local what=$1; shift
  until "$@" >/dev/null; do
    [ $SECONDS -lt "$deadline" ] || fail "timed out waiting for $what"
    sleep 0.5
  done
}

slurm_packages_missing() {
  local c
  for c in slurmctld slurmd sbatch squeue sinfo scancel munged; do
    command -v "$c" >/dev/null 2>&1 || return 0
  done
  return 1
}

local_slurm_require() {
  slurm_packages_missing || return 0
  if [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "local slurm: installing slurm-wlm and munge"
    DEBIAN_FRONTEND=noninteractive timeout 300 apt-get install -y -qq --no-install-recommends \
      slurm-wlm munge >/dev/null 2>&1 || true
  fi
  if slurm_packages_missing; then
    echo "local slurm: SKIPPED: slurm-wlm and munge are not installed and cannot be" \
         "installed here (scripts/setup.sh installs them as root)"
    exit 77
  fi
}

local_slurm_cleanup() {
  local status=$? pid
  set +e
  [ -n "$work" ] || exit $status
  # Jobs first (their steps run outside the daemons), then the daemons this script started.
  if [ ${#pids[@]} -gt 0 ]; then
    timeout 10 scancel --quiet --user "$(id -un)" 2>/dev/null
    for _ in $(seq 20); do
      [ -z "$(timeout 5 squeue -h 2>/dev/null)" ] && break
      sleep 0.5
    done
  fi
  [ -f "$work/munged.pid" ] && pids+=("$(cat "$work/munged.pid")")
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 20); do kill -0 "$pid" 2>/dev/null || break; sleep 0.25; done
    kill -9 "$pid" 2>/dev/null
  done
  if [ $status -ne 0 ] && [ $status -ne 77 ]; then
    for log in "$work"/*.log "$work"/plan*/logs/*.log; do
      [ -f "$log" ] && { echo "== $log"; tail -n 20 "$log"; }
    done
  fi
  rm -rf "$work"
  exit $status
}

# Empty queue: every job ended. A failed render task leaves a merge that depends on it
# waiting for ever: stop at once.
queue_empty() {
  local queue
  queue=$(timeout 5 squeue -h -o "%i %r") || return 1
  if grep -q DependencyNeverSatisfied <<<"$queue"; then
    fail "a job failed; the job depending on it can never run"
  fi
  [ -z "$queue" ]
}

local_slurm_start() {
  work=$(mktemp -d /tmp/lamina-slurm.XXXXXX)
  export SLURM_CONF=$work/slurm.conf
  trap local_slurm_cleanup EXIT
  trap 'exit 1' INT TERM

  # munge: its own key, socket and files in the scratch directory.
  dd if=/dev/urandom of="$work/munge.key" bs=1024 count=1 status=none
  chmod 0400 "$work/munge.key"
  mkdir -m 0700 "$work/munge"
  timeout 20 munged --force --key-file="$work/munge.key" --socket="$work/munge/socket" \
    --pid-file="$work/munged.pid" --log-file="$work/munged.log" --seed-file="$work/munge.seed" \
    || fail "munged did not start"
  wait_for "munged" test -S "$work/munge/socket"

  local host port node
  host=$(hostname -s)
  port=$((20000 + RANDOM % 20000))
  mkdir -p "$work/state" "$work/spool"
  node=$(slurmd -C | head -n 1)  # this machine's NodeName=... CPUs=... line
  cat > "$SLURM_CONF" <<CONF
ClusterName=lamina-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=$(id -un)
SlurmdUser=$(id -un)
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$work/munge/socket
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SwitchType=switch/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
SlurmdParameters=config_overrides
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
SlurmctldTimeout=30
SlurmdTimeout=30
$node NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF

  slurmctld -D -i -f "$SLURM_CONF" >"$work/slurmctld.out" 2>&1 &
  pids+=($!)
  slurmd -D -N "$host" -f "$SLURM_CONF" >"$work/slurmd.out" 2>&1 &
  pids+=($!)
  node_idle() { [ "$(timeout 5 sinfo -h -N -o %t | head -n 1)" = idle ]; }
  wait_for "the node to be idle" node_idle
}
