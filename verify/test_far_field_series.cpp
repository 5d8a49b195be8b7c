// verify/test_far_field_series.cpp — the far-field series of the segment
// moments (include/skelconv/detail/far_field_series.hpp, docs/mathematics.md
// §2 "Far from the segment") against binary128 quadrature of the moments'
// definition, on the sweep's samples:
//   * the remainder bound B_N holds: the series summed in binary128 (so that
//     only truncation is left) to the order N the bound picks differs from
//     the reference by at most B_N relative, for every moment the generated
//     kernels ask for (k ≤ 4, levels m = i and i + 2);
//   * the bound is not vacuous: one order fewer (N − 2, the previous pair of
//     terms) leaves more than 2^−53 somewhere on the same samples, so a
//     bound that asked for too few terms would fail the first check;
//   * the generated functions in double, where the series now serves them
//     (P 2–10 |AB| from the midpoint, between the sweep's generic region,
//     ≤ 3 |AB|, and its far region, ≥ 10 |AB|), within 1e-14 of the sweep's
//     binary128 reference for f and |∇f|, like the far region itself.
// Samples: the sweep's far region (verify/sampling.hpp, seed 20240601), and the
// same segments with P moved to 2–10 |AB| from the midpoint.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "error_stats.hpp"
#include "extended_precision.hpp"
#include "generated_kernels.hpp"
#include "point_evaluation.hpp"
#include "reference_quadrature.hpp"
#include "sampling.hpp"
#include "skelconv/detail/far_field_series.hpp"

