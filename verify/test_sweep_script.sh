#!/usr/bin/env bash
# ctest verify_sweep_script: scripts/sweep.sh runs a small sweep as
# 3 shards, 2 at a time, and merges them; the merged maxima must equal an
# unsharded run's exactly (compare with k = 1 and no floors, both ways: any
# difference fails one direction), and the heat map must render.
# (Field-by-field equality of every statistic: verify_report_tools.)
#   verify/test_sweep_script.sh SKELCONV_VERIFY WORK_DIR
set -euo pipefail
verify="$1" work="$2"
source_dir="$(cd "$(dirname "$0")/.." && pwd)"
small=(--family compact --degree 6 --points 12 --chunk 4)
rm -rf "$work" && mkdir -p "$work"

"$source_dir/scripts/sweep.sh" --shards 3 --jobs 2 --out "$work/sharded" --verify "$verify" --heatmap -- "${small[@]}"
"$verify" --quiet --threads 2 "${small[@]}" --json "$work/single.json" > "$work/single.txt"

grep -q '"merged_shards":3' "$work/sharded/merged.json" || { echo "FAIL: merged.json does not say 3 shards"; exit 1; }
exact=(--tolerance-factor 1 --double-floor 0 --extended-floor 0)
"$verify" compare "${exact[@]}" "$work/single.json" "$work/sharded/merged.json" | tail -1
"$verify" compare "${exact[@]}" "$work/sharded/merged.json" "$work/single.json" | tail -1
grep -q '^| 6 |' "$work/sharded/merged.md" || { echo "FAIL: merged.md has no row for degree 6"; exit 1; }
[ -s "$work/sharded/heatmap.png" ] || { echo "FAIL: no heat map"; exit 1; }
echo "sweep.sh: 3 shards merged = the unsharded run"
