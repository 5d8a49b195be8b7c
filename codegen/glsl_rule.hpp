// codegen/glsl_rule.hpp — the GLSL target's form of the segment and SCALIS
// segment kernels: their definition integral by a fixed Gauss–Legendre rule
// (glsl_rule.cpp says why, and why this rule).
#pragma once

#include <string>

#include "segment_families.hpp"

namespace skelconv::codegen {

/// The guarded GLSL block every segment and SCALIS segment file carries:
/// skelconv_segment_rule, the rule itself, and its node table.
const std::string& glsl_rule_block();

/// NAME_f and NAME_f_and_grad of a segment kernel (every family, degree and
/// weight degree), each a call of skelconv_segment_rule.
std::string glsl_segment_rule_functions(const SegmentKernelSpec& spec);

/// The same for a SCALIS segment kernel (unnormalised F, docs/mathematics.md §4).
std::string glsl_scalis_rule_functions(const ScalisKernelSpec& spec);

}  // namespace skelconv::codegen
