#!/usr/bin/env bash
# ctest verify_slurm_scripts: runs scripts/slurm/submit_sweep.sh
# end to end with a stand-in `sbatch` (no Slurm here) that runs an array's
# tasks one after another with SLURM_ARRAY_TASK_ID set, and a job only when
# its afterok dependency has run; a small sweep in 3 shards must merge.
#   verify/test_slurm_scripts.sh SKELCONV_VERIFY WORK_DIR
set -euo pipefail
verify="$1" work="$2"
source_dir="$(cd "$(dirname "$0")/.." && pwd)"
rm -rf "$work" && mkdir -p "$work/bin"
cat > "$work/bin/sbatch" <<'FAKE'
#!/usr/bin/env bash
# Stand-in for sbatch: --parsable, --array=a-b, --output (with %a),
# --dependency=afterok:ID (ID must be a job this stand-in already ran).
set -euo pipefail
array="" output="/dev/null" dependency=""
while [[ "$1" == --* ]]; do
  case "$1" in
    --array=*) array="${1#--array=}" ;;
    --output=*) output="${1#--output=}" ;;
    --dependency=afterok:*) dependency="${1#--dependency=afterok:}" ;;
    --parsable) ;;
    *) echo "fake sbatch: unexpected option $1" >&2; exit 2 ;;
  esac
  shift
done
jobs_file="$FAKE_SBATCH_DIR/jobs"
touch "$jobs_file"
if [ -n "$dependency" ]; then grep -qx "$dependency" "$jobs_file" || { echo "fake sbatch: no job $dependency" >&2; exit 2; }; fi
script="$1"; shift
if [ -n "$array" ]; then
  for ((t = ${array%-*}; t <= ${array#*-}; ++t)); do
    SLURM_ARRAY_TASK_ID=$t bash "$script" "$@" > "${output//%a/$t}" 2>&1
  done
else
  bash "$script" "$@" > "$output" 2>&1
fi
id=$(( $(wc -l < "$jobs_file") + 1000 ))
echo "$id" >> "$jobs_file"
echo "$id"
FAKE
chmod +x "$work/bin/sbatch"
cd "$source_dir"
PATH="$work/bin:$PATH" FAKE_SBATCH_DIR="$work" SKELCONV_VERIFY="$verify" \
  scripts/slurm/submit_sweep.sh 3 "$work/out" --family cauchy --degree 2 --points 9 --chunk 3
grep -q '"merged_shards":3' "$work/out/merged.json" || { echo "FAIL: no merged report of 3 shards"; cat "$work/out/merge.log"; exit 1; }
tail -1 "$work/out/merged.txt"
echo "Slurm scripts: 3 array tasks and the dependent merge ran"
