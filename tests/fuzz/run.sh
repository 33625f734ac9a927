#!/usr/bin/env bash
# Runs every libFuzzer harness of tests/fuzz for SECONDS each (default 60), with ASan and
# UBSan, on a corpus grown from the test fixtures and tests/fuzz/seeds. A crash, a hang of
# more than 5 s on one input, a leak or an undocumented exception fails the run; the input
# that did it is kept as BUILD/fuzz-findings/HARNESS/crash-... (or timeout-, leak-, oom-).
#
#   tools/setup.sh --fuzz && tests/fuzz/run.sh [SECONDS] [--only H1,H2] [--record FILE]
#
# --only runs just the named harnesses (long runs can be spread over several sittings).
# --record FILE updates the table between "<!-- fuzz:begin -->" and "<!-- fuzz:end -->" in FILE:
# the rows of the harnesses run are replaced with the coverage reached and today's date, the
# others kept; the line below it names the latest run's version and machine.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
seconds=60
record=""
harnesses=(fuzz_world fuzz_plan fuzz_report fuzz_outcomes fuzz_script fuzz_foreign fuzz_numbers)
while (($# > 0)); do
  case "$1" in
    --record) record=$2; shift 2 ;;
    --only) IFS=, read -r -a harnesses <<<"$2"; shift 2 ;;
    *) seconds=$1; shift ;;
  esac
done
build="$root/build-fuzz"
here="$root/tests/fuzz"
rows=""
declare -A reads=(
  [fuzz_world]="world YAML" [fuzz_plan]="plan JSON, checked against the default world"
  [fuzz_report]="report JSON (and its JUnit XML)" [fuzz_outcomes]="stress outcome JSON"
  [fuzz_script]="action scripts" [fuzz_foreign]="trajectories made elsewhere (ROS 2 YAML, CSV, gripper YAML)"
  [fuzz_numbers]="command-line numbers"
)

# the harness and the folders of inputs it starts from
declare -A seeds=(
  [fuzz_world]="$root/tests/core/worlds/good $root/tests/core/worlds/bad $root/worlds $root/worlds/handwritten"
  [fuzz_plan]="$root/tests/core/plans/good $root/tests/core/plans/bad"
  [fuzz_report]="$here/seeds/report"
  [fuzz_outcomes]="$here/seeds/outcomes"
  [fuzz_script]="$here/seeds/script"
  [fuzz_foreign]="$here/seeds/foreign"
  [fuzz_numbers]="$here/seeds/numbers"
)

failed=()
for harness in "${harnesses[@]}"; do
  [[ -n "${seeds[$harness]:-}" ]] || { echo "fuzz: no harness $harness" >&2; exit 2; }
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
    cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*')
    ft=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*')
    runs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | grep -o '[0-9]*$')
    size=$(ls "$corpus" | wc -l)
    echo "fuzz: $harness: $runs inputs in $seconds s, coverage $cov edges, $ft features, corpus $size"
    rows+="| \`$harness\` | ${reads[$harness]} | $seconds | $runs | $cov | $ft | $size | $(date -u +%Y-%m-%d) |"$'\n'
  else
    echo "fuzz: $harness FAILED; the input: $(ls -t "$findings" | head -1); log: $log" >&2
    tail -40 "$log" >&2
    failed+=("$harness")
  fi
done
((${#failed[@]} == 0)) || { echo "fuzz: findings in ${failed[*]}" >&2; exit 1; }

if [[ -n "$record" ]]; then
  version=$(grep -oP 'project\(dashbed VERSION \K[0-9.]+' "$root/CMakeLists.txt")
  machine="$(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores"
  footer="Each row is its harness's latest long run (\`tests/fuzz/run.sh SECONDS --only HARNESS --record\`). Latest: dashbed $version, $machine, $(clang++ --version | head -1)."
  python3 - "$record" "$rows" "$footer" <<'PY'
import sys
path, rows, footer = sys.argv[1], sys.argv[2], sys.argv[3]
order = ["fuzz_world", "fuzz_plan", "fuzz_report", "fuzz_outcomes", "fuzz_script", "fuzz_foreign", "fuzz_numbers"]
text = open(path).read()
begin, end = "<!-- fuzz:begin -->", "<!-- fuzz:end -->"
i, j = text.index(begin) + len(begin), text.index(end)
def name(row):
    return row.split("|")[1].strip().strip("`")
kept = {name(r): r for r in text[i:j].splitlines() if r.startswith("| `")}
kept.update({name(r): r for r in rows.splitlines() if r})
header = "| harness | reads | seconds | inputs run | coverage (edges) | features | corpus | date |\n|---|---|---:|---:|---:|---:|---:|---|"
table = "\n".join([header] + [kept[h] for h in order if h in kept])
open(path, "w").write(text[:i] + "\n" + table + "\n\n" + footer + "\n" + text[j:])
PY
  echo "fuzz: recorded in $record"
fi
