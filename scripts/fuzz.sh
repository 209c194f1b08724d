#!/usr/bin/env bash
# Runs every libFuzzer target of a fuzz build (tests/fuzz/CMakeLists.txt) for SECONDS each:
# first replays the inputs that once crashed it (tests/fuzz/regressions/TARGET), then fuzzes
# from the seed corpus. Fails on any crash, leak, timeout (a hang) or out-of-memory; the
# offending input is left in BUILD_DIR/fuzz-artifacts/ to be added to regressions/.
# JOBS targets run at once (default: the number of cores), each on one core.
#   bash scripts/fuzz.sh BUILD_DIR [SECONDS]
set -euo pipefail
build=$1 seconds=${2:-30}
jobs=${JOBS:-$(nproc)}
cd "$(dirname "$0")/.."
artifacts="$build/fuzz-artifacts"
mkdir -p "$artifacts"
export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

# One target: its report goes to $artifacts/TARGET.report, printed when it ends.
fuzz_target() {
  local target=$1 dir=$2
  local binary="$build/tests/fuzz/lamina_fuzz_$target" work="$build/fuzz-corpus/$target"
  mkdir -p "$work"
  local regressions=(tests/fuzz/regressions/"$target"/*)
  if [ -e "${regressions[0]}" ]; then
    echo "fuzz: $target: replayed ${#regressions[@]} regression inputs"
    if ! "$binary" -timeout=10 -rss_limit_mb=2048 "${regressions[@]}" \
         >"$artifacts/$target-replay.log" 2>&1; then
      tail -n 40 "$artifacts/$target-replay.log"
      echo "fuzz: $target: a regression input fails"
      return 1
    fi
  fi
  # -timeout: one input taking 10 s is a hang; -rss_limit_mb: a reader must not exhaust memory.
  if ! "$binary" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
       -artifact_prefix="$artifacts/$target-" -print_final_stats=1 \
       "$work" "$dir" >"$artifacts/$target.log" 2>&1; then
    tail -n 40 "$artifacts/$target.log"
    echo "fuzz: $target: failed; the input is in $artifacts/"
    return 1
  fi
  echo "fuzz: $target: ${seconds} s"
  grep -E "stat::number_of_executed_units|cov:" "$artifacts/$target.log" | tail -n 2 || true
}

declare -A running=()  # pid -> target
failed=()
finish_one() {
  local pid status=0
  wait -n -p pid "${!running[@]}" || status=$?
  cat "$artifacts/${running[$pid]}.report"
  [ "$status" -eq 0 ] || failed+=("${running[$pid]}")
  unset "running[$pid]"
}
for dir in tests/fuzz/corpus/*/; do
  target=$(basename "$dir")
  while [ ${#running[@]} -ge "$jobs" ]; do finish_one; done
  fuzz_target "$target" "$dir" >"$artifacts/$target.report" 2>&1 &
  running[$!]=$target
done
while [ ${#running[@]} -gt 0 ]; do finish_one; done
if [ ${#failed[@]} -gt 0 ]; then echo "fuzz: failed: ${failed[*]}"; exit 1; fi
echo "fuzz: every target ran ${seconds} s without a crash, leak or hang"
