// codegen/helper_costs.hpp — what one call of each hand-written helper that
// generated code calls costs, in the units of skelconv/kernels/op_count.hpp.
//
// One source of truth: each cost is measured by running the helper itself
// once on tools/counting_scalar.hpp's CountingDouble, which tallies every
// operation executed. No cost is modelled by hand, and nothing is read from
// a helper's name. A fixed rule (segment_moments_gauss<T, N>,
// polygon_edge_H_near_plane) costs the same at every input. A helper whose
// loop length depends on P is run at the longest loop the generated code can
// hand it (helper_costs.cpp says which input that is and why), so the
// "longest path" columns of generated/opcounts.csv are upper bounds, not a
// path that left the loop out. A change to a helper changes these counts,
// and the regeneration test (codegen_regeneration_is_byte_identical) then
// fails until generated/ is regenerated.
#pragma once

#include <string>

#include <skelconv/kernels/op_count.hpp>

namespace skelconv::codegen::helper_costs {

/// segment_moments_gauss<T, nodes>: every level m_lo, m_lo + 2, …, m_hi,
/// moments k = 0…k_max. `nodes` is one of Boost's tabulated 7, 10, 15, 20, 25, 30.
OpCount gauss_rule(int nodes, int m_lo, int m_hi, int k_max);

/// segment_moments_gauss_panels<T> at its deepest grading in double (P
/// 1e-150 |AB| beyond an end of the segment, on its line).
OpCount gauss_panels(int m_lo, int m_hi, int k_max);

/// segment_moments_beyond_end<T> at the largest per-step factor the
/// generated code allows (ρ → 7/10), beyond B (the costlier end).
OpCount moments_beyond_end(int m_lo, int m_hi, int k_max);

/// J_downward<T>(n, …) (ρ → 7/10) and J_upward_compact<T>(n, …) (ρ → 17/20),
/// the helpers generated code calls inside expressions: `function` is the
/// GiNaC function's name. Throws std::logic_error for any other name.
OpCount expression_helper(const std::string& function, int n);

/// polygon_edge_H_near_plane<T> (20-point rule; fixed cost).
OpCount polygon_H_near_plane(int n_lo, int n_hi);

/// polygon_edge_G_compact_chord<T> with its most panels (u over [−√3, √3]).
OpCount polygon_G_compact_chord(int p_lo, int p_hi);

/// segment_moments_gauss_sine<T, nodes> (fixed cost; its mapped table is
/// computed once per type, not per call). Only nodes = 30.
OpCount gauss_sine_rule(int nodes, int m_lo, int m_hi, int k_max);

/// segment_exact_cross<T> (skelconv/detail/exact_cross.hpp; fixed cost, each
/// fused multiply-add counted as one × and one +).
OpCount exact_cross();

/// segment_moments_between_roots<T, nodes> (linear map; nodes 7–30) or
/// <T, 30, NodeMap::sine> (`sine`); fixed cost.
OpCount between_roots(int nodes, bool sine, int m_lo, int m_hi, int k_max);

/// exact_point_support_gap<T>, exact_line_support_gap<T>
/// (skelconv/detail/support_gap.hpp; fixed cost, fma as one × and one +).
OpCount point_support_gap();
OpCount line_support_gap();

/// The compact SCALIS segment's work around its generated closed form
/// (skelconv/detail/scalis_compact_support.hpp), per point: prepare,
/// closed_form_input and finish, at a point inside the support with both
/// ends of the segment inside it (the generic path: the plain products of
/// support_depths, no root clips the segment), F alone or F and ∇F.
OpCount scalis_compact_around_closed_form(int degree, bool with_grad);
/// Its preparation, once per segment: prepare_segment.
OpCount scalis_compact_segment_preparation(int degree);

}  // namespace skelconv::codegen::helper_costs
