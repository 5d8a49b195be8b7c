// skelconv/reconstruct/medial_fit.hpp — the radii of a medial mesh fitted to
// the input surface (docs/reconstruction_medial.md, "Fit").
//
// The skeleton's primitives are normalised so that f = iso at distance r
// from a long segment or a wide triangle of radius r: near a sphere of the
// medial mesh the surface lies about its radius away, and a change Δr moves
// it by about Δr. Each round therefore evaluates f and the exact ∇f of the
// whole skeleton at area-weighted points of the input, takes each point's
// first-order signed distance δ = (f − iso) / |∇f| (> 0: the point is inside
// the reconstruction, which is too fat there) and gives each point to the
// sphere whose surface is nearest (|p − c| − r smallest). Then every radius
// takes a damped Gauss–Newton step on its own points' Σ w δ², with
// ∂δ/∂r_i = (∂f/∂r_i) / |∇f| from a forward difference of the primitives
// that use sphere i, clamped to [r/2, 2r]: a Jacobi iteration with the
// diagonal of the Jacobian. The steps ignore how neighbouring spheres share
// points, so all of them together can overshoot: the round takes the steps
// × 1, 1/2, … 1/16, the first that lowers the weighted RMS of δ, and the fit
// stops when none does (the RMS never rises). The derivative is needed, not assumed: a
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
  /// A sphere whose radius moves its points' surface by less than this per
  /// unit of radius (∂δ/∂r_i) is left alone that round.
  double minimum_slope = 0.05;
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
