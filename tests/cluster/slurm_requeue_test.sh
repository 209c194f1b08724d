#!/usr/bin/env bash
# Farm work is not lost: on a single-node Slurm on localhost (local_slurm.sh), one array task of
# `lamina farm plan --submit` is requeued by `scontrol requeue` while it renders (Slurm stops it
# with a signal and runs it again, as after a preemption or a drained node). The restarted task
# must resume from the partial shard its first run wrote (its log says "resuming" and how many
# samples it kept) instead of starting over, and the merged image must equal one render of all
# the samples (R, G, B relative 1e-6). Every wait is bounded; the daemons are stopped and the
# scratch directory removed on every way out.
# Usage: slurm_requeue_test.sh LAMINA EXR_AGREEMENT SCENE
set -euo pipefail

lamina=$1 agreement=$2 scene=$3
deadline=$((SECONDS + 270))  # CTest's timeout is 330 s: leave time to clean up

source "$(dirname "$0")/local_slurm.sh"
local_slurm_require
local_slurm_start

# Two shards of 1024 samples, about ten seconds each on one thread: long enough to interrupt.
settings=(--spp 2048 --resolution 64x64 --max-depth 4)
timeout 30 "$lamina" farm plan "$scene" --shards 2 "${settings[@]}" --threads 1 \
  -o "$work/plan" --submit || fail "farm plan --submit"

# Task 0 rendering, with samples to lose: Slurm calls a task RUNNING before its script has
# started lamina, and a signal that arrives before lamina's first finished sample leaves nothing
# to resume (on a loaded machine a fixed two-second sleep was not enough). The shards render
# quietly (-q), so the sign is task 0's lamina process having used half a second of CPU time: its
# scene is loaded and some of its samples are done.
task_running() { timeout 5 squeue -h -t RUNNING -o "%i" | grep -q "_0$"; }
wait_for "array task 0 to run" task_running
# (from /proc, not procps, which a minimal Debian lacks)
task_rendered_a_while() {
  local cmdline stat fields
  for cmdline in /proc/[0-9]*/cmdline; do
    [[ "$(tr '\0' ' ' 2>/dev/null <"$cmdline")" == *" render "*" --samples 0:1024 "* ]] || continue
    stat=$(cat "${cmdline%cmdline}stat" 2>/dev/null) || continue
    read -r -a fields <<<"${stat##*) }"  # fields from the third on; utime is the 14th
    [ "${fields[11]:-0}" -ge $(($(getconf CLK_TCK) / 2)) ] && return 0
  done
  return 1
}
wait_for "array task 0 to render for half a second" task_rendered_a_while
task=$(timeout 5 squeue -h -t RUNNING -o "%i" | grep "_0$" | head -n 1)
timeout 10 scontrol requeue "$task" || fail "scontrol requeue $task"
echo "cluster test: requeued $task while it rendered"
# Slurm holds a requeued job back (its begin time about two minutes on); no need to wait here.
task_pending() { timeout 5 squeue -h -t PENDING -o "%i" | grep -q "_0$"; }
wait_for "the requeued task to be pending" task_pending
timeout 10 scontrol update JobId="$task" StartTime=now || fail "scontrol update $task"

wait_for "the array and the merge job" queue_empty
[ -f "$work/plan/image.exr" ] || fail "the merge job wrote no image"
grep -h "lamina: resuming" "$work"/plan/logs/*.log ||
  fail "no task resumed its partial shard (logs: $(ls "$work"/plan/logs))"

timeout 120 "$lamina" render "$scene" "${settings[@]}" -q -o "$work/single.exr"
"$agreement" "$work/plan/image.exr" "$work/single.exr" R G B ||
  fail "the merged image of a requeued run differs from one render"
echo "cluster test: a task requeued mid-render resumed its shard; the merge equals one render"
