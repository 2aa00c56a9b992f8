#!/usr/bin/env bash
# Submits a sharded batch to Slurm: the job array (bespoke-array.sbatch, one
# task per shard) and a merge job that runs when every task has ended
# (afterany: the merge reports shards that failed for good).
#   scripts/slurm/submit.sh SHARDS INPUT OUT_DIR [bespoke batch options...]
# Prints the two job ids. BESPOKE (default `bespoke`) is passed to the tasks.
# Extra sbatch options for both jobs: SBATCH_EXTRA="--partition=long ...".
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: $0 SHARDS INPUT OUT_DIR [bespoke batch options...]" >&2
  exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
shards=$1 input=$2 out=$3
shift 3
BESPOKE=${BESPOKE:-bespoke}
mkdir -p "$out"
# shellcheck disable=SC2086
array=$(sbatch --parsable ${SBATCH_EXTRA:-} --array=1-"$shards" --output="$out/slurm-%A_%a.out" \
  --export=ALL,BESPOKE="$BESPOKE" "$here/bespoke-array.sbatch" "$input" "$out" "$@")
# shellcheck disable=SC2086
merge=$(sbatch --parsable ${SBATCH_EXTRA:-} --dependency=afterany:"$array" --job-name=bespoke-merge \
  --output="$out/slurm-merge-%j.out" --wrap "\"$BESPOKE\" batch-merge \"$out\"")
echo "array job $array ($shards tasks), merge job $merge; results in $out/report.html"
