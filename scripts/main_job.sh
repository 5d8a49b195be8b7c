#!/usr/bin/env bash
# README command 1: install what is missing, build, regenerate the kernels
# and diff them against generated/, run the default verification sweeps
# (segments, polygons) and print their summary tables.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_dependencies.sh
# Only what this job runs: the generator (for the regeneration diff) and the
# two verifiers. Not the runtime, the CLI, the mesher, the tests, the
# benchmarks, the figures or the Python module (scripts/test.sh builds those).
scripts/build.sh --target skelconv-codegen skelconv-verify skelconv-verify-polygons

echo "== regenerating the kernels and diffing them against generated/"
ctest --preset release -R codegen_regeneration_is_byte_identical --output-on-failure

echo "== verification sweep (default size)"
mkdir -p build/release/reports
build/release/verify/skelconv-verify --json build/release/reports/verify_default.json
echo "== report written to build/release/reports/verify_default.json"

echo "== polygon verification sweep (default size, long double reference)"
build/release/verify/skelconv-verify-polygons --json build/release/reports/verify_polygons_default.json
echo "== report written to build/release/reports/verify_polygons_default.json"
