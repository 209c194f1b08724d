#!/usr/bin/env bash
# Equal-time error of the `coated` material's `samples` (walks per eval and pdf; docs/bsdf.md,
# "Performance"): scenes/reciprocity/coated.json with both coated materials at samples 1, 2
# and 4, one `path` render each at the same sample count, its MSE and relMSE against one long
# reference of an independent seed, and the CPU time of its samples (user + system, all
# threads, minus the CPU time of a 1-spp render of the same scene: start-up, loading, BVH).
# The equal-time error is the error times the CPU time over a budget of BUDGET CPU-seconds:
# for an unbiased estimator the error falls as 1 / samples, so this is the error a render of
# BUDGET CPU-seconds would have. CPU time, not a wall-clock --time budget, because the machine
# is shared: the wall-clock rate changes with what else runs, the CPU time much less.
#   bash benchmarks/coated_samples.sh [LAMINA] [SPP] [REFERENCE_SPP] [RESOLUTION] [BUDGET]
# A benchmark, not a test: its numbers depend on the machine and what else runs on it (the
# load average is printed before and after).
set -euo pipefail
lamina=${1:-build/app/lamina}
spp=${2:-256}
reference_spp=${3:-4096}
resolution=${4:-48}
budget=${5:-10}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The scene with every coated material at `samples` $1.
variant() {
    sed "s/\"type\": \"coated\",/\"type\": \"coated\", \"samples\": $1,/g" \
        "$root/scenes/reciprocity/coated.json" >"$work/coated-$1.json"
    [ "$(grep -o "\"samples\": $1," "$work/coated-$1.json" | wc -l)" -eq 2 ]
}

# Runs a render; prints its CPU seconds (user + system of the child).
cpu_seconds() {
    local TIMEFORMAT='%U %S'
    { time "$@" >/dev/null 2>&1; } 2>&1 | awk '{ print $1 + $2 }'
}

# The last row of an error log: seconds, spp, MSE, relMSE, MAE.
last() { tail -n 1 "$1"; }

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg) ($(nproc) cores)"
variant 1
cpu=$(cpu_seconds "$lamina" render "$work/coated-1.json" -q --resolution "${resolution}x${resolution}" \
    --spp "$reference_spp" --seed 1000 -o "$work/reference.exr")
echo "reference: samples 1, $reference_spp spp, seed 1000, $cpu CPU s"
for n in 1 2 4; do
    variant "$n"
    startup=$(cpu_seconds "$lamina" render "$work/coated-$n.json" -q \
        --resolution "${resolution}x${resolution}" --spp 1 --seed 2 -o "$work/startup-$n.exr")
    total=$(cpu_seconds "$lamina" render "$work/coated-$n.json" -q \
        --resolution "${resolution}x${resolution}" --spp "$spp" --seed 1 \
        --reference "$work/reference.exr" --error-log "$work/samples-$n.csv" \
        -o "$work/samples-$n.exr")
    cpu=$(awk -v t="$total" -v s="$startup" 'BEGIN { print t - s }')
    IFS=, read -r s done_spp m r mae < <(last "$work/samples-$n.csv")
    awk -v n="$n" -v spp="$done_spp" -v cpu="$cpu" -v m="$m" -v r="$r" -v b="$budget" 'BEGIN {
        printf "samples %d  %5d spp  %7.2f CPU s  MSE %.4g  relMSE %.4g  at %g CPU s: MSE %.4g  relMSE %.4g\n",
               n, spp, cpu, m, r, b, m * cpu / b, r * cpu / b }'
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
