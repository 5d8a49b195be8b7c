# Two `skelconv skeletonize` runs that must write the same skeleton file,
# byte for byte: the same surface given two ways (e.g. with vertices that no
# triangle uses, which are no part of it). Invoked by CTest as
#   cmake -DSKELCONV=<binary> -DINPUT=<mesh> -DSAME_AS=<mesh> -DOUT=<prefix> [-DARGS=<options>] -P same_skeleton.cmake
cmake_minimum_required(VERSION 3.25)

separate_arguments(args UNIX_COMMAND "${ARGS}")
set(run_a ${INPUT})
set(run_b ${SAME_AS})
foreach(which a b)
  file(REMOVE ${OUT}_${which}.json)
  execute_process(COMMAND ${SKELCONV} skeletonize ${run_${which}} -o ${OUT}_${which}.json --quiet ${args}
                  OUTPUT_QUIET ERROR_VARIABLE stderr RESULT_VARIABLE exit_code)
  if(NOT exit_code EQUAL 0)
    message(FATAL_ERROR "skelconv skeletonize ${run_${which}}: exit code ${exit_code}\n${stderr}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}_a.json ${OUT}_b.json RESULT_VARIABLE different)
if(different)
  message(FATAL_ERROR "${INPUT} and ${SAME_AS} gave different skeleton files (${OUT}_a.json, ${OUT}_b.json)")
endif()