namespace skelconv::verify {
namespace {

constexpr std::uint64_t seed = 20240601;  // the sweep's default seed
constexpr int samples_per_degree = 40;    // per (family, degree, band)
constexpr int k_max = 4;                  // weights t^k the generated ∇f of weight degree 3 needs
constexpr int max_degree = 16;            // the generated inverse and Cauchy segment degrees

/// The quadratic q = a t² − 2 b t + c of a sample (docs/mathematics.md §2),
/// formed in binary128 from the double inputs: q = α|P − Γ(t)|² + β.
struct Quadratic {
  extended a, b, c;
};

Quadratic quadratic_of(const SweepProblem& pb) {
  const Vec3<extended> A = widen(pb.a), B = widen(pb.b), P = widen(pb.p);
  const Vec3<extended> ab = sub(B, A), ap = sub(P, A);
  const extended alpha = pb.family == KernelFamily::cauchy ? extended(pb.s) : extended(1);
  const extended beta = pb.family == KernelFamily::cauchy ? extended(1) : extended(0);
  return {alpha * dot(ab, ab), alpha * dot(ab, ap), beta + alpha * dot(ap, ap)};
}

/// M_{k,m} = ∫_0^1 t^k q^(−m/2) dt for k ≤ k_max and m = m_lo, m_lo + 2
/// (layout of far_series_moments) by the 40-point Gauss–Legendre rule in
/// binary128 on [0, ½] and [½, 1] (`split`), or on [0, 1]. Where the series
/// applies (ρ ≤ 1/4) q's roots lie at least 2 |AB| from the midpoint, so
/// ≥ 1.5 |AB| from either half, i.e. at ≥ 6 half-widths of a half:
/// Bernstein parameter ≥ 11.9, and the rule's error ~ 11.9^(−80) ≈ 1e-86
/// times the pole order's factor, far below binary128's 1e-34. That the
/// split and whole rules agree is checked below.
std::array<extended, 2 * (k_max + 1)> reference_moments(const Quadratic& q, int m_lo, bool split = true) {
  using Rule = boost::math::quadrature::gauss<extended, 40>;
  std::array<extended, 2 * (k_max + 1)> out{};
  const auto add = [&](const extended& from, const extended& to) {
    const extended half = (to - from) / 2, middle = (to + from) / 2;
    const auto& x = Rule::abscissa();
    const auto& w = Rule::weights();
    for (std::size_t i = 0; i < x.size(); ++i) {
      for (const int sign : {1, -1}) {
        if (i == 0 && sign == -1 && x[0] == 0) continue;  // the middle node once (odd point count)
        const extended t = middle + sign * half * x[i];
        const extended value = q.c + t * (q.a * t - 2 * q.b);
        extended weight = w[i] * half / (m_lo % 2 == 1 ? sqrt(value) : extended(1));
        for (int e = 0; e < m_lo / 2; ++e) weight /= value;
        for (int level = 0; level < 2; ++level) {
          extended term = weight;
          for (int k = 0; k <= k_max; ++k) {
            out[std::size_t(level * (k_max + 1) + k)] += term;
            term *= t;
          }
          weight /= value;
        }
      }
    }
  };
  if (split) {
    add(extended(0), extended(0.5));
    add(extended(0.5), extended(1));
  } else {
    add(extended(0), extended(1));
  }
  return out;
}

/// The same segment with P moved along its direction from the midpoint to a
/// distance log-uniform in [lo, hi] |AB| (deterministic in the sample).
SweepProblem moved_to_band(SweepProblem pb, double lo, double hi) {
  DeterministicRandom rng(splitmix64(pb.index * 7919 + std::uint64_t(pb.degree) * 104729 + std::uint64_t(pb.family)));
  Vec3<double> mid, dir;
  double length2 = 0, dir_norm2 = 0;
  for (int c = 0; c < 3; ++c) {
    mid[c] = 0.5 * (pb.a[c] + pb.b[c]);
    dir[c] = pb.p[c] - mid[c];
    length2 += (pb.b[c] - pb.a[c]) * (pb.b[c] - pb.a[c]);
    dir_norm2 += dir[c] * dir[c];
  }
  const double distance = std::sqrt(length2) * rng.log_uniform(lo, hi);
  for (int c = 0; c < 3; ++c) pb.p[c] = mid[c] + distance * dir[c] / std::sqrt(dir_norm2);
  return pb;
}

/// The samples: the far region's, and the same segments moved to 2–10 |AB|.
std::vector<SweepProblem> samples(KernelFamily family, int degree) {
  std::vector<SweepProblem> out;
  for (int index = 0; index < samples_per_degree; ++index) {
    const SweepProblem far = draw_problem(seed, family, degree, Region::far, std::uint64_t(index));
    out.push_back(far);
    out.push_back(moved_to_band(far, 2, 10));
  }
  return out;
}

constexpr std::array<KernelFamily, 2> families{KernelFamily::inverse, KernelFamily::cauchy};

TEST(FarFieldSeries, RemainderBoundHoldsAndOneOrderFewerMissesIt) {
  const double unit = 0x1p-53;
  double worst_ratio = 0;        // max over moments of error / (B_N |M|)
  double worst_one_fewer = 0;    // max relative error with N − 2 terms
  double worst_reference = 0;    // max relative difference of the split and whole rules
  int series_samples = 0;
  for (const KernelFamily family : families) {
    for (int degree = 1; degree <= max_degree; ++degree) {
      const int m_lo = degree, m_hi = degree + 2;
      for (const SweepProblem& pb : samples(family, degree)) {
        const Quadratic q = quadratic_of(pb);
        const extended Q = q.c - q.b + q.a / 4;
        const extended P = (q.a / 2 - q.b) / (2 * Q);
        const extended S = q.a / (4 * Q);
        if (!skelconv::detail::far_series_applies(m_hi, static_cast<double>(S))) continue;
        // the order the double code takes, and its bound
        const int N = skelconv::detail::far_series_order(m_hi, static_cast<double>(S));
        ASSERT_GT(N, 2) << "no order within the cap at rho² = " << static_cast<double>(S);
        const double bound = skelconv::detail::far_series_bound(m_hi, k_max, N, static_cast<double>(S));
        ASSERT_LE(bound, 0x1p-53);
        ++series_samples;
        std::array<extended, 2 * (k_max + 1)> series{}, fewer{};
        skelconv::detail::far_series_moments<extended>(m_lo, m_hi, k_max, Q, P, S, N, series.data());
        skelconv::detail::far_series_moments<extended>(m_lo, m_hi, k_max, Q, P, S, N - 2, fewer.data());
        const auto reference = reference_moments(q, m_lo);
        const auto whole = pb.index % 8 == 0 ? reference_moments(q, m_lo, false) : reference;
        for (int level = 0; level < 2; ++level) {
          for (int k = 0; k <= k_max; ++k) {
            const int m = m_lo + 2 * level;
            const std::size_t at = std::size_t(level * (k_max + 1) + k);
            const extended& ref = reference[at];
            worst_reference = std::max(worst_reference, static_cast<double>(abs(whole[at] - ref) / ref));
            const double error = static_cast<double>(abs(series[at] - ref) / ref);
            // binary128 rounding of the sums (~N ε₁₂₈ ≈ 1e-32) is the only allowance
            EXPECT_LE(error, bound + 1e-30) << family_name(family) << " i=" << degree << " k=" << k << " m=" << m
                                            << " sample " << pb.index << " N=" << N;
            worst_ratio = std::max(worst_ratio, error / bound);
            worst_one_fewer = std::max(worst_one_fewer, static_cast<double>(abs(fewer[at] - ref) / ref));
          }
        }
      }
    }
  }
  std::printf("series samples %d; worst error/bound %.3g; worst error with one order fewer %.3g (2^-53 = %.3g); "
              "reference halves vs whole %.3g\n",
              series_samples, worst_ratio, worst_one_fewer, unit, worst_reference);
  EXPECT_GT(series_samples, 1000);
  EXPECT_LE(worst_reference, 1e-30) << "the binary128 reference is not converged";
  EXPECT_GT(worst_one_fewer, unit) << "one order fewer stays within 2^-53 everywhere: the bound asks for too many terms";
}

TEST(FarFieldSeries, GeneratedFunctionsWithin1e14BetweenTheGenericAndFarRegions) {
  constexpr double target = 1e-14;  // the far region's accuracy line, f and |∇f|
  ReferenceIntegrators integrators{ReferenceTolerances{}};
  const AccuracyTargets targets{};
  for (const KernelFamily family : families) {
    double worst_f = 0, worst_grad = 0;
    for (int degree = 1; degree <= max_degree; ++degree) {
      const KernelsByWeightDegree kernels = find_kernels(family, degree);
      std::array<CellStats, max_weight_degree + 1> cells{};
      for (int index = 0; index < samples_per_degree; ++index) {
        const SweepProblem far = draw_problem(seed, family, degree, Region::far, std::uint64_t(index));
        evaluate_sample(moved_to_band(far, 2, 10), kernels, integrators, targets, cells);
      }
      for (int d = 0; d <= max_weight_degree; ++d) {
        if (!kernels[d].in_double) continue;
        EXPECT_EQ(cells[d].excluded, 0u);
        const auto where = [&](const std::optional<SweepProblem>& pb) {
          if (!pb) return std::string();
          const Quadratic q = quadratic_of(*pb);
          const extended Q = q.c - q.b + q.a / 4;
          const extended D = q.a * q.c - q.b * q.b;
          std::ostringstream os;
          os << " at sample " << pb->index << ": |P − M| = " << static_cast<double>(sqrt(q.a / Q) / 2) << "^-1/2 |AB|"
             << ", rho² = " << static_cast<double>(q.a / (4 * Q)) << ", D/a² = " << static_cast<double>(D / (q.a * q.a))
             << ", t* = " << static_cast<double>(q.b / q.a);
          return os.str();
        };
        worst_f = std::max(worst_f, cells[d].in_double.max_f);
        worst_grad = std::max(worst_grad, cells[d].in_double.max_grad);
        EXPECT_LE(cells[d].in_double.max_f, target)
            << family_name(family) << " i=" << degree << " w" << d << where(cells[d].in_double.worst_f);
        EXPECT_LE(cells[d].in_double.max_grad, target)
            << family_name(family) << " i=" << degree << " w" << d << where(cells[d].in_double.worst_grad);
      }
    }
    std::printf("%s, P 2-10 |AB| from the midpoint: worst f %.2g, worst |grad f| %.2g\n",
                std::string(family_name(family)).c_str(), worst_f, worst_grad);
  }
}

}  // namespace
}  // namespace skelconv::verify
