#!/usr/bin/env bash
# Equal-time error of the `coated` material's `samples` (walks per eval and pdf; docs/bsdf.md,
# "Performance"): scenes/reciprocity/coated.json with both coated materials at samples 1, 2
# and 4, one `path` render each with the same --time budget, its MSE and relMSE against one
# long reference of an independent seed; prints the error ratios measured in this one run.
#   bash benchmarks/coated_samples.sh [LAMINA] [SECONDS] [REFERENCE_SPP] [RESOLUTION]
# A benchmark, not a test: its numbers depend on the machine and what else runs on it (the
# load average is printed before and after).
set -euo pipefail
lamina=${1:-build/app/lamina}
seconds=${2:-20}
reference_spp=${3:-4096}
resolution=${4:-64}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The scene with every coated material at `samples` $1.
variant() {
    sed "s/\"type\": \"coated\",/\"type\": \"coated\", \"samples\": $1,/g" \
        "$root/scenes/reciprocity/coated.json" >"$work/coated-$1.json"
    grep -c "\"samples\": $1" "$work/coated-$1.json" >/dev/null
}

# The last row of an error log: seconds, spp, MSE, relMSE, MAE.
last() { tail -n 1 "$1"; }

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg) ($(nproc) cores)"
variant 1
start=$(date +%s)
"$lamina" render "$work/coated-1.json" -q --resolution "$resolution" "$resolution" \
    --spp "$reference_spp" --seed 1000 -o "$work/reference.exr"
echo "reference: samples 1, $reference_spp spp, seed 1000, $(($(date +%s) - start)) s"
declare -A mse=() rel=()
for n in 1 2 4; do
    variant "$n"
    "$lamina" render "$work/coated-$n.json" -q --resolution "$resolution" "$resolution" \
        --time "$seconds" --seed 1 --reference "$work/reference.exr" \
        --error-log "$work/samples-$n.csv" -o "$work/samples-$n.exr"
    IFS=, read -r s spp m r mae < <(last "$work/samples-$n.csv")
    mse[$n]=$m
    rel[$n]=$r
    printf 'samples %d  %6.2f s %6d spp  MSE %.4g  relMSE %.4g\n' "$n" "$s" "$spp" "$m" "$r"
done
awk -v m1="${mse[1]}" -v m2="${mse[2]}" -v m4="${mse[4]}" \
    -v r1="${rel[1]}" -v r2="${rel[2]}" -v r4="${rel[4]}" 'BEGIN {
        printf "MSE    samples 2 / 1 = %.2f, samples 4 / 1 = %.2f\n", m2 / m1, m4 / m1
        printf "relMSE samples 2 / 1 = %.2f, samples 4 / 1 = %.2f\n", r2 / r1, r4 / r1 }'
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
