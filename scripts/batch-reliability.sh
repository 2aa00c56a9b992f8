#!/usr/bin/env bash
# Reliability evidence for `bespoke batch` (docs/batch.md):
#   1. 100 inputs: 90 generated scans + 10 malformed/hostile files (truncated,
#      huge count, all NaN, zero points, empty, garbage, header lying about its
#      types, a folder named like a scan, a FIFO, a dangling symlink). Every good
#      scan must come out ok, every bad one be listed with an input_error
#      reason, and the exit code be 1 (some scans failed on bad input).
#   2. Interrupt and resume: the same batch again, kill -9 mid-run, debris
#      added (stray temporary files, a half-written folder, a damaged output),
#      then --resume: summary.csv and failures.csv must be byte-identical to
#      the uninterrupted run's, with no lost or duplicated rows.
# Usage: scripts/batch-reliability.sh [WORK_DIR]   (default /tmp/bespoke-reliability)
#   BUILD_DIR (default build), JOBS (default: all CPUs), POINTS (default 100000)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
BESPOKE=$PWD/$BUILD_DIR/bespoke
CORPUS=$PWD/$BUILD_DIR/batch_corpus
WORK=${1:-/tmp/bespoke-reliability}
JOBS=${JOBS:-0}
POINTS=${POINTS:-100000}
for tool in "$BESPOKE" "$CORPUS"; do
  [ -x "$tool" ] || { echo "missing $tool: build first (scripts/build.sh)" >&2; exit 2; }
done
rm -rf "$WORK"
mkdir -p "$WORK"
fail() { echo "FAIL: $*" >&2; exit 1; }

echo "== generating 90 scans ($POINTS points) + 10 hostile files in $WORK/in"
"$CORPUS" "$WORK/in" --good 90 --points "$POINTS" --hostile
entries=$(find "$WORK/in" -mindepth 1 -maxdepth 1 ! -name '.*' | wc -l)
[ "$entries" -eq 100 ] || fail "expected 100 inputs, found $entries"

echo "== run 1: uninterrupted"
start=$(date +%s.%N)
set +e
"$BESPOKE" --quiet batch "$WORK/in" -o "$WORK/out" --jobs "$JOBS"
rc=$?
set -e
end=$(date +%s.%N)
rows=$(($(wc -l < "$WORK/out/summary.csv") - 1))
ok=$(grep -c ',ok,' "$WORK/out/summary.csv" || true)
failed=$(($(wc -l < "$WORK/out/failures.csv") - 1))
input_errors=$(grep -c ',input_error,' "$WORK/out/failures.csv" || true)
echo "exit code $rc; rows $rows; ok $ok; failed $failed (input_error $input_errors);" \
     "wall $(awk "BEGIN{printf \"%.1f\", $end - $start}") s"
[ "$rc" -eq 1 ] || fail "exit code $rc, expected 1"
[ "$rows" -eq 100 ] && [ "$ok" -eq 90 ] && [ "$failed" -eq 10 ] && [ "$input_errors" -eq 10 ] \
  || fail "counts differ from 100 rows / 90 ok / 10 input_error"
cut -d, -f1,3,6- "$WORK/out/failures.csv" | sed "s|$WORK/in/||g" | cut -c1-150
# Every good scan measured: its measurements.json exists and holds measurements
# (the summary's "measurements" column); skipped ones are listed with reasons.
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) { if ($i == "measurements") m = i; if ($i == "measurements_skipped") k = i } }
         NR > 1 && $2 == "ok" { n++; if ($m + 0 < 1) bad++; if (min == "" || $m < min) min = $m;
                                if ($m > max) max = $m; skipped += $k; if ($k > 0) with++ }
         END { printf "measured: %d ok scans, %d-%d measurements each, %d skipped in %d scans\n", n, min, max, skipped, with;
               exit bad > 0 }' "$WORK/out/summary.csv" || fail "an ok scan has no measurements"
for f in "$WORK"/out/*/measurements.json; do
  grep -q '"skipped": \[\]' "$f" || echo "  $(basename "$(dirname "$f")"): $(grep -o '"reason": "[^"]*"' "$f" | sort -u | head -3 | tr '\n' ' ')"
done

echo "== run 2: kill -9 after 30 scans, debris, --resume"
"$BESPOKE" --quiet batch "$WORK/in" -o "$WORK/out2" --jobs "$JOBS" 2>/dev/null &
pid=$!
while [ "$(find "$WORK/out2" -mindepth 2 -maxdepth 2 -name done.json 2>/dev/null | wc -l)" -lt 30 ]; do
  kill -0 "$pid" 2>/dev/null || fail "the batch finished before it could be killed"
  sleep 0.05
done
kill -9 "$pid"
wait "$pid" 2>/dev/null || true
killed_at=$(find "$WORK/out2" -mindepth 2 -maxdepth 2 -name done.json | wc -l)
sleep 1
partial=$(for d in "$WORK"/out2/good_*/; do [ -f "$d/done.json" ] || echo "$d"; done | wc -l)
echo "killed with $killed_at scans done; $partial planned scan folders without done.json"
done_good=$(find "$WORK/out2" -mindepth 2 -maxdepth 2 -path '*/good_*/done.json' | sort)
first_done=$(dirname "$(echo "$done_good" | sed -n 1p)")
echo '{"torn' > "$first_done/measurements.json.tmp-424242-0"
echo 'scan_id,sta' > "$WORK/out2/summary.csv.tmp-424242-1"
mkdir -p "$WORK/out2/good_089" && echo 'half' > "$WORK/out2/good_089/input.json"
second_done=$(dirname "$(echo "$done_good" | sed -n 2p)")
out_file=$(ls "$second_done" | grep -v -e done.json -e run.log | sed -n 1p || true)
echo '{}' > "$second_done/$out_file"   # damaged after done.json: must be redone
set +e
"$BESPOKE" --quiet batch "$WORK/in" -o "$WORK/out2" --jobs "$JOBS" --resume
rc2=$?
set -e
[ "$rc2" -eq 1 ] || fail "resumed exit code $rc2, expected 1"
cmp "$WORK/out/summary.csv" "$WORK/out2/summary.csv" || fail "summary.csv differs after resume"
cmp "$WORK/out/failures.csv" "$WORK/out2/failures.csv" || fail "failures.csv differs after resume"
dups=$(cut -d, -f1 "$WORK/out2/summary.csv" | sort | uniq -d | wc -l)
[ "$dups" -eq 0 ] || fail "$dups duplicated rows"
stray=$(find "$WORK/out2" -name '*.tmp-*' | wc -l)
[ "$stray" -eq 0 ] || fail "$stray temporary files left"
echo "resume: exit code $rc2; summary.csv and failures.csv byte-identical to run 1;" \
     "100 rows, no duplicates, no temporary files left"
echo "reports: $WORK/out/report.html $WORK/out2/report.html"
echo "PASS"
