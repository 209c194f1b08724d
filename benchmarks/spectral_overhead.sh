#!/usr/bin/env bash
# Spectral / RGB cost of every shipped scene (docs/performance.md, "Spectral overhead"): CPU
# seconds of the whole process (/usr/bin/time %U), one thread, the fastest of REPEATS runs
# per scene, mode and binary. Given several binaries (before and after a change), each scene
# is rendered by all of them in turn, so all are measured in the same conditions.
#   SPP=16 REPEATS=3 bash benchmarks/spectral_overhead.sh [LAMINA...]
# A benchmark, not a test: its numbers depend on the machine and what else runs on it (the
# ratio, measured in one run, is the stable figure).
set -euo pipefail
spp=${SPP:-16}
repeats=${REPEATS:-3}
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# -gt 0 ] || set -- "$root/build/app/lamina"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The fastest of $repeats renders of scene $2 in mode $3 by binary $1, in CPU seconds.
fastest() {
    local best=""
    for _ in $(seq "$repeats"); do
        /usr/bin/time -f %U -o "$work/time" "$1" render "$2" -o "$work/image.exr" \
            --mode "$3" --spp "$spp" --threads 1 -q
        best=$(awk -v a="$(cat "$work/time")" -v b="$best" 'BEGIN { print (b == "" || a < b) ? a : b }')
    done
    echo "$best"
}

echo "CPU seconds, --threads 1, --spp $spp, fastest of $repeats; load average $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-28s %-3s %8s %8s %8s\n' scene bin "RGB s" "spec. s" ratio
for file in "$root"/scenes/*.json; do
    for b in $(seq $#); do
        lamina=${!b}
        rgb=$(fastest "$lamina" "$file" rgb)
        spectral=$(fastest "$lamina" "$file" spectral)
        awk -v n="$(basename "$file")" -v b="$b" -v r="$rgb" -v s="$spectral" \
            'BEGIN { printf "%-28s %-3s %8.2f %8.2f %8.2f\n", n, b, r, s, s / r }'
    done
done
echo "bin: $(for b in $(seq $#); do printf '%s = %s  ' "$b" "${!b}"; done)"
echo "load average at the end $(cut -d' ' -f1-3 /proc/loadavg)"
