// src/simd/polygon_batch.cpp — skelconv::simd::value_and_gradient for
// polygons (include/skelconv/simd/batch.hpp, docs/simd.md).
//
// The same structure as the segment batch: a scalar pre-pass puts every
// point in the polygon's frame (Polygon::single_closed_form, ScaledFrame)
// and sends to the scalar path the points Polygon::value_and_gradient treats
// apart (a non-finite P; inverse kernels: z = 0 exactly, where the runtime
// decides between +inf and a finite value, and P near the plane, where the
// height comes from the exact vertices, skelconv/detail/plane_height.hpp; the far
// field, ≥ 5 radii from the vertex centroid, polygon_far_field.hpp). The
// others run, a group of 4 or 8 lanes at a time (group_runner-inl.hpp),
// through polygon_evaluate's contour sum written on Lanes: the generated
// edge kernel `polygon_edge_<family>_i<i>_f_and_grad` (the function the scalar path
// calls, through a pointer there) on every edge, the same sums in the same
// order, Θ snapped to a multiple of 2π, f and ∇f assembled and scaled back
// from the frame. A lane whose P̄ lies on an edge's line (h = 0) or whose
// result is not a normal double is handed to the scalar path.
//
// Compiled once per Highway target (foreach_target.h re-includes this file).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/simd/polygon_batch.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "generated/polygon_cauchy.hpp"
#include "generated/polygon_inverse.hpp"
#include "skelconv/detail/integer_power.hpp"
#include "skelconv/primitives/polygon.hpp"
#include "skelconv/detail/polygon_far_field.hpp"
#include "skelconv/primitives/polygon_field.hpp"
#include "skelconv/simd/batch.hpp"
#include "src/simd/group_runner-inl.hpp"
#include "src/simd/lanes-inl.hpp"
#include "src/simd/polygon_kernels.hpp"
#include "src/simd/scalar_fallback.hpp"

#ifndef SKELCONV_SIMD_POLYGON_UNIFORMS
#define SKELCONV_SIMD_POLYGON_UNIFORMS
namespace skelconv::simd::detail {
/// What every lane of a polygon batch shares, and the points in the frame.
struct PolygonUniforms {
  PolygonInput<double> input;  ///< vertices, normal, family, degree, s (in the frame)
  double value_scale;          ///< 2^(m e): f = f'·value_scale
  double gradient_scale;       ///< 2^((m − 1) e)
  const double* x;             ///< the points in the frame, by point index
  const double* y;
  const double* z;
};
}  // namespace skelconv::simd::detail
#endif

