#!/usr/bin/env bash
# Tests the Slurm job array FOR REAL on a one-node cluster on localhost:
#   1. installs Debian's slurm-wlm and munge if missing (apt-get; needs root),
#   2. generates 12 scans plus the 10 malformed/hostile files of the batch
#      tests, and runs `bespoke batch` locally as the reference,
#   3. starts munged, slurmctld and slurmd (as root, ProctrackType=
#      proctrack/linuxproc, a minimal slurm.conf generated in a temp folder,
#      private ports and munge socket, so nothing of the machine's own set-up
#      is touched),
#   4. submits scripts/slurm/bespoke-array.sbatch as a 4-task array with
#      `sbatch --wait`, with try 1 of task 2 killed (SIGKILL) after its first
#      scan, so the task's retry loop has to resume it,
#   5. merges with `bespoke batch-merge` and checks that summary.csv and
#      failures.csv equal the local run's byte for byte and that the report
#      shows the retried shard,
#   6. stops the daemons it started (trap), and removes the temp folder
#      (KEEP=1 keeps it).
# Usage: scripts/slurm/test-slurm.sh
#   BUILD_DIR (default build; relative to the checkout, or absolute)
#   SLURM_TEST_PORT (default 20000 + pid % 10000; slurmd uses the next port)
# Prints the time of each phase; exit 0 on success, 1 on failure, 77 (skip)
# when not root. ctest runs it as `batch_slurm_array` (label slurm).
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD
BUILD_DIR=${BUILD_DIR:-build}
case $BUILD_DIR in /*) ;; *) BUILD_DIR=$ROOT/$BUILD_DIR ;; esac
BESPOKE=$BUILD_DIR/bespoke
CORPUS=$BUILD_DIR/batch_corpus
PORT=${SLURM_TEST_PORT:-$((20000 + $$ % 10000))}
t0=$(date +%s)
phase() { echo "== [$(( $(date +%s) - t0 )) s] $*"; }
fail() { echo "FAIL: $*" >&2; exit 1; }

if [ "$(id -u)" -ne 0 ]; then
  echo "SKIP: needs root (slurmd and munged run as root here)"
  exit 77
fi
for tool in "$BESPOKE" "$CORPUS"; do
  [ -x "$tool" ] || fail "missing $tool: build first (scripts/build.sh)"
done

phase "installing slurm-wlm and munge (if missing)"
if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q
  apt-get install -y -q --no-install-recommends slurm-wlm munge
fi
echo "$(slurmctld -V), munge $(munged --version 2>&1 | head -1)"

TMP=$(mktemp -d /tmp/bespoke-slurm.XXXXXX)
chmod 755 "$TMP"
PIDS=()
cleanup() {
  local pid
  for pid in "${PIDS[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${PIDS[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  done
  if [ "${KEEP:-0}" = 1 ]; then echo "kept $TMP"; else rm -rf "$TMP"; fi
}
trap cleanup EXIT

phase "generating 12 scans + 10 hostile files; local reference run"
"$CORPUS" "$TMP/in" --good 12 --points 40000 --hostile
set +e
"$BESPOKE" --quiet batch "$TMP/in" -o "$TMP/local" --jobs 2
local_rc=$?
set -e
[ "$local_rc" -eq 1 ] || fail "local batch exit code $local_rc, expected 1 (hostile files)"

phase "starting munged, slurmctld, slurmd"
mkdir -p "$TMP/munge" "$TMP/etc" "$TMP/state" "$TMP/spool" "$TMP/log"
chmod 700 "$TMP/munge"
mungekey --create --keyfile="$TMP/munge/munge.key" 2>/dev/null ||
  dd if=/dev/urandom of="$TMP/munge/munge.key" bs=1024 count=1 status=none
chmod 600 "$TMP/munge/munge.key"
munged --force --foreground --socket="$TMP/munge/munge.sock" --key-file="$TMP/munge/munge.key" \
  --pid-file="$TMP/munge/munged.pid" --log-file="$TMP/log/munged.log" \
  --seed-file="$TMP/munge/munged.seed" > "$TMP/log/munged.out" 2>&1 &
PIDS+=($!)
for _ in $(seq 50); do [ -S "$TMP/munge/munge.sock" ] && break; sleep 0.1; done
[ -S "$TMP/munge/munge.sock" ] || fail "munged did not start: $(cat "$TMP/log/munged.out")"

CPUS=$(nproc)
MEM_MB=$(( $(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 / 2 ))
cat > "$TMP/etc/slurm.conf" <<CONF
ClusterName=bespoketest
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$PORT
SlurmdPort=$((PORT + 1))
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$TMP/munge/munge.sock
SlurmUser=root
SlurmdUser=root
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
MpiDefault=none
MailProg=/bin/true
ReturnToService=2
StateSaveLocation=$TMP/state
SlurmdSpoolDir=$TMP/spool
SlurmctldPidFile=$TMP/slurmctld.pid
SlurmdPidFile=$TMP/slurmd.pid
SlurmctldLogFile=$TMP/log/slurmctld.log
SlurmdLogFile=$TMP/log/slurmd.log
SlurmctldTimeout=30
SlurmdTimeout=30
InactiveLimit=0
KillWait=5
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$CPUS RealMemory=$MEM_MB State=UNKNOWN
PartitionName=test Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$TMP/etc/slurm.conf
slurmctld -D -i -f "$SLURM_CONF" > "$TMP/log/slurmctld.out" 2>&1 &
PIDS+=($!)
slurmd -D -N localhost -f "$SLURM_CONF" > "$TMP/log/slurmd.out" 2>&1 &
PIDS+=($!)
state=""
for _ in $(seq 120); do
  state=$(sinfo -h -n localhost -o %T 2>/dev/null || true)
  [ "$state" = idle ] && break
  sleep 0.5
done
[ "$state" = idle ] || fail "node not idle ($state): $(tail -5 "$TMP/log/slurmctld.log" "$TMP/log/slurmd.log")"
sinfo

phase "sbatch --wait: 4-task array, try 1 of task 2 killed after its first scan"
set +e
sbatch --wait --array=1-4 --cpus-per-task=1 --mem=1G --output="$TMP/slurm-%A_%a.out" \
  --export=ALL,BESPOKE="$BESPOKE",BESPOKE_SLURM_KILL_TASK=2 \
  scripts/slurm/bespoke-array.sbatch "$TMP/in" "$TMP/out" --timeout-s 300
sbatch_rc=$?
set -e
for f in "$TMP"/slurm-*.out; do echo "--- $(basename "$f")"; cat "$f"; done
# Task exit codes: 1 where a shard holds hostile files; sbatch --wait then exits 1.
[ "$sbatch_rc" -le 1 ] || fail "sbatch --wait exit code $sbatch_rc"
grep -q "test hook: killed try 1 of shard 2/4" "$TMP"/slurm-*_2.out || fail "task 2 was not killed"
grep -q "shard 2/4 try 2" "$TMP"/slurm-*_2.out || fail "task 2 was not retried"

phase "bespoke batch-merge; comparing with the local run"
set +e
"$BESPOKE" batch-merge "$TMP/out"
merge_rc=$?
set -e
[ "$merge_rc" -eq 1 ] || fail "merge exit code $merge_rc, expected 1"
cmp "$TMP/local/summary.csv" "$TMP/out/summary.csv" || fail "merged summary.csv differs from the local run's"
cmp "$TMP/local/failures.csv" "$TMP/out/failures.csv" || fail "merged failures.csv differs"
grep -q "1 shard(s) needed more than one attempt" "$TMP/out/report.html" ||
  fail "the report does not show the retried shard"
grep -q "task 2 try 2" "$TMP/out/report.html" || fail "the report does not list try 2 of task 2"
rows=$(($(wc -l < "$TMP/out/summary.csv") - 1))
echo "merged: $rows rows, summary.csv and failures.csv identical to the local run's;" \
     "report shows shard 2/4's retry"
phase "PASS (daemons are stopped on exit)"
