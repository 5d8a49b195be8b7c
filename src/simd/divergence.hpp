// src/simd/divergence.hpp — which lanes of a vector group follow which branch
// of a generated kernel (docs/simd.md, "Forms and divergence").
//
// The generated kernels choose between stable forms with `if (condition)`.
// Run on a vector of lanes (src/simd/lanes-inl.hpp), a condition is a mask,
// and the branch can be taken only one way. Divergence::decide takes the side
// of the majority of the still-active lanes and sets the others aside: they
// leave the active set, and each is labelled with a key that encodes every
// decision up to and including its own side. After the call, the active lanes
// hold correct results; the set-aside lanes are re-run together with lanes of
// the same key (group_runner-inl.hpp), which agree on every branch up to that
// point, so each form runs vectorised on the lanes that need it. Every group
// run finishes at least one lane (the majority side is never empty, and the
// lanes handed to the scalar path are finished too), so the re-runs
// terminate.
//
// A lane can also be handed to the scalar path (hand_to_scalar,
// hand_lane_to_scalar): where a helper cannot run vectorised (the Gauss
// panels of the SCALIS segments) or refuses a lane (a Miller recurrence that
// would not converge: the scalar path then reports the error).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

namespace skelconv::simd {

/// The most lanes of doubles in one vector (AVX-512: 8); the width of the
/// lane bit sets below.
inline constexpr std::size_t max_lanes = 8;

class Divergence {
 public:
  /// A new group of `lanes` lanes (≤ max_lanes), all active, no decision yet.
  explicit Divergence(std::size_t lanes) : active_((1u << lanes) - 1u) {}

  /// The side of a branch taken by the group: `taken` has bit k set when lane
  /// k's condition holds. Lanes of the minority side (ties go to `true`)
  /// leave the active set.
  bool decide(unsigned taken) {
    const unsigned yes = taken & active_;
    const unsigned no = active_ & ~taken;
    bool side = true;
    if (yes != 0 && no != 0) {
      side = std::popcount(yes) >= std::popcount(no);
      const unsigned leaving = side ? no : yes;
      const std::uint64_t their_key = extend(key_, !side);
      for (unsigned lane = 0; lane < max_lanes; ++lane) {
        if (leaving >> lane & 1u) set_aside_key_[lane] = their_key;
      }
      active_ &= ~leaving;
    } else {
      side = yes != 0;
    }
    key_ = extend(key_, side);
    return side;
  }

  /// The active lanes need a form that is evaluated point by point: they are
  /// marked for the scalar path and leave the active set.
  void hand_to_scalar() {
    to_scalar_ |= active_;
    active_ = 0;
  }

  /// The same for active lane `lane` alone.
  void hand_lane_to_scalar(std::size_t lane) {
    to_scalar_ |= active_ & (1u << lane);
    active_ &= ~(1u << lane);
  }

  /// Lane k is active (its results are valid) when bit k is set.
  unsigned active() const { return active_; }
  /// Lane k must be evaluated by the scalar path when bit k is set.
  unsigned to_scalar() const { return to_scalar_; }
  /// The key of a lane set aside: lanes with equal keys took the same
  /// branches up to the one where they left.
  std::uint64_t set_aside_key(std::size_t lane) const { return set_aside_key_[lane]; }

 private:
  /// The key after one more decision (a multiplicative hash of the path; a
  /// collision only groups lanes that may diverge again, never a wrong result).
  static std::uint64_t extend(std::uint64_t key, bool side) {
    return (key ^ (side ? 0x9e3779b97f4a7c15u : 0x632be59bd9b4e019u)) * 0xbf58476d1ce4e5b9u;
  }

  unsigned active_;
  unsigned to_scalar_ = 0;
  std::uint64_t key_ = 1;
  std::uint64_t set_aside_key_[max_lanes] = {};
};

}  // namespace skelconv::simd
