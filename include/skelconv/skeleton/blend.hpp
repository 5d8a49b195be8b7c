// skelconv/skeleton/blend.hpp — the blend operators of a skeleton's node
// tree (docs/mathematics.md §6, Ferley 1996 §2.2), f and ∇f by the exact chain rule, on any
// scalar type.
//
// A skelconv field f has its surface at f = c (the iso value) and is larger
// inside. A blend node combines its children's fields f_k (with gradients
// ∇f_k) into one field of the same convention:
//
// sum (Hubert 2012 §2; Ferley §2.2.2), optional weights w_k (default 1):
//     f = Σ_k w_k f_k,            ∇f = Σ_k w_k ∇f_k.
//
// union (Ferley §2.2.1):
//     f = max_k f_k,              ∇f = ∇f_m, m the FIRST child (lowest index)
//                                 whose value is the maximum.
//   ∇f jumps where the maximum switches from one child to another (the
//   surface has a crease there); on such a tie the gradient returned is the
//   lowest-index tied child's, a one-sided gradient, never an average.
//
// super_elliptic (Rockwood's blend, Ferley §2.2.3), parameters t > 0,
// r_k > 0 and the node's iso c > 0. Ferley writes it for fields V_k that are
// 0 on their surfaces and, as his four zones "outside the initial surfaces"
// show, positive outside them (the blend region is 0 ≤ V_k ≤ r_k):
//     B = 1 − Σ_k [1 − V_k/r_k]₊^t,   surface B = 0, B < 0 inside,
// [x]₊ = max(0, x). A skelconv child maps to Ferley's V_k and back by
//     V_k = c − f_k                   (0 on the child's surface f_k = c,
//                                      positive outside, in field units)
//     f   = c (1 − B) = c Σ_k [x_k]₊^t,   x_k = 1 − V_k/r_k = (f_k − c + r_k)/r_k,
// so f = c exactly where B = 0, f > c where B < 0 (inside), and f = 0 where
// every f_k ≤ c − r_k: with r_k ≤ c a blend of compact-support children has
// compact support too. Far from child j's influence (f_j ≤ c − r_j) the
// surface is child k's own surface f_k = c; where both reach into their
// bands the surfaces are joined by a fillet. Gradient:
//     ∇f = c Σ_{x_k > 0} t x_k^(t−1) ∇f_k / r_k.
// The derivative of [x]₊^t at x = 0 is taken as 0 (its left value: exact for
// t > 1; for t = 1 the field has a kink there, for t < 1 a cusp).
//
// super_elliptic with "angle_weighted" (binary only, Ferley §2.2.3 after
// Rockwood): r_k is replaced by r_k a, a = 1 − cos θ, θ the angle between
// ∇V_1 and ∇V_2 (= the angle between ∇f_1 and ∇f_2); both terms are
// subtracted (Ferley prints "+" before the second: a misprint, docs/mathematics.md §9):
//     f = c ([1 − V_1/(r_1 a)]₊^t + [1 − V_2/(r_2 a)]₊^t).
// Where the children's surfaces are tangent (θ = 0) the band vanishes and
// the blend is their union; at θ = 90° it is the plain blend; past 90° the
// band widens (Bloomenthal's "peaks" at acute angles). Conventions:
// a is clamped to ≥ min_angle_factor (below), and where ∇f_1 or ∇f_2 is 0
// (outside a compact support) cos θ is taken as 0 (a = 1). The gradient
// needs ∇(cos θ), hence the children's Hessians H_k:
//     ∇f = c Σ_k t x_k^(t−1) [∇f_k/(r_k a) + V_k ∇a/(r_k a²)],  ∇a = −∇cos θ,
//     ∇cos θ = (H_1 ∇f_2 + H_2 ∇f_1)/(|∇f_1||∇f_2|)
//              − cos θ (H_1 ∇f_1/|∇f_1|² + H_2 ∇f_2/|∇f_2|²),
// with the four Hessian-vector products given by the caller (the skeleton
// takes central differences of the children's exact gradients, see
// skeleton.hpp); this is the one gradient in skelconv that is not exact to
// rounding.
//
// Markers: a child value of +inf (an inverse kernel on its own skeleton)
// makes every blend return +inf with gradient (+inf, +inf, +inf), whatever
// the weights, so that no blend ever produces NaN.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace skelconv {

