// verify/build_info.hpp — which source the verifier (and the generated
// kernels it checks) was built from, for the sweep's report: shard reports
// from different commits must not be merged (merge_reports).
#pragma once

#include <string_view>

namespace skelconv::verify {

/// `git rev-parse HEAD` of the source tree at build time, with "-dirty" when
/// tracked files differed from it, or "unknown" outside a git checkout.
/// Written by write_commit.cmake before every build of the verifier.
std::string_view build_commit();

}  // namespace skelconv::verify
