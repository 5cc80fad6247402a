#!/usr/bin/env bash
# Runs each fuzz target of tests/fuzz for a fixed time over its committed corpus
# (corpus/NAME) and its past findings (findings/NAME), two at a time; stops by
# itself. Any crash, sanitizer report, failed check, leak or input slower than
# 10 s fails the run; the input is kept in the scratch folder printed at the end.
# New inputs go to the scratch folder, not into the repository, unless
# --update-corpus is given (a long run, docs/robustness.md).
# Usage: tests/fuzz/run_fuzzers.sh [--update-corpus] BUILD_DIR SECONDS [NAME...]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
update=0
[ "${1:-}" = --update-corpus ] && { update=1; shift; }
build=$(cd "$1" && pwd)
seconds=$2
shift 2
names=("$@")
[ ${#names[@]} -gt 0 ] || names=(decimal law table_spec scene points table_csv proven_table surrogate dem)
scratch=$(mktemp -d "${TMPDIR:-/tmp}/viscor-fuzz.XXXXXX")

run_one() {
  local name=$1 out
  out=$scratch/$name
  mkdir -p "$out/new"
  local dirs=("$out/new" "$here/corpus/$name")
  [ "$update" = 1 ] && dirs=("$here/corpus/$name")
  [ -d "$here/findings/$name" ] && dirs+=("$here/findings/$name")
  local start=$SECONDS
  if "$build/tests/fuzz/fuzz_$name" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
       -artifact_prefix="$out/" "${dirs[@]}" > "$out/log" 2>&1; then
    echo "fuzz $name: $(grep -a -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$out/log" | grep -o '[0-9]*$') runs in" \
         "$((SECONDS - start)) s, corpus $(ls "$here/corpus/$name" | wc -l) committed + $(ls "$out/new" | wc -l) new, no finding"
  else
    echo "fuzz $name: FINDING (log: $out/log)"
    grep -a -E 'ERROR|runtime error|fuzz check failed|SUMMARY|Test unit written|^==' "$out/log" | head -20
    return 1
  fi
}
export -f run_one
export scratch here build seconds update

status=0
printf '%s\n' "${names[@]}" | xargs -P 2 -I{} bash -c 'run_one {}' || status=1
if [ "$status" -eq 0 ]; then
  rm -rf "$scratch"
  echo "fuzz: ${#names[@]} targets, ${seconds} s each, no finding"
else
  echo "fuzz: findings above; inputs and logs in $scratch" >&2
fi
exit "$status"
