#!/usr/bin/env bash
# README command 1: install what is missing, build, regenerate the kernels
# and diff them against generated/, run the default verification sweeps
# (segments, polygons) and print their summary tables.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_dependencies.sh
scripts/build.sh

echo "== regenerating the kernels and diffing them against generated/"
ctest --preset release -R codegen_regeneration_is_byte_identical --output-on-failure

echo "== verification sweep (default size)"
mkdir -p build/release/reports
build/release/verify/skelconv-verify --json build/release/reports/verify_default.json
echo "== report written to build/release/reports/verify_default.json"

echo "== polygon verification sweep (default size, long double reference)"
build/release/verify/skelconv-verify-polygons --json build/release/reports/verify_polygons_default.json
echo "== report written to build/release/reports/verify_polygons_default.json"
