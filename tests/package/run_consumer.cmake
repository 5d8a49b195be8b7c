# Builds tests/package/consumer against skelconv and compares its output
# with `skelconv eval` (tests/package/CMakeLists.txt says what each MODE checks).
# Fails (FATAL_ERROR) with the step that went wrong.

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

set(work ${WORK}/${MODE})
file(REMOVE_RECURSE ${work})
set(configure ${CMAKE_COMMAND} -S ${CONSUMER} -B ${work}/build -DCMAKE_CXX_COMPILER=${CXX})
if(LAUNCHER)
  list(APPEND configure -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()

if(MODE STREQUAL "install")
  set(prefix ${work}/prefix)
  run_step("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
  run_step("configuring the consumer" ${configure} -DCMAKE_BUILD_TYPE=${BUILD_TYPE} -DCMAKE_PREFIX_PATH=${prefix}
           -DAPI_EXAMPLE=${API_EXAMPLE})
else()
  # No build type: the consumer checks that skelconv leaves it unset (only a
  # top-level skelconv picks Release).
  run_step("configuring the consumer" ${configure} -DSKELCONV_SOURCE_DIR=${SOURCE_DIR})
endif()
run_step("building the consumer" ${CMAKE_COMMAND} --build ${work}/build -j 2)

# The points: those the example prints (install), or a fixed list (subdirectory).
if(MODE STREQUAL "install")
  run_step("running the example" ${work}/build/consumer ${SKELETON})
  string(REGEX MATCHALL "[^\n]+" lines "${step_output}")
  set(points "")
  set(values "")
  foreach(line IN LISTS lines)
    if(line MATCHES "^([^ ]+ [^ ]+ [^ ]+) ([^ ]+ [^ ]+ [^ ]+ [^ ]+)$")
      string(APPEND points "${CMAKE_MATCH_1}\n")
      string(APPEND values "${CMAKE_MATCH_2}\n")
    endif()
  endforeach()
  run_step("running the reconstruction and canal consumer" ${work}/build/consumer_reconstruct_canal)
  if(NOT step_output MATCHES "^canal mesh: [0-9]+ triangles, closed\n$")
    message(FATAL_ERROR "the reconstruction and canal consumer printed:\n${step_output}")
  endif()
  # The default skeleton runs too: bounds and the scalar types line.
  run_step("running the example without arguments" ${work}/build/consumer)
  if(NOT step_output MATCHES "in \\[.*\\]\nfloat .*, double .*, long double .*, cpp_bin_float_50 ")
    message(FATAL_ERROR "the example printed:\n${step_output}")
  endif()
else()
  set(points "0 0 1\n0.5 0.25 -0.125\n3 2 1\n-1 0.5 0.5\n")
  file(WRITE ${work}/points.txt "${points}")
  run_step("running the consumer" ${work}/build/consumer ${SKELETON} INPUT_FILE ${work}/points.txt)
  set(values "${step_output}")
endif()
string(REGEX MATCHALL "\n" count "${points}")
list(LENGTH count count)
if(count LESS 4)
  message(FATAL_ERROR "expected at least 4 points, got ${count}")
endif()

file(WRITE ${work}/points.txt "${points}")
run_step("skelconv eval" ${SKELCONV} eval ${SKELETON} INPUT_FILE ${work}/points.txt)
if(NOT values STREQUAL step_output)
  message(FATAL_ERROR "consumer output:\n${values}\ndiffers from skelconv eval:\n${step_output}")
endif()

# The Python module installed by the same cmake --install.
if(MODE STREQUAL "install" AND PYTHON)
  set(ENV{PYTHONPATH} ${prefix}/${PYTHON_DIR})
  run_step("importing the installed Python module" ${PYTHON} -c
    # (newlines, not semicolons: a semicolon would split the CMake argument)
    "import os, skelconv
s = skelconv.Skeleton([{'type': 'segment', 'a': [0, 0, 0], 'b': [1, 0, 0], 'kernel': {'family': 'inverse', 'degree': 3}}])
f, g = s.field([[0.5, 1, 0]])
assert f[0] > 0 and g.shape == (1, 3) and g[0, 1] < 0, (f, g)
print(os.path.dirname(skelconv.__file__))")
  string(STRIP "${step_output}" where)
  if(NOT where STREQUAL "${prefix}/${PYTHON_DIR}")
    message(FATAL_ERROR "skelconv was imported from ${where}, not from the install prefix ${prefix}/${PYTHON_DIR}")
  endif()
endif()
message(STATUS "${MODE}: ${count} points agree with skelconv eval")
