# One `skelconv skeletonize` run on a closed mesh, checked through its
# --report (docs/reconstruction.md, "The report"). Invoked by CTest as
#   cmake -DSKELCONV=<binary> -DINPUT=<mesh> -DOUT=<prefix> [checks] -P run_skeletonize_case.cmake
# Checks (each optional):
#   RESULT=<stage>        the result (last) stage's name, e.g. ball or fitted
#   POINTS=<n>            its number of point primitives
#   MAX_HAUSDORFF=<h>     its two-sided Hausdorff distance / diagonal is below h
#   MAX_RMS=<r>           its RMS distance / diagonal is below r
#   SAME_EULER=ON         its meshed surface has the input's Euler characteristic
#   INPUT_EULER=<n>       the input's Euler characteristic (after any repair) is n
#   SAME_COMPONENTS=ON    its meshed surface has as many components as the input has parts
#   REPAIRED=union|holes|flipped  the report's input_repair names the boolean
#                         union of crossing triangles (union), the holes filled
#                         (holes) or the triangles turned round (flipped);
#                         without it, input_repair must be null
#   ARGS=<options>        more options for skeletonize, separated by spaces (e.g. "--method curve")
#   EXIT=<code>, STDERR=<substring>: a refused input; then neither <prefix>.json
#                         nor <prefix>_report.json may exist afterwards.
# The measured numbers are printed, so that `ctest -V` shows them.
cmake_minimum_required(VERSION 3.25)

set(skeleton ${OUT}.json)
set(report ${OUT}_report.json)
file(REMOVE ${skeleton} ${report})
separate_arguments(args UNIX_COMMAND "${ARGS}")
execute_process(COMMAND ${SKELCONV} skeletonize ${INPUT} -o ${skeleton} --report ${report} --report-stages result --quiet
                        ${args}
                OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr RESULT_VARIABLE exit_code)
set(run "skelconv skeletonize ${INPUT}\nexit code: ${exit_code}\nstdout:\n${stdout}\nstderr:\n${stderr}")
if(NOT DEFINED EXIT)
  set(EXIT 0)
endif()
if(NOT exit_code STREQUAL EXIT)
  message(FATAL_ERROR "expected exit code ${EXIT}\n${run}")
endif()
if(NOT EXIT EQUAL 0)
  if(NOT stderr MATCHES "^skelconv: error: [^\n]+\n$" OR NOT stdout STREQUAL "")
    message(FATAL_ERROR "a refused input must print one line \"skelconv: error: ...\" and nothing else\n${run}")
  endif()
  string(FIND "${stderr}" "${STDERR}" found)
  if(found EQUAL -1)
    message(FATAL_ERROR "stderr does not contain: ${STDERR}\n${run}")
  endif()
  if(EXISTS ${skeleton} OR EXISTS ${report})
    message(FATAL_ERROR "a refused input must write no file\n${run}")
  endif()
  return()
endif()

file(READ ${report} json)
string(JSON stages LENGTH "${json}" stages)
math(EXPR last "${stages} - 1")
string(JSON name GET "${json}" stages ${last} name)
string(JSON hausdorff GET "${json}" stages ${last} hausdorff)
string(JSON rms GET "${json}" stages ${last} rms)
string(JSON points GET "${json}" stages ${last} primitives point)
string(JSON euler_out GET "${json}" stages ${last} euler_characteristic)
string(JSON euler_in GET "${json}" input_euler_characteristic)
string(JSON components_out GET "${json}" stages ${last} components)
string(JSON components_in GET "${json}" input_components)
string(JSON result GET "${json}" result)
message(STATUS "${INPUT}: result ${name}, ${points} point primitive(s), Hausdorff ${hausdorff}, RMS ${rms} of the "
               "diagonal, Euler characteristic ${euler_in} in, ${euler_out} out, components ${components_in} in, "
               "${components_out} out")
if(NOT result STREQUAL name)
  message(FATAL_ERROR "the report's result (${result}) is not its last stage (${name})\n${run}")
