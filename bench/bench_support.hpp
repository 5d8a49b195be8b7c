// bench/bench_support.hpp — what the benchmark programs share: the generated
// kernels as plain function pointers, reproducible workloads (query points
// around one segment) and adaptive Gauss–Kronrod quadrature of the definition
// integrals, the method numerical skeleton libraries use today.
//
// Only bench/kernel_set.cpp includes generated/segment_table.hpp (a ~1 minute
// compile), so the benchmark programs that call kernels through the table are
// cheap to rebuild.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "skelconv/detail/clip.hpp"
#include "skelconv/kernels/op_count.hpp"
#include "skelconv/kernels/read_trait.hpp"
#include "skelconv/primitives/segment_input.hpp"

namespace skelconv::bench {

using Input = SegmentInput<double>;
using Vec = std::array<double, 3>;

// --- The generated kernels (docs/generated_api.md) ---------------------------

/// One entry of generated::segment_kernels<double>(), without its equation.
struct KernelRef {
  KernelFamily family;
  int degree;
  int weight_degree;
  double (*f)(const Input&);
  Vec (*grad)(const Input&);
  double (*f_and_grad)(const Input&, Vec&);
  std::string name;  // e.g. "segment_cauchy_i4_w1"
  OpCount ops_f, ops_grad, ops_f_and_grad;  // per point
  OpCount ops_prepare;                       // once per segment
  // The split kernel's two halves (docs/generated_api.md); prepare is null
  // for a kernel that is not split (the derived Gaussian).
  std::size_t prepared_size = 0;
  void (*prepare)(const Input&, double*) = nullptr;
  double (*f_at)(const double*, const SegmentPoint<double>&) = nullptr;
  Vec (*grad_at)(const double*, const SegmentPoint<double>&) = nullptr;
  double (*f_and_grad_at)(const double*, const SegmentPoint<double>&, Vec&) = nullptr;
};

/// `k` at each of `inputs` as `Segment` evaluates it: every segment prepared
/// once, here before any timing, and only the per-point half timed. The
/// closed forms' speed is their speed per point; the preparation is paid
/// once per primitive when a skeleton is loaded. A kernel that is not split
/// is evaluated whole.
class PreparedPoints {
 public:
  PreparedPoints(const KernelRef& k, const std::vector<Input>& inputs) : k_(&k), inputs_(&inputs) {
    if (!k.prepare) return;
    prepared_.resize(inputs.size() * k.prepared_size);
    points_.reserve(inputs.size());
    for (std::size_t j = 0; j < inputs.size(); ++j) {
      k.prepare(inputs[j], prepared_.data() + j * k.prepared_size);
      points_.push_back({inputs[j].p, inputs[j].t0, inputs[j].t1});
    }
  }
  std::size_t size() const { return inputs_->size(); }
  double f(std::size_t j) const {
    return k_->prepare ? k_->f_at(at(j), points_[j]) : k_->f((*inputs_)[j]);
  }
  Vec grad(std::size_t j) const {
    return k_->prepare ? k_->grad_at(at(j), points_[j]) : k_->grad((*inputs_)[j]);
  }
  double f_and_grad(std::size_t j, Vec& g) const {
    return k_->prepare ? k_->f_and_grad_at(at(j), points_[j], g) : k_->f_and_grad((*inputs_)[j], g);
  }

