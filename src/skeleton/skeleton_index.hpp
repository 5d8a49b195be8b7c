// src/skeleton/skeleton_index.hpp — the bounding-volume index of a Skeleton
// (one SupportGrid per large sum node), which sum nodes hold primitives of
// one type only, and its once-only lazy construction.
// Internal to skelconv_runtime.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "skelconv/field/support_grid.hpp"
#include "../detail/far_rule_batch.hpp"
#include "skelconv/primitives/far_segment_rule.hpp"

namespace skelconv::detail {

struct SkeletonIndex {
  /// grids[id]: the grid of node id's children, or none (not a sum node,
  /// too few children, or no compact-support primitive child).
  std::vector<std::optional<SupportGrid>> grids;
  /// one_primitive_type[id]: node id is a sum whose children are all
  /// primitives of one type (Skeleton::evaluate_sum loops over them with
  /// that type's evaluation).
  std::vector<bool> one_primitive_type;
  /// For a plain list (the root sum, no weight, no blend node) of at least
  /// Skeleton::min_far_rule_segments segments that all have a far rule
  /// (Segment::far_rule: Cauchy, no negative weight coefficient;
  /// ScalisSegment::far_rule: Cauchy, radii > 0), of one kind or both,
  /// copies of those rules in order, side by side in memory for the
  /// tolerance mode's passes over them; else empty.
  std::vector<FarSegmentRule> far_rules;
  /// The degree and kind of every far rule when they share both, else 0
  /// (Skeleton::evaluate then reads them per rule).
  int far_rule_degree = 0;
  bool far_rule_scalis = false;
  /// far_rules side by side, chosen and summed many at a time, when they
  /// are of one kind, degree and weight degree (FarRuleBatch::make); the
  /// same values as add_segments_within's passes over far_rules.
  std::optional<FarRuleBatch> far_batch;
  /// The skeleton is a list of primitives of one type: no blend node below
  /// the root, no weight, no grid (Skeleton::evaluate loops over the
  /// primitives without walking the tree).
  bool primitive_list = false;
  /// nonnegative_sum[id]: node id is a sum without weights whose every
  /// child is a primitive whose field is never negative (SCALIS, a point
  /// of positive weight) or such a sum (Skeleton::reaches adds its terms
  /// only until the total is well past the level).
  std::vector<bool> nonnegative_sum;
};

/// Built once per version of the skeleton; std::call_once lets any number
/// of threads ask for it at once, and a validation error leaves it unbuilt
/// (the next evaluation reports it again).
struct IndexCache {
  std::once_flag once;
  std::unique_ptr<const SkeletonIndex> index;
  /// Set (release) once `index` is built: evaluations test it (acquire)
  /// before std::call_once, which in libstdc++ sets thread-local state and
  /// calls pthread_once on every call, even when done.
  std::atomic<bool> built{false};
};

}  // namespace skelconv::detail
