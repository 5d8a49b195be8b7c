#!/usr/bin/env bash
# README command 1: install what is missing, build, regenerate the kernels
# and diff them against generated/, run every test that CI does not run
# (the ctest label `long`: the default-size verification sweeps and their
# baseline compare, the full SCALIS property sweep, the reconstruction
# quality table, the long fuzz run, the package test, the slow figure
# claims), then the sanitizer run (scripts/sanitize.sh) and the libFuzzer
# harnesses (scripts/fuzz.sh), and print the
# sweeps' summary tables. `ctest -N -L long` lists exactly what stage 3 runs.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
stage() { echo "== [$((SECONDS - start)) s] $*"; }

scripts/install_dependencies.sh --main-job
stage "building everything (the long tests need the command, the test programs and the verifiers)"
scripts/build.sh

stage "regenerating the kernels and diffing them against generated/"
ctest --test-dir build/release -R codegen_regeneration_is_byte_identical --output-on-failure

stage "the long tests: $(ctest --test-dir build/release -N -L long | grep -c 'Test *#') tests (ctest -L long)"
ctest --test-dir build/release -L long --output-on-failure -j2

stage "sanitizers: ASan + UBSan build of the runtime, the command and the unit tests"
scripts/sanitize.sh

stage "libFuzzer: the PLY/OBJ reader and the point lines, ${SKELCONV_FUZZ_SECONDS:-30} s each"
scripts/fuzz.sh

stage "summary of the default-size segment sweep (build/release/verify/verify_sweep_default.json)"
build/release/verify/skelconv-verify markdown build/release/verify/verify_sweep_default.json | head -60
stage "main job done"