 private:
  const double* at(std::size_t j) const { return prepared_.data() + j * k_->prepared_size; }
  const KernelRef* k_;
  const std::vector<Input>* inputs_;
  std::vector<double> prepared_;
  std::vector<SegmentPoint<double>> points_;
};

/// Every generated kernel, in the table's order.
const std::vector<KernelRef>& generated_kernels();
/// nullptr when (family, degree, weight degree) was not generated.
const KernelRef* find_kernel(KernelFamily family, int degree, int weight_degree);

/// f at the point of `in`; for a finite-support family the clip interval moves
/// with P, so it is recomputed (an empty clip gives 0), as any caller of a
/// finite-difference gradient would have to.
inline double f_reclipped(const KernelRef& k, Input in) {
  if (kernels::has_finite_support(k.family)) {
    const auto clip = clip_to_ball(in.a, in.b, in.p, in.R);
    if (!clip) return 0.0;
    in.t0 = clip->t0;
    in.t1 = clip->t1;
  }
  return k.f(in);
}

/// f and a finite-difference gradient, the alternative to f_and_grad:
/// central differences (7 evaluations of f, step ~ eps^(1/3)) or forward
/// differences (4 evaluations, step ~ eps^(1/2)), for unit-scale geometry.
template <bool central>
double f_and_fd_gradient(const KernelRef& k, Input in, Vec& g) {
  const double h = central ? 6e-6 : 1.5e-8;
  const double f = k.f(in);
  for (int c = 0; c < 3; ++c) {
    const double x = in.p[c];
    in.p[c] = x + h;
    const double forward = f_reclipped(k, in);
    if constexpr (central) {
      in.p[c] = x - h;
      g[c] = (forward - f_reclipped(k, in)) / (2 * h);
    } else {
      g[c] = (forward - f) / h;
    }
    in.p[c] = x;
  }
  return f;
}

/// The kernels compared in detail: Zanni et al. 2013 Table 4's three classical rows, and
/// the compact family (even degrees are polynomial; odd ones need sqrt and
/// atan).
struct KernelKey {
  KernelFamily family;
  int degree, weight_degree;
};
inline constexpr KernelKey detailed_kernels[] = {
    {KernelFamily::inverse, 3, 1}, {KernelFamily::cauchy, 4, 1}, {KernelFamily::cauchy, 4, 3},
    {KernelFamily::compact, 4, 0}, {KernelFamily::compact, 6, 0}, {KernelFamily::compact, 3, 0},
};

// --- Workloads ----------------------------------------------------------------

/// The segment every kernel benchmark uses: a generic direction (no axis
/// alignment the compiler or the closed form could exploit), |AB| ≈ 1.27.
inline constexpr Vec bench_a{0.1, -0.2, 0.3};
inline constexpr Vec bench_b{1.1, 0.4, -0.2};
/// Weight coefficients w0..w3 (a kernel of weight degree d reads w0..wd).
inline constexpr std::array<double, 4> bench_weight{1.0, 0.5, 0.25, 0.125};
inline constexpr double bench_s = 1.0;  ///< Cauchy sharpness
inline constexpr double bench_R = 1.0;  ///< compact support radius

/// `count` query points, uniform in the segment's bounding box grown by
/// bench_R, kept when their distance d to the segment satisfies
/// min_distance ≤ d ≤ max_distance, by default 0.1 ≤ d ≤ 0.9 (the region where a level set is drawn: not on the
/// inverse kernel's singularity, and inside the compact support so the clip
/// is never empty). Inputs are complete: for the compact family t0, t1 come
/// from skelconv::clip_to_ball (its cost is not part of a kernel timing).
std::vector<Input> make_inputs(KernelFamily family, std::size_t count = 1024, std::uint64_t seed = 42,
                               double min_distance = 0.1, double max_distance = 0.9);

/// The "near" workload: points at distance 0.01 ≤ d ≤ 0.1 from the segment
/// (thin features: a level set close to its skeleton), where the integrand
/// is sharply peaked and adaptive quadrature has to subdivide.
inline constexpr double near_min_distance = 0.01, near_max_distance = 0.1;

/// Same points, uniform in the box grown by 1.5 bench_R with no distance
/// filter: about a third of them are outside the compact support. For the
/// batch benchmarks, which must handle both cases.
std::vector<Vec> make_box_points(std::size_t count, std::uint64_t seed = 7);

/// Input with everything but the point (and the clip interval) filled in.
Input segment_input(KernelFamily family);

/// For a compact kernel, sets in.t0, in.t1 to the part of the segment inside
/// the support (skelconv::clip_to_ball); false when it is empty (the point
/// is then not a kernel input). Other families: true, `in` unchanged.
bool clip_compact_support(KernelFamily family, Input& in);

/// Distance from p to the segment [bench_a, bench_b].
double distance_to_segment(const Vec& p);

/// The generic region (gsl_bench.cpp, instruction_counts.cpp):
/// 256 inputs at distance d |AB| (± 10 %) from the segment, every direction
/// (beyond the ends too), for d in generic_region_distances. Compact kernels
/// get R = 5 |AB| (every distance inside the support) and come clipped.
inline constexpr std::array<double, 4> generic_region_distances{0.1, 0.3, 1.0, 3.0};  // × |AB|
inline constexpr std::size_t generic_region_points = 256;
inline constexpr double generic_region_compact_R = 5.0;  // × |AB|
std::vector<Input> generic_region_inputs(KernelFamily family, double d);

/// The distance bands of the GSL comparison (gsl_bench.cpp): 256 inputs at
/// distance d |AB| from the segment, d log-uniform in [lo, hi], every
/// direction (beyond the ends too). Compact kernels get R = (hi + 2) |AB|, so
/// that the support holds the whole segment at every distance, and come
/// clipped.
struct DistanceBand {
  double lo, hi;  // × |AB|
};
inline constexpr std::array<DistanceBand, 3> distance_bands{{{0.01, 0.1}, {0.1, 1.0}, {1.0, 10.0}}};
std::vector<Input> band_inputs(KernelFamily family, DistanceBand band);

// --- Adaptive quadrature of the definition (docs/mathematics.md §2) ---------------------------

struct QuadratureResult {
  double f = 0;
  Vec grad{0, 0, 0};
  std::size_t evaluations = 0;  ///< integrand evaluations, all integrals together
};

/// The adaptive rule: Boost.Math's gauss_kronrod<double, 61> (maximum depth
/// 15), or GSL's gsl_integration_qag with the 61-point Gauss–Kronrod rule
/// (GSL_INTEG_GAUSS61, up to 1,000 subintervals), what numerical skeleton
/// libraries built on GSL use.
enum class AdaptiveRule { boost_gauss_kronrod_61, gsl_qag_61 };

/// f(P) = |AB| ∫_{t0}^{t1} w(t) K(|P − Γ(t)|) dt and ∇f by `rule` (default Boost.Math's
/// adaptive 61-point Gauss–Kronrod rule, one integral for f and one per
/// gradient component (4 adaptive integrals) when `with_gradient`; relative
/// tolerance `tolerance`, default maximum depth 15. The kernel K is
/// (family, degree) with input.s / input.R; the weight reads w0..w_{weight_degree}.
QuadratureResult quadrature(KernelFamily family, int degree, int weight_degree, const Input& input,
                            double tolerance, bool with_gradient,
                            AdaptiveRule rule = AdaptiveRule::boost_gauss_kronrod_61);

}  // namespace skelconv::bench
