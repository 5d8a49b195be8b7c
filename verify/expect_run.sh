#!/usr/bin/env bash
# ctest helper: runs COMMAND and passes only if it exits with STATUS and some
# line of its output (stdout and stderr) matches the extended regular
# expression MUST_MATCH. ctest's PASS_REGULAR_EXPRESSION alone ignores the
# exit status, so a crash after the matching line would pass; this does not.
# A run that does not hold prints "CHECK-FAILED: <what>" and exits 1.
#   verify/expect_run.sh STATUS MUST_MATCH COMMAND [ARG ...]
set -uo pipefail
[ $# -ge 3 ] || { echo "usage: $0 STATUS MUST_MATCH COMMAND [ARG ...]"; exit 2; }
expected="$1" must="$2"
shift 2
out=$("$@" 2>&1)
status=$?
printf '%s\n' "$out"
[ "$status" = "$expected" ] || { echo "CHECK-FAILED: '$1' exited with status $status, expected $expected"; exit 1; }
grep -Eq -- "$must" <<< "$out" || { echo "CHECK-FAILED: no line of the output matches '$must'"; exit 1; }
echo "ran as expected (exit status $status, a line matches '$must')"
