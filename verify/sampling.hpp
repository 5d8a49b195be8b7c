// verify/sampling.hpp — deterministic random segments and query points for the
// regions of verify/regions.hpp.
//
// Reproducibility: std::mt19937_64 is fully specified by the standard, but the
// std::*_distribution classes are not (their output differs between library
// versions), so we map the engine's 64-bit words to doubles ourselves. Every
// point has its own engine, seeded from (seed, family, degree, region, index),
// so a point does not depend on chunking, sharding, threads or filters.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include "extended_precision.hpp"
#include "regions.hpp"
#include "skelconv/primitives/segment_input.hpp"

namespace skelconv::verify {

/// One sweep sample: a segment, a point, a weight and the kernel parameters.
struct SweepProblem {
  KernelFamily family = KernelFamily::inverse;
  int degree = 1;
  Region region = Region::generic;
  std::uint64_t index = 0;
  Vec3<double> a{}, b{}, p{};
  std::array<double, 4> w{};  ///< weight coefficients; weight degree d uses w[0..d]
  double s = 1;               ///< Cauchy sharpness
  double R = 1;               ///< support radius (compact, soft, wyvill)
  double gaussian_a = 1;      ///< Gaussian sharpness
  double gaussian_b = 1;      ///< Gaussian height
};

/// SplitMix64 finaliser: a bijective 64-bit mixer.
constexpr std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

constexpr std::uint64_t point_seed(std::uint64_t seed, KernelFamily family, int degree, Region region,
                                   std::uint64_t index) {
  std::uint64_t h = splitmix64(seed);
  h = splitmix64(h ^ static_cast<std::uint64_t>(family));
  h = splitmix64(h ^ static_cast<std::uint64_t>(degree));
  h = splitmix64(h ^ static_cast<std::uint64_t>(region));
  return splitmix64(h ^ index);
}

/// Random numbers with our own, library-independent mapping.
class DeterministicRandom {
 public:
  explicit DeterministicRandom(std::uint64_t seed) : engine_(seed) {}

  /// Uniform on [0, 1) with 53 random bits.
  double uniform01() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
  /// Log-uniform on [lo, hi): every decade equally likely.
  double log_uniform(double lo, double hi) { return lo * std::exp(std::log(hi / lo) * uniform01()); }
  bool coin() { return (engine_() >> 63) != 0; }

  /// Uniform on the unit sphere (Archimedes: z uniform, azimuth uniform).
  Vec3<double> unit_vector() {
    const double z = uniform(-1, 1);
    const double phi = uniform(0, 2 * std::numbers::pi);
    const double rho = std::sqrt(1 - z * z);
    return {rho * std::cos(phi), rho * std::sin(phi), z};
  }

  /// A random unit vector perpendicular to the unit vector `axis`.
  Vec3<double> unit_perpendicular(const Vec3<double>& axis) {
    for (;;) {
      const Vec3<double> v = unit_vector();
      const Vec3<double> perp = axpy(-dot(v, axis), axis, v);
      const double len = norm(perp);
      if (len > 0.1) return {perp[0] / len, perp[1] / len, perp[2] / len};
    }
  }

 private:
  std::mt19937_64 engine_;
};

/// Distance from P to the segment [A, B].
inline double distance_to_segment(const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& p) {
  const Vec3<double> ab = sub(b, a), ap = sub(p, a);
  double t = dot(ab, ap) / dot(ab, ab);
  t = t < 0 ? 0 : (t > 1 ? 1 : t);
  return norm(axpy(-t, ab, ap));
}

namespace detail {

struct RandomSegment {
  Vec3<double> a, b, dir;
  double length;
  Vec3<double> at(double t) const { return axpy(t * length, dir, a); }
};

/// A in [-2, 2]³, |AB| log-uniform in [0.2, 5], direction uniform.
inline RandomSegment random_segment(DeterministicRandom& rng) {
  RandomSegment seg;
  seg.a = {rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2)};
  seg.length = rng.log_uniform(0.2, 5);
  seg.dir = rng.unit_vector();
  seg.b = seg.at(1);
  return seg;
}

/// A point at distance `dist` from the segment, its nearest point anywhere:
/// inside (a perpendicular offset) or at an end (a direction in the half-space
/// away from the segment, so the end is the nearest point).
inline Vec3<double> point_at_distance(DeterministicRandom& rng, const RandomSegment& seg, double dist) {
  const double tau = rng.uniform(-0.25, 1.25);
  const Vec3<double> perp = rng.unit_perpendicular(seg.dir);
  if (tau >= 0 && tau <= 1) return axpy(dist, perp, seg.at(tau));
  const double theta = rng.uniform(0, std::numbers::pi / 2);  // angle from the outward axis
  const double outward = tau < 0 ? -1.0 : 1.0;
  const Vec3<double> direction = axpy(std::sin(theta), perp, Vec3<double>{outward * std::cos(theta) * seg.dir[0],
                                                                          outward * std::cos(theta) * seg.dir[1],
                                                                          outward * std::cos(theta) * seg.dir[2]});
  return axpy(dist, direction, tau < 0 ? seg.a : seg.b);
}

}  // namespace detail

