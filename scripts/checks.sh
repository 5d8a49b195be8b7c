#!/usr/bin/env bash
# The check suite: what neither the main job nor CI runs, because it is long
# (docs/checks.md). Installs what is missing (clang, Chromium, CGAL's sample
# meshes besides CI's packages), builds everything with the benchmark
# programs, then runs
#   1. the long tests (`ctest -L long`: the long fuzz run, the reconstruction
#      tables on real meshes, the browser test, the package builds, the
#      benchmarks' smoke tests, the slow figure claims);
#   2. the AddressSanitizer + UndefinedBehaviorSanitizer build and run
#      (scripts/sanitize.sh);
#   3. the libFuzzer harnesses of the readers of untrusted text
#      (scripts/fuzz.sh).
# Any failure fails the suite; every stage prints its elapsed time.
#
#   scripts/checks.sh          the suite
#   scripts/checks.sh --full   also the full sizes (`ctest -L full`: default-size
#                              sweeps, 2,000 SCALIS samples, 20,000 fuzzed
#                              skeleton files), 400 fuzzed files under the
#                              sanitizers and 60 s per libFuzzer harness
set -euo pipefail
cd "$(dirname "$0")/.."
full=0
case "${1:-}" in
  --full) full=1 ;;
  "") ;;
  *) echo "usage: scripts/checks.sh [--full]" >&2; exit 2 ;;
esac
start=$SECONDS
stage() { echo "== checks [$((SECONDS - start)) s] $*"; }

scripts/install_dependencies.sh --checks
stage "building everything, the benchmark programs and the programs only the check suite runs"
scripts/build.sh --target all skelconv_bench skelconv_check_programs

labels=long
if [ "$full" = 1 ]; then
  labels='long|full'
  export SKELCONV_SANITIZE_FUZZ_ITERATIONS="${SKELCONV_SANITIZE_FUZZ_ITERATIONS:-400}"
  export SKELCONV_FUZZ_SECONDS="${SKELCONV_FUZZ_SECONDS:-60}"
fi
stage "the long tests: $(ctest --test-dir build/release -N -L "$labels" | grep -c 'Test *#') tests (ctest -L '$labels')"
ctest --test-dir build/release -L "$labels" --output-on-failure -j2

stage "sanitizers: ASan + UBSan build and run"
scripts/sanitize.sh

stage "libFuzzer: the PLY/OBJ/OFF reader and the point lines, ${SKELCONV_FUZZ_SECONDS:-30} s each"
scripts/fuzz.sh
stage "check suite passed"
