#!/usr/bin/env bash
# Builds the runtime, the `skelconv` command and the test programs with
# AddressSanitizer and UndefinedBehaviorSanitizer (preset asan, build/asan,
# -O1) and runs, under them: the unit tests, the reconstruction tests
# (skelconv_reconstruct_tests), the mesher tests (skelconv_mesh_test), the
# replay of every fuzzer-found input (tests/data/fuzz/), every command-line
# case (bad skeleton files, bad point lines, the mesher's refusals) and the
# mutation fuzzer over skeleton files (tests/fuzz_skeletons.cpp) for a fixed
# number of iterations. Any report fails the run: UBSan does not recover,
# ASan aborts.
# Part of the check suite (scripts/checks.sh); runs alone too.
set -euo pipefail
cd "$(dirname "$0")/.."
iterations="${SKELCONV_SANITIZE_FUZZ_ITERATIONS:-400}"

# The fuzzer's driver only mutates files and starts the command under test
# (build/asan/src/skelconv): the release build's driver serves when it is
# there (the check suite builds it), so the ASan build compiles the runtime,
# the command and the unit tests only.
driver=build/release/tests/skelconv_fuzz_skeletons
targets=(skelconv skelconv_tests skelconv_reconstruct_tests skelconv_mesh_test
         skelconv_fuzz_replay_mesh_reader skelconv_fuzz_replay_point_lines)
if [ ! -x "$driver" ]; then
  driver=build/asan/tests/skelconv_fuzz_skeletons
  targets+=(skelconv_fuzz_skeletons)
fi

cmake --preset asan > /dev/null
start=$SECONDS
cmake --build --preset asan --target "${targets[@]}"
echo "sanitize: ASan build $((SECONDS - start)) s"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
start=$SECONDS
build/asan/tests/skelconv_tests --gtest_brief=1
echo "sanitize: unit tests $((SECONDS - start)) s"
start=$SECONDS
build/asan/tests/skelconv_reconstruct_tests --gtest_brief=1
echo "sanitize: reconstruction tests $((SECONDS - start)) s"
start=$SECONDS
build/asan/tests/skelconv_mesh_test --gtest_brief=1
echo "sanitize: mesher tests $((SECONDS - start)) s"
start=$SECONDS
for name in mesh_reader point_lines; do
  build/asan/tests/skelconv_fuzz_replay_$name "tests/data/fuzz/$name" > /dev/null
done
echo "sanitize: fuzzer inputs replayed $((SECONDS - start)) s"
start=$SECONDS
# The three shape cases with --report (cube, tetrahedron, sphere) mesh and
# measure both reconstruction paths: 4–6 min each at -O1 under ASan. Their
# code runs here in the smaller cases (skeletonize.medial_small: the medial
# path; skeletonize.segment, off_tetrahedron: the curve path); they run in
# CI at full speed.
ctest --test-dir build/asan --output-on-failure -j2 -R '^cli\.' -E '^cli\.skeletonize\.(cube|tetrahedron|sphere)$'
echo "sanitize: command-line cases $((SECONDS - start)) s"
start=$SECONDS
"$driver" build/asan/src/skelconv tests/data/good --iterations "$iterations" --seed 36
echo "sanitize: $iterations fuzzed skeleton files $((SECONDS - start)) s"
echo "sanitize: clean (ASan + UBSan: unit, reconstruction and mesher tests, fuzzer inputs, command-line cases," \
     "$iterations fuzzed skeleton files)"
