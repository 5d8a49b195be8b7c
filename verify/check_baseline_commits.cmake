# Fails if a committed baseline report (verify/baselines/*.json) was made
# from a tree with uncommitted changes, or names no commit at all.
#   cmake -DDIR=verify/baselines -P check_baseline_commits.cmake
file(GLOB baselines "${DIR}/*.json")
if(NOT baselines)
  message(FATAL_ERROR "no baseline reports in ${DIR}")
endif()
foreach(baseline IN LISTS baselines)
  file(READ "${baseline}" text)
  string(JSON commit ERROR_VARIABLE missing GET "${text}" settings commit)
  if(missing OR NOT commit MATCHES "^[0-9a-f]+$")
    message(FATAL_ERROR "${baseline}: settings.commit is \"${commit}\": regenerate the baseline from a clean "
                        "checkout of a commit")
  endif()
  message(STATUS "${baseline}: made at commit ${commit}")
endforeach()
