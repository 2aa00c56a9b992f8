#!/usr/bin/env bash
# The resize evidence on oracle bodies (docs/resize.md, "Results"): makes N
# parametric oracle subjects far from the designs' standard size with
# `bespoke synth-body --truth` (exact reference measurements, no scan), then
# runs resize_evidence on them.
#
#   scripts/resize-oracle-evidence.sh [OUT_DIR]      (default: a new temp dir)
#   BUILD_DIR (default build)  COUNT (default 20)  EVIDENCE_ARGS (extra resize_evidence options)
#
# Subject i (0-based) is a man (even i, the model's average man) or a woman
# (odd i, its average woman) with every girth times g_i and every length
# times l_i, then each size times its own factor in [0.95, 1.05] (chest and
# bust follow the under-bust girth as in the model's own draws): g_i is
# 0.85-0.93 or 1.12-1.35 (never near the standard size), l_i 0.90-1.10.
# Limb girths below the elbow and knee scale by sqrt(g_i) and the shoulder
# width by sqrt(g_i) l_i, as the model's own seeded draws do, so every
# subject passes the model's range and ratio checks. Deterministic: the same
# subjects every run. About 3-6 s per subject on 2 cores; the evidence run
# itself about 5-10 s per body and design.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
COUNT=${COUNT:-20}
OUT=${1:-$(mktemp -d /tmp/resize-oracle.XXXXXX)}
BESPOKE="$BUILD_DIR/bespoke"
EVIDENCE="$BUILD_DIR/eval/bench/resize_evidence"
for tool in "$BESPOKE" "$EVIDENCE"; do
  [ -x "$tool" ] || { echo "missing $tool (build it: cmake --build $BUILD_DIR --target bespoke resize_evidence)" >&2; exit 1; }
done
mkdir -p "$OUT"

# name=value pairs for subject $1, one per line.
params() {
  awk -v i="$1" 'BEGIN {
    split("0.86 1.30 0.90 1.22 0.88 1.35 0.92 1.25 0.87 1.15 1.28 0.89 1.18 0.91 1.32 0.85 1.24 0.93 1.12 1.27", G, " ");
    split("0.92 1.06 1.10 0.94 1.02 0.96 1.08 0.90 1.04 0.98", L, " ");
    g = G[i % 20 + 1]; l = L[i % 10 + 1];
    srand(1000 + i);
    man = (i % 2 == 0);
    # The parametric model'"'"'s average man / average woman (parametric_options.cc).
    if (man) {
      v["stature_mm"] = 1760; v["neck_girth_mm"] = 390; v["chest_girth_mm"] = 1000;
      v["under_bust_girth_mm"] = 920; v["waist_girth_mm"] = 880; v["middle_hip_girth_mm"] = 940;
      v["hip_girth_mm"] = 990; v["upper_arm_girth_mm"] = 310; v["wrist_girth_mm"] = 175;
      v["thigh_girth_mm"] = 560; v["knee_girth_mm"] = 385; v["calf_girth_mm"] = 375;
      v["ankle_girth_mm"] = 235; v["arm_length_mm"] = 600; v["crotch_height_mm"] = 815;
      v["shoulder_width_mm"] = 410; v["stance_width_mm"] = 230;
    } else {
      v["stature_mm"] = 1660; v["neck_girth_mm"] = 350; v["chest_girth_mm"] = 900;
      v["under_bust_girth_mm"] = 780; v["waist_girth_mm"] = 760; v["middle_hip_girth_mm"] = 900;
      v["hip_girth_mm"] = 1000; v["upper_arm_girth_mm"] = 290; v["wrist_girth_mm"] = 155;
      v["thigh_girth_mm"] = 570; v["knee_girth_mm"] = 370; v["calf_girth_mm"] = 360;
      v["ankle_girth_mm"] = 220; v["arm_length_mm"] = 560; v["crotch_height_mm"] = 760;
      v["shoulder_width_mm"] = 370; v["stance_width_mm"] = 220;
    }
    n = split("neck_girth_mm under_bust_girth_mm waist_girth_mm middle_hip_girth_mm hip_girth_mm upper_arm_girth_mm thigh_girth_mm", full, " ");
    for (k = 1; k <= n; ++k) v[full[k]] *= g * (0.95 + 0.1 * rand());
    n = split("wrist_girth_mm knee_girth_mm calf_girth_mm ankle_girth_mm", half, " ");
    for (k = 1; k <= n; ++k) v[half[k]] *= sqrt(g) * (0.95 + 0.1 * rand());
    v["stature_mm"] *= l;
    v["arm_length_mm"] *= l * (0.98 + 0.04 * rand());
    v["crotch_height_mm"] *= l * (0.98 + 0.04 * rand());
    v["stance_width_mm"] *= l;
    v["shoulder_width_mm"] *= sqrt(g) * l;
    # Chest and bust from the under-bust girth, as the model'"'"'s seeded draws.
    v["chest_girth_mm"] = v["under_bust_girth_mm"] * (man ? 1.087 : 1.154) * (0.98 + 0.04 * rand());
    v["bust_girth_mm"] = man ? v["chest_girth_mm"] : v["under_bust_girth_mm"] * 1.19;
    for (name in v) printf "%s=%.1f\n", name, v[name];
  }'
}

start=$(date +%s)
for ((i = 0; i < COUNT; ++i)); do
  dir=$(printf "%s/subject_%03d" "$OUT" "$i")
  mkdir -p "$dir"
  args=()
  while read -r p; do args+=(--param "$p"); done < <(params "$i")
  "$BESPOKE" -q synth-body --seed 0 "${args[@]}" -o "$dir/body.obj" \
    --truth "$dir/truth.json" 2> "$dir/synth.log" ||
    { cat "$dir/synth.log" >&2; exit 1; }
  printf "%s\n" "${args[@]}" | grep -v -- --param > "$dir/params.txt"
done
echo "made $COUNT oracle subjects in $OUT in $(( $(date +%s) - start )) s" >&2
# shellcheck disable=SC2086
"$EVIDENCE" --truth-dir "$OUT" --bodies "$COUNT" ${EVIDENCE_ARGS:-}
