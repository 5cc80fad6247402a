#!/usr/bin/env bash
# Runs each fuzz target of tests/fuzz for a fixed time over its committed corpus
# (corpus/NAME) and its past findings (findings/NAME), two at a time; stops by
# itself. Any crash, sanitizer report, failed check, leak or input slower than
# the timeout fails the run; the input is kept in the scratch folder printed at
# the end. New inputs go to the scratch folder; with --update-corpus, those that
# reach new code are merged into corpus/NAME at the end (-merge=1).
# --cpu-time: SECONDS counts each fuzzer's own CPU time (user + system), not wall
# time, so a long run on a shared machine gets the time it is credited with; the
# fuzzer is stopped by SIGUSR1 (libFuzzer's graceful exit) once it has used it,
# and an input may take 120 s of wall time before it counts as a hang (a busy
# machine stretches wall time; a CI run keeps 10 s), and every input merged into the
# corpus must then replay within 3 CPU-seconds.
# Usage: tests/fuzz/run_fuzzers.sh [--update-corpus] [--cpu-time] BUILD_DIR SECONDS [NAME...]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
update=0
cpu_time=0
while [ $# -gt 0 ]; do
  case "$1" in
    --update-corpus) update=1; shift ;;
    --cpu-time) cpu_time=1; shift ;;
    *) break ;;
  esac
done
build=$(cd "$1" && pwd)
seconds=$2
shift 2
names=("$@")
[ ${#names[@]} -gt 0 ] || names=(decimal law table_spec scene points table_csv proven_table surrogate dem manifest formula_values)
scratch=$(mktemp -d "${TMPDIR:-/tmp}/viscor-fuzz.XXXXXX")

# CPU seconds (user + system, all threads) a process has used so far.
cpu_seconds_of() {
  local stat
  stat=$(cat "/proc/$1/stat" 2>/dev/null) || { echo 0; return; }
  stat=${stat##*) }   # the fields after the command name, which may hold spaces
  set -- $stat        # now $12 is utime, $13 stime (fields 14 and 15 of proc(5))
  echo $(( (${12} + ${13}) / $(getconf CLK_TCK) ))
}

# The children's CPU seconds (user + system) in the output of bash's `times`,
# which must run in the shell that waited for them, not in a subshell.
children_cpu_seconds() {
  local user sys
  { read -r _; read -r user sys; } < "$1"
  awk -v u="$user" -v s="$sys" 'function sec(t) { split(t, p, /[ms]/); return p[1] * 60 + p[2] }
    BEGIN { printf "%d", sec(u) + sec(s) }'
}

run_one() {
  local name=$1 out fuzzer pid rc=0
  out=$scratch/$name
  fuzzer=$build/tests/fuzz/fuzz_$name
  mkdir -p "$out/new"
  local dirs=("$out/new" "$here/corpus/$name")
  [ -d "$here/findings/$name" ] && dirs+=("$here/findings/$name")
  local committed_before
  committed_before=$(ls "$here/corpus/$name" | wc -l)
  local wall_limit=$seconds timeout=10
  [ "$cpu_time" = 1 ] && { wall_limit=$((seconds * 20)); timeout=120; }
  local start=$SECONDS
  "$fuzzer" -max_total_time="$wall_limit" -timeout="$timeout" -rss_limit_mb=2048 -print_final_stats=1 \
    -handle_usr1=1 -artifact_prefix="$out/" "${dirs[@]}" > "$out/log" 2>&1 &
  pid=$!
  if [ "$cpu_time" = 1 ]; then
    while kill -0 "$pid" 2>/dev/null; do
      if [ "$(cpu_seconds_of "$pid")" -ge "$seconds" ]; then kill -USR1 "$pid" 2>/dev/null || true; break; fi
      sleep 5
    done
  fi
  wait "$pid" || rc=$?
  local used
  times > "$out/times"   # the fuzzer, plus milliseconds of cat and getconf
  used=$(children_cpu_seconds "$out/times")
  if [ "$rc" -ne 0 ]; then
    echo "fuzz $name: FINDING (log: $out/log)"
    grep -a -E 'ERROR|runtime error|fuzz check failed|SUMMARY|Test unit written|^==' "$out/log" | head -20
    return 1
  fi
  local merged=0
  if [ "$update" = 1 ] && [ -n "$(ls -A "$out/new")" ]; then
    ls "$here/corpus/$name" > "$out/committed"
    "$fuzzer" -merge=1 "$here/corpus/$name" "$out/new" > "$out/merge.log" 2>&1
    # A long run's hang limit is 120 s; a CI run's is 10 s of wall time on a slower
    # machine: an input merged now must replay within 3 CPU-seconds, else it is a
    # finding (kept in $out/slow, not committed).
    local input slow=0
    for input in $(ls "$here/corpus/$name" | grep -vxF -f "$out/committed"); do
      if ! (ulimit -t 3; "$fuzzer" "$here/corpus/$name/$input" > /dev/null 2>&1); then
        mkdir -p "$out/slow"
        mv "$here/corpus/$name/$input" "$out/slow/"
        slow=$((slow + 1))
      fi
    done
    merged=$(( $(ls "$here/corpus/$name" | wc -l) - committed_before ))
    if [ "$slow" -gt 0 ]; then
      echo "fuzz $name: FINDING: $slow new inputs took more than 3 CPU-seconds each (kept in $out/slow, not merged)"
      return 1
    fi
  fi
  echo "fuzz $name: $(grep -a -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$out/log" | grep -o '[0-9]*$') runs in" \
       "$((SECONDS - start)) s (${used} s of CPU), corpus $committed_before committed + $(ls "$out/new" | wc -l) new" \
       "($merged merged), no finding"
}
export -f run_one cpu_seconds_of children_cpu_seconds
export scratch here build seconds update cpu_time

status=0
printf '%s\n' "${names[@]}" | xargs -P 2 -I{} bash -c 'run_one {}' || status=1
if [ "$status" -eq 0 ]; then
  rm -rf "$scratch"
  echo "fuzz: ${#names[@]} targets, ${seconds} s each, no finding"
else
  echo "fuzz: findings above; inputs and logs in $scratch" >&2
fi
exit "$status"
