// codegen/segment_families.cpp — see segment_families.hpp.
#include "segment_families.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "segment_program_builder.hpp"

namespace skelconv::codegen {

REGISTER_FUNCTION(nonnegative_part, dummy())
REGISTER_FUNCTION(minimum, dummy())
REGISTER_FUNCTION(maximum, dummy())

namespace {

std::string weight_text(int weight_degree) {
  if (weight_degree == 0) return "w0";
  std::string s = "(w0";
  for (int k = 1; k <= weight_degree; ++k) s += " + w" + std::to_string(k) + (k == 1 ? " t" : " t^" + std::to_string(k));
  return s + ")";
}

}  // namespace

std::string SegmentKernelSpec::name() const {
  return "segment_" + std::string(family_name(family)) + "_i" + std::to_string(degree) + "_w" +
         std::to_string(weight_degree);
}

std::string SegmentKernelSpec::equation() const {
  const std::string i = std::to_string(degree);
  const std::string w = weight_text(weight_degree);
  switch (family) {
    case KernelFamily::inverse:
      return "f(P) = |AB| ∫_0^1 " + w + " |P − Γ(t)|^(−" + i + ") dt";
    case KernelFamily::cauchy:
      return "f(P) = |AB| ∫_0^1 " + w + " (1 + s |P − Γ(t)|²)^(−" + i + "/2) dt";
    case KernelFamily::compact:
      return "f(P) = |AB| ∫_t0^t1 " + w + " (1 − |P − Γ(t)|²/R²)^(" + i + "/2) dt";
  }
  throw std::logic_error("unknown family");
}

StraightLineProgram build_segment_program(const SegmentKernelSpec& spec, SegmentOutputs outputs) {
  return SegmentProgramBuilder(spec).build(outputs);
}

}  // namespace skelconv::codegen
