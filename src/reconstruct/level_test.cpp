// Implementation of level_test.hpp.
#include "level_test.hpp"

#include <cmath>
#include <limits>

#include "skelconv/errors.hpp"

namespace skelconv::reconstruct {
namespace {

/// Whether every blend node of the tree is an unweighted sum: then f is the
/// plain sum of every primitive, whatever the nesting.
bool plain_sum(const Skeleton& skeleton, Skeleton::NodeId id) {
  const Blend& blend = skeleton.blend(id);
  if (blend.kind != BlendKind::sum || !blend.weights.empty()) return false;
  for (std::size_t k = 0; k < skeleton.child_count(id); ++k) {
    const auto [is_blend, index] = skeleton.child(id, k);
    if (is_blend && !plain_sum(skeleton, index)) return false;
  }
  return true;
}

bool has_far_rule(const Primitive& primitive) {
  if (const Segment* segment = std::get_if<Segment>(&primitive)) return segment->far_rule() != nullptr;
  if (const ScalisSegment* segment = std::get_if<ScalisSegment>(&primitive)) return segment->far_rule() != nullptr;
  return false;
}

}  // namespace

LevelTest::LevelTest(const Skeleton& skeleton) : skeleton_(skeleton) {
  const std::vector<Primitive>& primitives = skeleton.primitives();
  if (primitives.size() < Skeleton::min_far_rule_segments || !plain_sum(skeleton, Skeleton::root)) return;
  for (const Primitive& primitive : primitives)
    if (!has_far_rule(primitive)) return;
  list_.emplace(primitives, skeleton.iso());
  list_->prepare();
  // |f̃ − f| ≤ ε f plus a few units of rounding (docs/field.md), and the
  // exact sum of N positive terms errs by at most (N − 1) u of f beside its
  // kernels' errors: four times the sum of the three.
  const double unit = std::numeric_limits<double>::epsilon() / 2;
  margin_ = 4.0 * (tolerance + kernel_error + double(primitives.size() + 8) * unit);
}

bool LevelTest::at_or_above(const Vec3& p) const {
  const double iso = skeleton_.iso();
  if (list_) {
    try {
      const double f = list_->value(p, tolerance);
      if (f > 0.0 && std::isfinite(f) && std::abs(f - iso) > margin_ * f) return f >= iso;
    } catch (const InputError&) {
    } catch (const EvaluationError&) {
      // The exact evaluation below says what is wrong, as without the filter.
    }
  }
  exact_questions_.fetch_add(1, std::memory_order_relaxed);
  return skeleton_.value(p, tolerance) >= iso;
}

}  // namespace skelconv::reconstruct
