// skelconv/skeleton/thickness_correction.hpp — the thickness correction of
// Zanni et al. 2013 §5.1 (Figure 13: "local optimisation of the weights of
// the graph nodes that need correction") for a graph of classical
// convolution segments blended by their sum (docs/thickness_correction.md).
//
// A classical segment (docs/mathematics.md §2) of constant weight w has, on a long straight
// skeleton, a constant thickness r(w); where segments meet, their fields add
// and the surface bulges (a fork, a corner), and at a free end half the
// skeleton is missing and it thins. The correction:
//   1. the graph: segment ends that coincide are one node; every segment
//      starts with the base weight w_τ, the constant weight that gives a long
//      straight segment the thickness τ (measured, not assumed: the field of
//      a segment long enough for the compact support at distance τ);
//   2. the thickness along the skeleton: at sample points of each segment,
//      the distance along the normal n of the skeleton's plane at which the
//      sum crosses the iso level (outermost crossing, bracketed by a scan
//      and refined by a safeguarded secant);
//   3. detection: a node needs correction when a sample within the kernel's
//      support radius R of it departs from τ by more than `tolerance`·τ;
//   4. local optimisation: each segment leaving a corrected node is split at
//      R/ramp_nodes, 2R/ramp_nodes, …, R from it (classical convolution is
//      additive, so splitting with interpolated weights changes nothing);
//      the unknowns are the weights of the node and of the split points
//      closer than R (the point at R keeps w_τ, so the change stays within
//      the node's reach) and the weight ≥ 0 of a point primitive of the same
//      kernel family at the node, of support point_support_ratio·R (Zanni's
//      "point skeleton" at the node, with its "influence"). They are
//      fitted by Levenberg–Marquardt on the measured thickness,
//      min Σ_j ((r_j − τ)/τ)² + λ Σ_k x_k². The field is linear in the
//      weights (each node owns a hat function: weight 1 at it, 0 at its
//      neighbours), so ∂r_j/∂w_k = −φ_k(Q_j) / (n·∇f(Q_j)) at the surface
//      point Q_j. Segment weights may become negative: the sum is what
//      defines the surface, and near a free end the fit pairs the point
//      primitive with a lower (possibly negative) end weight to shape a
//      rounded cap of radius τ.
//
// Why this variant: the paper corrects SCALIS surfaces by point primitives
// at the extremities and thickness maxima, whose weights are chosen from the
// radius variation of the segments leaving the node (Figure 13), mixed by
// Barthe blends whose operators the text does not give (docs/mathematics.md §6). For
// classical convolution with the sum blend the node weights and the point
// weights enter the field linearly, so one local fit handles both the thin
// free ends (a missing half-skeleton) and the bulging junctions (fields that
// add), with no blend the paper leaves unspecified. SCALIS graphs, the
// paper's own case: skelconv/skeleton/scalis_thickness_correction.hpp.
//
// Supported: top-level segment primitives (no blend node: their sum is the
// field), one compact-support kernel (family "compact", any degree the
// generated table offers for linear weights) shared by all, coplanar (the
// thickness is measured along the plane's normal, which no neighbour's
// fillet crosses). A compact kernel makes the correction local: a weight
// changes the field only within R. Anything else is an InputError located at
// the primitive ("primitives[2].kernel.family: ...").
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "skelconv/geometry.hpp"
#include "skelconv/kernels/kernel_spec.hpp"
#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv {

/// The segments of a skeleton as a graph: nodes (coinciding ends merged),
/// edges between them, the shared kernel, the plane's unit normal.
struct SegmentGraph {
  struct Edge {
    std::size_t a = 0, b = 0;  ///< node indices
    std::string location;      ///< the primitive in the file, "primitives[2]"
  };
  std::vector<Vec3> nodes;
  std::vector<Edge> edges;
  KernelSpec kernel;
  double iso = 1.0;
  Vec3 normal = Vec3::UnitZ();
};

/// Ends closer than this fraction of the skeleton's bounding-box diagonal are
/// one node: far below any meaningful geometry, far above the rounding of
/// coordinates written with 17 digits.
inline constexpr double node_merge_ratio = 1e-9;

/// The graph of `skeleton`'s segments. InputError (located at the primitive)
/// for a blend node, a primitive other than a segment, a kernel other than
/// compact or different from the first segment's, a non-coplanar graph, and
/// for a skeleton without segments ("primitives: ...").
SegmentGraph segment_graph_of(const Skeleton& skeleton);

/// ThicknessCorrectionOptions::progress: (iteration, worst departure).
using ThicknessProgress = std::function<void(int iteration, double worst_departure)>;

