#!/usr/bin/env bash
# ctest helper: runs `skelconv-verify compare BASE NEW` and checks
# its exit status and which cells it calls worse.
#   verify/expect_compare.sh SKELCONV_VERIFY BASE NEW STATUS [MUST_MATCH [MUST_NOT_MATCH]]
# MUST_MATCH / MUST_NOT_MATCH: extended regular expressions on the output.
set -uo pipefail
verify="$1" base="$2" new="$3" expected="$4" must="${5:-}" must_not="${6:-}"
out=$("$verify" compare "$base" "$new")
status=$?
echo "$out"
[ "$status" = "$expected" ] || { echo "CHECK-FAILED: compare exited with $status, expected $expected"; exit 1; }
if [ -n "$must" ] && ! grep -Eq "$must" <<< "$out"; then echo "CHECK-FAILED: no line matches '$must'"; exit 1; fi
if [ -n "$must_not" ] && grep -Eq "$must_not" <<< "$out"; then echo "CHECK-FAILED: a line matches '$must_not'"; exit 1; fi
echo "compare behaved as expected (exit status $status)"
