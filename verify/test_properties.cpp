// verify/test_properties.cpp — properties the papers promise, checked on the
// generated segment functions (docs/mathematics.md §2):
//   * additivity: splitting [A,B] into pieces, with the weight re-parameterised
//     to each piece, leaves f and ∇f unchanged;
//   * thickness (Hubert & Cani Prop. 4.1, Hubert §3.2–3.4): the level κ of the
//     formula of docs/mathematics.md §2 is reached at distance τ on the bisector, and nowhere
//     farther; for k_R^i the middle part is an exact cylinder;
//   * recurrence (1) of docs/mathematics.md §2 between generated J_i and J_{i−2}.
// Each property is checked in double against the sweep's generic targets, at
// points that are generic for every evaluation involved, and in binary128
// against `binary128_identity_tolerance`.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <boost/math/quadrature/tanh_sinh.hpp>

#include "error_stats.hpp"
#include "extended_precision.hpp"
#include "generated_kernels.hpp"
#include "reference_quadrature.hpp"
#include "sampling.hpp"
#include "skelconv/detail/clip.hpp"

namespace skelconv::verify {
namespace {

/// In double, every evaluation below is at a generic point (distance 0.1–3
/// lengths), where the sweep asserts |error| ≤ target · |value| for each
/// one; an identity Σ x_j = y between such values therefore holds to
/// target · (Σ|x_j| + |y|). This is that target, not a new number.
constexpr AccuracyTargets double_targets{};

/// In binary128 (eps ≈ 1.9e-34) a correct, numerically stable closed form
/// keeps all but a few of its 34 digits at generic points; 1e-25 leaves nine
/// digits of headroom for amplification. A wrong term in a formula shows at
/// ≥ 1e-16 (it is visible in double), so this separates the two cleanly.
constexpr double binary128_identity_tolerance = 1e-25;

constexpr int samples_per_kernel = 4;

template <class T>
struct Field {
  T f;
  Vec3<T> grad;
};

template <class T>
Vec3<T> to(const Vec3<double>& v) {
  return {T(v[0]), T(v[1]), T(v[2])};
}

/// Evaluates a generated kernel through f_and_grad; compact inputs are
/// clipped in T as the runtime does (an empty clip gives 0).
template <class T>
Field<T> evaluate(const GeneratedKernel<T>& kernel, const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& p,
                  const std::array<T, 4>& w, const T& s, const T& R) {
  SegmentInput<T> in;
  in.a = a;
  in.b = b;
  in.p = p;
  in.w = w;
  in.s = s;
  in.R = R;
  if (kernel.family == KernelFamily::compact) {
    const auto clip = clip_to_ball(a, b, p, R);
    if (!clip) return {T(0), {T(0), T(0), T(0)}};
    in.t0 = clip->t0;
    in.t1 = clip->t1;
  }
  Field<T> out;
  out.f = kernel.f_and_grad(in, out.grad);
  return out;
}

std::vector<std::pair<KernelFamily, int>> generated_pairs() {
  std::vector<std::pair<KernelFamily, int>> out;
  for (const auto& k : generated_kernels_double())
    if (k.weight_degree == 0) out.emplace_back(k.family, k.degree);
  return out;
}

std::string label(KernelFamily family, int degree, int weight_degree, int sample) {
  std::ostringstream os;
  os << family_name(family) << " i=" << degree << " w=" << weight_degree << " sample " << sample;
  return os.str();
}

// ---------------------------------------------------------------- additivity

/// A segment whose split points Γ(t_j) and re-parameterised weights are exact
/// in double: coordinates are multiples of 2^-6 in [-2, 2], split parameters
/// multiples of 2^-6, weights multiples of 2^-4. Every product below then has
/// ≤ 44 significant bits, so the pieces are the same segment exactly.
struct SplitSegment {
  Vec3<double> a, b, p;
  std::array<double, 4> w;
  std::vector<double> cuts;  // 0 = t_0 < t_1 < … < t_k = 1
  double s, R;
};

/// Coefficients of w(t_a + (t_b − t_a) u) in u (exact in double here).
std::array<double, 4> reparameterised(const std::array<double, 4>& w, double ta, double tb) {
  static constexpr double binomial[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
  const double span = tb - ta;
  std::array<double, 4> out{};
  for (int m = 0; m < 4; ++m)
    for (int k = m; k < 4; ++k) out[m] += w[k] * binomial[k][m] * std::pow(ta, k - m) * std::pow(span, m);
  return out;
}

std::optional<SplitSegment> draw_split_segment(std::uint64_t seed, int pieces) {
  DeterministicRandom rng(seed);
  const auto dyadic = [&](double lo, double hi, double unit) { return std::round(rng.uniform(lo, hi) / unit) * unit; };
  for (int attempt = 0; attempt < 10000; ++attempt) {
    SplitSegment sp;
    for (int c = 0; c < 3; ++c) sp.a[c] = dyadic(-2, 2, 0x1p-6), sp.b[c] = dyadic(-2, 2, 0x1p-6);
    const double length = norm(sub(sp.b, sp.a));
    if (length < 0.5) continue;
    for (double& wk : sp.w) wk = dyadic(0.25, 2, 0x1p-4);
    // k − 1 distinct interior cuts on the grid m/64, pieces ≥ 4/64 long.
    sp.cuts = {0, 1};
    while (static_cast<int>(sp.cuts.size()) < pieces + 1) {
      const double t = dyadic(4.0 / 64, 60.0 / 64, 0x1p-6);
      if (std::all_of(sp.cuts.begin(), sp.cuts.end(), [&](double c) { return std::abs(c - t) >= 4.0 / 64; }))
        sp.cuts.push_back(t);
    }
    std::sort(sp.cuts.begin(), sp.cuts.end());
    // P beside the middle; accept only if it is generic (0.1–3 lengths away)
    // for the whole segment and for every piece.
    const Vec3<double> dir{(sp.b[0] - sp.a[0]) / length, (sp.b[1] - sp.a[1]) / length, (sp.b[2] - sp.a[2]) / length};
    sp.p = axpy(length * rng.uniform(0.2, 0.8), rng.unit_perpendicular(dir),
                axpy(rng.uniform(0.3, 0.7), sub(sp.b, sp.a), sp.a));
    const auto generic = [&](const Vec3<double>& a, const Vec3<double>& b) {
      const double ratio = distance_to_segment(a, b, sp.p) / norm(sub(b, a));
      return ratio >= 0.1 && ratio <= 3;
    };
    bool all_generic = generic(sp.a, sp.b);
    for (int j = 0; j < pieces && all_generic; ++j)
      all_generic = generic(axpy(sp.cuts[j], sub(sp.b, sp.a), sp.a), axpy(sp.cuts[j + 1], sub(sp.b, sp.a), sp.a));
    if (!all_generic) continue;
    sp.s = rng.log_uniform(0.2, 5);
    sp.R = distance_to_segment(sp.a, sp.b, sp.p) + length * rng.uniform(0.3, 2);
    return sp;
  }
  return std::nullopt;
}

template <class T>
void check_additivity(const GeneratedKernel<T>& kernel, const SplitSegment& sp, double f_tolerance,
                      double grad_tolerance, const std::string& what) {
  using std::abs;
  const T s(sp.s), R(sp.R);
  std::array<T, 4> w{};
  for (int k = 0; k < 4; ++k) w[k] = k <= kernel.weight_degree ? T(sp.w[k]) : T(0);
  const Field<T> whole = evaluate(kernel, to<T>(sp.a), to<T>(sp.b), to<T>(sp.p), w, s, R);
  T f_sum(0), f_abs(0);
  Vec3<T> g_sum{T(0), T(0), T(0)};
  T g_abs(0);
  std::array<double, 4> w_truncated{};
  for (int k = 0; k <= kernel.weight_degree; ++k) w_truncated[k] = sp.w[k];
  const int pieces = static_cast<int>(sp.cuts.size()) - 1;
  for (int j = 0; j < pieces; ++j) {
    const Vec3<double> ab = sub(sp.b, sp.a);
    const Vec3<double> a_j = axpy(sp.cuts[j], ab, sp.a), b_j = axpy(sp.cuts[j + 1], ab, sp.a);
    // Exactness of the construction (else the identity would be perturbed).
    for (int c = 0; c < 3; ++c)
      ASSERT_EQ(extended(a_j[c]), extended(sp.a[c]) + extended(sp.cuts[j]) * (extended(sp.b[c]) - extended(sp.a[c])));
    const std::array<double, 4> w_j = reparameterised(w_truncated, sp.cuts[j], sp.cuts[j + 1]);
    std::array<T, 4> wt{};
    for (int k = 0; k < 4; ++k) wt[k] = T(w_j[k]);
    const Field<T> part = evaluate(kernel, to<T>(a_j), to<T>(b_j), to<T>(sp.p), wt, s, R);
    f_sum += part.f;
    f_abs += abs(part.f);
    for (int c = 0; c < 3; ++c) g_sum[c] += part.grad[c];
    g_abs += norm(part.grad);
  }
  const double f_gap = static_cast<double>(abs(f_sum - whole.f) / (f_abs + abs(whole.f)));
  const double g_gap = static_cast<double>(norm(sub(g_sum, whole.grad)) / (g_abs + norm(whole.grad)));
  EXPECT_LE(f_gap, f_tolerance) << what << " pieces=" << pieces;
  EXPECT_LE(g_gap, grad_tolerance) << what << " pieces=" << pieces;
}

TEST(Properties, AdditivityUnderSplitting) {
  for (const auto& [family, degree] : generated_pairs())
    for (int sample = 0; sample < samples_per_kernel; ++sample) {
      const int pieces = 2 + sample % 4;  // 2..5
      const auto sp = draw_split_segment(splitmix64(1000 * degree + 10 * sample + static_cast<int>(family)), pieces);
      ASSERT_TRUE(sp.has_value());
      for (int d = 0; d <= max_weight_degree; ++d) {
        const auto* kd = find_generated_double(family, degree, d);
        const auto* ke = find_generated_extended(family, degree, d);
        if (!kd || !ke) continue;
        check_additivity(*kd, *sp, double_targets.generic_f, double_targets.generic_grad,
                         "double " + label(family, degree, d, sample));
        check_additivity(*ke, *sp, binary128_identity_tolerance, binary128_identity_tolerance,
                         "binary128 " + label(family, degree, d, sample));
      }
    }
}

// ----------------------------------------------------------------- thickness

/// J_i(a, b, c) = ∫_0^1 (a t² − 2 b t + c)^(−i/2) dt by binary128 tanh-sinh,
/// split at the minimum of the quadratic: the (a, b, c) form of docs/mathematics.md §2,
/// independent of both the geometric reference and the generated code.
extended j_by_quadrature(int i, const extended& a, const extended& b, const extended& c) {
  static thread_local boost::math::quadrature::tanh_sinh<extended> quadrature;
  const auto integrand = [&](const extended& t) {
    const extended q = (a * t - 2 * b) * t + c;
    return 1 / (integer_power(sqrt(q), i));
  };
  const extended t_min = std::clamp<extended>(b / a, 0, 1);
  extended sum = 0;
  for (const auto& [lo, hi] : {std::pair<extended, extended>{0, t_min}, std::pair<extended, extended>{t_min, 1}}) {
    extended error = 0, l1 = 0;
    if (lo < hi) sum += quadrature.integrate(integrand, lo, hi, extended(1e-30), &error, &l1);
    EXPECT_LE(static_cast<double>(error), 1e-28 * static_cast<double>(l1));
  }
  return sum;
}

/// A segment with an exact orthonormal frame, so that the points the
/// thickness formulas talk about (on the bisector, on the cylinder) are
/// represented exactly in double: the frame is a signed permutation of
///   dir = (3, 4, 12)/13,  n1 = (4, −3, 0)/5,  n2 = (36, 48, −25)/65
/// (Pythagorean, orthonormal), lengths are multiples of 13 h, 5 h, 65 h
/// (h = 2^-6) along them, and A has coordinates on the grid h. No coordinate
/// axis is special for the generated code.
struct ExactSegment {
  static constexpr double h = 0x1p-6;
  Vec3<double> a, b;
  Vec3<double> dir13, n1_5, n2_65;  // integer vectors: 13 dir, 5 n1, 65 n2
  int m = 0;                        // |AB| = 13 m h
  double length() const { return 13 * m * h; }
  Vec3<double> dir() const { return {dir13[0] / 13, dir13[1] / 13, dir13[2] / 13}; }
  /// Γ(j/256) + (5 q h) n1 or n2 (side 0..3: ±n1, ±n2 with heights 5qh / 65qh):
  /// exact as long as the integers stay small.
  Vec3<double> exact_point(int j, int q, int side) const {
    const Vec3<double>& normal = side % 2 == 0 ? n1_5 : n2_65;
    const double sign = side < 2 ? 1.0 : -1.0;
    Vec3<double> out;
    for (int c = 0; c < 3; ++c) out[c] = a[c] + (j * m * h / 256) * dir13[c] + sign * q * h * normal[c];
    return out;
  }
  /// Height of exact_point(·, q, side) over the segment's line.
  double exact_height(int q, int side) const { return (side % 2 == 0 ? 5.0 : 65.0) * q * h; }
  /// Any point at distance `height` from Γ(t) in the normal plane (not exact).
  Vec3<double> at(double t, double height, double angle) const {
    const double c = height * std::cos(angle), s = height * std::sin(angle);
    Vec3<double> out;
    for (int k = 0; k < 3; ++k) out[k] = a[k] + t * m * h * dir13[k] + c * n1_5[k] / 5 + s * n2_65[k] / 65;
    return out;
  }
};

ExactSegment exact_segment(int m, DeterministicRandom& rng) {
  std::array<Vec3<double>, 3> frame{Vec3<double>{3, 4, 12}, Vec3<double>{4, -3, 0}, Vec3<double>{36, 48, -25}};
  std::array<int, 3> perm{0, 1, 2};
  for (int k = 2; k > 0; --k) std::swap(perm[k], perm[static_cast<int>(rng.uniform(0, k + 1 - 1e-9))]);
  std::array<double, 3> flip{};
  for (double& f : flip) f = rng.coin() ? -1.0 : 1.0;
  ExactSegment seg;
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) (k == 0 ? seg.dir13 : k == 1 ? seg.n1_5 : seg.n2_65)[c] = flip[c] * frame[k][perm[c]];
  for (double& x : seg.a) x = std::round(rng.uniform(-1, 1) / ExactSegment::h) * ExactSegment::h;
  seg.m = m;
  for (int c = 0; c < 3; ++c) seg.b[c] = seg.a[c] + m * ExactSegment::h * seg.dir13[c];
  return seg;
}

/// A point at distance `tau` (up to rounding) from the segment, anywhere
/// around it: beside it, or on the cap around an end.
Vec3<double> point_on_tube(const ExactSegment& seg, double tau, DeterministicRandom& rng) {
  const double t = rng.uniform(-0.2, 1.2);
  const double angle = rng.uniform(0, 2 * std::numbers::pi);
  if (t >= 0 && t <= 1) return seg.at(t, tau, angle);
  const double polar = rng.uniform(0, std::numbers::pi / 2);  // from the outward axis
  const double along = (t < 0 ? -1.0 : 1.0) * tau * std::cos(polar) / seg.length();
  return seg.at((t < 0 ? 0.0 : 1.0) + along, tau * std::sin(polar), angle);
}

TEST(Properties, ThicknessInverseAndCauchy) {
  for (const auto& [family, degree] : generated_pairs()) {
    // κ below is the formula (docs/mathematics.md §2) for p^i and c_s^i only.
    if (family != KernelFamily::inverse && family != KernelFamily::cauchy) continue;
    const auto* kd = find_generated_double(family, degree, 0);
    const auto* ke = find_generated_extended(family, degree, 0);
    ASSERT_TRUE(kd && ke);
    ReferenceIntegrator integrator;
    for (int sample = 0; sample < samples_per_kernel; ++sample) {
      DeterministicRandom rng(splitmix64(2000 * degree + sample + 100 * static_cast<int>(family)));
      const ExactSegment seg = exact_segment(static_cast<int>(rng.uniform(3, 20)), rng);  // l ≈ 0.6–4.7
      const double l = seg.length();
      // The bisector point at height τ, τ/l in the generic 0.1–3 (exact).
      const int side = static_cast<int>(rng.uniform(0, 4 - 1e-9));
      const double unit = seg.exact_height(1, side);
      const int q = static_cast<int>(std::ceil(0.1 * l / unit)) +
                    static_cast<int>(rng.uniform(0, std::floor(2.9 * l / unit)));
      const double tau = seg.exact_height(q, side);
      const Vec3<double> bisector = seg.exact_point(128, q, side);
      const double s = rng.log_uniform(0.2, 5);
      const extended L(l), T(tau), S(s);
      // κ by the formula, the J integral by quadrature in (a, b, c) form:
      //   p^i:   κ = l J_i(l², l²/2, l²/4 + τ²)
      //   c_s^i: κ = l J_i(s l², s l²/2, 1 + s(l²/4 + τ²))
      const extended kappa = family == KernelFamily::inverse
                                 ? L * j_by_quadrature(degree, L * L, L * L / 2, L * L / 4 + T * T)
                                 : L * j_by_quadrature(degree, S * L * L, S * L * L / 2, 1 + S * (L * L / 4 + T * T));
      const std::string what = label(family, degree, 0, sample);
      // The formula is the definition at the bisector point (geometric reference).
      const ReferenceField def = integrator.field(
          integrator.moments({family, degree, S, extended(1)}, widen(seg.a), widen(seg.b), widen(bisector)),
          {1, 0, 0, 0}, 0);
      EXPECT_LE(static_cast<double>(abs(def.f / kappa - 1)), 1e-25) << what << ": κ formula vs definition";
      // Generated f at the bisector point is κ.
      const std::array<double, 4> unit_w{1, 0, 0, 0};
      const Field<double> fd = evaluate(*kd, seg.a, seg.b, bisector, unit_w, s, 1.0);
      const Field<extended> fe =
          evaluate(*ke, widen(seg.a), widen(seg.b), widen(bisector), {1, 0, 0, 0}, S, extended(1));
      EXPECT_LE(std::abs(fd.f / static_cast<double>(kappa) - 1), double_targets.generic_f) << what;
      EXPECT_LE(static_cast<double>(abs(fe.f / kappa - 1)), binary128_identity_tolerance) << what;
      // Nowhere at distance τ is the field above κ (Prop. 4.1: the level set
      // {f = κ} is farthest from the segment on the bisector). Points near the
      // bisector are below κ by O(δt²); the generic target is the margin.
      for (int k = 0; k < 8; ++k) {
        const Vec3<double> point = point_on_tube(seg, tau, rng);
        const Field<double> at = evaluate(*kd, seg.a, seg.b, point, unit_w, s, 1.0);
        EXPECT_LE(at.f, static_cast<double>(kappa) * (1 + double_targets.generic_f)) << what << " tube point " << k;
      }
      if (family == KernelFamily::cauchy) {
        // Hubert 2012 §3.3: the level set crosses the segment for l J_i(sl², 0, 1) ≤ κ ≤
        // l J_i(sl², sl²/2, 1 + sl²/4): those bounds are f at A and f at the
        // midpoint of the segment (both exact points).
        const extended at_end = L * j_by_quadrature(degree, S * L * L, 0, 1);
        const extended at_middle = L * j_by_quadrature(degree, S * L * L, S * L * L / 2, 1 + S * L * L / 4);
        const Field<extended> ge =
            evaluate(*ke, widen(seg.a), widen(seg.b), widen(seg.a), {1, 0, 0, 0}, S, extended(1));
        const Field<extended> gm = evaluate(*ke, widen(seg.a), widen(seg.b), widen(seg.exact_point(128, 0, 0)),
                                            {1, 0, 0, 0}, S, extended(1));
        EXPECT_LE(static_cast<double>(abs(ge.f / at_end - 1)), binary128_identity_tolerance) << what << " at A";
        EXPECT_LE(static_cast<double>(abs(gm.f / at_middle - 1)), binary128_identity_tolerance) << what << " at mid";
      }
    }
  }
}

TEST(Properties, ThicknessCompactCylindricalMiddle) {
  for (const auto& [family, degree] : generated_pairs()) {
    if (family != KernelFamily::compact) continue;
    const auto* kd = find_generated_double(family, degree, 0);
    const auto* ke = find_generated_extended(family, degree, 0);
    ASSERT_TRUE(kd && ke);
    ReferenceIntegrator integrator;
    for (int sample = 0; sample < samples_per_kernel; ++sample) {
      DeterministicRandom rng(splitmix64(3000 * degree + sample));
      const double R = std::round(rng.uniform(0.5, 2) / ExactSegment::h) * ExactSegment::h;
      const int side = 2 * static_cast<int>(rng.uniform(0, 2 - 1e-9));  // ±n1: height 5 q h
      const int q = static_cast<int>(rng.uniform(0.3, 0.9) * R / (5 * ExactSegment::h));
      const double tau = 5 * q * ExactSegment::h;
      const double half_chord = std::sqrt(R * R - tau * tau);  // the ball at height τ cuts the line over ±half_chord
      // l > 2√(R² − τ²): a cylindrical middle part exists (docs/mathematics.md §2, k_R^i).
      const int m = static_cast<int>(std::ceil((2 * half_chord + R * rng.uniform(0.5, 3)) / (13 * ExactSegment::h)));
      const ExactSegment seg = exact_segment(m, rng);
      const double l = seg.length();
      const Vec3<double> middle = seg.exact_point(128, q, side);
      // κ = f at distance τ from the middle, by the reference (definition).
      const extended kappa = integrator
                                 .field(integrator.moments({family, degree, extended(1), extended(R)}, widen(seg.a),
                                                           widen(seg.b), widen(middle)),
                                        {1, 0, 0, 0}, 0)
                                 .f;
      const std::string what = label(family, degree, 0, sample);
      const std::array<double, 4> unit_w{1, 0, 0, 0};
      // Along the middle part, |t − ½| ≤ ½ − half_chord/l, the ball around the
      // point cuts a full chord of the segment: f = κ exactly (translation).
      // t = j/256 on that range keeps the points exact.
      const int j_half_range = static_cast<int>(std::floor(256 * (0.5 - half_chord / l)));
      for (int k = 0; k < 8; ++k) {
        const int j = 128 + static_cast<int>(std::round(rng.uniform(-1, 1) * j_half_range));
        const Vec3<double> point = seg.exact_point(j, q, (side + 2 * (k % 2)) % 4);
        const Field<double> fd = evaluate(*kd, seg.a, seg.b, point, unit_w, 1.0, R);
        const Field<extended> fe = evaluate(*ke, widen(seg.a), widen(seg.b), widen(point), {1, 0, 0, 0}, extended(1),
                                            extended(R));
        EXPECT_LE(std::abs(fd.f / static_cast<double>(kappa) - 1), double_targets.generic_f) << what << " k=" << k;
        EXPECT_LE(static_cast<double>(abs(fe.f / kappa - 1)), binary128_identity_tolerance) << what << " k=" << k;
      }
      // And nowhere at distance τ is the field above κ.
      for (int k = 0; k < 8; ++k) {
        const Vec3<double> point = point_on_tube(seg, tau, rng);
        const Field<double> at = evaluate(*kd, seg.a, seg.b, point, unit_w, 1.0, R);
        EXPECT_LE(at.f, static_cast<double>(kappa) * (1 + double_targets.generic_f)) << what << " tube point " << k;
      }
    }
  }
}

// ---------------------------------------------------------------- recurrence

struct Quadratic {
  extended a, b, c;  ///< q(t) = a t² − 2 b t + c
};

/// Relative residual of docs/mathematics.md §2 recurrence (1) at index n,
///   (n−2)(ca − b²) J_n + a(3−n) J_{n−2} = (a−b) q(1)^((2−n)/2) + b q(0)^((2−n)/2),
/// divided by the sum of the magnitudes of its four terms.
extended recurrence_residual(int n, const Quadratic& q, const extended& j_n, const extended& j_n_minus_2) {
  // q(1), q(0) ≥ 0 on the integration interval; clamp their rounding.
  const extended q1 = std::max<extended>(0, q.a - 2 * q.b + q.c), q0 = std::max<extended>(0, q.c);
  const extended t1 = (n - 2) * (q.c * q.a - q.b * q.b) * j_n;
  const extended t2 = q.a * (3 - n) * j_n_minus_2;
  const extended r1 = (q.a - q.b) * half_integer_power(q1, 2 - n);
  const extended r0 = q.b * half_integer_power(q0, 2 - n);
  return abs(t1 + t2 - r1 - r0) / (abs(t1) + abs(t2) + abs(r1) + abs(r0));
}

/// J_i of a generated weight-degree-0 kernel: f / |AB| with w = 1 (docs/mathematics.md §2:
/// p^i: C = |AB| J_i(|AB|², AB·AP, |AP|²); c_s^i: C = |AB| J_i(s|AB|², s AB·AP, 1 + s|AP|²)).
extended generated_j(KernelFamily family, int degree, const SweepProblem& pb) {
  const auto* kernel = find_generated_extended(family, degree, 0);
  EXPECT_NE(kernel, nullptr) << family_name(family) << " i=" << degree;
  if (!kernel) return extended(0);
  const Field<extended> field = evaluate(*kernel, widen(pb.a), widen(pb.b), widen(pb.p), {1, 0, 0, 0},
                                         extended(pb.s), extended(pb.R));
  return field.f / norm(sub(widen(pb.b), widen(pb.a)));
}

TEST(Properties, RecurrenceInverseAndCauchy) {
  for (const auto& [family, degree] : generated_pairs()) {
    if (family == KernelFamily::compact || degree < 3) continue;  // n = 2 is trivial: a J_0 = a
    for (int sample = 0; sample < samples_per_kernel; ++sample) {
      const SweepProblem pb = draw_problem(4000, family, degree, Region::generic, sample);
      const Vec3<extended> ab = sub(widen(pb.b), widen(pb.a)), ap = sub(widen(pb.p), widen(pb.a));
      const extended s(pb.s);
      const Quadratic q = family == KernelFamily::inverse
                              ? Quadratic{dot(ab, ab), dot(ab, ap), dot(ap, ap)}
                              : Quadratic{s * dot(ab, ab), s * dot(ab, ap), 1 + s * dot(ap, ap)};
      const extended residual =
          recurrence_residual(degree, q, generated_j(family, degree, pb), generated_j(family, degree - 2, pb));
      EXPECT_LE(static_cast<double>(residual), binary128_identity_tolerance) << label(family, degree, 0, sample);
    }
  }
}

TEST(Properties, RecurrenceCompactNegativeIndices) {
  // k_R^i on the clipped [A_P, B_P] is |A_PB_P| J_{−i}(a, b, c) with
  // a = −|A_PB_P|²/R², b = −A_PP·A_PB_P/R², c = 1 − |A_PP|²/R² (docs/mathematics.md §2), so
  // recurrence (1) at n = −i links degrees i and i + 2.
  for (const auto& [family, degree] : generated_pairs()) {
    if (family != KernelFamily::compact || !find_generated_extended(family, degree + 2, 0)) continue;
    for (int sample = 0; sample < samples_per_kernel; ++sample) {
      const SweepProblem pb = draw_problem(5000, family, degree, Region::generic, sample);
      const Vec3<extended> a = widen(pb.a), b = widen(pb.b), p = widen(pb.p);
      const extended R(pb.R);
      const auto clip = clip_to_ball(a, b, p, R);
      ASSERT_TRUE(clip.has_value());
      const Vec3<extended> ab = sub(b, a);
      const Vec3<extended> start = axpy(clip->t0, ab, a), end = axpy(clip->t1, ab, a);
      const Vec3<extended> sub_ab = sub(end, start), sub_ap = sub(p, start);
      const Quadratic q{-dot(sub_ab, sub_ab) / (R * R), -dot(sub_ap, sub_ab) / (R * R), 1 - dot(sub_ap, sub_ap) / (R * R)};
      const extended to_j = norm(ab) / norm(sub_ab);  // generated_j divides by |AB|, J_{−i} wants |A_PB_P|
      const extended residual = recurrence_residual(-degree, q, generated_j(family, degree, pb) * to_j,
                                                    generated_j(family, degree + 2, pb) * to_j);
      EXPECT_LE(static_cast<double>(residual), binary128_identity_tolerance) << label(family, degree, 0, sample);
    }
  }
}

}  // namespace
}  // namespace skelconv::verify
