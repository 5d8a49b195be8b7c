// src/detail/far_rule_batch.hpp — the far rules of a list of Cauchy
// segments of one kind and degree (FarSegmentRule), chosen and summed many
// segments at a time (docs/field.md, "Tolerance").
//
// FarSegmentRule chooses and sums one segment at a time: per (point,
// segment) pair a call, the segment's constants read from an object of a
// few hundred bytes, and a rule whose two SSE2 lanes hold two nodes of the
// same segment. Here the constants the passes read are copied side by side
// (a structure of arrays), and each SSE2 lane holds one segment: the ends'
// Q, the focal sum S and the lower bound of two segments at a time, then the
// n-node sums of two segments that take the same n at a time. Every lane
// does the operations FarSegmentRule does for its segment, in the same
// order (a rule's even and odd nodes summed apart, then added), and the
// caller adds the terms in the order Skeleton's tolerance mode always has
// (grouped by n within chunks of `chunk` segments): the same rules and the
// same values, bit for bit (tests/far_rule_batch_test.cpp). Internal to
// skelconv_runtime: the skeleton's index holds one (skeleton_index.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "skelconv/geometry.hpp"
#include "skelconv/primitives/far_segment_rule.hpp"

namespace skelconv::detail {

class FarRuleBatch {
 public:
  /// Segments whose terms are added grouped by node count (Skeleton's
  /// tolerance mode): the order of additions is fixed per chunk.
  static constexpr std::size_t chunk = 64;

  /// The batch of `rules` (copied), or nothing where they are not all of
  /// one kind, one degree and (classical) one weight degree: such lists
  /// keep FarSegmentRule's own passes.
  static std::optional<FarRuleBatch> make(std::span<const FarSegmentRule> rules);

  std::size_t size() const { return rules_.size(); }
  const std::vector<FarSegmentRule>& rules() const { return rules_; }

  /// The passes below work on `lanes` segments (or nodes) at a time: 2,
  /// SSE2's lanes (x86-64's baseline), or 4, AVX's, on processors that have
  /// it; every lane does the same operations in the same order (no fused
  /// multiply-add), so the rules and the terms are the same bits either way.
  /// The widest this processor runs, the default: 4 or 2.
  static int widest_lanes();

  /// The rules at P (Skeleton's tolerance mode, `tolerance` ε > 0): into
  /// nodes[k] the n of segment k, 0 for the exact function; the same n as
  /// FarSegmentRule::nodes with the budget ε f̲ / N.
  void choose(const Vec3& p, double tolerance, std::uint8_t* nodes, int lanes = widest_lanes()) const;
  /// The rules for every point within `radius` of `centre`: the same n as
  /// FarSegmentRule::ball_nodes with f̲ from ball_mean_square.
  void choose_near(const Vec3& centre, double radius, double tolerance, std::uint8_t* nodes,
                   int lanes = widest_lanes()) const;

  /// The terms of segments first … first + size − 1 (size ≤ chunk) at P,
  /// in the order they are added: the exact ones (n = 0) first, then by n,
  /// each group in order of position.
  /// Entries 0 … size − 1 are written before they are read (no
  /// initialisation: a point of a short list would pay for it).
  struct Terms {
    std::size_t size = 0;
    std::array<std::uint8_t, chunk> order;  ///< order[j]: the segment's position − first
    /// f and ∇f (0 without gradient) of segment first + order[j] at [j].
    std::array<double, chunk> value, gradient_x, gradient_y, gradient_z;
    /// Term j is left to the exact function: n = 0, or the rule's f or ∇f
    /// not a normal double (FarSegmentRule::evaluate_with's test).
    std::array<bool, chunk> exact;
  };
  /// The terms of the chunk from `first` by the rules in nodes[first …]:
  /// f and, with `gradient`, ∇f (else ∇f = 0).
  void terms(const Vec3& p, std::size_t first, const std::uint8_t* nodes, bool gradient, Terms& out,
             int lanes = widest_lanes()) const;

 private:
  FarRuleBatch() = default;
  /// choose (Ball false) and choose_near for degree I and one kind, `Lanes`
  /// segments at a time: 2 (SSE2) or 4 (AVX; far_rule_batch.cpp).
  template <int I, bool Scalis, bool Ball, int Lanes>
  void choose_lanes(const Vec3& p, double radius, double tolerance, std::uint8_t* nodes) const;
  /// choose_lanes on 2 lanes, and on 4 for processors with AVX: the same bits.
  template <int I, bool Scalis, bool Ball>
  void choose_impl(const Vec3& p, double radius, double tolerance, std::uint8_t* nodes) const;
  template <int I, bool Scalis, bool Ball>
  [[gnu::target("avx")]] void choose_impl_avx(const Vec3& p, double radius, double tolerance,
                                              std::uint8_t* nodes) const;
  /// terms for degree I and one kind, with or without ∇f, each rule's
  /// nodes summed on `Lanes` lanes: 2 (SSE2) or 4 (AVX; far_rule_batch.cpp).
  template <int I, bool Scalis, bool Gradient, int Lanes>
  void terms_lanes(const Vec3& p, std::size_t first, const std::uint8_t* nodes, Terms& out) const;
  /// terms_lanes on 2 lanes, and on 4 for processors with AVX: the same bits.
  template <int I, bool Scalis, bool Gradient>
  void terms_impl(const Vec3& p, std::size_t first, const std::uint8_t* nodes, Terms& out) const;
  template <int I, bool Scalis, bool Gradient>
  [[gnu::target("avx")]] void terms_impl_avx(const Vec3& p, std::size_t first, const std::uint8_t* nodes,
                                             Terms& out) const;
  /// Those passes at [degree] (far_rule_batch.cpp).
  template <bool Scalis, bool Ball, bool Avx, int... I>
  static constexpr auto choose_table(std::integer_sequence<int, I...>);
  template <bool Scalis, bool Gradient, bool Avx, int... I>
  static constexpr auto terms_table(std::integer_sequence<int, I...>);
  /// Those tables for AVX's lanes and SSE2's, and (terms) with and without
  /// ∇f, at degrees 1 … Degrees.
  template <bool Scalis, bool Ball, int Degrees>
  static constexpr auto choose_tables();
  template <bool Scalis, int Degrees>
  static constexpr auto terms_tables();

  std::vector<FarSegmentRule> rules_;
  int degree_ = 0;
  bool scalis_ = false;
  /// What the passes read of segment k at [k] (FarSegmentRule's members of
  /// the same names): A, B − A, Q's offsets at the ends, 2/L', the
  /// centroid and spread of mean_square, q_unit and the lower bound's front.
  std::vector<double> a_x_, a_y_, a_z_, ab_x_, ab_y_, ab_z_, offset_a_, offset_b_, two_over_length_;
  std::vector<double> centroid_x_, centroid_y_, centroid_z_, spread_, q_unit_, lower_front_;
  /// The choice's factors of the budget (nodes_between) and whether W
  /// varies with S.
  std::vector<double> f_factor_, gradient_factor_;
  std::vector<std::uint8_t> weight_varies_;
  /// The integrand (classical s and weight; SCALIS c0, c1) and the fronts
  /// of f and ∇f.
  std::vector<double> s_, c0_, c1_, front_, gradient_front_;
  std::array<std::vector<double>, FarSegmentRule::Integrand::weight_count> w_;
  int weight_degree_ = 0;
};

}  // namespace skelconv::detail
