#!/usr/bin/env bash
# Runs every libFuzzer target of a fuzz build (tests/fuzz/CMakeLists.txt) for SECONDS each:
# first replays the inputs that once crashed it (tests/fuzz/regressions/TARGET), then fuzzes
# from the seed corpus. Fails on any crash, leak, timeout (a hang) or out-of-memory; the
# offending input is left in build-fuzz/fuzz-artifacts/ to be added to regressions/.
#   bash scripts/fuzz.sh BUILD_DIR [SECONDS]
set -euo pipefail
build=$1 seconds=${2:-30}
cd "$(dirname "$0")/.."
artifacts="$build/fuzz-artifacts"
mkdir -p "$artifacts"
failed=()
export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
for dir in tests/fuzz/corpus/*/; do
  target=$(basename "$dir")
  binary="$build/tests/fuzz/lamina_fuzz_$target"
  work="$build/fuzz-corpus/$target"
  mkdir -p "$work"
  regressions=(tests/fuzz/regressions/"$target"/*)
  if [ -e "${regressions[0]}" ]; then
    echo "fuzz: $target: replaying ${#regressions[@]} regression inputs"
    "$binary" -timeout=10 -rss_limit_mb=2048 "${regressions[@]}" >"$artifacts/$target-replay.log" 2>&1 ||
      { tail -n 40 "$artifacts/$target-replay.log"; echo "fuzz: $target: a regression input fails"
        failed+=("$target"); continue; }
  fi
  echo "fuzz: $target: ${seconds} s"
  # -timeout: one input taking 10 s is a hang; -rss_limit_mb: a reader must not exhaust memory.
  if ! "$binary" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
       -artifact_prefix="$artifacts/$target-" -print_final_stats=1 \
       "$work" "$dir" >"$artifacts/$target.log" 2>&1; then
    tail -n 40 "$artifacts/$target.log"
    echo "fuzz: $target: failed; the input is in $artifacts/"
    failed+=("$target"); continue
  fi
  grep -E "stat::number_of_executed_units|cov:" "$artifacts/$target.log" | tail -n 2 || true
done
if [ ${#failed[@]} -gt 0 ]; then echo "fuzz: failed: ${failed[*]}"; exit 1; fi
echo "fuzz: every target ran ${seconds} s without a crash, leak or hang"
