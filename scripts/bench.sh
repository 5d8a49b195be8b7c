#!/usr/bin/env bash
# scripts/bench.sh — the one benchmark command (docs/bench.md).
#
# Configures and builds the release preset's benchmark targets, runs the
# Google Benchmark suites (JSON to bench/results/, GSL comparison included), counts instructions with
# callgrind, and writes bench/results/SUMMARY.md and OPCOUNTS.md.
# About 5–8 minutes on 2 cores from a clean clone (most of it the build).
#
#   scripts/bench.sh            full run
#   scripts/bench.sh --quick    short timings (min time 0.02 s, 1 repetition):
#                               checks the pipeline, numbers not meaningful
# SKELCONV_BENCH_BUILD_DIR=dir  builds in dir instead of build/release.
set -euo pipefail
cd "$(dirname "$0")/.."

min_time=0.1
repetitions=3
for arg in "$@"; do
  case "$arg" in
    --quick) min_time=0.02; repetitions=1 ;;
    *) echo "usage: $0 [--quick]" >&2; exit 2 ;;
  esac
done

results=bench/results
scratch=$(mktemp -d "${TMPDIR:-/tmp}/skelconv-bench.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
start=$SECONDS
step() { echo "[bench $(( SECONDS - start ))s] $*" >&2; }

for tool in cmake python3 valgrind objdump /usr/bin/time; do
  command -v "$tool" >/dev/null || { echo "scripts/bench.sh: $tool is required" >&2; exit 1; }
done

if [ -x scripts/install_dependencies.sh ]; then scripts/install_dependencies.sh >&2; fi

if [ -n "${SKELCONV_BENCH_BUILD_DIR:-}" ]; then
  # A private build tree (e.g. while build/release is busy): same options as
  # the release preset.
  build=$SKELCONV_BENCH_BUILD_DIR
  step "configure and build in $build (Release, target skelconv_bench)"
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" --target skelconv_bench -j 2
else
  build=build/release
  step "configure and build (release preset, target skelconv_bench)"
  cmake --preset release >/dev/null
  cmake --build --preset release --target skelconv_bench
fi
bin=$build/bench

mkdir -p "$results"
rm -f "$results"/*.json "$results"/SUMMARY.md "$results"/OPCOUNTS.md
{
  echo "commit: $(git rev-parse --short HEAD 2>/dev/null || echo unknown)$(git diff --quiet HEAD -- generated include src codegen 2>/dev/null || echo ' (+ uncommitted changes)')"
  echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "compiler: $(c++ --version | head -1)"
  echo "bench flags: -O3 -march=$(grep -Po '(?<=SKELCONV_BENCH_ARCH:STRING=).*' "$build/CMakeCache.txt" || echo default) -fno-math-errno -fno-trapping-math"
  echo "kernel: $(uname -sr)"
  lscpu | grep -v '^Flags' | head -20
  echo "SIMD flags: $(grep -m1 '^flags' /proc/cpuinfo | tr ' ' '\n' | grep -E '^(sse4_2|avx|avx2|fma|avx512f)$' | tr '\n' ' ')"
} > "$results/machine.txt"

gbench=(--benchmark_min_time="$min_time" --benchmark_repetitions="$repetitions"
        --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true
        --benchmark_out_format=json)

step "1/6 kernel suite: closed form, finite differences, quadrature, degrees (~2 min)"
"$bin/skelconv_bench_kernels" "${gbench[@]}" --benchmark_out="$results/kernels.json"

step "2/6 whole skeleton: 1,000 primitives, 128^3 grid (~10 s; progress below)"
"$bin/skelconv_bench_skeleton" --benchmark_out="$results/skeleton.json" --benchmark_out_format=json

step "3/6 SCALIS segments against quadrature (~30 s)"
"$bin/skelconv_bench_scalis" "${gbench[@]}" --benchmark_out="$results/scalis.json"
"$bin/skelconv_scalis_compact_opcounts" > "$results/scalis_compact_opcounts.md"

step "4/6 closed forms against GSL's adaptive QAG (61-point rule), 0.1-3 |AB| (~1 min)"
"$bin/skelconv_bench_gsl" "${gbench[@]}" --benchmark_out="$results/gsl.json"

step "4b/6 public paths against the generated function; the mesher on Zanni's ant (~2 min)"
"$bin/skelconv_bench_public_path" --benchmark_min_time="$min_time" --benchmark_repetitions="$repetitions" \
  --benchmark_report_aggregates_only=true --benchmark_out_format=json --benchmark_out="$results/public_path.json"
# Zanni Table 1's ant at its triangle count (--size 0.04: ~95k triangles), 3
# runs (summarize.py takes the median), pinned to one core as the goal states
# (unpinned, OpenVDB's worker and the field's threads add the second core's
# time to the CPU seconds). CPU seconds as well (/usr/bin/time): on a shared
# machine they mean more.
for run in 1 2 3; do
  /usr/bin/time -f 'cpu_seconds: %U %S' taskset -c 0 "$build/src/skelconv" mesh papers_figures/skeletons/zanni_table1_ant.json \
    --size 0.04 --method grid -o "$scratch/ant.ply" --quiet 2>&1
done > "$results/mesh_ant.txt"

step "5/6 callgrind instruction counts (~1 min)"
valgrind --tool=callgrind --callgrind-out-file="$scratch/callgrind.out.%p" --dump-instr=no \
  --collect-jumps=no "$bin/skelconv_bench_counts" 2> "$scratch/valgrind.log" \
  || { cat "$scratch/valgrind.log" >&2; exit 1; }
# The public paths' instructions per primitive and point (public/… regions).
valgrind --tool=callgrind --callgrind-out-file="$scratch/callgrind.out.%p" --dump-instr=no \
  --collect-jumps=no "$bin/skelconv_bench_public_path" --counts 2> "$scratch/valgrind_public.log" \
  || { cat "$scratch/valgrind_public.log" >&2; exit 1; }
"$bin/skelconv_bench_counts" --opcounts "$results/opcounts.json"

step "6/6 summary"
python3 bench/summarize.py --results "$results" --callgrind "$scratch" \
  --command "$(echo "scripts/bench.sh $*" | sed 's/ *$//')"
step "done: $results/SUMMARY.md"
