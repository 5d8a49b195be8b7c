// src/reconstruct/medial_step.hpp — the medial fit's damped Levenberg–Marquardt
// step, with the radius bound's active edges as constraints of the step
// (docs/reconstruction_medial.md, "The fit"). Internal: medial_fit.cpp is
// its one user.
//
// The fit keeps every ball out of its neighbour's (|r_u − r_v| ≤ slope ×
// |c_u − c_v| along every edge, limit_radius_slope) by lowering radii after
// each step. Where an edge is at the bound and the step pushes it past, the
// bound cuts the step back in proportion to it: a first-order change the
// step's linear model does not see, and damping shrinks it with the step,
// so a round can find no damping that lowers the objective (homer's Newton
// phase stopped so at its round 5: the damped step lowered the objective
// by 5.3e-9 without the bound and raised it by 4.9e-9 with it, 38 radii
// lowered). So where no damping makes a round's step descend, the fit
// tries the round again with each radius the bound lowered tied to the
// neighbour that bounded it: its change is no unknown of its own but that
// neighbour's radius change plus slope × the change of their centres'
// distance, linearised (the edge's slack stays what it was), and the
// linear model sees what the bound will do. A tie is an equality where the
// bound is an inequality (a tied radius cannot leave the bound inward in
// that round): tying on every round slowed the fit where the bound did not
// stop it (MedialFitOptions::bound_tie_passes).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Sparse>

#include "skelconv/reconstruct/medial_mesh.hpp"

namespace skelconv::detail {

/// Unknowns per sphere: its centre (x, y, z), then its radius.
constexpr std::size_t unknowns_per_sphere = 4;

/// The normal equations of the Levenberg–Marquardt step of all unknowns
/// together on Σ w ρ(δ), as reweighted least squares: JᵀWJ and JᵀWδ with W
/// the area weights times the reweighting. They do not depend on the damping
/// λ, so a round builds them once for all its attempts.
struct NormalEquations {
  Eigen::SparseMatrix<double> normal;  ///< JᵀWJ
  Eigen::VectorXd gradient, diagonal;  ///< JᵀWδ, diag JᵀWJ
  double floor = 0.0;  ///< μ, a trace-relative floor that keeps an unknown no point sees at 0
};

/// Ties the radius of each sphere the bound lowered (`bounded_by`, from
/// limit_radius_slope, after the step) to the neighbour that bounded it, in
/// `tied_to` (one entry per sphere: the sphere its radius follows, itself
/// where it is free). A sphere already tied keeps its tie, a `held` sphere
/// (one flag per sphere, or empty) is never tied, and a tie that would
/// close a loop of ties is not made. Returns how many ties it made.
std::size_t tie_lowered_radii(std::vector<std::size_t>& tied_to, const std::vector<std::size_t>& bounded_by,
                              const std::vector<std::uint8_t>& held);

/// The change of variables Δθ = Z φ that keeps the ties of `tied_to` to
/// first order about `mesh`: each tied sphere v's radius change is its
/// neighbour p's (itself expanded where p is tied in turn) plus slope ×
/// u·(Δc_v − Δc_p), u the unit vector from c_p to c_v; every other unknown
/// is its own. The columns of tied radii and of `fixed` unknowns (one flag
/// per unknown, or empty) are empty, and a fixed unknown contributes
/// nothing to a tied radius.
Eigen::SparseMatrix<double> radius_ties(const reconstruct::MedialMesh& mesh, const std::vector<std::size_t>& tied_to,
                                        double slope, const std::vector<std::uint8_t>& fixed);

/// The damped step: (JᵀWJ + λ (diag JᵀWJ + μ)) Δθ = −JᵀWδ, the `fixed`
/// unknowns (one flag per unknown, or empty) held at 0. With `ties` (Z of
/// radius_ties), solved in φ: (ZᵀJᵀWJZ + λ (diag ZᵀJᵀWJZ + μ)) φ = −ZᵀJᵀWδ,
/// Δθ = Z φ. Zero where the factorisation fails.
Eigen::VectorXd damped_solution(const NormalEquations& equations, double lambda, const std::vector<std::uint8_t>& fixed,
                                const Eigen::SparseMatrix<double>* ties = nullptr);

}  // namespace skelconv::detail