/// A value and gradient on any scalar type.
template <class T>
struct ScalarSample {
  T value{};
  std::array<T, 3> gradient{};
};

enum class BlendKind { sum, union_max, super_elliptic };

/// "sum", "union", "super_elliptic" (the JSON names).
constexpr std::string_view blend_name(BlendKind kind) {
  switch (kind) {
    case BlendKind::sum: return "sum";
    case BlendKind::union_max: return "union";
    case BlendKind::super_elliptic: return "super_elliptic";
  }
  return "?";
}

constexpr std::optional<BlendKind> blend_from_name(std::string_view name) {
  for (BlendKind kind : {BlendKind::sum, BlendKind::union_max, BlendKind::super_elliptic}) {
    if (blend_name(kind) == name) return kind;
  }
  return std::nullopt;
}

/// A blend node's operator and parameters (file comment). Checked by
/// validate_blend against the node's number of children.
struct Blend {
  /// The angle factor a = 1 − cos θ is clamped to at least this: at a = 0
  /// (tangent children) x_k = 1 − V_k/(r_k a) would be 0/0 on a surface.
  /// 1e-6 keeps the band r_k a at least a millionth of r_k, narrower than
  /// anything a mesher resolves, while x_k stays finite.
  static constexpr double min_angle_factor = 1e-6;

  BlendKind kind = BlendKind::sum;
  std::vector<double> weights;  ///< sum: one per child, or empty for all 1
  double t = 2.0;               ///< super_elliptic: exponent, > 0
  std::vector<double> r;        ///< super_elliptic: one per child, or one for all; > 0
  bool angle_weighted = false;  ///< super_elliptic: Rockwood's θ variant (2 children)
  double iso = 1.0;             ///< super_elliptic: c, > 0

  static Blend sum(std::vector<double> weights = {}) {
    Blend blend;
    blend.weights = std::move(weights);
    return blend;
  }
  static Blend union_max() {
    Blend blend;
    blend.kind = BlendKind::union_max;
    return blend;
  }
  static Blend super_elliptic(double t, std::vector<double> r, double iso = 1.0, bool angle_weighted = false) {
    Blend blend;
    blend.kind = BlendKind::super_elliptic;
    blend.t = t;
    blend.r = std::move(r);
    blend.angle_weighted = angle_weighted;
    blend.iso = iso;
    return blend;
  }

  /// The band width r_k of child k.
  double r_of(std::size_t k) const { return r.size() == 1 ? r[0] : r[k]; }
  /// The weight w_k of child k.
  double weight_of(std::size_t k) const { return weights.empty() ? 1.0 : weights[k]; }
};

/// Throws InputError located at the offending field ("children",
/// "weights", "weights[1]", "t", "r", "r[0]", "iso", "angle_weighted").
void validate_blend(const Blend& blend, std::size_t child_count);

