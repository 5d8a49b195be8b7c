#!/usr/bin/env bash
# README command 1, the main job: what skelconv exists for, end to end.
#   1. install what is missing and build (the command, the generator, the
#      verifiers, the tests' programs);
#   2. regenerate the kernels with the generator and diff them against
#      generated/ (same input, same bytes);
#   3. verify every generated function against float128 quadrature of its
#      definition integral (segments, polygons, SCALIS segments) at the main
#      job's sizes, compare with the committed baselines, and print the
#      accuracy per family and region;
#   4. print the operation counts beside Zanni et al. 2013, Table 4;
#   5. redraw every figure and table of the papers, each claim checked;
#   6. write the summary page, build/summary/index.html (and index.md): for
#      each result, what was checked and whether it holds.
# A stage that fails is reported and the job goes on to the summary (a failed
# build stops it); the exit status is 0 only when every stage passed.
# The long tests, the sanitizers and the fuzzers are the check suite
# (scripts/checks.sh); CI runs scripts/test.sh. docs/build.md gives the time
# of each stage.
set -uo pipefail
cd "$(dirname "$0")/.."
[ $# -eq 0 ] || { echo "usage: scripts/main_job.sh (no arguments; the full sizes are in scripts/checks.sh --full)" >&2; exit 2; }

summary=build/summary
mkdir -p "$summary"
stages="$summary/stages.tsv"
: > "$stages"
start=$SECONDS
failed=0
# run_stage NAME COMMAND...: prints a progress line with the elapsed time,
# runs the command, records its time and status for the summary page.
run_stage() {
  local name="$1"; shift
  local stage_start=$SECONDS
  echo "== main job [$((SECONDS - start)) s] $name"
  "$@"
  local status=$?
  printf '%s\t%d\t%d\n' "$name" "$((SECONDS - stage_start))" "$status" >> "$stages"
  if [ "$status" -ne 0 ]; then
    echo "== main job: '$name' FAILED (exit status $status)"
    failed=1
  fi
  return "$status"
}

run_stage "installing missing packages" scripts/install_dependencies.sh || exit 1
run_stage "building" scripts/build.sh || { echo "== main job: the build failed; nothing else can run" >&2; exit 1; }

run_stage "regenerating the kernels and diffing them against generated/" \
  ctest --test-dir build/release -R '^codegen_regeneration_is_byte_identical$' --output-on-failure

# The sweeps at the main job's size and their baseline comparisons (ctest
# label `main`: `ctest -N -L main` lists them).
run_stage "verifying against quadrature of the definitions: $(ctest --test-dir build/release -N -L main | grep -c 'Test *#') tests" \
  ctest --test-dir build/release -L main --output-on-failure -j2
if [ -f build/release/verify/verify_sweep_main.json ]; then
  build/release/verify/skelconv-verify markdown build/release/verify/verify_sweep_main.json > "$summary/segment_accuracy.md" \
    && echo "segment accuracy per kernel and region: $summary/segment_accuracy.md"
fi

# The papers' figures and tables: every registered entry but the project's
# own experiments (experiment_*, drawn by scripts/figures.sh).
paper_figures=$(sed 's/#.*//' papers_figures/figures.txt | awk 'NF && $1 !~ /^experiment_/ {print $1}')
# shellcheck disable=SC2086  # one name per word
run_stage "drawing the papers' figures and tables ($(echo $paper_figures | wc -w)), checking their claims" \
  /usr/bin/python3 papers_figures/run.py --skelconv build/release/src/skelconv --out build/figures --check --jobs 2 \
    --only $paper_figures

# The summary page prints the accuracy per family and region and the
# operation counts beside Table 4; it fails when a result does not hold.
run_stage "writing the summary page" \
  /usr/bin/python3 scripts/summary_page.py --out "$summary" --stages "$stages" \
    --sweep build/release/verify/verify_sweep_main.json \
    --polygon-sweep build/release/verify/verify_polygon_sweep_main.json \
    --scalis-report build/release/verify/verify_scalis_properties_main.json --opcounts generated/opcounts.csv --figures build/figures
sed -n '/^## Accuracy of the segment kernels/,/^## The papers/p' "$summary/index.md" | sed '$d'
echo "== main job [$((SECONDS - start)) s] done: $([ "$failed" = 0 ] && echo 'every stage passed' || echo 'a stage FAILED'); open $summary/index.html"
exit "$failed"
