#!/usr/bin/env bash
# Speed of `bespoke measure` on a ~500k-point virtual scan, load to
# measurements written, with the per-stage table (wall and CPU). A reference
# run of `bespoke clean` on the same file in the same script gives the ratio
# (wall figures on a shared machine vary; CPU and ratios are steadier).
#   BUILD_DIR (default build)  RUNS (default 3)  OUT (default /tmp/bespoke-bench-measure)
#   MODEL=makehuman: a MakeHuman body of the full population, arms at 30 deg,
#   scanned by the 500k booth (needs ../shared), instead of the parametric one
set -euo pipefail
cd "$(dirname "$0")/.."
bespoke=${BUILD_DIR:-build}/bespoke
runs=${RUNS:-3}
model=${MODEL:-parametric}
out=${OUT:-/tmp/bespoke-bench-measure-$model}
mkdir -p "$out"
if [ ! -f "$out/scan.ply" ] && [ "$model" = makehuman ]; then
  "$bespoke" --quiet synth-body --model makehuman --population full --posture arms-30 --seed 7 \
    -o "$out/body.obj" --truth "$out/truth.json"
  "$bespoke" --quiet scan-sim "$out/body.obj" -o "$out/scan.ply" --truth "$out/truth.json" \
    --booth 500k --seed 7
elif [ ! -f "$out/scan.ply" ]; then
  "$bespoke" --quiet synth-body --seed 3 -o "$out/body.obj" --truth "$out/truth.json"
  "$bespoke" --quiet scan-sim "$out/body.obj" -o "$out/scan.ply" --truth "$out/truth.json" \
    --resolution 290x216 --seed 3
fi
"$bespoke" info "$out/scan.ply" | head -3
echo "== reference: bespoke clean (read + clean + write)"
/usr/bin/time -f "clean: wall %e s, cpu %U+%S s" "$bespoke" --quiet clean "$out/scan.ply" -o "$out/clean.ply"
for i in $(seq "$runs"); do
  echo "== bespoke measure, run $i"
  /usr/bin/time -f "measure process: wall %e s, cpu %U+%S s, max RSS %M kB" \
    "$bespoke" measure "$out/scan.ply" -o "$out/m.json" --csv "$out/m.csv" --vit "$out/m.vit" \
    --freesewing "$out/fs.json" 2>&1 | grep -v '^info'
done
