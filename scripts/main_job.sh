#!/usr/bin/env bash
# README command 1: install what is missing, build, regenerate the kernels
# and diff them against generated/, run the verification sweeps (segments and
# polygons, at half their default sizes) and print their summary tables. The
# default sizes are under `ctest --preset release -L long`.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
stage() { echo "== [$((SECONDS - start)) s] $*"; }

scripts/install_dependencies.sh
# Only what this job runs: the generator (for the regeneration diff) and the
# two verifiers, which link the double segment table and not the rest of the
# runtime. Not the CLI, the mesher, the tests, the benchmarks, the figures or
# the Python module (scripts/test.sh builds those).
stage "building the generator and the two verifiers"
# One target for the three (CMakeLists.txt says why).
scripts/build.sh --target skelconv-main-job

stage "regenerating the kernels and diffing them against generated/"
ctest --preset release -R codegen_regeneration_is_byte_identical --output-on-failure

mkdir -p build/release/reports
# Both sweeps at half their default size, to keep this job within minutes on
# 2 cores; `ctest --preset release -L long` runs the default sizes
# (verify_sweep_default, verify_polygon_sweep_default, each compared with its
# committed baseline where it has one).
stage "segment verification sweep (1,000 generic samples, 100 in every other region, per cell)"
build/release/verify/skelconv-verify --generic-points 1000 --other-points 100 \
  --json build/release/reports/verify_segments.json
echo "== report written to build/release/reports/verify_segments.json"

stage "polygon verification sweep (1,000 generic samples, 100 in every other region, per family; long double reference)"
build/release/verify/skelconv-verify-polygons --generic-points 1000 --points 100 \
  --json build/release/reports/verify_polygons.json
echo "== report written to build/release/reports/verify_polygons.json"
stage "main job done"