endif()
if(DEFINED RESULT AND NOT name STREQUAL RESULT)
  message(FATAL_ERROR "expected the result ${RESULT}, got ${name}\n${run}")
endif()
if(DEFINED POINTS AND NOT points EQUAL POINTS)
  message(FATAL_ERROR "expected ${POINTS} point primitive(s), got ${points}\n${run}")
endif()
# if(LESS) compares the two strings as floating-point numbers (exponents too).
if(DEFINED MAX_HAUSDORFF AND NOT hausdorff LESS MAX_HAUSDORFF)
  message(FATAL_ERROR "Hausdorff ${hausdorff} of the diagonal, goal below ${MAX_HAUSDORFF}\n${run}")
endif()
if(DEFINED MAX_RMS AND NOT rms LESS MAX_RMS)
  message(FATAL_ERROR "RMS ${rms} of the diagonal, goal below ${MAX_RMS}\n${run}")
endif()
if(SAME_EULER AND NOT euler_in EQUAL euler_out)
  message(FATAL_ERROR "Euler characteristic ${euler_in} in, ${euler_out} out\n${run}")
endif()
if(SAME_COMPONENTS AND NOT components_in EQUAL components_out)
  message(FATAL_ERROR "${components_in} component(s) in, ${components_out} out\n${run}")
endif()
if(DEFINED INPUT_EULER AND NOT euler_in EQUAL INPUT_EULER)
  message(FATAL_ERROR "the input's Euler characteristic is ${euler_in}, expected ${INPUT_EULER}\n${run}")
endif()
string(JSON repair_type TYPE "${json}" input_repair)
if(REPAIRED STREQUAL "union")
  if(NOT repair_type STREQUAL "OBJECT")
    message(FATAL_ERROR "the report's input_repair is ${repair_type}, expected the repair\n${run}")
  endif()
  string(JSON action GET "${json}" input_repair self_intersection action)
  string(JSON pairs GET "${json}" input_repair self_intersection crossing_pairs)
  message(STATUS "input_repair: ${action}, ${pairs} crossing pairs")
  if(NOT action STREQUAL "boolean_union" OR NOT pairs GREATER 0)
    message(FATAL_ERROR "input_repair: ${action}, ${pairs} crossing pairs; expected boolean_union, > 0\n${run}")
  endif()
elseif(REPAIRED STREQUAL "holes")
  if(NOT repair_type STREQUAL "OBJECT")
    message(FATAL_ERROR "the report's input_repair is ${repair_type}, expected the repair\n${run}")
  endif()
  string(JSON holes GET "${json}" input_repair holes holes_filled)
  string(JSON added GET "${json}" input_repair holes triangles_added)
  string(JSON largest GET "${json}" input_repair holes largest_hole_area)
  message(STATUS "input_repair: ${holes} hole(s) filled, +${added} triangles, the largest ${largest} of the area")
  if(NOT holes GREATER 0 OR NOT added GREATER 0)
    message(FATAL_ERROR "input_repair: ${holes} holes filled, +${added} triangles; expected > 0\n${run}")
  endif()
elseif(REPAIRED STREQUAL "flipped")
  if(NOT repair_type STREQUAL "OBJECT")
    message(FATAL_ERROR "the report's input_repair is ${repair_type}, expected the repair\n${run}")
  endif()
  string(JSON flipped GET "${json}" input_repair holes triangles_flipped)
  message(STATUS "input_repair: ${flipped} triangles turned round")
  if(NOT flipped GREATER 0)
    message(FATAL_ERROR "input_repair: ${flipped} triangles turned round; expected > 0\n${run}")
  endif()
elseif(DEFINED REPAIRED)
  message(FATAL_ERROR "REPAIRED=${REPAIRED}: expected union, holes or flipped")
elseif(NOT repair_type STREQUAL "NULL")
  message(FATAL_ERROR "the report's input_repair is ${repair_type}: the input was repaired\n${run}")
endif()
