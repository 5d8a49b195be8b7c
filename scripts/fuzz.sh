#!/usr/bin/env bash
# libFuzzer runs (clang++-14, -fsanitize=fuzzer,address,undefined, -O1) of
# the readers of untrusted text: the PLY/OBJ/OFF reader (tests/fuzz/fuzz_mesh_reader.cpp)
# and `skelconv eval`'s point lines (tests/fuzz/fuzz_point_lines.cpp), each
# for SKELCONV_FUZZ_SECONDS (default 30) seconds. Each harness is compiled
# from the few sources it needs (no CMake build: no runtime library is built
# twice). Seeds and every input that once failed: tests/data/fuzz/NAME/
# (libFuzzer replays them first); a new failing input is written to
# build/fuzz/crashes/ and fails the run (fix the reader, then add the input
# to tests/data/fuzz/NAME/, which the ctests fuzz_replay_NAME replay in CI).
# Part of the check suite (scripts/checks.sh); runs alone too.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${SKELCONV_FUZZ_SECONDS:-30}"
out=build/fuzz
mkdir -p "$out/crashes"
flags=(-std=c++20 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
       -Iinclude -isystem /usr/include/eigen3)
declare -A sources=(
  [mesh_reader]="src/mesh/mesh_reader.cpp src/mesh/triangle_mesh.cpp src/errors.cpp"
  [point_lines]="src/cli/point_lines.cpp src/errors.cpp"
)
# The two compiles run side by side; each is waited for on its own and any
# failure stops the run (a bare `wait` returns 0, and a stale binary from an
# earlier run would then be fuzzed and reported clean), and the old binary is
# removed first.
declare -A compiles=()
for name in mesh_reader point_lines; do
  rm -f "$out/fuzz_$name"
  # shellcheck disable=SC2086  # the source list is split on purpose
  clang++-14 "${flags[@]}" "tests/fuzz/fuzz_${name}.cpp" ${sources[$name]} -lfmt -o "$out/fuzz_$name" &
  compiles[$name]=$!
done
failed=0
for name in mesh_reader point_lines; do
  wait "${compiles[$name]}" || { echo "fuzz: the $name harness does not compile"; failed=1; }
done
[ "$failed" = 0 ] || exit 1
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
for name in mesh_reader point_lines; do
  mkdir -p "$out/corpus/$name"
  # -timeout: an input that takes over 10 s is a finding (a reader that hangs).
  "$out/fuzz_$name" -max_total_time="$seconds" -timeout=10 -print_final_stats=1 -artifact_prefix="$out/crashes/${name}-" \
    "$out/corpus/$name" "tests/data/fuzz/$name" 2> "$out/$name.log" \
    || { tail -40 "$out/$name.log"; echo "fuzz: $name failed (input in $out/crashes/)"; exit 1; }
  echo "fuzz: $name clean, $(grep -o 'Done [0-9]* runs' "$out/$name.log") in ${seconds} s"
done