/// Kind of a support_boundary sample: two in three have the sphere cutting
/// the segment, one in three has P just outside the support (f = 0: checks
/// that the double clip agrees).
enum class SupportCase { sphere_cuts_segment, just_outside };

inline SupportCase support_case(std::uint64_t index) {
  return index % 3 == 2 ? SupportCase::just_outside : SupportCase::sphere_cuts_segment;
}

/// The sample `index` of (family, degree, region) for `seed`.
inline SweepProblem draw_problem(std::uint64_t seed, KernelFamily family, int degree, Region region,
                                 std::uint64_t index) {
  DeterministicRandom rng(point_seed(seed, family, degree, region, index));
  SweepProblem pb;
  pb.family = family;
  pb.degree = degree;
  pb.region = region;
  pb.index = index;
  const detail::RandomSegment seg = detail::random_segment(rng);
  const double L = seg.length;
  pb.a = seg.a;
  pb.b = seg.b;
  for (double& wk : pb.w) wk = rng.uniform(0.2, 2);  // positive: no cancellation from the weight itself
  pb.s = rng.log_uniform(0.2, 5);

  bool radius_set = false;
  switch (region) {
    case Region::generic: pb.p = detail::point_at_distance(rng, seg, L * rng.log_uniform(0.1, 3)); break;
    case Region::near_line_beside: {
      const double d = L * rng.log_uniform(1e-6, 1e-2);
      pb.p = axpy(d, rng.unit_perpendicular(seg.dir), seg.at(rng.uniform(0, 1)));
      break;
    }
    case Region::near_line_beyond: {
      const double d = L * rng.log_uniform(1e-6, 1e-2);
      const double beyond = rng.log_uniform(0.05, 2);
      const double tau = rng.coin() ? -beyond : 1 + beyond;
      pb.p = axpy(d, rng.unit_perpendicular(seg.dir), seg.at(tau));
      break;
    }
    case Region::near_ends: {
      // Within 1e-4–0.05 |AB| of an end, at ≥ 30° from the segment so that P
      // stays off the segment itself (where p^i is infinite): its distance to
      // the segment is at least half its distance to the end.
      const double rho = L * rng.log_uniform(1e-4, 0.05);
      const bool at_a = rng.coin();
      const Vec3<double> inward = at_a ? seg.dir : Vec3<double>{-seg.dir[0], -seg.dir[1], -seg.dir[2]};
      Vec3<double> direction = rng.unit_vector();
      while (dot(direction, inward) > std::cos(std::numbers::pi / 6)) direction = rng.unit_vector();
      pb.p = axpy(rho, direction, at_a ? seg.a : seg.b);
      break;
    }
    case Region::far: {
      const double dist = L * rng.log_uniform(10, 1e4);
      pb.p = axpy(dist, rng.unit_vector(), seg.at(0.5));
      // Compact: a ball 1.1–3 times the distance holds the whole segment, so
      // f ≠ 0 and the kernel is flat across it (the far-field cancellation).
      pb.R = distance_to_segment(pb.a, pb.b, pb.p) * rng.uniform(1.1, 3);
      radius_set = true;
      break;
    }
    case Region::support_boundary: {
      pb.R = L * rng.uniform(0.3, 2);
      radius_set = true;
      switch (support_case(index)) {
        case SupportCase::sphere_cuts_segment: {
          // The sphere |X − P| = R crosses the segment at Γ(τc): P is at
          // height h over the line and √(R² − h²) along it from Γ(τc).
          const double h = pb.R * rng.uniform(0, 0.95);
          const double tau_cut = rng.uniform(0.02, 0.98);
          const double along = std::sqrt(pb.R * pb.R - h * h) / L;
          const double tau_p = tau_cut + (rng.coin() ? along : -along);
          pb.p = axpy(h, rng.unit_perpendicular(seg.dir), seg.at(tau_p));
          break;
        }
        case SupportCase::just_outside:
          pb.p = detail::point_at_distance(rng, seg, pb.R * (1 + rng.log_uniform(1e-6, 1e-2)));
          break;
      }
      break;
    }
    case Region::support_grazing:
      // The ball reaches 1e-6–1e-2 R past P's distance to the segment: the
      // clipped interval is short and f ~ ε^((i+2)/2) is tiny (docs/mathematics.md §1 k_R^i).
      pb.R = L * rng.uniform(0.3, 2);
      radius_set = true;
      pb.p = detail::point_at_distance(rng, seg, pb.R * (1 - rng.log_uniform(1e-6, 1e-2)));
      break;
  }
  // Compact elsewhere: the ball reaches 0.3–2 |AB| past the nearest point.
  const double distance = distance_to_segment(pb.a, pb.b, pb.p);
  if (!radius_set) pb.R = distance + L * rng.log_uniform(0.3, 2);
  // Gaussian (drawn last, so the other families keep their samples): widths
  // 1/√a from 0.03 to 10 |AB|, i.e. c = a|AB|² from 1e-2 to 1e3, capped so
  // that K at the nearest point is at least e^(−30) b (f stays a normal
  // double however far P is: the far region then has wide Gaussians).
  pb.gaussian_a = std::min(rng.log_uniform(1e-2, 1e3) / (L * L), 30 / (distance * distance));
  pb.gaussian_b = rng.log_uniform(0.2, 5);
  return pb;
}

}  // namespace skelconv::verify
