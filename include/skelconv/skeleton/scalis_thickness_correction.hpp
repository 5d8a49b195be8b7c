// skelconv/skeleton/scalis_thickness_correction.hpp — the thickness
// correction of Zanni et al. 2013 §5.1 on what the paper corrects: a graph of
// SCALIS segments (docs/mathematics.md §4) blended by their sum (docs/thickness_correction.md).
//
// A SCALIS segment of radius τ(t) has the thickness τ(t) only where it has
// enough skeleton to integrate: at a free end of non-zero radius and at a
// node of maximal radius it is too thin (the paper's two cases), where
// segments meet at an angle their fields add and it bulges, and along a
// segment whose radius varies the thickness departs from τ(t) by an amount
// set by the slope (scale invariance: a cone's surface is a cone, of the same
// apex but not of slope exactly τ'). The correction:
//   1. the graph: coinciding segment ends are one node; the radii stay the
//      file's (they are the thickness asked for);
//   2. the thickness along the skeleton: at samples of each segment, the
//      distance along the normal of the skeleton's plane at which the sum
//      crosses the iso level (as thickness_correction.hpp); the target at a
//      sample is the segment's τ(t) there (a sample of radius 0, a tip, is
//      not counted);
//   3. detection, with the factors m_e of step 4: a node of radius τ_n > 0
//      (the largest radius of its segments there) needs correction when a
//      sample within its support radius σ τ_n departs from its target by
//      more than `tolerance`;
//   4. the fit: each segment keeps its radii and gets the constant factor
//      m_e that gives its radius exactly on a long segment of its slope
//      (scale invariance: on a cone the thickness is a fixed multiple of the
//      radius, so one factor per segment removes the slope's departure);
//      the segments leaving a corrected node n get a ramp of classical
//      compact segments of support σ τ_n over ramp_reach · σ τ_n, with hat
//      weights at ramp_nodes points (the last one 0), and the node gets a
//      point primitive of the compact kernel of support point_support_ratio
//      · σ τ_n (the paper's point skeletons at extremities and thickness
//      maxima). Hat values and point weights have either sign (the sum is
//      what defines the surface); the field is linear in them, and they are
//      fitted by the Levenberg–Marquardt of src/skeleton/thickness_fit.hpp
//      with the exact derivative of the measured thickness.
//
// Why this variant: the paper mixes its point corrections by Barthe blends
// whose operators it does not give (docs/mathematics.md §6) and chooses their influence
// from the radius variation at the node (Figure 13). Here the points enter
// the sum, and their weights and the ramps' hat weights are fitted to the
// thickness the radii ask for. The ramps are classical segments because a
// SCALIS primitive's factor must be positive, and a free end wants negative
// weights next to its node (as in the classical correction).
//
// Supported: top-level "scalis_segment" primitives of one compact kernel
// (family, degree, σ), coplanar, with σ · |τ1 − τ0| / |AB| < 1 on each
// (beyond, a longer cone of the same slope has no finite field: the support
// of its far part covers every point). Anything else is an InputError
// located at the primitive.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "skelconv/geometry.hpp"
#include "skelconv/primitives/scalis_segment.hpp"
#include "skelconv/skeleton/skeleton.hpp"
#include "skelconv/skeleton/thickness_correction.hpp"

namespace skelconv {

/// The SCALIS segments of a skeleton as a graph (nodes merged as for
/// SegmentGraph); radius[k] = {τ at edges[k].a, τ at edges[k].b}.
struct ScalisSegmentGraph {
  std::vector<Vec3> nodes;
  std::vector<SegmentGraph::Edge> edges;
  std::vector<std::array<double, 2>> radius;
  std::vector<double> factor;  ///< each primitive's own "iso" factor c (f = c F / h)
  ScalisKernel kernel;
  double iso = 1.0;
  Vec3 normal = Vec3::UnitZ();
};

/// InputError (located at the primitive) for a blend node, a primitive other
/// than a SCALIS segment, a kernel other than compact or different from the
/// first one, a slope σ |τ1 − τ0| / |AB| ≥ 1, a non-coplanar graph, and for a
/// skeleton without SCALIS segments.
ScalisSegmentGraph scalis_segment_graph_of(const Skeleton& skeleton);

struct ScalisThicknessCorrectionOptions {
  /// As ThicknessCorrectionOptions::tolerance (relative to the target τ(t)).
  double tolerance = 0.01;
  int max_iterations = 30;
  /// Hat points per ramp (the last one, at its end, stays 0).
  int ramp_nodes = 8;
  /// A ramp's length in units of σ τ_n. Longer than the support σ τ_n: at
  /// a thickness maximum (radii decreasing away from the node on both
  /// sides) the point's field reaches beyond σ τ_n, and with ramps of σ τ_n
  /// the fit stops ~5% from τ there (the (0,1,0) case of
  /// tests/thickness_correction_test.cpp); with 2 σ τ_n it converges.
  double ramp_reach = 2.0;
  /// Samples per length τ̄ (the segment's mean radius) along each segment.
  double samples_per_thickness = 4.0;
  /// λ on the unknowns (hat values in units of the weight that gives τ_n on
  /// a long ramp segment, point weights in units of the weight at which the
  /// point alone gives iso at distance τ_n); as for classical graphs.
  double regularisation = 1e-5;
  /// A node point's support in units of σ τ_n (the reason for > 1: the
  /// file comment of thickness_correction.hpp).
  double point_support_ratio = 1.25;
  /// As ThicknessCorrectionOptions::progress.
  ThicknessProgress progress;
};

struct ScalisThicknessCorrection {
  /// An input segment with its factor: its field is m_e times the file's.
  struct Piece {
    std::size_t edge = 0;
    Vec3 a, b;
    double tau_a = 0, tau_b = 0;
    double multiplier = 1;
  };
  /// A classical compact segment of the correction near a node: support R,
  /// weight linear from weight[0] at a to weight[1] at b (either sign).
  struct RampSegment {
    std::size_t edge = 0;  ///< the input segment it lies on
    Vec3 a, b;
    double support = 0;
    std::array<double, 2> weight{0, 0};
  };
  struct NodePoint {
    std::size_t node = 0;
    double support = 0;  ///< R of the compact point kernel
    double weight = 0;   ///< either sign; 0: the fit did not use it
  };
  std::vector<Piece> pieces;  ///< one per input segment
  std::vector<std::size_t> corrected_nodes;
  std::vector<RampSegment> ramps;
  std::vector<NodePoint> points;  ///< one per corrected node
  std::vector<ThicknessSample> before, after;  ///< targets τ(t)
  int iterations = 0;
  bool converged = false;
};

ScalisThicknessCorrection correct_scalis_thickness(const ScalisSegmentGraph& graph,
                                                   const ScalisThicknessCorrectionOptions& options);

/// The corrected skeleton (the segments with their factors, the ramps and
/// the points of non-zero weight), as a
/// Skeleton and as skelconv JSON (17 significant digits).
Skeleton scalis_corrected_skeleton(const ScalisSegmentGraph& graph, const ScalisThicknessCorrection& c);
std::string scalis_corrected_skeleton_json(const ScalisSegmentGraph& graph, const ScalisThicknessCorrection& c);

}  // namespace skelconv
