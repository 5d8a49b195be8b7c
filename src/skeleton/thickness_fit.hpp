// src/skeleton/thickness_fit.hpp — the fit both thickness corrections share
// (skelconv/skeleton/thickness_correction.hpp: classical segments;
// skelconv/skeleton/scalis_thickness_correction.hpp: SCALIS segments).
//
// The field is linear in the unknowns x: f = build(x), and unknown k moves it
// by basis[k] per unit. At sample j (foot F_j, target thickness t_j) the
// thickness r_j is where f crosses iso along the normal n; the fit minimises
//     Σ_j ((r_j − t_j)/t_j)² + λ |x|²,   x_k ≥ lower_k,
// by Levenberg–Marquardt with the exact derivative of the thickness:
//     ∂r_j/∂x_k = −basis_k(Q_j) / (n·∇f(Q_j)),  Q_j = F_j + r_j n
// (implicit function theorem on f(F_j + r n) = iso). A step that leaves the
// bounds is projected onto them. It stops when every sample is within
// `tolerance` of its target, after `max_iterations`, or when no damping
// lowers the objective (a local minimum of the model).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "skelconv/skeleton/skeleton.hpp"
#include "skelconv/skeleton/thickness_correction.hpp"

namespace skelconv::detail {

/// The most thickness samples a correction makes (both sample layouts).
/// Each costs a root search per fit iteration (8,002 samples: 12.7 s for two
/// unit segments at τ = 1e-3), so a thickness far below the segments' length
/// would run for hours; at τ = 1e-300 the count overflowed int and the fit
/// returned NaN weights.
inline constexpr double max_thickness_samples = 100'000;

struct LinearThicknessModel {
  std::vector<Skeleton> basis;  ///< the field of unknown k at unit value
  std::vector<double> lower;    ///< x_k ≥ lower[k] (−inf: free)
  std::function<Skeleton(const Eigen::VectorXd&)> build;  ///< the whole field at x
};

struct ThicknessFitSettings {
  Vec3 normal = Vec3::UnitZ();
  double iso = 1.0;
  double reach = 1.0;  ///< beyond it, along the normal, the field is below iso
  double tolerance = 0.01;
  int max_iterations = 30;
  double regularisation = 0.0;  ///< λ
  ThicknessProgress progress;   ///< ThicknessCorrectionOptions::progress
};

struct ThicknessFitResult {
  Eigen::VectorXd x;
  std::vector<ThicknessSample> after;
  int iterations = 0;
  bool converged = false;
};

/// The options both corrections share, each refused by its own name:
/// InputError at "ramp_nodes" unless in [1, 100] (each ramp node is an
/// unknown of the dense fit, and past 100 its spacing R/ramp_nodes is below
/// the samples' for any τ above R/25: unknowns no sample tells apart; the
/// bound also keeps an absurd count from running without end), at
/// "samples_per_thickness" unless in [1, 100], at "regularisation" unless
/// finite and >= 0 (an infinite one makes the fit's weights NaN), at
/// "point_support_ratio" unless in [1, 4].
void require_fit_options(int ramp_nodes, double samples_per_thickness, double regularisation,
                         double point_support_ratio);

/// The index of the node at `p` in `nodes` (within `merge`), appended if new.
std::size_t node_of(std::vector<Vec3>& nodes, const Vec3& p, double merge);

/// The unit normal of the plane holding every node of `edges` (any unit
/// vector normal to the line for a collinear graph); InputError located at
/// the first edge out of the plane. `size`: the graph's bounding-box diagonal.
Vec3 plane_normal(const std::vector<Vec3>& nodes, const std::vector<SegmentGraph::Edge>& edges, double size);

/// InputError at `where` + ".kernel.family" unless the family's trait says
/// the corrections are written for it (kernels/compact.hpp,
/// thickness_correction); the message names those families, from the traits.
void require_correction_family(KernelFamily family, const std::string& where);

/// iso / f₁(τ), f₁ the field at distance τ from the middle of a segment of
/// weight 1 and half-length R: its support ball (radius R) meets only
/// skeleton, so f₁ is the infinite line's field (Zanni §4.3, fig. 11). The
/// constant weight that gives a long segment of `kernel` the thickness τ.
double long_segment_weight(const KernelSpec& kernel, double iso, double tau);

/// Thickness at every sample of `samples` for `field` (ThicknessSample::thickness).
void measure_thickness(std::vector<ThicknessSample>& samples, const Skeleton& field, const ThicknessFitSettings& s);

/// max_j |r_j − t_j|/t_j over the samples of positive target.
double worst_departure(const std::vector<ThicknessSample>& samples);

/// The fit of the file comment from x0 (`samples` give feet and targets).
ThicknessFitResult fit_thickness(const LinearThicknessModel& model, const Eigen::VectorXd& x0,
                                 std::vector<ThicknessSample> samples, const ThicknessFitSettings& settings);

}  // namespace skelconv::detail