HWY_BEFORE_NAMESPACE();
namespace skelconv::simd::HWY_NAMESPACE {
namespace {

using detail::PolygonUniforms;

/// Bit k set where lane k of `mask` holds.
unsigned mask_bits(LaneVectorMask mask) {
  uint8_t bits[8] = {};
  hn::StoreMaskBits(LaneTag(), mask, bits);
  return bits[0];
}

/// Θ snapped as detail::snap_winding_angle does, lane by lane (std::round).
Lanes snapped_winding_angle(Lanes theta_sum) {
  const LaneTag d;
  const double two_pi = 2 * std::numbers::pi_v<double>;
  alignas(64) double v[max_lanes];
  hn::Store(theta_sum.vec(), d, v);
  for (std::size_t k = 0; k < lane_count(); ++k) {
    const double turns = std::round(v[k] / two_pi);
    v[k] = std::abs(v[k] - turns * two_pi) <= 1e-6 ? turns * two_pi : v[k];
  }
  return Lanes(hn::Load(d, v));
}

/// value · scale where both are normal doubles (or, for a gradient, its
/// largest component), else NaN: the lane then goes to the scalar path,
/// which returns or reports what ScaledFrame::restore_* decides.
LaneVector restored(LaneVector value, LaneVector largest, double scale) {
  const LaneTag d;
  const LaneVector world = hn::Mul(value, hn::Set(d, scale));
  const LaneVector world_largest = hn::Mul(largest, hn::Set(d, scale));
  const auto normal = [&](LaneVector v) {
    return hn::And(hn::Ge(v, hn::Set(d, DBL_MIN)), hn::Le(v, hn::Set(d, DBL_MAX)));
  };
  const auto fine = hn::And(normal(largest), normal(world_largest));
  return hn::IfThenElse(fine, world, hn::Set(d, std::numeric_limits<double>::quiet_NaN()));
}

/// f and ∇f at points[0..max_lanes) by polygon_evaluate's contour sum on
/// Lanes, the edge terms by the generated EdgeFull (`flatten`: compiled for
/// this target). Inverse and Cauchy kernels (the pre-pass keeps z = 0 of an
/// inverse kernel and the far field out).
template <auto EdgeFull>
__attribute__((flatten)) void polygon_group(const PolygonUniforms& u, const std::uint32_t* lanes,
                                            Divergence& divergence, GroupResult& r) {
  const LaneTag d;
  const PolygonInput<double>& poly = u.input;
  alignas(64) double x[max_lanes], y[max_lanes], zc[max_lanes];
  for (std::size_t k = 0; k < max_lanes; ++k) {
    x[k] = u.x[lanes[k]];
    y[k] = u.y[lanes[k]];
    zc[k] = u.z[lanes[k]];
  }
  const std::array<Lanes, 3> p = {Lanes(hn::Load(d, x)), Lanes(hn::Load(d, y)), Lanes(hn::Load(d, zc))};
  const auto& v = poly.vertices;
  const auto& n = poly.normal;
  const std::size_t count = v.size();
  const Lanes z = (p[0] - v[0][0]) * n[0] + (p[1] - v[0][1]) * n[1] + (p[2] - v[0][2]) * n[2];
  PolygonEdgeInput<Lanes> in;
  plane_foot(p, z, {Lanes(n[0]), Lanes(n[1]), Lanes(n[2])}, in.p, in.p_lo);
  in.normal = {n[0], n[1], n[2]};
  in.z = z;
  in.s = poly.s;
  in.R = poly.R;
  std::array<Lanes, 3> grad = {Lanes(0.0), Lanes(0.0), Lanes(0.0)};
  Lanes theta_sum(0.0), S_f(0.0), S_g(0.0);
  current_divergence = &divergence;
  for (std::size_t m = 0; m < count; ++m) {
    const auto& a = v[m];
    const auto& b = v[(m + 1) % count];
    in.a = {a[0], a[1], a[2]};
    in.b = {b[0], b[1], b[2]};
    PolygonEdgeTerms<Lanes> terms;
    EdgeFull(in, terms);
    // P̄ on the edge's line: the scalar path leaves the edge out (and tells
    // whether P̄ is on the boundary).
    const unsigned on_line = mask_bits(hn::Eq(terms.h.vec(), hn::Zero(d))) & divergence.active();
    for (std::size_t k = 0; k < max_lanes; ++k)
      if (on_line >> k & 1u) divergence.hand_lane_to_scalar(k);
    theta_sum += terms.theta;
    S_f += terms.S_f;
    S_g += terms.S_g;
    // In-plane part: −(E × n) ∫ K over the edge (divergence theorem).
    const double e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    grad[0] -= Lanes(e[1] * n[2] - e[2] * n[1]) * terms.J_g;
    grad[1] -= Lanes(e[2] * n[0] - e[0] * n[2]) * terms.J_g;
    grad[2] -= Lanes(e[0] * n[1] - e[1] * n[0]) * terms.J_g;
  }
  current_divergence = nullptr;
  // C = (ζ^(2−i) Θ − Σ H_{i−2}) / (α(i − 2)), ∂C/∂z = −z (ζ^(−i) Θ − Σ H_i).
  const Lanes Theta = snapped_winding_angle(theta_sum);
  const int i = poly.degree;
  const PolygonKernelForm<double> form = polygon_kernel_form(poly);
  const Lanes alpha(form.alpha);
  const Lanes zeta = sqrt(alpha * z * z + Lanes(form.beta));
  const auto no_winding = hn::Eq(Theta.vec(), hn::Zero(d));
  const Lanes winding_f(hn::IfThenZeroElse(no_winding, (integer_power(zeta, 2 - i) * Theta).vec()));
  const Lanes winding_g(hn::IfThenZeroElse(no_winding, (integer_power(zeta, -i) * Theta).vec()));
  const Lanes f = (winding_f - S_f) / (alpha * Lanes(double(i - 2)));
  const Lanes dfdz = -z * (winding_g - S_g);
  for (int k = 0; k < 3; ++k) grad[std::size_t(k)] += dfdz * n[std::size_t(k)];
  const LaneVector largest =
      hn::Max(hn::Max(hn::Abs(grad[0].vec()), hn::Abs(grad[1].vec())), hn::Abs(grad[2].vec()));
  hn::Store(restored(f.vec(), hn::Abs(f.vec()), u.value_scale), d, r.f);
  hn::Store(restored(grad[0].vec(), largest, u.gradient_scale), d, r.gx);
  hn::Store(restored(grad[1].vec(), largest, u.gradient_scale), d, r.gy);
  hn::Store(restored(grad[2].vec(), largest, u.gradient_scale), d, r.gz);
}

using GroupFunction = void (*)(const PolygonUniforms&, const std::uint32_t*, Divergence&, GroupResult&);

GroupFunction find_group([[maybe_unused]] KernelFamily family, [[maybe_unused]] int degree) {
  // The portable SCALAR target (x86 machines without AVX2) would run the
  // generated code on one-lane vectors: the scalar path's work plus the lane
  // bookkeeping. It hands every point to the scalar path instead, which saves
  // a third of this file's compile time (docs/simd.md).
#if HWY_TARGET == HWY_SCALAR || HWY_TARGET == HWY_EMU128
  return nullptr;
#else
#define SKELCONV_SIMD_ENTRY(FAMILY, I) \
  if (family == KernelFamily::FAMILY && degree == I) \
    return &polygon_group<&generated::polygon_edge_##FAMILY##_i##I##_f_and_grad<Lanes>>;
  SKELCONV_SIMD_POLYGON_KERNELS(SKELCONV_SIMD_ENTRY)
#undef SKELCONV_SIMD_ENTRY
  return nullptr;
#endif
}

}  // namespace

/// Vector part of simd::value_and_gradient for polygons: runs the points of
/// `work` (the pre-pass's); false if the kernel has no vector instantiation.
bool polygon_batch(const PolygonUniforms& u, std::vector<std::uint32_t> work, FieldSoA out,
                   std::vector<std::uint32_t>& scalar, BatchCounts& counts) {
  const GroupFunction group_function = find_group(u.input.family, u.input.degree);
  if (group_function == nullptr) return false;
  auto group = [&](const std::uint32_t* lanes, Divergence& divergence, GroupResult& r) {
    group_function(u, lanes, divergence, r);
  };
  run_lanes(std::move(work), group, out, scalar, counts);
  return true;
}

}  // namespace skelconv::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace skelconv::simd {
HWY_EXPORT(polygon_batch);

