#!/usr/bin/env bash
# Runs every libFuzzer harness of tests/fuzz for SECONDS each (default 60), with ASan and
# UBSan, on a corpus grown from the test fixtures and tests/fuzz/seeds. A crash, a hang of
# more than 5 s on one input, a leak or an undocumented exception fails the run; the input
# that did it is kept as BUILD/fuzz-findings/HARNESS/crash-... (or timeout-, leak-, oom-).
#
#   tools/setup.sh --fuzz && tests/fuzz/run.sh [SECONDS] [BUILD]     (BUILD: build-fuzz/)
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
seconds=${1:-60}
build=${2:-$root/build-fuzz}
here="$root/tests/fuzz"

# the harness and the folders of inputs it starts from
declare -A seeds=(
  [fuzz_world]="$root/tests/core/worlds/good $root/tests/core/worlds/bad $root/worlds $root/worlds/handwritten"
  [fuzz_plan]="$root/tests/core/plans/good $root/tests/core/plans/bad"
  [fuzz_report]="$here/seeds/report"
  [fuzz_outcomes]="$here/seeds/outcomes"
  [fuzz_script]="$here/seeds/script"
  [fuzz_numbers]="$here/seeds/numbers"
)

failed=()
for harness in fuzz_world fuzz_plan fuzz_report fuzz_outcomes fuzz_script fuzz_numbers; do
  binary="$build/tests/fuzz/$harness"
  [[ -x "$binary" ]] || { echo "fuzz: $binary is missing (run tools/setup.sh --fuzz)" >&2; exit 1; }
  corpus="$build/fuzz-corpus/$harness"
  findings="$build/fuzz-findings/$harness"
  mkdir -p "$corpus" "$findings"
  for dir in ${seeds[$harness]}; do
    [[ -n "$(ls -A "$dir")" ]] || { echo "fuzz: seed folder $dir is empty" >&2; exit 1; }
  done
  log="$build/fuzz-findings/$harness.log"
  # the largest fixture plan is about 200 kB: inputs up to 512 kB
  if "$binary" "$corpus" ${seeds[$harness]} -max_total_time="$seconds" -timeout=5 -rss_limit_mb=4096 \
      -max_len=524288 -dict="$here/dashbed.dict" -artifact_prefix="$findings/" -print_final_stats=1 \
      >"$log" 2>&1; then
    echo "fuzz: $harness: $(grep -o 'cov: [0-9]* ft: [0-9]*' "$log" | tail -1), $(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | grep -o '[0-9]*$') inputs in ${seconds} s, corpus $(ls "$corpus" | wc -l)"
  else
    echo "fuzz: $harness FAILED; the input: $(ls -t "$findings" | head -1); log: $log" >&2
    tail -40 "$log" >&2
    failed+=("$harness")
  fi
done
((${#failed[@]} == 0)) || { echo "fuzz: findings in ${failed[*]}" >&2; exit 1; }
