#!/usr/bin/env bash
# A real cluster in the tests: a single-node Slurm (slurmctld, slurmd, munged from Debian's
# slurm-wlm and munge) on localhost, started in a scratch directory with a generated
# slurm.conf (proctrack/linuxproc, task/none, no systemd, no cgroups), runs the plan of
# `lamina farm plan --submit`: a 4-task job array rendering the Cornell box in four sample
# ranges and the merge job after it. The merged image must equal a single-process render of
# all the samples (R, G, B relative 1e-6) and its Variance.Y the single render's.
# Every wait is bounded; the daemons are stopped and the directory removed on every way out.
# Exit 77 (CTest: skipped) only when the packages are missing and cannot be installed.
# Usage: slurm_array_test.sh LAMINA EXR_AGREEMENT SCENE
set -euo pipefail

lamina=$1 agreement=$2 scene=$3
deadline=$((SECONDS + 240))  # CTest's timeout is 300 s: leave time to clean up

need=(slurmctld slurmd sbatch squeue sinfo scancel munged)
missing() {
  for c in "${need[@]}"; do
    command -v "$c" >/dev/null 2>&1 || PATH=$PATH:/usr/sbin command -v "$c" >/dev/null 2>&1 || return 0
  done
  return 1
}
export PATH=$PATH:/usr/sbin
if missing; then
  if [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "cluster test: installing slurm-wlm and munge"
    DEBIAN_FRONTEND=noninteractive timeout 300 apt-get install -y -qq --no-install-recommends \
      slurm-wlm munge >/dev/null 2>&1 || true
  fi
  if missing; then
    echo "cluster test: SKIPPED: slurm-wlm and munge are not installed and cannot be" \
         "installed here (scripts/setup.sh installs them as root)"
    exit 77
  fi
fi

work=$(mktemp -d /tmp/lamina-slurm.XXXXXX)
pids=()
export SLURM_CONF=$work/slurm.conf

cleanup() {
  local status=$?
  set +e
  # Jobs first (their steps run outside the daemons), then the daemons we started.
  if [ -f "$SLURM_CONF" ] && [ ${#pids[@]} -gt 0 ]; then
    timeout 10 scancel --quiet --user "$(id -un)" 2>/dev/null
    for _ in $(seq 20); do
      [ -z "$(timeout 5 squeue -h 2>/dev/null)" ] && break
      sleep 0.5
    done
  fi
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 20); do kill -0 "$pid" 2>/dev/null || break; sleep 0.25; done
    kill -9 "$pid" 2>/dev/null
  done
  if [ -f "$work/munged.pid" ]; then
    pid=$(cat "$work/munged.pid")
    kill "$pid" 2>/dev/null
    for _ in $(seq 20); do kill -0 "$pid" 2>/dev/null || break; sleep 0.25; done
    kill -9 "$pid" 2>/dev/null
  fi
  if [ $status -ne 0 ] && [ $status -ne 77 ]; then
    for log in "$work"/*.log "$work"/plan/logs/*.log; do
      [ -f "$log" ] && { echo "== $log"; tail -n 20 "$log"; }
    done
  fi
  rm -rf "$work"
  exit $status
}
trap cleanup EXIT
trap 'exit 1' INT TERM

fail() { echo "cluster test: FAILED: $*" >&2; exit 1; }
# wait_for WHAT COMMAND...: polls COMMAND until it succeeds or the deadline passes.
wait_for() {
  local what=$1; shift
  until "$@" >/dev/null 2>&1; do
    [ $SECONDS -lt $deadline ] || fail "timed out waiting for $what"
    sleep 0.5
  done
}

# munge: its own key, socket and files in the scratch directory.
dd if=/dev/urandom of="$work/munge.key" bs=1024 count=1 status=none
chmod 0400 "$work/munge.key"
mkdir -m 0700 "$work/munge"
timeout 20 munged --force --key-file="$work/munge.key" --socket="$work/munge/socket" \
  --pid-file="$work/munged.pid" --log-file="$work/munged.log" --seed-file="$work/munge.seed" \
  || fail "munged did not start"
wait_for "munged" test -S "$work/munge/socket"

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

# The plan, submitted: four shards of 2 samples, then the merge.
timeout 30 "$lamina" farm plan "$scene" --shards 4 --spp 8 --resolution 64x64 --max-depth 4 \
  --threads 1 -o "$work/plan" --submit || fail "farm plan --submit"
queue_empty() {
  local queue
  queue=$(timeout 5 squeue -h -o "%i %r") || return 1
  # A failed render task leaves the merge waiting for ever: stop at once.
  if grep -q DependencyNeverSatisfied <<<"$queue"; then
    fail "a render task failed; the merge job can never run"
  fi
  [ -z "$queue" ]
}
wait_for "the array and the merge job" queue_empty
[ -f "$work/plan/image.exr" ] || fail "the merge job wrote no image"

# The same render in one process; with --aovs for its Variance.Y.
timeout 60 "$lamina" render "$scene" --spp 8 --resolution 64x64 --max-depth 4 -q \
  -o "$work/single.exr"
timeout 60 "$lamina" render "$scene" --spp 8 --resolution 64x64 --max-depth 4 -q --aovs \
  -o "$work/single-aovs.exr"
"$agreement" "$work/plan/image.exr" "$work/single.exr" R G B || fail "the merged image differs"
"$agreement" "$work/plan/image.exr" "$work/single-aovs.exr" Variance.Y ||
  fail "the merged variance differs"
echo "cluster test: 4 array tasks and the merge job on a local Slurm agree with one render"
