#!/usr/bin/env bash
# Runs `dashbed run` on hand-written worlds and compares each outcome with the one its manifest
# expects: the exit code and a text the output must contain (PASSED, an infeasibility reason,
# the file:line:field of a bad input).
#
#   tools/check_worlds.sh [-d DASHBED] [-o OUT_DIR] [-j JOBS] [-m MANIFEST] [NAME...]
#
# Defaults: build/dashbed, build/check_worlds, 1 job, worlds/handwritten/expected.tsv; NAMEs
# pick manifest rows (all when none). Each world's output, plan and report are kept in OUT_DIR.
# Prints one line per world and a summary; exits 1 when any world's outcome differs.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dashbed="$root/build/dashbed"
out_dir="$root/build/check_worlds"
jobs=1
manifest="$root/worlds/handwritten/expected.tsv"
while getopts "d:o:j:m:h" opt; do
  case "$opt" in
    d) dashbed=$OPTARG ;;
    o) out_dir=$OPTARG ;;
    j) jobs=$OPTARG ;;
    m) manifest=$OPTARG ;;
    *) sed -n '2,10p' "${BASH_SOURCE[0]}" | cut -c3-; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[[ -x "$dashbed" ]] || { echo "check_worlds: no dashbed binary at $dashbed" >&2; exit 2; }
[[ -r "$manifest" ]] || { echo "check_worlds: cannot read manifest $manifest" >&2; exit 2; }
world_dir=$(dirname "$manifest")
mkdir -p "$out_dir"

# manifest rows: name <TAB> exit code <TAB> expected text <TAB> ctest label (comments: #)
rows=$(grep -v '^#' "$manifest" | grep -v '^[[:space:]]*$')
if (($# > 0)); then
  wanted=$(printf '%s\n' "$@")
  rows=$(awk -F'\t' 'NR == FNR { want[$1] = 1; next } ($1 in want)' <(echo "$wanted") <(echo "$rows"))
  for name in "$@"; do
    grep -q "^$name"$'\t' <<<"$rows" || { echo "check_worlds: $name is not in $manifest" >&2; exit 2; }
  done
fi

# one world: run it, print "ok|FAIL name (exit N, seconds) detail"
check_one() {
  local name=$1 want_code=$2 want_text=$3
  local log="$out_dir/$name"
  local start=$SECONDS code=0
  "$dashbed" run "$world_dir/$name.yaml" --quiet --plan-out "$log.plan.json" --report "$log.report.json" \
    >"$log.out" 2>"$log.err" || code=$?
  local took=$((SECONDS - start)) verdict=ok detail=""
  if [[ "$code" != "$want_code" ]]; then
    verdict=FAIL detail="expected exit $want_code"
  elif ! grep -qsF -- "$want_text" "$log.out" "$log.err" "$log.report.json"; then
    verdict=FAIL detail="output and report lack '$want_text'"
  fi
  [[ "$verdict" == ok ]] || detail="$detail; see $log.out, $log.err"
  printf '%-4s %-26s exit %s, %3d s %s\n' "$verdict" "$name" "$code" "$took" "$detail"
}
export -f check_one
export dashbed out_dir world_dir

# each row goes to its job as one argument: no quoting of the expected texts
results=$(echo "$rows" |
  xargs -d '\n' -n 1 -P "$jobs" bash -c 'IFS=$'"'"'\t'"'"' read -r n c t _ <<<"$1"; check_one "$n" "$c" "$t"' _)
echo "$results" | sort -k2
total=$(echo "$results" | grep -c .)
failed=$(echo "$results" | grep -c '^FAIL' || true)
echo "check_worlds: $((total - failed)) of $total worlds as expected"
((failed == 0))
