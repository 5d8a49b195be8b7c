#!/usr/bin/env bash
# Runs the accuracy sweep (skelconv-verify) as N shards, J at a time on this
# machine (xargs -P, from findutils: no extra package), then merges the shard
# reports into the report of the unsharded sweep. docs/verify.md, "Sweeps in
# parallel", gives the same with GNU parallel, a Slurm job array and a GitHub
# Actions matrix.
#
#   scripts/sweep.sh --shards N --jobs J [--out DIR] [--verify PATH] [--heatmap] [-- SWEEP OPTIONS...]
#
# SWEEP OPTIONS go to every shard (e.g. --full, --points 500, --family cauchy);
# each shard runs on one thread unless they say --threads. Writes into DIR
# (default build/release/sweep): shard-K-of-N.json/.txt, merged.json,
# merged.md, merged.txt (and heatmap.png with --heatmap). Exit status: the
# merged sweep's verdict (0 passed, 1 failed), 2 on bad arguments or when a
# shard or the merge could not run.
set -euo pipefail
cd "$(dirname "$0")/.."

usage() { sed -n '6,14p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
shards="" jobs="" out="build/release/sweep" verify="build/release/verify/skelconv-verify" heatmap=0
while [ $# -gt 0 ]; do
  case "$1" in
    --shards) shards="${2:-}"; shift 2 ;;
    --jobs) jobs="${2:-}"; shift 2 ;;
    --out) out="${2:-}"; shift 2 ;;
    --verify) verify="${2:-}"; shift 2 ;;
    --heatmap) heatmap=1; shift ;;
    --) shift; break ;;
    -h|--help) usage ;;
    *) echo "sweep.sh: unknown argument '$1' (sweep options go after --)" >&2; exit 2 ;;
  esac
done
positive='^[1-9][0-9]*$'
[[ "$shards" =~ $positive ]] || { echo "sweep.sh: --shards must be a positive integer, got '$shards'" >&2; exit 2; }
[[ "$jobs" =~ $positive ]] || { echo "sweep.sh: --jobs must be a positive integer, got '$jobs'" >&2; exit 2; }
[ -x "$verify" ] || { echo "sweep.sh: $verify is not built (cmake --build --preset release --target skelconv-verify)" >&2; exit 2; }
sweep_options=("$@")
threads=(--threads 1)
for option in "${sweep_options[@]}"; do [ "$option" = "--threads" ] && threads=(); done

mkdir -p "$out"
rm -f "$out"/shard-*-of-"$shards".*
# One line per shard index into xargs; each shard writes its report, its text
# table and its exit status (1 = its own verdict, which the merge recomputes).
export SWEEP_VERIFY="$verify" SWEEP_OUT="$out" SWEEP_SHARDS="$shards"
# shellcheck disable=SC2016  # the single-quoted script is expanded by the inner bash
seq 0 $((shards - 1)) | xargs -P "$jobs" -I{} bash -c '
  k=$1; shift
  base="$SWEEP_OUT/shard-$k-of-$SWEEP_SHARDS"
  status=0
  "$SWEEP_VERIFY" --quiet --shard "$k/$SWEEP_SHARDS" --json "$base.json" "$@" > "$base.txt" 2>&1 || status=$?
  echo "$status" > "$base.status"' shard {} "${threads[@]}" "${sweep_options[@]}"

for ((k = 0; k < shards; ++k)); do
  base="$out/shard-$k-of-$shards"
  status=$(cat "$base.status" 2>/dev/null || echo missing)
  if [ "$status" != 0 ] && [ "$status" != 1 ]; then
    echo "sweep.sh: shard $k/$shards did not run (status $status); its output: $base.txt" >&2
    tail -5 "$base.txt" >&2 || true
    exit 2
  fi
done

status=0
"$verify" merge "$out"/shard-*-of-"$shards".json --json "$out/merged.json" --markdown "$out/merged.md" \
  > "$out/merged.txt" || status=$?
cat "$out/merged.txt"
[ "$status" -le 1 ] || { echo "sweep.sh: the merge failed (status $status)" >&2; exit 2; }
if [ "$heatmap" = 1 ]; then
  /usr/bin/python3 verify/heatmap.py "$out/merged.json" "$out/heatmap.png"
fi
echo "sweep.sh: $shards shards merged into $out/merged.json ($out/merged.md)"
exit "$status"
