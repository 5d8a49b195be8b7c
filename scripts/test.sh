#!/usr/bin/env bash
# README command 2: install what is missing, build, run every test.
# CI (.ci/run) runs exactly this.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_dependencies.sh
scripts/build.sh
ctest --preset release "$@"
