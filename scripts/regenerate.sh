#!/usr/bin/env bash
# After a formula change: regenerate the kernels, show what changed in
# generated/, rebuild what includes a changed file, and verify one family
# against quadrature of its definition integral (docs/build.md, "A formula
# change").
#
#   scripts/regenerate.sh FAMILY [--points N]
#
# FAMILY: inverse, cauchy, compact (segments: skelconv-verify),
#         polygon-inverse, polygon-cauchy, polygon-compact (polygons:
#         skelconv-verify-polygons), scalis-inverse, scalis-cauchy, scalis-compact
#         (SCALIS segments: verify_scalis_properties).
# --points N: samples per (kernel, region) cell of the sweep (default 100, CI's
#         size; the main job runs 500 generic and 200 elsewhere).
#
# The generator rewrites only the files whose bytes change, and each family's
# formulas and table entries live in that family's header alone, so only the
# translation units that instantiate that family recompile (with ccache, a
# file that did not change costs nothing). Exit status: 0 when the family
# passes, 1 when its verification fails, 2 on bad arguments or a failed build.
set -euo pipefail
cd "$(dirname "$0")/.."

usage() { sed -n '7,15p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
[ $# -ge 1 ] || usage
family="$1"; shift
points=100
while [ $# -gt 0 ]; do
  case "$1" in
    --points) points="${2:-}"; shift 2 ;;
    -h|--help) usage ;;
    *) echo "regenerate.sh: unknown argument '$1'" >&2; usage ;;
  esac
done
[[ "$points" =~ ^[1-9][0-9]*$ ]] || { echo "regenerate.sh: --points must be a positive integer, got '$points'" >&2; exit 2; }

case "$family" in
  inverse|cauchy|compact)
    target=skelconv-verify
    verify=(build/release/verify/skelconv-verify --threads 2 --family "$family" --points "$points"
            --json "build/release/verify/regenerate_$family.json"
            --markdown "build/release/verify/regenerate_$family.md") ;;
  polygon-inverse|polygon-cauchy|polygon-compact)
    target=skelconv-verify-polygons
    verify=(build/release/verify/skelconv-verify-polygons --threads 2 --family "${family#polygon-}"
            --generic-points "$points" --points "$points") ;;
  scalis-inverse|scalis-cauchy|scalis-compact)
    target=verify_scalis_properties
    # The test's parameter names are the family names (families_under_test).
    verify=(env SKELCONV_SCALIS_GENERIC_POINTS="$points" build/release/verify/verify_scalis_properties
            --gtest_brief=1 "--gtest_filter=*/${family#scalis-}") ;;
  *) echo "regenerate.sh: unknown family '$family'" >&2; usage ;;
esac

start=$SECONDS
stage() { echo "== regenerate [$((SECONDS - start)) s] $*"; }

cmake --preset release > /dev/null
stage "building the generator"
cmake --build --preset release --target skelconv-codegen > /dev/null || { echo "regenerate.sh: the generator does not build" >&2; exit 2; }
stage "regenerating generated/ (files whose bytes do not change are left alone)"
build/release/codegen/skelconv-codegen --out generated
git --no-pager diff --stat -- generated/ || true
stage "rebuilding $target and what it links"
cmake --build --preset release --target "$target" || { echo "regenerate.sh: $target does not build" >&2; exit 2; }
stage "verifying $family against quadrature of its definition (${points} samples per cell)"
status=0
"${verify[@]}" || status=$?
if [ "$status" -eq 0 ]; then
  stage "$family passes"
else
  stage "$family FAILS its verification (exit status $status)"
  [ "$status" -eq 1 ] || status=1
fi
exit "$status"
