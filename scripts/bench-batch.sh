#!/usr/bin/env bash
# Batch throughput benchmark (docs/batch.md): SCANS generated scans of POINTS
# points each, through `bespoke batch` (every step of `bespoke run` that this
# build has: see the "steps" line printed) with --jobs 1 and --jobs 2, fresh
# output folders each time. Prints scans per minute and the speed-up, and
# checks that both runs give the same summary.csv.
# Usage: scripts/bench-batch.sh [WORK_DIR]   (default /tmp/bespoke-bench-batch)
#   BUILD_DIR (default build), SCANS (default 50), POINTS (default 300000),
#   JOBS_LIST (default "1 2")
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
case $BUILD_DIR in /*) ;; *) BUILD_DIR=$PWD/$BUILD_DIR ;; esac
BESPOKE=$BUILD_DIR/bespoke
CORPUS=$BUILD_DIR/batch_corpus
WORK=${1:-/tmp/bespoke-bench-batch}
SCANS=${SCANS:-50}
POINTS=${POINTS:-300000}
JOBS_LIST=${JOBS_LIST:-1 2}
for tool in "$BESPOKE" "$CORPUS"; do
  [ -x "$tool" ] || { echo "missing $tool: build first (scripts/build.sh)" >&2; exit 2; }
done
mkdir -p "$WORK"
if [ "$(find "$WORK/in" -name 'good_*.ply' 2>/dev/null | wc -l)" -ne "$SCANS" ]; then
  rm -rf "$WORK/in"
  echo "generating $SCANS scans of $POINTS body points (+10 % floor) in $WORK/in"
  # The floor adds 10 %, so ask for 300k/1.1 body points to get 300k in all.
  "$CORPUS" "$WORK/in" --good "$SCANS" --points $((POINTS * 10 / 11))
fi
first=$(find "$WORK/in" -name 'good_*.ply' | sort | sed -n 1p)
rm -rf "$WORK/probe"
"$BESPOKE" --quiet run "$first" -o "$WORK/probe" > /dev/null
echo "steps: $(grep -o '"name": "[a-z]*"\|"skipped": "[^"]*"' "$WORK/probe/done.json" | tr '\n' ' ')"
echo "machine: $(nproc) CPUs, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
printf '%-6s %-10s %-12s %-14s %-10s\n' jobs wall_s scans/min mean_scan_s speed-up
base=""
for jobs in $JOBS_LIST; do
  rm -rf "$WORK/out-j$jobs"
  start=$(date +%s.%N)
  set +e
  "$BESPOKE" --quiet batch "$WORK/in" -o "$WORK/out-j$jobs" --jobs "$jobs" 2> "$WORK/log-j$jobs.txt"
  rc=$?
  set -e
  end=$(date +%s.%N)
  [ "$rc" -eq 0 ] || { echo "batch --jobs $jobs exit code $rc (see $WORK/log-j$jobs.txt)" >&2; exit 1; }
  wall=$(awk "BEGIN{print $end - $start}")
  [ -n "$base" ] || base=$wall
  mean=$(awk -F, 'NR>1 {s+=$3; n++} END {printf "%.2f", s/n}' "$WORK/out-j$jobs/timings.csv")
  printf '%-6s %-10.1f %-12.1f %-14s %-10.2f\n' "$jobs" "$wall" \
    "$(awk "BEGIN{print 60 * $SCANS / $wall}")" "$mean" "$(awk "BEGIN{print $base / $wall}")"
done
set -- $JOBS_LIST
if [ $# -ge 2 ]; then
  if cmp -s "$WORK/out-j$1/summary.csv" "$WORK/out-j$2/summary.csv"; then
    echo "summary.csv identical for --jobs $1 and --jobs $2"
  else
    echo "summary.csv DIFFERS between --jobs $1 and --jobs $2" >&2
    exit 1
  fi
fi
