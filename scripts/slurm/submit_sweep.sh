#!/usr/bin/env bash
# Submits the accuracy sweep to Slurm as a job array of N shards and a merge
# job that runs once every shard has succeeded (docs/verify.md, "On a Slurm
# cluster"). Run it from the repository root of a built checkout on a shared
# file system (the shards and the merge read build/release/verify/skelconv-verify):
#
#   scripts/slurm/submit_sweep.sh N OUT_DIR [SWEEP OPTIONS...]      e.g.
#   scripts/slurm/submit_sweep.sh 256 /scratch/$USER/sweep --full
#
# Each array task k runs `skelconv-verify --shard k/N` (verify_shard.sbatch);
# the merge (merge_shards.sbatch) depends on the whole array with afterok, so
# it does not start when a shard failed to run. A shard whose verdict fails
# still exits 0 here: the verdict belongs to the merged report.
set -euo pipefail
[ $# -ge 2 ] || { sed -n '6,7p' "$0" >&2; exit 2; }
shards="$1" out="$2"
shift 2
[[ "$shards" =~ ^[1-9][0-9]*$ ]] || { echo "submit_sweep.sh: N must be a positive integer, got '$shards'" >&2; exit 2; }
mkdir -p "$out"
here="$(cd "$(dirname "$0")" && pwd)"
array_job=$(sbatch --parsable --array=0-$((shards - 1)) --output="$out/shard-%a.log" \
  "$here/verify_shard.sbatch" "$shards" "$out" "$@")
array_job="${array_job%%;*}"  # --parsable prints "jobid[;cluster]"
merge_job=$(sbatch --parsable --dependency=afterok:"$array_job" --output="$out/merge.log" \
  "$here/merge_shards.sbatch" "$shards" "$out")
echo "submitted shards as job array $array_job (0-$((shards - 1))), merge as job ${merge_job%%;*}"
echo "the merged report will be $out/merged.json ($out/merged.md, $out/heatmap.png)"
