#!/usr/bin/env bash
# README command 1: installs what is needed, builds, and runs the main job on
# data the project generates itself:
#   1. a body (the built-in parametric body, seed 7) and its exact truth
#      (datum points and reference measurements): bespoke synth-body
#   2. a realistic scan of it from a virtual body-scanner booth (noise,
#      occlusion holes, outliers, a floor, in metres, arbitrarily rotated):
#      bespoke scan-sim
#   3. the whole job on that scan: clean + body frame, landmarks,
#      measurements, and a shirt pattern fitted to them: bespoke run
#
#   scripts/demo.sh [OUT_DIR]      (default demo-out/)
#   SEED=N  another body; DESIGN=trousers  another pattern
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-demo-out}
seed=${SEED:-7}
design=${DESIGN:-shirt}
scripts/setup-debian.sh
TARGETS=bespoke scripts/build.sh  # only what the demo runs; scripts/test.sh builds the rest
bespoke=${BUILD_DIR:-build}/bespoke
mkdir -p "$out"

echo "== 1. body (parametric, seed $seed) and its truth"
"$bespoke" synth-body --seed "$seed" -o "$out/body.obj" --truth "$out/truth.json"
echo "== 2. virtual scan (metres, rotated, 1 mm noise, 2 % outliers, floor)"
"$bespoke" scan-sim "$out/body.obj" -o "$out/scan.ply" --truth "$out/truth.json" \
  --seed "$seed" --transform random --units m --preview "$out/scan.png"
echo "== 3. the job: clean, landmarks, measurements, $design pattern"
rm -rf "$out/run"
"$bespoke" run "$out/scan.ply" -o "$out/run" --design "$design"

echo
echo "Outputs in $out/:"
echo "  body.obj, truth.json     the generated body and its exact datum points and measurements"
echo "  scan.ply, scan.png       the simulated scan and a picture of it"
for f in "$out"/run/*; do
  echo "  run/$(basename "$f")"
done
