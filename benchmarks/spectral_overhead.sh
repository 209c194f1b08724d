#!/usr/bin/env bash
# Spectral / RGB cost of every shipped scene (docs/performance.md, "Spectral overhead"), or of
# any mode against another (BASE=spectral MODE=polarised: "Polarised overhead"): CPU
# seconds of the whole process (/usr/bin/time %U), one thread, the fastest of REPEATS runs
# per scene, mode and binary, at SPP and at 8 x SPP samples per pixel. The ratio is that of
# the differences, the cost of 7 x SPP samples: a process spends about 0.4 s before its
# first ray (loading libraries and the scene), the same in both modes, and a ratio of whole
# process times would pull every short render towards 1. Given several binaries (before and
# after a change), each scene is rendered by all of them in turn, so all are measured in the
# same conditions.
#   SPP=16 REPEATS=3 [BASE=rgb MODE=spectral] [SCENES="a.json b.json"] \
#     bash benchmarks/spectral_overhead.sh [LAMINA...]
# A benchmark, not a test: its numbers depend on the machine and what else runs on it (the
# ratio, measured in one run, is the stable figure).
set -euo pipefail
spp=${SPP:-16}
repeats=${REPEATS:-3}
base=${BASE:-rgb}
mode=${MODE:-spectral}
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# -gt 0 ] || set -- "$root/build/app/lamina"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The fastest of $repeats renders of scene $2 in mode $3 at $4 spp by binary $1, in CPU seconds.
fastest() {
    local best=""
    for _ in $(seq "$repeats"); do
        /usr/bin/time -f %U -o "$work/time" "$1" render "$2" -o "$work/image.exr" \
            --mode "$3" --spp "$4" --threads 1 -q
        best=$(awk -v a="$(cat "$work/time")" -v b="$best" 'BEGIN { print (b == "" || a < b) ? a : b }')
    done
    echo "$best"
}

echo "CPU seconds, --threads 1, --spp $spp and $((8 * spp)), fastest of $repeats; load average $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-28s %-3s %15s %15s %8s\n' scene bin "$base s" "$mode s" ratio
for file in ${SCENES:-"$root"/scenes/*.json}; do
    for b in $(seq $#); do
        lamina=${!b}
        rgb=$(fastest "$lamina" "$file" "$base" "$spp")
        rgb8=$(fastest "$lamina" "$file" "$base" $((8 * spp)))
        spectral=$(fastest "$lamina" "$file" "$mode" "$spp")
        spectral8=$(fastest "$lamina" "$file" "$mode" $((8 * spp)))
        # A difference at or below 0 (noise larger than the work) has no ratio: say so.
        awk -v n="$(basename "$file")" -v b="$b" -v r="$rgb" -v r8="$rgb8" -v s="$spectral" \
            -v s8="$spectral8" 'BEGIN {
                ratio = (r8 > r && s8 > s) ? sprintf("%8.2f", (s8 - s) / (r8 - r)) : "   noise"
                printf "%-28s %-3s %6.2f / %6.2f %6.2f / %6.2f %s\n", n, b, r, r8, s, s8, ratio }'
    done
done
echo "bin: $(for b in $(seq $#); do printf '%s = %s  ' "$b" "${!b}"; done)"
echo "load average at the end $(cut -d' ' -f1-3 /proc/loadavg)"
