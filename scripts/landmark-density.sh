#!/usr/bin/env bash
# How many measurements `bespoke measure` gives on sparse scans: parametric
# bodies (synth-body seeds 1..N) scanned with the default booth at smaller
# depth images per sensor, one line per scan and a total per resolution.
#   BUILD_DIR (default build)  N (default 16)  RESOLUTIONS (default "120x90 100x75")
#   OUT (default /tmp/bespoke-landmark-density; reused: bodies/scans are kept)
set -euo pipefail
cd "$(dirname "$0")/.."
bespoke=$(realpath "${BUILD_DIR:-build}/bespoke")
n=${N:-16}
out=${OUT:-/tmp/bespoke-landmark-density}
mkdir -p "$out"
for res in ${RESOLUTIONS:-120x90 100x75}; do
  complete=0 skipped=0
  for seed in $(seq "$n"); do
    body="$out/body$seed.obj" scan="$out/scan${seed}_$res.ply"
    [ -f "$body" ] || "$bespoke" --quiet synth-body --seed "$seed" -o "$body"
    [ -f "$scan" ] || "$bespoke" --quiet scan-sim "$body" -o "$scan" --resolution "$res" --seed "$seed"
    line=$("$bespoke" measure "$scan" -o "$out/m${seed}_$res.json" 2>&1 | grep 'measurements (' || true)
    s=$(sed -E 's/.* ([0-9]+) skipped.*/\1/' <<< "$line")
    [ -n "$s" ] || s=50
    skipped=$((skipped + s)); [ "$s" = 0 ] && complete=$((complete + 1))
    echo "$res seed $seed: $line"
  done
  echo "== $res: $complete of $n scans with all 50 measurements; $skipped measurements skipped in all"
done
