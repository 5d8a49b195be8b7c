# docs/api.md must show docs/api_example.cpp verbatim (the code ctest compiles).
file(READ ${SOURCE} source)
file(READ ${MARKDOWN} markdown)
string(FIND "${markdown}" "${source}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${MARKDOWN} does not contain ${SOURCE} verbatim: copy the file into its ```cpp block")
endif()
