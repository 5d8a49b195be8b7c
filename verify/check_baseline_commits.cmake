# Fails if a committed baseline report (verify/baselines/*.json) was made
# from a tree with uncommitted changes, names no commit at all, or, where the
# source tree has a full git history, names a commit that history does not hold
# (`git cat-file -e COMMIT^{commit}`). Without git or a history (a source
# archive, a shallow clone) the existence check is skipped with a message saying so.
#   cmake -DDIR=verify/baselines -P check_baseline_commits.cmake
file(GLOB baselines "${DIR}/*.json")
if(NOT baselines)
  message(FATAL_ERROR "no baseline reports in ${DIR}")
endif()
find_program(GIT git)
set(history FALSE)
if(GIT)
  execute_process(COMMAND "${GIT}" -C "${DIR}" rev-parse --is-shallow-repository
                  RESULT_VARIABLE not_a_tree OUTPUT_VARIABLE shallow OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT not_a_tree AND shallow STREQUAL "false")
    set(history TRUE)
  endif()
endif()
if(NOT history)
  message(STATUS "no full git history at ${DIR} (no git, not a checkout, or a shallow clone): "
                 "the baselines' commits are not looked up")
endif()
foreach(baseline IN LISTS baselines)
  file(READ "${baseline}" text)
  string(JSON commit ERROR_VARIABLE missing GET "${text}" settings commit)
  if(missing OR NOT commit MATCHES "^[0-9a-f]+$")
    message(FATAL_ERROR "${baseline}: settings.commit is \"${commit}\": regenerate the baseline from a clean "
                        "checkout of a commit")
  endif()
  if(history)
    execute_process(COMMAND "${GIT}" -C "${DIR}" cat-file -e "${commit}^{commit}"
                    RESULT_VARIABLE absent OUTPUT_QUIET ERROR_QUIET)
    if(absent)
      message(FATAL_ERROR "${baseline}: settings.commit ${commit} is not a commit of this repository's history: "
                          "regenerate the baseline from a clean checkout of a commit")
    endif()
  endif()
  message(STATUS "${baseline}: made at commit ${commit}")
endforeach()
