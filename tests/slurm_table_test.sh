#!/usr/bin/env bash
# The Slurm job array of docs/tables.md ("Shards and batch schedulers"), run on a real
# single-node Slurm cluster started here from Debian's packages (munge, slurmctld,
# slurmd; tools/install-deps.sh installs them): the script is extracted from the page
# and submitted unchanged (sbatch options on the command line set the array size and
# the CPUs of this machine), one array task is sent SIGTERM mid-run as the time limit
# does (--signal), requeued so that it continues with --resume, and the shards merged
# with `viscor table merge` must give, byte for byte, the table of one process.
#
# Usage: slurm_table_test.sh SOURCE_DIR BUILD_DIR (the directory holding the viscor program)
# (VISCOR_SLURM_TEST_LOGS=1 prints the daemons' and tasks' logs on success too.)
# Exit 77 (skipped) when Slurm or munge is missing, unless VISCOR_REQUIRE_ALL_DEPS=1
# (CMake's VISCOR_REQUIRE_ALL_DEPS=ON): then that is a failure.
# The cluster (munged, slurmctld, slurmd: private key, socket, ports, state and spool
# directories in a temporary directory) is stopped and removed on every exit: by a
# trap, and by a reaper in its own session that outlives a killed test.
set -uo pipefail

# Stops what the test started in WORK (the job, the daemons whose ids are in
# WORK/daemons.pid) and removes WORK; does nothing when WORK is gone.
cleanup_cluster() {
  local work=$1 job pid pids=()
  [ -d "$work" ] || return 0
  if [ -f "$work/job.id" ] && [ -f "$work/slurm.conf" ]; then
    # the job's processes run under slurmstepd, which outlives slurmd: cancel, then wait
    job=$(cat "$work/job.id")
    SLURM_CONF="$work/slurm.conf" scancel --quiet "$job" > /dev/null 2>&1
    for _ in $(seq 100); do
      [ -z "$(SLURM_CONF="$work/slurm.conf" squeue --noheader --jobs="$job" --states=RUNNING,COMPLETING 2> /dev/null)" ] &&
        break
      sleep 0.2
    done
  fi
  [ -f "$work/daemons.pid" ] && mapfile -t pids < "$work/daemons.pid"
  for pid in "${pids[@]}"; do kill -TERM "$pid" 2> /dev/null; done
  for _ in $(seq 50); do
    local alive=0
    for pid in "${pids[@]}"; do kill -0 "$pid" 2> /dev/null && alive=1; done
    [ "$alive" = 0 ] && break
    sleep 0.1
  done
  for pid in "${pids[@]}"; do kill -KILL "$pid" 2> /dev/null; done
  rm -rf "$work"
}

# The reaper (started below in its own session): waits for the test's shell to end,
# however it ends (a trap does not run on SIGKILL, as at a ctest timeout), then cleans up.
if [ "${1:-}" = --reap ]; then
  while kill -0 "$2" 2> /dev/null; do sleep 0.5; done
  cleanup_cluster "$3"
  exit 0
fi

self="$(cd "$(dirname "$0")" && pwd)/$(basename "$0")"
source_dir=$(cd "$1" && pwd)
build_dir=$(cd "$2" && pwd)
viscor="$build_dir/viscor"  # BUILD_DIR: the directory of the viscor program
tasks=4

fail() {
  echo "slurm_table_test: [${SECONDS}s] FAIL: $*" >&2
  dump_logs
  exit 1
}

missing=()
for tool in munged slurmctld slurmd sbatch scontrol scancel squeue; do
  command -v "$tool" > /dev/null 2>&1 || [ -x "/usr/sbin/$tool" ] || missing+=("$tool")
done
# slurmd starts job steps as their user, which needs root (CI runs as root).
[ "$(id -u)" -eq 0 ] || missing+=("root (slurmd must run as root)")
if [ "${#missing[@]}" -gt 0 ]; then
  if [ "${VISCOR_REQUIRE_ALL_DEPS:-0}" = "1" ]; then
    echo "slurm_table_test: [${SECONDS}s] FAIL: missing (required by VISCOR_REQUIRE_ALL_DEPS): ${missing[*]}" \
         "(apt-get install slurm-wlm munge, or tools/install-deps.sh)" >&2
    exit 1
  fi
  echo "slurm_table_test: [${SECONDS}s] SKIP: missing ${missing[*]} (apt-get install slurm-wlm munge)"
  exit 77
fi
PATH="$PATH:/usr/sbin:/sbin"
[ -x "$viscor" ] || { echo "slurm_table_test: [${SECONDS}s] FAIL: no $viscor (build viscor_cli)" >&2; exit 1; }

