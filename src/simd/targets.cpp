// src/simd/targets.cpp — which Highway target the batches use
// (include/skelconv/simd/batch.hpp). Compiled with the same target list as
// the batch translation units (HWY_DISABLED_TARGETS in src/CMakeLists.txt).
#include <hwy/highway.h>
#include <hwy/targets.h>

#include <cstdint>
#include <string>

#include "skelconv/simd/batch.hpp"

namespace skelconv::simd {

std::string active_target() {
  const std::int64_t usable = hwy::SupportedTargets() & HWY_TARGETS;
  return hwy::TargetName(usable & -usable);  // the lowest bit is the best target
}

bool force_target(const std::string& name) {
  hwy::SetSupportedTargetsForTest(0);  // back to what the CPU supports
  if (name.empty()) return true;
  for (std::int64_t targets = hwy::SupportedTargets() & HWY_TARGETS; targets != 0; targets &= targets - 1) {
    const std::int64_t target = targets & -targets;
    if (name == hwy::TargetName(target)) {
      hwy::SetSupportedTargetsForTest(target);
      return true;
    }
  }
  return false;
}

}  // namespace skelconv::simd
