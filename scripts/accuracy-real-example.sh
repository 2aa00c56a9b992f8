#!/usr/bin/env bash
# The example of docs/accuracy.md ("Real subjects: scans against a tape"),
# made from the oracle: `bespoke accuracy --scans` run on a folder of scans
# and a REF.csv as a user would bring them, with the oracle's exact truth
# standing in for the tape.
#
#   scripts/accuracy-real-example.sh [OUT_DIR]      (default: a new temp dir)
#   BUILD_DIR (default build)  COUNT (default 10 subjects)  SEED (default 5)
#   JOBS (scans measured at once; default all CPUs)
#
# 1. `bespoke synth-set --count COUNT --seed SEED --units mm`: parametric
#    subjects (body seed SEED * 1000 + i + 1), each with its exact truth and
#    one scan in the default booth.
# 2. A second scan of each body (`bespoke scan-sim`, another scanner seed,
#    the body placed anew in the booth with --transform random).
# 3. OUT_DIR/scans/subject_<i>_1.ply and subject_<i>_2.ply, and
#    OUT_DIR/REF.csv: one row per subject and measurement with the truth's
#    value (method "oracle truth").
# 4. `bespoke accuracy --scans OUT_DIR/scans --reference OUT_DIR/REF.csv -o
#    OUT_DIR/report`, then summary.csv and repeatability.csv printed as one
#    Markdown table (the table of docs/accuracy.md).
# About 20 s of CPU per subject (its exact truth, two scans measured).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
COUNT=${COUNT:-10}
SEED=${SEED:-5}
OUT=${1:-$(mktemp -d /tmp/accuracy-real.XXXXXX)}
BESPOKE="$BUILD_DIR/bespoke"
[ -x "$BESPOKE" ] || { echo "missing $BESPOKE (build it: cmake --build $BUILD_DIR --target bespoke)" >&2; exit 1; }
jobs=()
[ -n "${JOBS:-}" ] && jobs=(--jobs "$JOBS")
mkdir -p "$OUT/scans"

"$BESPOKE" -q synth-set --count "$COUNT" --seed "$SEED" --units mm -o "$OUT/set"
echo "subject,measurement,value_mm,method" > "$OUT/REF.csv"
for ((i = 0; i < COUNT; ++i)); do
  subject=$(printf "subject_%03d" "$i")
  cp "$OUT/set/$subject/scan.ply" "$OUT/scans/${subject}_1.ply"
  "$BESPOKE" -q scan-sim "$OUT/set/$subject/body.obj" --units mm --transform random \
    --seed $((SEED * 1000 + i + 1 + 500000)) -o "$OUT/scans/${subject}_2.ply"
  # truth.json is ours: pretty-printed, keys sorted, so each measurement's
  # "name" line comes before its "value_mm" line.
  awk -v subject="$subject" '
    /^  "measurements": \[/ { inside = 1; next }
    inside && /^  \]/ { inside = 0 }
    inside && /^      "name": / { name = $2; gsub(/[",]/, "", name) }
    inside && /^      "value_mm": / { v = $2; gsub(/,/, "", v); if (v != "null") print subject "," name "," v ",oracle truth" }
    inside && /^    }/ { name = "" }' "$OUT/set/$subject/truth.json" >> "$OUT/REF.csv"
done
rm -f "$OUT"/scans/*.scan.json

"$BESPOKE" accuracy --scans "$OUT/scans" --reference "$OUT/REF.csv" "${jobs[@]}" -o "$OUT/report"

echo
echo "| measurement | class | limit (mm) | n | bias (mm) | SD (mm) | 95 % CI of the mean (mm) | limits of agreement (mm) | MAE (mm) | verdict | within-subject SD (mm) | repeatability coefficient (mm) |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
awk -F, 'function f(x, d) { return x == "" ? "-" : sprintf("%." d "f", x) }
  FNR == 1 { for (i = 1; i <= NF; ++i) c[FILENAME, $i] = i; next }
  FILENAME ~ /repeatability/ { sw[$1] = $c[FILENAME, "within_subject_sd_mm"]; rc[$1] = $c[FILENAME, "repeatability_coefficient_mm"]; next }
  { s = FILENAME
    printf "| %s | %s | %s | %s | %s | %s | [%s, %s] | [%s, %s] | %s | %s | %s | %s |\n",
      $c[s, "measurement"], $c[s, "iso_class"], $c[s, "tolerance_mm"], $c[s, "n"], f($c[s, "bias_mm"], 1),
      f($c[s, "sd_mm"], 1), f($c[s, "ci_low_mm"], 1), f($c[s, "ci_high_mm"], 1), f($c[s, "loa_low_mm"], 1),
      f($c[s, "loa_high_mm"], 1), f($c[s, "mae_mm"], 1), $c[s, "verdict"], f(sw[$1], 2), f(rc[$1], 2) }' \
  "$OUT/report/repeatability.csv" "$OUT/report/summary.csv"
echo
echo "report: $OUT/report/index.html"
