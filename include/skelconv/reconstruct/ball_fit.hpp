// skelconv/reconstruct/ball_fit.hpp — the fallback reconstruction of a
// shape whose curve skeleton is empty or degenerate (a ball, a blob, a
// low-poly cube: pruning leaves no branch): one point primitive per
// connected component, whose iso-surface is a sphere, with centre and
// radius fitted to the surface (docs/reconstruction.md, "Shapes without
// branches").
//
// The fit minimises Σ w_k (|p_k − c| − R)² over area-weighted surface points
// (the centroids of a barycentric subdivision of every triangle, each
// weighted by its sub-triangle's area), the geometric least-squares sphere,
// by Gauss–Newton from the points' centroid: with c fixed the optimal R is the
// weighted mean of |p_k − c|, and the steps in (c, R) solve the 4 × 4
// normal equations of the linearised residuals.
#pragma once

#include <limits>
#include <vector>

#include "skelconv/mesh/triangle_mesh.hpp"
#include "skelconv/reconstruct/branch_graph.hpp"  // Vec4
#include "skelconv/reconstruct/weighted_point.hpp"
#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv::reconstruct {

/// Points spread over every triangle of `mesh`, weighted by area: each
/// triangle is cut into n² equal sub-triangles (n = ⌈longest edge / h⌉, at
/// least 1) and each sub-triangle gives its centroid with its area.
std::vector<WeightedPoint> area_weighted_points(const TriangleMesh& mesh, double h);

/// `points` merged per cell of a grid of spacing h (cells [i h, (i+1) h)
/// per axis): one point per cell that holds any, at their weighted
/// centroid with their total weight, in the order of each cell's first
/// point. The area is kept and the count bounded by about the area / h²
/// (a fine mesh gives at least one point per triangle).
/// With `on_surface`, each cell's point is instead the one of its points
/// nearest to that centroid (the first of equals): where the surface bends
/// within a cell the centroid leaves it, into the air above a crease and
/// under a ridge, and a fit to such points fills creases and flattens
/// ridges by as much.
std::vector<WeightedPoint> merged_in_cells(const std::vector<WeightedPoint>& points, double h,
                                           bool on_surface = false);

/// The indices of the points merged_in_cells(points, h, true) keeps, one
/// per cell (each cell's point nearest to its points' weighted centroid),
/// in increasing order.
std::vector<std::size_t> nearest_in_cells(const std::vector<WeightedPoint>& points, double h);

/// The area-weighted points of `mesh` at spacing h (area_weighted_points)
/// merged per cell as merged_in_cells with `on_surface`, but only the points
/// of triangles that face alike: within a cell, a point joins the first
/// group whose first triangle's normal is within `facing_angle` (radians)
/// of its own triangle's, else starts a group of its own, and each group
/// gives one point with the group's area. Merged by cell alone, the two
/// faces of a wall thinner than h (CGAL's blade: 0.65 thick, h = 2.0) give
/// one point in each cell, on either face at random with both faces'
/// weight, and the two faces of a sharp edge one point on one of them: a
/// fit to them leaves the other face where it likes. A group of less than
/// `least_area` × h² joins its cell's largest group: the sides of a part
/// thinner than a cell (a claw) face every way within the cell, and kept
/// apart they hold the fit's spheres to both sides of the part, which
/// thins it until the sum of fields lets it come apart (CGAL's dino); the
/// two faces of a sharp edge or a thin wall that cross a cell each hold
/// about h² of it. With `facing_angle` π, or with every group below
/// `least_area`, one point per cell: merged_in_cells(area_weighted_points(
/// mesh, h), h, true), the same points.
std::vector<WeightedPoint> surface_points_in_cells(const TriangleMesh& mesh, double h, double facing_angle,
                                                   double least_area = 0.0);

/// One least-squares sphere per connected component of `mesh` (triangles
/// sharing a vertex), in the order of each component's first triangle,
/// each from its area-weighted points at spacing h, starting from their
/// centroid. Where that sphere is wider than `max_radius` (a flat part:
/// Gauss–Newton drifts towards its plane, the centre far outside the
/// input), the component gets the sphere about its points' centroid at
/// their mean distance instead, and `flat` (if set) counts it.
std::vector<Vec4> fit_component_spheres(const TriangleMesh& mesh, double h,
                                        double max_radius = std::numeric_limits<double>::infinity(),
                                        std::size_t* flat = nullptr);

/// The least-squares sphere (x, y, z, radius) of `points`, starting from
/// centre `start`. At most `iterations` Gauss–Newton steps; stops when a
/// step moves the centre by less than 1e-12 × the radius. A step that
/// increases the error is halved (up to 30 times); if none decreases it,
/// the current sphere is returned.
Vec4 fit_sphere(const std::vector<WeightedPoint>& points, const Vec3& start, int iterations = 50);

/// A cheap estimate of how far the surface f = iso of `skeleton` is from
/// `points`: the weighted RMS of the first-order distance |f − iso| / |∇f|
/// (exact for a point primitive's sphere up to O(d²), an over-estimate far
/// from the surface, where it is clamped to `cap`). At most `max_points`
/// points are used, every k-th in order. It chooses between the curve
/// skeleton and a ball (reconstruct.cpp); the reported distances are the
/// meshed, two-sided ones (surface_distance.hpp).
double first_order_rms(const Skeleton& skeleton, const std::vector<WeightedPoint>& points, double cap,
                       std::size_t max_points = 4000);

}  // namespace skelconv::reconstruct
