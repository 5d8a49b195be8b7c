// skelconv/reconstruct/medial_fit.hpp — the radii of a medial mesh fitted to
// the input surface (docs/reconstruction_medial.md, "The fit").
//
// The skeleton's primitives are normalised so that f = iso at distance r
// from a long segment or a wide triangle of radius r: near a sphere of the
// medial mesh the surface lies about its radius away, and a change Δr moves
// it by about Δr. Each round therefore evaluates f and the exact ∇f of the
// whole skeleton at area-weighted points of the input, takes each point's
// first-order signed distance δ = (f − iso) / |∇f| (> 0: the point is inside
// the reconstruction, which is too fat there) and gives each point to the
// sphere whose surface is nearest (|p − c| − r smallest), which bounds δ
// (clamped to that radius). Then all radii take one Levenberg–Marquardt
// step together on Σ w δ²: the Jacobian ∂δ_k/∂r_i = (∂f/∂r_i) / |∇f| from a
// forward difference of the primitives that use sphere i (the others do
// not depend on r_i), evaluated at the points inside their supports; the
// normal equations (JᵀWJ + λ diag) Δr = −JᵀWδ, sparse (a sphere couples
// only with the spheres whose primitives reach the same points), solved by
// Eigen's sparse LDLᵀ, each step clamped to [−r/2, r]. A step
// that does not lower the weighted RMS of δ is retried with λ × 10; the fit
// stops when none does (the RMS never rises). Neighbouring spheres share
// points, so a step per sphere on its own points alone overshoots and
// stalls; the joint step does not. The derivative is needed, not assumed: a
// triangle or segment much shorter than its radius has a field that
// *falls* as the radius grows (F → K(0) area / τ² for a triangle), so
// "grow where the surface is short" diverges there. The skeleton is
// rebuilt in memory each round (no files).
#pragma once

#include <functional>
#include <string_view>
#include <vector>

#include "skelconv/reconstruct/medial_mesh.hpp"
#include "skelconv/reconstruct/weighted_point.hpp"
#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv::reconstruct {

struct MedialFitOptions {
  int rounds = 8;
  /// The forward difference of ∂f/∂r_i uses r_i × (1 + this).
  double relative_step = 1e-4;
  /// The Levenberg–Marquardt damping λ of the first round (relative to the
  /// diagonal of JᵀWJ), and how many times a round may multiply it by 10
  /// before it gives up (the step then barely moves: the fit has stopped).
  double initial_damping = 1e-3;
  int damping_attempts = 6;
};

struct MedialFitReport {
  /// The weighted RMS of δ before the fit and after each round taken
  /// (absolute; decreasing).
  std::vector<double> rms;
};

/// The field of a medial mesh (the caller's choice of kernel and blend).
using MedialField = std::function<Skeleton(const MedialMesh&)>;

/// `mesh` with its radii fitted to `points` as described above. `progress`
/// (if set) gets one line per round.
MedialMesh fit_medial_radii(MedialMesh mesh, const std::vector<WeightedPoint>& points, const MedialField& field_of,
                            const MedialFitOptions& options, MedialFitReport* report,
                            const std::function<void(std::string_view)>& progress = {});

}  // namespace skelconv::reconstruct