namespace {

/// Whether a vector kernel is compiled for (family, degree).
bool listed(KernelFamily family, int degree) {
#define SKELCONV_SIMD_ENTRY(FAMILY, I) \
  if (family == KernelFamily::FAMILY && degree == I) return true;
  SKELCONV_SIMD_POLYGON_KERNELS(SKELCONV_SIMD_ENTRY)
#undef SKELCONV_SIMD_ENTRY
  return false;
}

/// polygon_evaluate's far-field test (same arithmetic): P at ≥
/// polygon_far_field_ratio radii from the vertex centroid, the radius grown
/// by the Cauchy kernel's width.
class FarFieldTest {
 public:
  explicit FarFieldTest(const PolygonInput<double>& poly) {
    const auto& v = poly.vertices;
    for (const auto& q : v)
      for (int k = 0; k < 3; ++k) centre_[std::size_t(k)] += q[std::size_t(k)] / double(v.size());
    for (const auto& q : v)
      radius2_ = std::max(radius2_, (q[0] - centre_[0]) * (q[0] - centre_[0]) +
                                        (q[1] - centre_[1]) * (q[1] - centre_[1]) +
                                        (q[2] - centre_[2]) * (q[2] - centre_[2]));
    const PolygonKernelForm<double> form = polygon_kernel_form(poly);
    widening_ = form.beta / form.alpha;  // the kernel's complex singularity at r² = −β/α
  }
  bool far(double x, double y, double z) const {
    const double p[3] = {x, y, z};
    double distance2 = 0;
    for (int k = 0; k < 3; ++k) distance2 += (p[k] - centre_[std::size_t(k)]) * (p[k] - centre_[std::size_t(k)]);
    const double ratio = polygon_far_field_ratio;
    return distance2 + widening_ >= ratio * ratio * radius2_;
  }

