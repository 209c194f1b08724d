#!/usr/bin/env bash
# Equal-time error of the light selections (docs/performance.md, "Light selection"): for each
# scene, a long `bvh` reference, then one render per selection with the same --time budget,
# each with its MSE against the reference; prints the MSE ratios measured in this one run.
#   bash benchmarks/light_selection.sh [LAMINA] [SECONDS] [REFERENCE_SPP]
# A benchmark, not a test: its numbers depend on the machine and what else runs on it.
set -euo pipefail
lamina=${1:-build/app/lamina}
seconds=${2:-10}
reference_spp=${3:-2048}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The last row of an error log: seconds, spp, MSE, relMSE, MAE.
last() { tail -n 1 "$1"; }

for scene in many-lights light-selection/metal-environment; do
    file="$root/scenes/$scene.json"
    name=$(basename "$scene")
    "$lamina" render "$file" -q --light-selection bvh --spp "$reference_spp" --seed 1000 \
        -o "$work/$name-reference.exr"
    declare -A mse=()
    for selection in bvh power uniform; do
        "$lamina" render "$file" -q --light-selection "$selection" --time "$seconds" --seed 1 \
            --reference "$work/$name-reference.exr" --error-log "$work/$name-$selection.csv" \
            -o "$work/$name-$selection.exr"
        IFS=, read -r s spp m rel mae < <(last "$work/$name-$selection.csv")
        mse[$selection]=$m
        printf '%-18s %-8s %6.2f s %5d spp  MSE %.4g\n' "$name" "$selection" "$s" "$spp" "$m"
    done
    awk -v b="${mse[bvh]}" -v p="${mse[power]}" -v u="${mse[uniform]}" -v n="$name" \
        'BEGIN { printf "%-18s MSE power / bvh = %.2f, uniform / bvh = %.2f\n", n, p / b, u / b }'
    unset mse
done
