#!/usr/bin/env bash
# README command 1: install what is missing, build (CI's build and the
# benchmark programs), regenerate the kernels and diff them against
# generated/, run every test that CI does not run at the main job's sizes
# (the ctest label `long`: the verification sweeps and their baseline
# compares, the SCALIS accuracy test, the reconstruction quality table, the
# long fuzz run, the package test, the slow figure claims, the browser test,
# the benchmarks' smoke tests; docs/checks.md says what each size covers),
# then the sanitizer run (scripts/sanitize.sh) and the libFuzzer harnesses
# (scripts/fuzz.sh), and print the segment sweep's summary table.
# `ctest -N -L long` lists exactly what the long-test step runs.
#
#   scripts/main_job.sh          the main job
#   scripts/main_job.sh --full   the same, plus the full sizes: the tests
#                                labelled `full` (default-size sweeps and
#                                their baselines, 2,000 SCALIS accuracy
#                                samples, 20,000 fuzzed skeleton files), 400
#                                fuzzed files under the sanitizers, 60 s per
#                                libFuzzer harness
set -euo pipefail
cd "$(dirname "$0")/.."
full=0
case "${1:-}" in
  --full) full=1 ;;
  "") ;;
  *) echo "usage: scripts/main_job.sh [--full]" >&2; exit 2 ;;
esac
start=$SECONDS
stage() { echo "== [$((SECONDS - start)) s] $*"; }

scripts/install_dependencies.sh --main-job
stage "building everything: CI's build and the benchmark programs (the long tests need the command, the test programs, the verifiers and the benchmarks)"
scripts/build.sh --target all skelconv_bench

stage "regenerating the kernels and diffing them against generated/"
ctest --test-dir build/release -R codegen_regeneration_is_byte_identical --output-on-failure

labels=long
report=verify_sweep_main
if [ "$full" = 1 ]; then
  labels='long|full'
  report=verify_sweep_default
  export SKELCONV_SANITIZE_FUZZ_ITERATIONS="${SKELCONV_SANITIZE_FUZZ_ITERATIONS:-400}"
  export SKELCONV_FUZZ_SECONDS="${SKELCONV_FUZZ_SECONDS:-60}"
fi
stage "the long tests: $(ctest --test-dir build/release -N -L "$labels" | grep -c 'Test *#') tests (ctest -L '$labels')"
ctest --test-dir build/release -L "$labels" --output-on-failure -j2

stage "sanitizers: ASan + UBSan build of the runtime, the command and the unit tests"
scripts/sanitize.sh

stage "libFuzzer: the PLY/OBJ/OFF reader and the point lines, ${SKELCONV_FUZZ_SECONDS:-30} s each"
scripts/fuzz.sh

stage "summary of the segment sweep (build/release/verify/$report.json)"
build/release/verify/skelconv-verify markdown "build/release/verify/$report.json" | head -60
stage "main job done"