 private:
  std::array<double, 3> centre_ = {0.0, 0.0, 0.0};
  double radius2_ = 0, widening_ = 0;
};

}  // namespace

BatchCounts value_and_gradient(const Polygon& polygon, PointsSoA points, FieldSoA out) {
  BatchCounts counts;
  std::vector<std::uint32_t> scalar;
  detail::PolygonUniforms u;
  int exponent = 0, value_power = 0;
  // The vector path has the contour sums of the kernels of infinite support.
  bool vectorised = polygon.single_closed_form(u.input, exponent, value_power) &&
                    !kernels::family_facts(u.input.family).finite_support && listed(u.input.family, u.input.degree) &&
                    std::abs(value_power * exponent) < 1000 && std::abs((value_power - 1) * exponent) < 1000;
  if (vectorised) {
    u.value_scale = std::ldexp(1.0, value_power * exponent);
    u.gradient_scale = std::ldexp(1.0, (value_power - 1) * exponent);
    std::vector<double> x(points.n), y(points.n), z(points.n);
    u.x = x.data();
    u.y = y.data();
    u.z = z.data();
    const FarFieldTest far_field(u.input);
    const bool singular = kernels::family_facts(u.input.family).singular_at_zero;
    const Vec3 normal = polygon.normal();
    const Vec3 first(u.input.vertices[0][0], u.input.vertices[0][1], u.input.vertices[0][2]);
    std::vector<std::uint32_t> work;
    work.reserve(points.n);
    for (std::size_t p = 0; p < points.n; ++p) {
      // ScaledFrame::point: exact scaling by 2^−e.
      const Vec3 q(std::ldexp(points.x[p], -exponent), std::ldexp(points.y[p], -exponent),
                   std::ldexp(points.z[p], -exponent));
      x[p] = q.x();
      y[p] = q.y();
      z[p] = q.z();
      // Inverse kernels: z = 0 exactly (the runtime's on-plane decision), or
      // near the plane, where polygon_evaluate takes the exact height
      // (skelconv/detail/plane_height.hpp), a double-word fan the lanes do not have.
      const std::array<double, 3> point{q.x(), q.y(), q.z()};
      const double plain_z = plain_plane_height(point, u.input.vertices[0], u.input.normal);
      const bool singular_candidate = singular &&
                                      (normal.dot(q - first) == 0.0 ||
                                       needs_exact_plane_height(plain_z, point, u.input.vertices[0]));
      if (!q.allFinite() || singular_candidate || far_field.far(q.x(), q.y(), q.z())) {
        scalar.push_back(std::uint32_t(p));
      } else {
        work.push_back(std::uint32_t(p));
      }
    }
    vectorised = HWY_DYNAMIC_DISPATCH(polygon_batch)(u, std::move(work), out, scalar, counts);
  }
  if (!vectorised) scalar.clear();
  detail::finish_on_scalar_path(polygon, vectorised, scalar, points, out, counts);
  return counts;
}

bool has_vector_kernel(const Polygon& polygon) {
  return !kernels::family_facts(polygon.kernel().family).finite_support &&
         listed(polygon.kernel().family, polygon.kernel().degree);
}

}  // namespace skelconv::simd
#endif  // HWY_ONCE
