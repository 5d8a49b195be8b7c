#!/usr/bin/env bash
# Builds the runtime, the `skelconv` command and the unit tests with
# AddressSanitizer and UndefinedBehaviorSanitizer (preset asan, build/asan,
# -O1) and runs, under them: the unit tests, every command-line case (bad
# skeleton files, bad point lines, the mesher's refusals) and the mutation
# fuzzer over skeleton files (tests/fuzz_skeletons.cpp) for a fixed number of
# iterations. Any report fails the run: UBSan does not recover, ASan aborts.
# Part of README's main job (scripts/main_job.sh); runs alone too.
set -euo pipefail
cd "$(dirname "$0")/.."
iterations="${SKELCONV_SANITIZE_FUZZ_ITERATIONS:-400}"

cmake --preset asan > /dev/null
cmake --build --preset asan --target skelconv skelconv_tests skelconv_fuzz_skeletons
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
build/asan/tests/skelconv_tests --gtest_brief=1
ctest --test-dir build/asan --output-on-failure -j2 -R '^cli\.'
build/asan/tests/skelconv_fuzz_skeletons build/asan/src/skelconv tests/data/good --iterations "$iterations" --seed 36
echo "sanitize: clean (ASan + UBSan: unit tests, command-line cases, $iterations fuzzed skeleton files)"
