# Runs the skelconv binary once and checks its exit code, stdout and stderr.
# Invoked by CTest as
#   cmake -DSKELCONV=<binary> -DCASE=<case file> -P run_cli_case.cmake
# The case file (written by skelconv_cli_test in tests/CMakeLists.txt) sets:
#   CASE_ARGS           command-line arguments (a list)
#   CASE_STDIN          file fed to standard input
#   CASE_EXIT           expected exit code
#   CASE_STDOUT         if set: the exact expected stdout
#   CASE_STDOUT_LINES   if set: expected number of stdout lines, each of
#                       which must be four finite numbers "f gx gy gz"
#   CASE_STDERR         if set: a substring of the expected error message
#   CASE_ABSENT         if set: a file the run must not leave behind (removed
#                       before it), e.g. the output of a command that failed
# Failing cases must leave stdout empty and print exactly one line,
# "skelconv: error: ...", on stderr. A case that does not hold stops with
# "CHECK-FAILED: <what differs>" (matched by the test of this checker,
# cli_checker_refuses_truncated_output).
cmake_minimum_required(VERSION 3.25)

include(${CASE})
if(DEFINED CASE_ABSENT)
  file(REMOVE ${CASE_ABSENT})
endif()

execute_process(
  COMMAND ${SKELCONV} ${CASE_ARGS}
  INPUT_FILE ${CASE_STDIN}
  OUTPUT_VARIABLE stdout
  ERROR_VARIABLE stderr
  RESULT_VARIABLE exit_code)

set(report "skelconv ${CASE_ARGS} < ${CASE_STDIN}\nexit code: ${exit_code}\nstdout:\n${stdout}\nstderr:\n${stderr}")

if(NOT exit_code STREQUAL CASE_EXIT)
  message(FATAL_ERROR "CHECK-FAILED: expected exit code ${CASE_EXIT}\n${report}")
endif()

if(NOT CASE_EXIT EQUAL 0)
  if(NOT stdout STREQUAL "")
    message(FATAL_ERROR "CHECK-FAILED: a failing run must write nothing on stdout\n${report}")
  endif()
  if(NOT stderr MATCHES "^skelconv: error: [^\n]+\n$")
    message(FATAL_ERROR "CHECK-FAILED: stderr must be one line \"skelconv: error: ...\"\n${report}")
  endif()
endif()

if(DEFINED CASE_ABSENT AND EXISTS ${CASE_ABSENT})
  message(FATAL_ERROR "CHECK-FAILED: the run left ${CASE_ABSENT} behind\n${report}")
endif()
if(DEFINED CASE_STDERR)
  string(FIND "${stderr}" "${CASE_STDERR}" found)
  if(found EQUAL -1)
    message(FATAL_ERROR "CHECK-FAILED: stderr does not contain: ${CASE_STDERR}\n${report}")
  endif()
endif()

if(DEFINED CASE_STDOUT AND NOT stdout STREQUAL CASE_STDOUT)
  message(FATAL_ERROR "CHECK-FAILED: stdout differs; expected:\n${CASE_STDOUT}\n${report}")
endif()

if(DEFINED CASE_STDOUT_LINES)
  # %.17g of a finite double: optional sign, digits, optional fraction and exponent.
  set(number "-?[0-9]+(\\.[0-9]+)?(e[-+][0-9]+)?")
  string(REGEX MATCHALL "[^\n]*\n" lines "${stdout}")
  list(LENGTH lines count)
  if(NOT count EQUAL CASE_STDOUT_LINES)
    message(FATAL_ERROR "CHECK-FAILED: expected ${CASE_STDOUT_LINES} output lines, got ${count}\n${report}")
  endif()
  foreach(line IN LISTS lines)
    if(NOT line MATCHES "^${number} ${number} ${number} ${number}\n$")
      message(FATAL_ERROR "CHECK-FAILED: not four finite numbers: ${line}\n${report}")
    endif()
  endforeach()
endif()
