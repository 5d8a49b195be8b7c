// skelconv/canal/scalis_deviation.hpp — how far a SCALIS segment's
// iso-surface lies from its ideal shape, the canal surface of the spheres
// (Γ(t), τ(t)) (docs/canal.md §5).
//
// A SCALIS segment [A, B] with radius τ(t) = τ0 + (τ1 − τ0) t (docs/mathematics.md §4) is
// meant to have thickness τ (Zanni et al. §3–4): its surface f = iso should
// be the envelope of the spheres of centre Γ(t) and radius τ(t), a cone
// frustum closed by the two end spheres. Both are surfaces of revolution
// about AB, so one meridian tells everything. For points p of the canal
// surface's meridian, with outward unit normal ν there, the signed offset
//     δ(p) = s  such that f(p + s ν) = iso
// (found by bracketing and bisection; > 0: SCALIS bulges outside) is taken
// relative to the local radius: τ(t) on the frustum (p on the circle of
// parameter t), the end radius on a cap. The frustum is sampled at the
// midpoints of `frustum_samples` equal steps of t (so a cone's tip t = 0 is
// never a sample), each cap at `cap_samples` equal steps of the polar angle
// (a cap of radius 0 has none). "middle" is the frustum for t in
// [middle_begin, middle_end]; "ends" is the rest of the frustum and the caps.
#pragma once

#include <string>
#include <vector>

#include "skelconv/primitives/scalis_segment.hpp"

namespace skelconv::canal {

struct DeviationOptions {
  int frustum_samples = 200;
  int cap_samples = 40;
  double middle_begin = 0.25, middle_end = 0.75;
  /// Bisection stops when the bracket is below this × the local radius.
  double offset_tolerance = 1e-10;
};

/// Statistics of δ/τ over a set of points.
struct DeviationStats {
  double extreme = 0;  ///< the δ/τ of largest magnitude, with its sign
  double rms = 0;      ///< √(mean of (δ/τ)²)
  int points = 0;
  /// Points where f < iso all the way in to the skeleton: the surface
  /// does not reach there (counted as δ/τ = −1 in extreme and rms).
  int missing = 0;
};

struct ScalisDeviation {
  DeviationStats middle, ends;
};

/// δ/τ statistics for `segment` (any position; the measurement uses its
/// a(), b(), tau0(), tau1() and value()). Throws EvaluationError if f
/// cannot be evaluated at a probe point.
ScalisDeviation measure_scalis_deviation(const ScalisSegment& segment, const DeviationOptions& options = {});

/// One row of the table in docs/canal.md.
struct ScalisDeviationCase {
  std::string name;  ///< e.g. "cylinder τ = 0.1"
  double tau0, tau1;  ///< radii, with |AB| = 1
  ScalisKernel kernel;
};

/// The cases of docs/canal.md's table: every family, a few degrees and σ,
/// on a thin and a thick cylinder, two growing radii and a cone.
std::vector<ScalisDeviationCase> scalis_deviation_cases();

}  // namespace skelconv::canal
