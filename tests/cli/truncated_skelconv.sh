#!/usr/bin/env bash
# A purpose-built broken `skelconv` for the test of run_cli_case.cmake: runs
# the real command ($SKELCONV_REAL) and passes its output on with the last
# 10 bytes cut off (a run killed while writing), keeping its exit status.
# The case checker must refuse that output (ctest WILL_FAIL).
out=$("$SKELCONV_REAL" "$@")
status=$?
printf '%s' "${out%??????????}"
exit "$status"
