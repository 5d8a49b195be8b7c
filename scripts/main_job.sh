#!/usr/bin/env bash
# README command 1: install what is missing, build, regenerate the kernels
# and diff them against generated/, run the verification sweeps (segments at
# their default size, polygons at half of theirs) and print their summary
# tables. The default-size polygon sweep is under `ctest -L long`.
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
stage "segment verification sweep (default size: 2,000 generic samples, 200 in every other region, per cell)"
build/release/verify/skelconv-verify --json build/release/reports/verify_default.json
echo "== report written to build/release/reports/verify_default.json"

# Half the polygon sweep's default size (its binary128 retries near the plane
# make it the slower of the two); `ctest --preset release -L long` runs the
# default size (verify_polygon_sweep_default).
stage "polygon verification sweep (1,000 generic samples, 100 in every other region, per family; long double reference)"
build/release/verify/skelconv-verify-polygons --generic-points 1000 --points 100 \
  --json build/release/reports/verify_polygons.json
echo "== report written to build/release/reports/verify_polygons.json"
stage "main job done"