namespace detail {
template <class T>
bool any_infinite(std::span<const ScalarSample<T>> children) {
  for (const auto& child : children)
    if (child.value == std::numeric_limits<T>::infinity()) return true;
  return false;
}
template <class T>
ScalarSample<T> infinite_marker() {
  const T infinity = std::numeric_limits<T>::infinity();
  return {infinity, {infinity, infinity, infinity}};
}
template <class T>
void add_scaled(std::array<T, 3>& total, const T& scale, const std::array<T, 3>& v) {
  for (int j = 0; j < 3; ++j) total[j] += scale * v[j];
}
template <class T>
T dot(const std::array<T, 3>& a, const std::array<T, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
/// [x]₊^t and its derivative (0 at x ≤ 0).
template <class T>
std::pair<T, T> positive_power(const T& x, const T& t) {
  using std::pow;
  if (!(x > T(0))) return {T(0), T(0)};
  const T power = pow(x, t - T(1));
  return {power * x, t * power};
}
}  // namespace detail

/// Σ w_k f_k (file comment).
template <class T>
ScalarSample<T> blend_sum(const Blend& blend, std::span<const ScalarSample<T>> children) {
  if (detail::any_infinite(children)) return detail::infinite_marker<T>();
  ScalarSample<T> total;
  for (std::size_t k = 0; k < children.size(); ++k) {
    const T w(blend.weight_of(k));
    total.value += w * children[k].value;
    detail::add_scaled(total.gradient, w, children[k].gradient);
  }
  return total;
}

/// max_k f_k with the gradient of the first maximal child (file comment).
template <class T>
ScalarSample<T> blend_union(std::span<const ScalarSample<T>> children) {
  std::size_t best = 0;
  for (std::size_t k = 1; k < children.size(); ++k)
    if (children[k].value > children[best].value) best = k;
  return children[best];
}

/// Rockwood's blend without the angle (file comment).
template <class T>
ScalarSample<T> blend_super_elliptic(const Blend& blend, std::span<const ScalarSample<T>> children) {
  if (detail::any_infinite(children)) return detail::infinite_marker<T>();
  const T c(blend.iso), t(blend.t);
  ScalarSample<T> total;
  for (std::size_t k = 0; k < children.size(); ++k) {
    const T r(blend.r_of(k));
    const auto [term, slope] = detail::positive_power((children[k].value - c + r) / r, t);
    total.value += c * term;
    detail::add_scaled(total.gradient, c * slope / r, children[k].gradient);
  }
  return total;
}

/// The Hessian-vector products the angle-weighted blend needs: H_k ∇f_j.
template <class T>
struct AngleHessianProducts {
  std::array<T, 3> h1_g1, h1_g2, h2_g1, h2_g2;
};

/// cos θ between the children's gradients, 0 if either is zero.
template <class T>
T gradient_cosine(const ScalarSample<T>& first, const ScalarSample<T>& second) {
  using std::sqrt;
  const T n1 = sqrt(detail::dot(first.gradient, first.gradient));
  const T n2 = sqrt(detail::dot(second.gradient, second.gradient));
  if (n1 == T(0) || n2 == T(0)) return T(0);
  return detail::dot(first.gradient, second.gradient) / (n1 * n2);
}

/// Rockwood's θ-weighted binary blend (file comment); `hessian` may be
/// null when only the value is wanted (the gradient then lacks the ∇a
/// term and is not ∇f).
template <class T>
ScalarSample<T> blend_super_elliptic_angle(const Blend& blend, const ScalarSample<T>& first,
                                           const ScalarSample<T>& second, const AngleHessianProducts<T>* hessian) {
  using std::sqrt;
  const std::array<ScalarSample<T>, 2> children{first, second};
  if (detail::any_infinite(std::span<const ScalarSample<T>>(children))) {
    return detail::infinite_marker<T>();
  }
  const T c(blend.iso), t(blend.t);
  const T n1sq = detail::dot(first.gradient, first.gradient);
  const T n2sq = detail::dot(second.gradient, second.gradient);
  const bool has_angle = n1sq != T(0) && n2sq != T(0);
  const T cosine = gradient_cosine(first, second);
  const T raw_factor = T(1) - cosine;
  const bool clamped = raw_factor < T(Blend::min_angle_factor);
  const T a = clamped ? T(Blend::min_angle_factor) : raw_factor;

  // ∇a = −∇cos θ (0 where a is clamped or cos θ is the convention 0).
  std::array<T, 3> grad_a{};
  if (hessian != nullptr && !clamped && has_angle) {
    const T n1n2 = sqrt(n1sq) * sqrt(n2sq);
    for (int j = 0; j < 3; ++j) {
      const T grad_cos = (hessian->h1_g2[j] + hessian->h2_g1[j]) / n1n2 -
                         cosine * (hessian->h1_g1[j] / n1sq + hessian->h2_g2[j] / n2sq);
      grad_a[j] = -grad_cos;
    }
  }
  ScalarSample<T> total;
  for (std::size_t k = 0; k < 2; ++k) {
    const T r(blend.r_of(k));
    const T v = c - children[k].value;  // Ferley's V_k
    const auto [term, slope] = detail::positive_power(T(1) - v / (r * a), t);
    total.value += c * term;
    detail::add_scaled(total.gradient, c * slope / (r * a), children[k].gradient);
    detail::add_scaled(total.gradient, c * slope * v / (r * a * a), grad_a);
  }
  return total;
}

}  // namespace skelconv