work=$(mktemp -d "${TMPDIR:-/tmp}/viscor-slurm.XXXXXX")
chmod 700 "$work"
setsid bash "$self" --reap $$ "$work" < /dev/null > /dev/null 2>&1 &

dump_logs() {
  for log in "$work"/*.out "$work"/munged.log "$work"/slurmctld.log "$work"/slurmd.log "$work"/run/slurm-*.out; do
    [ -f "$log" ] || continue
    echo "----- ${log#"$work"/} (last 60 lines) -----" >&2
    tail -n 60 "$log" >&2
  done
}

cleanup() { cleanup_cluster "$work"; }
trap cleanup EXIT
trap 'exit 1' INT TERM HUP

# wait_for SECONDS DESCRIPTION COMMAND...: polls COMMAND every 0.1 s.
wait_for() {
  local seconds=$1 what=$2
  shift 2
  local deadline=$((SECONDS + seconds))
  until "$@"; do
    [ "$SECONDS" -lt "$deadline" ] || fail "timed out after ${seconds}s waiting for $what"
    sleep 0.1
  done
}

# --- munge: a private key and socket --------------------------------------------------
mkdir -p "$work/munge" "$work/state" "$work/spool" "$work/run"
chmod 700 "$work/munge"
if command -v mungekey > /dev/null 2>&1 || [ -x /usr/sbin/mungekey ]; then
  mungekey --create --keyfile="$work/munge/munge.key" --force > /dev/null 2>&1 ||
    dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none
else
  dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none
fi
chmod 600 "$work/munge/munge.key"
munge_socket="$work/munge/munge.socket"
munged --foreground --force --key-file="$work/munge/munge.key" --socket="$munge_socket" \
       --pid-file="$work/munge/munged.pid" --seed-file="$work/munge/munged.seed" \
       --log-file="$work/munged.log" > "$work/munged.out" 2>&1 &
echo $! >> "$work/daemons.pid"
wait_for 20 "munged's socket" test -S "$munge_socket"

# --- slurm.conf: this node, private ports and directories ----------------------------
node=$(hostname -s)
cpus=$(nproc)
user=$(id -un)
port=$((20000 + (RANDOM % 600) * 64))  # slurmctld port; slurmd: port + 1; srun: the next 62
export SLURM_CONF="$work/slurm.conf"
cat > "$SLURM_CONF" << EOF
ClusterName=viscortest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SrunPortRange=$((port + 2))-$((port + 63))
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$munge_socket
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
MpiDefault=none
ReturnToService=2
KillWait=10
MinJobAge=600
MailProg=/bin/true
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=viscor Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF

slurmctld -D -i -f "$SLURM_CONF" > "$work/slurmctld.out" 2>&1 &
echo $! >> "$work/daemons.pid"
slurmd -D -f "$SLURM_CONF" > "$work/slurmd.out" 2>&1 &
echo $! >> "$work/daemons.pid"
node_idle() { scontrol show node "$node" 2> /dev/null | grep -Eq "State=IDLE"; }
wait_for 60 "node $node to be IDLE (slurmctld and slurmd up)" node_idle

# --- the job script of docs/tables.md, unchanged ---------------------------------------
doc="$source_dir/docs/tables.md"
python3 - "$doc" "$work/run/table.sbatch" << 'EOF' || fail "no Slurm job array script (a sh block with '#SBATCH --array') in docs/tables.md"
import re, sys
text = open(sys.argv[1]).read()
blocks = [b for b in re.findall(r"^```sh\n(.*?)^```", text, re.S | re.M) if "#SBATCH --array" in b]
if len(blocks) != 1:
    sys.exit(1)
open(sys.argv[2], "w").write(blocks[0])
EOF
grep -q -- '--resume' "$work/run/table.sbatch" || fail "the job script does not pass --resume"
merge_command=$(python3 - "$doc" << 'EOF'
import re, sys
text = open(sys.argv[1]).read()
blocks = [b.strip() for b in re.findall(r"^```sh\n(.*?)^```", text, re.S | re.M) if b.strip().startswith("viscor table merge shards/")]
print(blocks[0] if len(blocks) == 1 else "")
EOF
)
[ -n "$merge_command" ] || fail "no 'viscor table merge shards/...' block in docs/tables.md"

# A small spec (laws x g x gamma = 2 x 2 x 301 rows, several seconds of CPU per shard).
cat > "$work/run/spec.json" << 'EOF'
{"laws": ["hertz_linear_damping", "hunt_crossley"],
 "gamma": {"from": 0, "to": 0.15, "step": 0.0005},
 "g": [0, 1],
 "digits": 30, "min_digits": 20}
EOF
mkdir -p "$work/run/shards"
cd "$work/run" || fail "cd"
export PATH="$build_dir:$PATH"  # the script runs `viscor` from PATH, as a user's would

submit=$(sbatch --parsable --array=0-$((tasks - 1)) --cpus-per-task=1 --time=00:10:00 \
         --output="$work/run/slurm-%A_%a.out" --chdir="$work/run" table.sbatch 2>&1) ||
  fail "sbatch failed: $submit"
job=${submit%%;*}
echo "$job" > "$work/job.id"
echo "slurm_table_test: [${SECONDS}s] submitted job array $job (tasks 0-$((tasks - 1)))"

task_state() { scontrol show job "${job}_$1" 2> /dev/null | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | head -n 1; }
task_ended() { case "$(task_state "$1")" in COMPLETED | FAILED | CANCELLED | TIMEOUT | NODE_FAIL | OUT_OF_MEMORY) return 0 ;; esac; return 1; }

# Interrupt task 1 once it has written some rows, as --signal=TERM@... does at a time limit.
victim=1
partial="$work/run/shards/part-$victim.csv.partial"
rows_in_partial() {
  [ -f "$partial" ] && [ "$(wc -l < "$partial")" -ge 6 ] && return 0
  task_ended "$victim" && fail "task $victim ended ($(task_state "$victim")) before it could be interrupted"
  return 1
}
wait_for 120 "task $victim to start writing rows" rows_in_partial
[ -f "$work/run/shards/part-$victim.csv" ] && fail "task $victim finished before it could be interrupted"
# (scancel may report that the batch step is "already completing": the signal goes to the
# step, viscor stops, and the task ends before scancel's retry; the task's state is checked.)
scancel --signal=TERM "${job}_${victim}" > "$work/scancel.log" 2>&1 || echo "scancel: $(cat "$work/scancel.log")"
echo "slurm_table_test: [${SECONDS}s] sent SIGTERM to task ${job}_${victim} after $(wc -l < "$partial") partial lines"

wait_for 120 "task $victim to stop after SIGTERM" task_ended "$victim"
state=$(task_state "$victim")
[ "$state" = FAILED ] || fail "task $victim ended $state after SIGTERM, expected FAILED (viscor exits with an error)"
[ -f "$work/run/shards/part-$victim.csv" ] && fail "task $victim wrote its table although interrupted"
kept=$(($(wc -l < "$partial") - 1))
[ "$kept" -ge 1 ] || fail "task $victim kept no finished rows in $partial"
echo "slurm_table_test: [${SECONDS}s] task $victim stopped (FAILED) with $kept finished rows kept"

# Requeue it: the same array task runs the same script again, and --resume continues.
echo "slurm_table_test: [${SECONDS}s] requeue"; scontrol requeue "${job}_${victim}" || fail "scontrol requeue ${job}_${victim}"
# Slurm delays a requeued job's start by a few minutes; the test asks for it at once.
scontrol update JobId="${job}_${victim}" StartTime=now ||
  echo "slurm_table_test: [${SECONDS}s] note: StartTime=now not set (already started?)"
all_ended() {
  local t
  for t in $(seq 0 $((tasks - 1))); do task_ended "$t" || return 1; done
}
wait_for 240 "every array task to complete" all_ended
for t in $(seq 0 $((tasks - 1))); do
  [ "$(task_state "$t")" = COMPLETED ] || fail "task $t ended $(task_state "$t")"
done
grep -q "resuming: $kept of 301 rows already done" "$work/run/slurm-${job}_${victim}.out" ||
  fail "the requeued task $victim did not resume from its $kept kept rows"
[ -f "$partial" ] && fail "$partial still exists after the requeued task completed"

# Merge exactly as the page does, and compare with one process.
echo "slurm_table_test: [${SECONDS}s] all tasks done"; eval "$merge_command" > merge.log 2>&1 || { cat merge.log >&2; fail "$merge_command"; }
viscor table spec.json -o single.csv --threads "$cpus" --quiet || fail "the one-process run failed"
cmp table.csv single.csv || fail "the merged table differs from the one-process table"
rows=$(($(wc -l < table.csv) - 1))
[ "$rows" -eq 1204 ] || fail "the merged table has $rows rows, expected 2 x 2 x 301 = 1204"
echo "slurm_table_test: [${SECONDS}s] PASS: $tasks array tasks, task $victim interrupted ($kept rows kept) and requeued;" \
     "merged table ($rows rows) byte-identical to the one-process table"
[ "${VISCOR_SLURM_TEST_LOGS:-0}" = 1 ] && dump_logs; true