struct ThicknessCorrectionOptions {
  double thickness = 0.0;  ///< τ > 0, below the kernel's support radius R
  /// Relative departure |r − τ|/τ above which a sample makes its nodes need
  /// correction; the optimiser stops once every sample is within it.
  double tolerance = 0.01;
  /// Gauss–Newton iterations at most (each re-measures every sample).
  int max_iterations = 30;
  /// Split points per segment leaving a corrected node (the free weights of
  /// the ramp, the last one at R fixed). More: a finer fit, more unknowns.
  /// In [1, 100] (thickness_correction.cpp says why).
  int ramp_nodes = 4;
  /// Samples per length τ along each segment (ends included).
  double samples_per_thickness = 4.0;
  /// λ of the fit's penalty λ Σ x_k² on the relative changes x_k of the
  /// unknowns (hat weight / w_τ − 1, point weight / (w_τ R)). Without it the
  /// fit trades a point primitive against a large negative end weight
  /// (both peak at the node) for little gain; 1e-5 keeps the weights within
  /// a few w_τ and costs a few tenths of a percent of thickness on the
  /// test graphs (tests/thickness_correction_test.cpp).
  double regularisation = 1e-5;
  /// Support radius of the point primitive at a corrected node, in units of
  /// the segments' R: the paper's "influence" of the point correction
  /// (Figure 13). It must differ from R: along the line at distance τ from
  /// the skeleton, a point of support R and the missing half-line it
  /// replaces at a free end vanish at the same place with different orders
  /// (the point as (x₀ − x)³, the half-line integral as (x₀ − x)⁴), so no
  /// ramp of hat weights of spacing R/4 brings the surface closer than
  /// ~1.2% to τ (least squares) there. With 1.25 R the same ramp reaches
  /// ~0.2% for τ/R from 0.3 to 0.7 (docs/thickness_correction.md).
  double point_support_ratio = 1.25;
  /// If set, called after the thickness before the fit is measured
  /// (iteration 0) and after each fit iteration, with the worst relative
  /// departure |r − τ|/τ of the samples then: every iteration re-measures
  /// every sample, seconds each at tens of thousands of samples, so a
  /// caller can show that the work goes on (`skelconv thickness`'s
  /// progress lines). The result does not depend on it.
  ThicknessProgress progress;
};

/// One thickness measurement: on edge `edge` of the graph it belongs to, at
/// parameter t from its node a; thickness 0 where the surface misses the
/// skeleton point. A target of 0 (a SCALIS tip) is not counted.
struct ThicknessSample {
  std::size_t edge = 0;
  double t = 0.0;
  Vec3 foot = Vec3::Zero();
  double thickness = 0.0;
  double target = 0.0;  ///< the thickness asked for at `foot`
};

struct ThicknessCorrection {
  double base_weight = 0.0;                  ///< w_τ
  std::vector<std::size_t> corrected_nodes;  ///< nodes of the input graph
  SegmentGraph refined;                      ///< the graph split at the ramp points
  std::vector<double> weights;               ///< per node of `refined`, after correction
  /// per node of `refined`: the weight of the point primitive at it (0: none)
  std::vector<double> point_weights;
  double point_support = 0.0;  ///< the point primitives' support radius

  /// Samples on the input graph's edges, with the base weight and after.
  std::vector<ThicknessSample> before, after;
  int iterations = 0;
  bool converged = false;  ///< every sample within tolerance
};

/// Runs steps 1–4 of the file comment on `graph`. InputError ("thickness",
/// "tolerance", ...) for options out of range. A graph whose nodes all stay
/// within tolerance comes back with no corrected node and its base weights.
ThicknessCorrection correct_thickness(const SegmentGraph& graph, const ThicknessCorrectionOptions& options);

/// The skeleton of `graph` with `weights` per node: one segment per edge,
/// linear weight from its node a's weight to its node b's.
/// `point_weights` (per node, 0: none) add point primitives of the graph's
/// kernel with support radius `point_support`.
Skeleton weighted_skeleton(const SegmentGraph& graph, const std::vector<double>& weights,
                           const std::vector<double>& point_weights = {}, double point_support = 0.0);

/// The same skeleton as skelconv JSON (the file format of skeleton_file.hpp),
/// numbers with 17 significant digits.
std::string weighted_skeleton_json(const SegmentGraph& graph, const std::vector<double>& weights,
                                   const std::vector<double>& point_weights = {}, double point_support = 0.0);

/// The corrected skeleton of `c` (its refined graph, weights and point
/// primitives), as a Skeleton and as skelconv JSON.
Skeleton corrected_skeleton(const ThicknessCorrection& c);
std::string corrected_skeleton_json(const ThicknessCorrection& c);

/// The distance from `foot` along the unit vector `normal` at which `field`
/// crosses `iso` last (the outermost crossing before `reach`, where the
/// field must be below iso); 0 if the field at foot is already below iso.
/// The crossing is bracketed by a scan of `scan_steps` steps and refined by
/// a safeguarded secant to a relative width of 1e-12.
double thickness_along(const Skeleton& field, const Vec3& foot, const Vec3& normal, double iso, double reach,
                       int scan_steps = 64);

}  // namespace skelconv
