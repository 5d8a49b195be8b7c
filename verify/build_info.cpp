// verify/build_info.cpp — see build_info.hpp. verify_commit.hpp is written
// into the build tree by write_commit.cmake (rewritten only when the commit
// changes, so only this file recompiles).
#include "build_info.hpp"

#include "verify_commit.hpp"

namespace skelconv::verify {

std::string_view build_commit() { return skelconv_verify_commit; }

}  // namespace skelconv::verify
