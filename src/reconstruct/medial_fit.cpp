// Implementation of skelconv/reconstruct/medial_fit.hpp.
#include "skelconv/reconstruct/medial_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <fmt/format.h>

#include "skelconv/field/support_box.hpp"
#include "skelconv/reconstruct/medial_derivatives.hpp"
#include "skelconv/reconstruct/medial_parts.hpp"
#include "skelconv/reconstruct/medial_slope.hpp"
#include "../detail/parallel_for.hpp"
#include "medial_step.hpp"

namespace skelconv::reconstruct {
namespace {

/// The sphere of `mesh` whose surface is nearest to p, among those of part
/// `part` when the mesh has parts (any, when that part has none).
std::size_t nearest_sphere(const MedialMesh& mesh, const Vec3& p, std::int32_t part) {
  const bool of_part = !mesh.parts.empty() && std::find(mesh.parts.begin(), mesh.parts.end(), part) != mesh.parts.end();
  std::size_t best = 0;
  double best_gap = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < mesh.spheres.size(); ++i) {
    if (of_part && mesh.parts[i] != part) continue;
    const Vec4& s = mesh.spheres[i];
    const double gap = std::abs((p - s.head<3>()).norm() - s.w());
    if (gap < best_gap) best_gap = gap, best = i;
  }
  return best;
}

/// The fit's points: the surface points first, then the inside points;
/// with the part of the input each lies on or in (all 0 for an input of
/// one part).
struct FitPoints {
  std::vector<WeightedPoint> all;
  std::vector<std::int32_t> parts;
  std::size_t surface = 0;
  bool on_surface(std::size_t k) const { return k < surface; }
};

/// The skeleton's fit to the points: each point's residual δ: for a surface
/// point its signed distance to the surface f = iso (> 0: the point is
/// inside, the reconstruction is too fat there), for an inside point the
/// same distance where it is negative (the point is outside the
/// reconstruction: a cavity has opened there) and 0 where it is inside;
/// where its last Newton step started (`foot`, where its Jacobian row is
/// taken) and the slope there; the weighted RMS of the surface points' δ
/// and its largest magnitude; `objective`, the weighted RMS of every
/// point's δ (the inside points' weighs the cavities in).
struct Evaluation {
  /// Per part of the input, its primitives (medial_mesh_part; the whole
  /// mesh for an input of one part) and their sum of fields. A point is
  /// measured against its own part's sum alone, distance and Jacobian row:
  /// the union of the parts' sums is that sum wherever the parts' surfaces
  /// stay apart. (Measuring a point inside another part's surface against
  /// that part instead, to draw it back, fused more parts on CGAL's bones,
  /// 9 → 4 components against 9 → 5, docs/reconstruction_medial.md.)
  std::vector<MedialMesh> part_meshes;
  std::vector<Skeleton> skeletons;
  std::vector<double> delta, slope;
  std::vector<Vec3> foot;
  /// No row: outside every support (f = 0, no first-order information), or
  /// an inside point inside the reconstruction. (Bytes, not std::vector<bool>:
  /// the points are evaluated on every core, each writing its own.)
  std::vector<std::uint8_t> no_row;
  double rms = 0.0;
  double objective = 0.0;
  double largest = 0.0;
  int newton_steps = 0;  ///< the Newton steps each distance took
};

/// One Newton step's length toward f = iso from a point where the field is
/// `s`: (f − iso) / √(|∇f|² + ((f − iso)/R)²). The bare first-order
/// distance (f − iso)/|∇f| grows without bound where ∇f is small (deep
/// inside, where the fields of close sheets add up) and is infinite where
/// it vanishes; the second term keeps the step within R, the radius of the
/// sphere whose surface is nearest, and keeps it a smooth function of f, so
/// that a point farther than R still has a row and the fit sees it come
/// closer. Near the surface it is the first-order distance.
double newton_step(const FieldSample& s, double iso, double radius, double* slope) {
  const double excess = s.value - iso;
  *slope = std::hypot(s.gradient.norm(), excess / radius);
  return excess / *slope;
}

Evaluation evaluate(const MedialMesh& mesh, const FitPoints& fit_points, const MedialField& field_of,
                    int newton_steps) {
  const std::vector<WeightedPoint>& points = fit_points.all;
  Evaluation e;
  e.newton_steps = newton_steps;
  if (mesh.parts.empty()) {
    e.part_meshes = {mesh};
  } else {
    // Every point's part, also one that no sphere lies deepest in (a thin
    // part beside a thick one, whose spheres the thick part's took).
    std::size_t parts = part_count(mesh);
    for (const std::int32_t part : fit_points.parts) parts = std::max(parts, std::size_t(part) + 1);
    for (std::size_t p = 0; p < parts; ++p) e.part_meshes.push_back(medial_mesh_part(mesh, std::int32_t(p)));
  }
  // A part left with no primitive (no sphere lies deepest in it, or all its
  // spheres merged away) has the empty sum, f = 0: nothing the fit moves
  // reaches its points, which have no row and are left out of the
  // objective (the result's measurement sees the part missing).
  double iso = 1.0;
  for (const MedialMesh& part : e.part_meshes) {
    const bool empty =
        !mesh.parts.empty() && part.edges.empty() && part.triangles.empty() && part.isolated.empty();
    e.skeletons.push_back(empty ? Skeleton() : field_of(part));
    if (!empty) iso = e.skeletons.back().iso();
  }
  e.delta.resize(points.size());
  e.slope.resize(points.size());
  e.foot.resize(points.size());
  e.no_row.resize(points.size());
  // Each point's distance on every core (each writes only its own slots),
  // then the sums in the points' order.
  skelconv::detail::parallel_for(points.size(), [&](std::size_t k) {
    const std::int32_t part = fit_points.parts[k];
    const Skeleton& skeleton = e.skeletons[std::size_t(part)];
    e.foot[k] = points[k].point;
    if (skeleton.primitives().empty()) {
      e.no_row[k] = true, e.delta[k] = 0.0, e.slope[k] = 0.0;
      return;
    }
    FieldSample s = skeleton.value_and_gradient(points[k].point);
    const double radius = mesh.spheres[nearest_sphere(mesh, points[k].point, part)].w();
    e.no_row[k] = !(s.value != 0.0) || !std::isfinite(s.value) || !s.gradient.allFinite();
    if (e.no_row[k]) {
      e.delta[k] = -radius, e.slope[k] = iso / radius;
    } else {
      // Newton's steps along the gradient: the first-order distance falls
      // short where the field saturates (deep inside a crease the blend
      // filled, the points that make the Hausdorff distance).
      double step = newton_step(s, iso, radius, &e.slope[k]);
      e.delta[k] = step;
      for (int n = 0; n < newton_steps && s.gradient.norm() > 0.0; ++n) {
        const Vec3 next = e.foot[k] - step * s.gradient.normalized();
        const FieldSample t = skeleton.value_and_gradient(next);
        if (!(t.value != 0.0) || !std::isfinite(t.value) || !t.gradient.allFinite()) break;
        double slope = 0.0;
        step = newton_step(t, iso, radius, &slope);
        e.delta[k] += step, e.foot[k] = next, e.slope[k] = slope, s = t;
      }
    }
  });
  double sum = 0.0, total = 0.0, inside_sum = 0.0, inside_total = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (e.skeletons[std::size_t(fit_points.parts[k])].primitives().empty()) continue;
    if (!fit_points.on_surface(k)) {
      if (e.delta[k] >= 0.0) e.delta[k] = 0.0, e.no_row[k] = true;
      inside_sum += points[k].weight * e.delta[k] * e.delta[k], inside_total += points[k].weight;
      continue;
    }
    sum += points[k].weight * e.delta[k] * e.delta[k], total += points[k].weight;
    e.largest = std::max(e.largest, std::abs(e.delta[k]));
  }
  e.rms = total > 0.0 ? std::sqrt(sum / total) : 0.0;
  e.objective = total + inside_total > 0.0 ? std::sqrt((sum + inside_sum) / (total + inside_total)) : 0.0;
  return e;
}

/// Unknowns per sphere: its centre (x, y, z) and its radius.
constexpr std::size_t per_sphere = skelconv::detail::unknowns_per_sphere;

/// The Jacobian of the points' distances δ_k in the spheres' centres and
/// radii, sparse: ∂δ_k/∂θ = (∂f/∂θ) / |∇f|, summed over the primitives whose
/// support holds the point (medial_derivatives.hpp), each derivative put on
/// the spheres the primitive was made of (field_of's order: edges,
/// triangles, isolated spheres; a triangle's radius is a mean of its
/// spheres' by `rule`: triangle_radius), at the
/// point's foot (where its last Newton step started: to first order the
/// distance to the surface changes as f does there). Points
/// outside every support have no row. Without `centres`, the centres'
/// columns stay empty.
struct Jacobian {
  std::vector<std::vector<std::pair<std::size_t, double>>> rows;  ///< per point: (unknown, ∂δ/∂θ)
};

Jacobian jacobian(const FitPoints& fit_points, const Evaluation& e, bool centres, const TriangleRadiusRule& rule) {
  const std::vector<WeightedPoint>& points = fit_points.all;
  // Per part: its primitives' support boxes.
  std::vector<std::vector<std::optional<SupportBox>>> boxes(e.part_meshes.size());
  for (std::size_t part = 0; part < e.part_meshes.size(); ++part) {
    const MedialMesh& mesh = e.part_meshes[part];
    const std::vector<Primitive>& primitives = e.skeletons[part].primitives();
    if (primitives.size() != mesh.edges.size() + mesh.triangles.size() + mesh.isolated.size())
      throw std::logic_error("fit_medial_mesh: the field's primitives are not the medial mesh's edges, triangles and "
                             "isolated spheres");
    for (const Primitive& primitive : primitives) boxes[part].push_back(support_box(primitive));
  }
  Jacobian j;
  j.rows.resize(points.size());
  const auto add = [&](std::size_t k, std::int32_t sphere, const Vec3& centre, double radius) {
    const std::size_t column = per_sphere * std::size_t(sphere);
    if (centres)
      for (std::size_t c = 0; c < 3; ++c)
        if (centre[Eigen::Index(c)] != 0.0) j.rows[k].emplace_back(column + c, centre[Eigen::Index(c)] / e.slope[k]);
    if (radius != 0.0) j.rows[k].emplace_back(column + 3, radius / e.slope[k]);
  };
  // Point by point on every core, each row's entries in the primitives'
  // order (those of the point's own part).
  skelconv::detail::parallel_for(points.size(), [&](std::size_t k) {
    const Vec3& p = e.foot[k];
    if (e.no_row[k]) return;
    const std::size_t part = std::size_t(fit_points.parts[k]);
    const MedialMesh& mesh = e.part_meshes[part];
    const std::vector<Primitive>& primitives = e.skeletons[part].primitives();
    for (std::size_t q = 0; q < primitives.size(); ++q) {
      if (boxes[part][q] && !boxes[part][q]->contains(p)) continue;
      if (q < mesh.edges.size()) {
        const auto& edge = mesh.edges[q];
        const PrimitiveDerivatives<2> d = derivatives(std::get<ScalisSegment>(primitives[q]), p);
        for (std::size_t v = 0; v < 2; ++v) add(k, edge[v], d.vertex[v], d.radius[v]);
      } else if (q < mesh.edges.size() + mesh.triangles.size()) {
        const auto& triangle = mesh.triangles[q - mesh.edges.size()];
        const PrimitiveDerivatives<3> d = derivatives(std::get<ScalisTriangle>(primitives[q]), p);
        // Its one radius τ is a mean of its spheres' (triangle_radius):
        // ∂τ/∂r_v = thirds[v] / 3.
        const std::array<double, 3> thirds =
            triangle_radius(mesh.spheres[std::size_t(triangle[0])].w(), mesh.spheres[std::size_t(triangle[1])].w(),
                            mesh.spheres[std::size_t(triangle[2])].w(), rule)
                .thirds;
        for (std::size_t v = 0; v < 3; ++v) add(k, triangle[v], d.vertex[v], d.radius[0] / 3.0 * thirds[v]);
      } else {
        const std::int32_t sphere = mesh.isolated[q - mesh.edges.size() - mesh.triangles.size()];
        const PrimitiveDerivatives<1> d =
            derivatives(std::get<PointPrimitive>(primitives[q]), mesh.spheres[std::size_t(sphere)].w(), p);
        add(k, sphere, d.vertex[0], d.radius[0]);
      }
    }
  });
  return j;
}

/// How much a point's δ counts in a round, on top of its area weight: the
/// round minimises Σ w ρ(δ) as reweighted least squares, W = w ψ(δ)/δ.
using Reweighting = std::function<double(double delta)>;

/// Huber's loss: quadratic up to `huber`, linear beyond, so that a point the
/// sum of primitives cannot reach (in a crease) does not drag its
/// neighbours.
Reweighting huber_weights(double huber) {
  return [huber](double delta) { return std::abs(delta) > huber ? huber / std::abs(delta) : 1.0; };
}

/// The L^p loss |δ|^p, p > 2: the larger a point's distance, the more it
/// counts, so the worst points, which make the Hausdorff distance, lead.
/// `scale` (the current L^p norm) only keeps the weights near 1.
Reweighting power_weights(double exponent, double scale) {
  return [exponent, scale](double delta) { return std::pow(std::abs(delta) / scale, exponent - 2.0); };
}

using skelconv::detail::NormalEquations;

/// The normal equations of the Levenberg–Marquardt step (medial_step.hpp),
/// W the area weights times `reweighting`.
NormalEquations normal_equations(const std::vector<WeightedPoint>& points, const Evaluation& e, const Jacobian& j,
                                 const Reweighting& reweighting, Eigen::Index n) {
  // J and the weighted residual as sparse matrices, JᵀWJ as their product:
  // its size is that of the unknown pairs sharing a point, never the sum over
  // points of their squared row lengths (spheres crowded about one centre,
  // as a ball's medial mesh is, would make that quadratic in the spheres).
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd weighted_delta(Eigen::Index(points.size()));
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double root = std::sqrt(points[k].weight * reweighting(e.delta[k]));
    weighted_delta[Eigen::Index(k)] = root * e.delta[k];
    for (const auto& [i, d] : j.rows[k]) entries.emplace_back(Eigen::Index(k), Eigen::Index(i), root * d);
  }
  Eigen::SparseMatrix<double> scaled(Eigen::Index(points.size()), n);  // W^½ J
  scaled.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SparseMatrix<double> transposed = scaled.transpose();
  NormalEquations equations;
  equations.normal = transposed * scaled;
  equations.gradient = transposed * weighted_delta;
  equations.diagonal = equations.normal.diagonal();
  equations.floor = 1e-9 * std::max(equations.diagonal.sum(), std::numeric_limits<double>::min()) /
                    double(std::max<Eigen::Index>(n, 1));
  return equations;
}

/// The step: (JᵀWJ + λ (diag JᵀWJ + μ)) Δθ = −JᵀWδ. Each radius step is
/// clamped to [−r/2, r] (radii stay positive) and to end at min_radius or
/// above, each centre step to a length of r/2 and to end within the
/// sphere's starting ball (`start`). The spheres `held` (one flag per
/// sphere, or empty) do not move: their unknowns are taken out of the
/// equations, so the others' step is the best one with them fixed. With
/// `tied_to` (one entry per sphere, medial_step.hpp), each tied radius
/// follows the radius it is tied to along their edge at the radius bound.
std::vector<double> joint_step(const MedialMesh& mesh, const NormalEquations& equations, double lambda,
                               double min_radius, const std::vector<Vec4>& start,
                               const std::vector<std::uint8_t>& held, double max_radius_slope,
                               const std::vector<std::size_t>* tied_to = nullptr) {
  const Eigen::Index n = Eigen::Index(per_sphere * mesh.spheres.size());
  const auto fixed = [&held](Eigen::Index unknown) {
    return !held.empty() && held[std::size_t(unknown) / per_sphere] != 0;
  };
  std::vector<std::uint8_t> fixed_unknowns;
  if (!held.empty())
    for (Eigen::Index i = 0; i < n; ++i) fixed_unknowns.push_back(fixed(i) ? 1 : 0);
  std::optional<Eigen::SparseMatrix<double>> ties;
  if (tied_to != nullptr) ties = skelconv::detail::radius_ties(mesh, *tied_to, max_radius_slope, fixed_unknowns);
  const Eigen::VectorXd solution =
      skelconv::detail::damped_solution(equations, lambda, fixed_unknowns, ties ? &*ties : nullptr);
  std::vector<double> step(std::size_t(n), 0.0);
  for (std::size_t i = 0; i < mesh.spheres.size(); ++i) {
    const double radius = mesh.spheres[i].w();
    const Eigen::Index at = Eigen::Index(per_sphere * i);
    Vec3 move = solution.segment<3>(at);
    if (!move.allFinite()) move.setZero();
    if (move.norm() > 0.5 * radius) move *= 0.5 * radius / move.norm();
    const Vec3 from_start = mesh.spheres[i].head<3>() + move - start[i].head<3>();
    if (from_start.norm() > start[i].w()) move -= from_start * (1.0 - start[i].w() / from_start.norm());
    for (std::size_t c = 0; c < 3; ++c) step[per_sphere * i + c] = move[Eigen::Index(c)];
    if (std::isfinite(solution[at + 3]))
      step[per_sphere * i + 3] = std::clamp(solution[at + 3], std::max(-0.5 * radius, min_radius - radius), radius);
    if (fixed(at))
      for (std::size_t c = 0; c < per_sphere; ++c) step[per_sphere * i + c] = 0.0;
  }
  return step;
}

double diagonal_of(const std::vector<WeightedPoint>& points) {
  if (points.empty()) return 0.0;
  Vec3 lo = points.front().point, hi = lo;
  for (const WeightedPoint& p : points) lo = lo.cwiseMin(p.point), hi = hi.cwiseMax(p.point);
  return (hi - lo).norm();
}

/// The weighted L^p mean of δ, (Σ w |δ|^p / Σ w)^(1/p).
double power_mean(const std::vector<WeightedPoint>& points, const Evaluation& e, double exponent) {
  double sum = 0.0, total = 0.0, largest = 0.0;
  for (const double d : e.delta) largest = std::max(largest, std::abs(d));
  if (!(largest > 0.0)) return 0.0;
  for (std::size_t k = 0; k < points.size(); ++k)
    sum += points[k].weight * std::pow(std::abs(e.delta[k]) / largest, exponent), total += points[k].weight;
  return total > 0.0 ? largest * std::pow(sum / total, 1.0 / exponent) : 0.0;
}

/// One stage of Levenberg–Marquardt rounds: each round reweights the points
/// (`weights` of the current evaluation) and keeps a step only if it lowers
/// `objective` without raising the RMS distance above `rms_limit`, so the
/// stage never ends worse than it started, whatever the weights made of the
/// step. It stops after `rounds`, when no step is kept, or when it has
/// stalled (fit_stalled).
struct Rounds {
  std::string name;  ///< in the progress lines
  int rounds = 0;
  std::function<Reweighting(const Evaluation&)> weights;
  std::function<double(const Evaluation&)> objective;
  double rms_limit = std::numeric_limits<double>::infinity();
  /// The Newton steps each point's distance takes in this stage.
  int newton_steps = 0;
  /// MedialFitOptions::stall_fall and stall_rounds (0: no stall rule).
  double stall_fall = 0.0;
  int stall_rounds = 1;
};

/// A step must also leave the topology error (`error`, when set) at most
/// `allowed`, and at most `checks_left` steps are tested; the stage stops
/// when none is left. The spheres `held` (one flag per sphere, or none) do
/// not move; localize_step finds them within `localize_left` meshings.
struct Guard {
  TopologyError error;
  long long allowed = 0;
  int checks_left = 0;
  int localize_left = 0;
  std::size_t hold_group = 1;
  std::vector<std::uint8_t> held;
  /// After each of the next `watched` rounds taken, the whole mesh is
  /// tested (`watch`) and the run stops where it is farther than `allowed`
  /// (`reopened`): a repair whose defect opens again shows it within a
  /// round or two, not after the rest of the fit. `watched_error` is the
  /// last test's, of the mesh after round `watched_round` (history's index).
  TopologyError watch;
  int watched = 0;
  bool reopened = false;
  long long watched_error = 0;
  std::optional<std::size_t> watched_round;
};

/// `mesh` with `step` taken by the spheres `moved` (one flag per sphere)
/// and the radius bound applied (limit_radius_slope; `bounded_by` as there).
MedialMesh stepped(const MedialMesh& mesh, const std::vector<double>& step, const std::vector<std::uint8_t>& moved,
                   double max_radius_slope, const Clearance& clearance,
                   std::vector<std::size_t>* bounded_by = nullptr) {
  MedialMesh trial = mesh;
  for (std::size_t i = 0; i < trial.spheres.size(); ++i)
    if (moved[i])
      for (std::size_t c = 0; c < per_sphere; ++c) trial.spheres[i][Eigen::Index(c)] += step[per_sphere * i + c];
  limit_radius_slope(trial, max_radius_slope, clearance, bounded_by);
  return trial;
}

/// A step the guard refused, taken in part: the spheres it moves, split in
/// two by the median of their centres along the axis where they spread
/// widest, each half tried on top of what passed so far, a failing half
/// split again, down to groups of guard.hold_group spheres, which are held
/// (guard.held). A topology defect opens between a few neighbouring spheres,
/// so one defect costs one or two meshings per halving. Where the first
/// half passes, the second fails without a test (together they are the step
/// that failed). Returns the step taken by the spheres that passed (the
/// last mesh tested that passed), or nothing where none did (then nothing
/// more is held). Within
/// guard.localize_left meshings: the spheres not tried by then stay where
/// they are for this step.
std::optional<MedialMesh> localize_step(const MedialMesh& mesh, const std::vector<double>& step, Guard& guard,
                                        double max_radius_slope, const Clearance& clearance) {
  std::vector<std::uint8_t> accepted(mesh.spheres.size(), 0);
  std::optional<MedialMesh> passing;
  const auto visit = [&](const auto& self, std::vector<std::size_t> group, bool fails) -> void {
    if (group.empty()) return;
    if (!fails) {
      if (guard.localize_left <= 0) return;
      --guard.localize_left;
      std::vector<std::uint8_t> moved = accepted;
      for (const std::size_t i : group) moved[i] = 1;
      MedialMesh trial = stepped(mesh, step, moved, max_radius_slope, clearance);
      if (guard.error(trial) <= guard.allowed) {
        accepted = std::move(moved), passing = std::move(trial);
        return;
      }
    }
    if (group.size() <= guard.hold_group) {
      for (const std::size_t i : group) guard.held[i] = 1;
      return;
    }
    Vec3 lo = mesh.spheres[group.front()].head<3>(), hi = lo;
    for (const std::size_t i : group)
      lo = lo.cwiseMin(mesh.spheres[i].head<3>()), hi = hi.cwiseMax(mesh.spheres[i].head<3>());
    Eigen::Index axis = 0;
    (hi - lo).maxCoeff(&axis);
    const auto half = group.begin() + std::ptrdiff_t(group.size() / 2);
    // Ties by index: the same split on every machine.
    std::nth_element(group.begin(), half, group.end(), [&](std::size_t a, std::size_t b) {
      const double ca = mesh.spheres[a][axis], cb = mesh.spheres[b][axis];
      return ca < cb || (ca == cb && a < b);
    });
    const std::vector<std::size_t> first(group.begin(), half), second(half, group.end());
    const std::size_t before = std::size_t(std::count(accepted.begin(), accepted.end(), 1));
    self(self, first, false);
    const bool first_passed = std::size_t(std::count(accepted.begin(), accepted.end(), 1)) == before + first.size();
    self(self, second, first_passed);
  };
  std::vector<std::size_t> moving;
  for (std::size_t i = 0; i < mesh.spheres.size(); ++i) {
    bool moves = false;
    for (std::size_t c = 0; c < per_sphere; ++c) moves = moves || step[per_sphere * i + c] != 0.0;
    if (moves && !guard.held[i]) moving.push_back(i);
  }
  const std::vector<std::uint8_t> held_before = guard.held;
  visit(visit, moving, true);
  // Where no part of the step passed, nothing is held: the step is refused
  // as before, and a smaller one (more damping) may pass whole.
  if (!passing) guard.held = held_before;
  return passing;
}

/// The meshings localize_step needs to reach one group of guard.hold_group
/// from the spheres not yet held (one a halving), at least 1. With fewer
/// left, a search holds nothing more and takes at most a part of the step
/// (CGAL's femur and homer: second searches of 5 and 4 meshings among 241
/// and 460 spheres held no sphere more, and their repairs failed).
int descent_meshings(const Guard& guard) {
  const std::size_t free = std::size_t(std::count(guard.held.begin(), guard.held.end(), 0));
  int halvings = 0;
  for (std::size_t group = free; group > guard.hold_group; group = (group + 1) / 2) ++halvings;
  return std::max(halvings, 1);
}

/// Runs `stage` from `now` (and `mesh`, which it describes); the objective
/// before (unless `values` holds it already) and after each round taken
/// goes to `values`, the spheres after each round taken to `history`. λ
/// carries over from one stage to the next (unless the caller resets it).
void run_rounds(MedialMesh& mesh, Evaluation& now, double& lambda, const FitPoints& points,
                const MedialField& field_of, const MedialFitOptions& o, const std::vector<Vec4>& start,
                const Rounds& stage, std::vector<double>& values, std::vector<std::vector<Vec4>>& history,
                Guard& guard, const Clearance& clearance, const std::function<void(std::string_view)>& progress) {
  double value = stage.objective(now);
  if (values.empty()) values.push_back(value);
  for (int round = 1; round <= stage.rounds; ++round) {
    const NormalEquations equations =
        normal_equations(points.all, now, jacobian(points, now, o.fit_centres, o.triangle_radius),
                         stage.weights(now), Eigen::Index(per_sphere * mesh.spheres.size()));
    // One attempt after another, λ × 10 each, until a step lowers the
    // objective (and keeps the topology, under a guard). With `tie`, the
    // radii the bound lowered after a step are each tied to the neighbour
    // that bounded it and the step solved again (medial_step.hpp), at most
    // bound_tie_passes times an attempt; the ties carry over to the round's
    // more damped attempts.
    bool better = false, spent = false;
    std::size_t ties = 0;
    const std::vector<std::uint8_t> every(mesh.spheres.size(), 1);
    const auto attempts = [&](bool tie) {
      std::vector<std::size_t> tied_to(mesh.spheres.size());
      for (std::size_t i = 0; i < tied_to.size(); ++i) tied_to[i] = i;
      for (int attempt = 0; attempt < o.damping_attempts && !better; ++attempt, lambda *= 10.0) {
        std::vector<double> step;
        MedialMesh trial;
        for (int pass = 0;; ++pass) {
          bool tied = false;
          for (std::size_t i = 0; i < tied_to.size() && !tied; ++i) tied = tied_to[i] != i;
          step = joint_step(mesh, equations, lambda, o.min_radius, start, guard.held, o.max_radius_slope,
                            tied ? &tied_to : nullptr);
          // Which neighbour bounded each radius is read only to tie it.
          std::vector<std::size_t> bounded_by;
          trial = stepped(mesh, step, every, o.max_radius_slope, clearance, tie ? &bounded_by : nullptr);
          if (!tie || pass >= o.bound_tie_passes) break;
          const std::size_t made = skelconv::detail::tie_lowered_radii(tied_to, bounded_by, guard.held);
          if (made == 0) break;
          ties += made;
        }
        Evaluation next = evaluate(trial, points, field_of, stage.newton_steps);
        const double next_value = stage.objective(next);
        if (next_value < value && next.rms <= stage.rms_limit) {
          if (guard.error) {
            if (guard.checks_left-- <= 0) {
              spent = true;
              return;
            }
            if (guard.error(trial) > guard.allowed) continue;
          }
          value = next_value, better = true;
          mesh = std::move(trial), now = std::move(next);
        }
      }
    };
    // The step as solved, the bound applied after it, first; where no
    // damping makes it descend, the bound may be what turns it uphill, and
    // the round is tried again, from the same damping, with the ties. Not
    // where each step is tested for its topology: the retry's steps spend
    // the guard's meshings (CGAL's camel, --repair: its tested resume ran
    // on to a result of one component, 3.23%, where stopping left two and
    // the medial path ran again with its thin protrusion joined, 1.35%).
    const double round_damping = lambda;
    attempts(false);
    if (!better && !spent && o.bound_tie_passes > 0 && !guard.error) {
      lambda = round_damping;
      attempts(true);
    }
    if (spent) {
      if (progress) progress(fmt::format("medial fit, {}, round {}: topology tests spent; stopped", stage.name, round));
      return;
    }
    if (!better) {
      if (progress) progress(fmt::format("medial fit, {}, round {}: no step lowers it; stopped", stage.name, round));
      break;
    }
    lambda = std::max(lambda / 30.0, o.initial_damping);  // the loop's last ×10, then ÷3
    values.push_back(value);
    history.push_back(mesh.spheres);
    if (progress)
      progress(fmt::format("medial fit, {}, round {} of {}: {:.4g} (RMS distance {:.4g}, largest {:.4g}), "
                           "damping {:.2g}{}",
                           stage.name, round, stage.rounds, value, now.rms, now.largest, lambda,
                           ties > 0 ? fmt::format(", {} radii tied at the radius bound", ties) : std::string()));
    if (guard.watched > 0) {
      --guard.watched;
      guard.watched_error = guard.watch(mesh), guard.watched_round = history.size() - 1;
      if (guard.watched_error > guard.allowed) {
        guard.reopened = true;
        if (progress)
          progress(fmt::format("medial fit, {}, round {}: the topology farther from the input's again; stopped",
                               stage.name, round));
        return;
      }
    }
    if (fit_stalled(values, stage.stall_fall, stage.stall_rounds)) {
      if (progress)
        progress(fmt::format("medial fit, {}: fell by less than {:g}% a round over {} rounds; stopped", stage.name,
                             100.0 * stage.stall_fall, stage.stall_rounds));
      break;
    }
  }
}

/// A stage of the fit planned: its rounds, where its objective goes and its
/// cap.
struct Planned {
  Rounds stage;
  std::vector<double>* values;
  int cap;
};

/// A fit under way: the mesh and its evaluation, the damping, the spheres
/// after each round taken (`history[0]`: before the fit), the stages, and
/// how to run them on from stage `from`, `kept` rounds of it kept.
struct FitInProgress {
  MedialMesh& mesh;
  Evaluation& now;
  double& lambda;
  std::vector<std::vector<Vec4>>& history;
  std::vector<Planned>& plan;
  const FitPoints& points;
  const MedialField& field_of;
  std::function<void(std::size_t from, int kept, Guard& guard)> run_stages;
};

/// Where the fit ended farther from the input's topology than it started
/// (`topology_error`), brings it back: by holding the spheres that took it
/// there and fitting the rest again, or else by going back to the last
/// round that kept it and testing each step from there. Apart from
/// fit_medial_mesh because it is a policy of its own over the rounds the
/// fit recorded, with its own budget of meshings.
void undo_topology_loss(FitInProgress& fit, const TopologyError& topology_error, const MedialFitOptions& o,
                        const Clearance& clearance, MedialFitReport& r,
                        const std::function<void(std::string_view)>& progress) {
  // The points see distances, not topology: a round may pinch a neck, fuse
  // two parts that nearly touch or open a hole through a thin sheet. Where
  // the fitted spheres end farther from the input's topology than the
  // unfitted ones, the fit finds the first round that did, by bisection
  // over the rounds (a topology lost stays lost in the rounds after,
  // mostly; each test meshes the skeleton once). That round's step is
  // taken without the spheres whose move takes the topology farther
  // (localize_step), which are held where they are, and the fit runs on
  // from there, its steps untested; its end is tested again, and so on,
  // within localize_checks meshings for the spheres and repairs times.
  // Where no part of the step passes, or the repairs are spent, the fit
  // goes back to the last round that passed and resumes from there with
  // every step tested (a step that goes farther is refused as one that
  // raises the objective is), within topology_checks tests.
  if (!topology_error || fit.history.size() <= 1) return;
  MedialMesh& mesh = fit.mesh;
  Evaluation& now = fit.now;
  double& lambda = fit.lambda;
  std::vector<std::vector<Vec4>>& history = fit.history;
  std::vector<Planned>& plan = fit.plan;
  const FitPoints& points = fit.points;
  const MedialField& field_of = fit.field_of;
  const auto& run_stages = fit.run_stages;
  const auto at_round = [&](std::size_t k) {
    MedialMesh m = mesh;
    m.spheres = history[k];
    return m;
  };
  long long final_error = topology_error(mesh);
  long long allowed = final_error;
  std::size_t kept = 0;  // a round whose error is `allowed`
  if (final_error > 0) {
    allowed = topology_error(at_round(0));
    // The unfitted spheres may be as far from it or farther (tubes
    // thinner than the mesh come back in pieces before the fit thickens
    // them), while the rounds between kept it better: the middle round
    // is tested too.
    const std::size_t middle = (history.size() - 1) / 2;
    if (allowed >= final_error && middle > 0) {
      const long long error = topology_error(at_round(middle));
      if (error < final_error) allowed = error, kept = middle;
    }
  }
  Guard guard;
  guard.error = topology_error, guard.allowed = allowed, guard.checks_left = o.topology_checks;
  guard.localize_left = o.localize_checks, guard.hold_group = std::size_t(std::max(o.hold_group, 1));
  guard.held.assign(mesh.spheres.size(), 0);
  // Goes back to round `kept`: the stage it belongs to and the rounds of
  // it kept (the end of a stage is the start of the next one taken); its
  // values and the later stages' go back to there, and so does the
  // history.
  const auto back_to = [&](std::size_t round, std::size_t& stage, std::size_t& in_stage) {
    mesh = at_round(round);
    history.resize(round + 1);
    stage = 0, in_stage = round;
    while (stage + 1 < plan.size() && !plan[stage + 1].values->empty()) {
      const std::size_t taken = plan[stage].values->empty() ? 0 : plan[stage].values->size() - 1;
      if (in_stage < taken) break;
      in_stage -= taken, ++stage;
    }
    if (!plan[stage].values->empty()) plan[stage].values->resize(in_stage + 1);
    for (std::size_t i = stage + 1; i < plan.size(); ++i) plan[i].values->clear();
    now = evaluate(mesh, points, field_of, plan[stage].stage.newton_steps);
  };
  // The last round of history (after `good`, which passes) that passes,
  // by bisection (a topology lost stays lost in the rounds after, mostly;
  // one meshing a test); `lost` is the first that does not.
  const auto last_passing = [&](std::size_t good, std::size_t& lost) {
    lost = history.size() - 1;
    while (lost - good > 1) {
      const std::size_t middle = (good + lost) / 2;
      (topology_error(at_round(middle)) <= allowed ? good : lost) = middle;
    }
    return good;
  };
  // Where the repairs fail, the fit goes back, nothing held, and tests
  // each step from there: to the last round of the repairs that passed
  // (`good`, of the history as the repairs left it) where its surface
  // points are closer than at the round the first bisection left it
  // (first_kept), else to that round, as if no repair had been tried.
  // Both are within `allowed`, so neither is farther from the input's
  // topology than the unfitted spheres. Going back to first_kept alone
  // threw away every round the repair fitted (CGAL's homer with its
  // vertices shuffled: the repair's rounds reached an RMS distance of
  // 0.0008 and its end lost the topology; the fit went back to its
  // unfitted spheres, 0.0094, and its tested steps were spent by 0.0076).
  std::optional<std::size_t> first_kept;
  std::size_t first_lost = 0, first_last = 0;
  std::vector<std::vector<Vec4>> first_history;
  std::vector<std::vector<double>> first_values;
  const auto fall_back = [&](std::optional<std::size_t> good, std::size_t good_lost) {
    // The candidates' distances measured alike: with the Newton steps of
    // the fit's last stage, whatever stage each round belongs to.
    const int steps = plan.back().stage.newton_steps;
    double first_rms = 0.0, good_rms = 0.0;
    if (good) {
      MedialMesh first = mesh;
      first.spheres = first_history[*first_kept];
      first_rms = evaluate(first, points, field_of, steps).rms;
      good_rms = evaluate(at_round(*good), points, field_of, steps).rms;
    }
    // Ties to the earlier round: the same choice on every machine.
    const bool repaired = good && good_rms < first_rms;
    const std::size_t good_last = history.size() - 1;
    if (repaired) {
      kept = *good;
    } else {
      kept = *first_kept, history = std::move(first_history);
      for (std::size_t i = 0; i < plan.size(); ++i) *plan[i].values = std::move(first_values[i]);
    }
    guard.held.clear();
    guard.localize_left = 0;
    r.rounds_kept = kept;
    if (good) r.back_to_repair = repaired;
    std::size_t stage = 0, in_stage = 0;
    back_to(kept, stage, in_stage);
    lambda = o.initial_damping;
    if (progress) {
      if (repaired)
        progress(fmt::format("medial fit: the repair's round {} of {} takes the topology farther from the input's "
                             "than round {}; resumed after round {} (RMS distance {:.4g}, closer than round {} "
                             "before the repair, {:.4g}) with each step tested",
                             good_lost, good_last, kept, kept, good_rms, *first_kept, first_rms));
      else
        progress(fmt::format("medial fit: round {} of {} takes the topology farther from the input's than round "
                             "{}; resumed after round {} (RMS distance {:.4g}{}) with each step tested",
                             first_lost, first_last, kept, kept, now.rms,
                             good ? fmt::format("; the repair's last round that kept it, round {}, no closer: "
                                                "{:.4g} against {:.4g}",
                                                *good, good_rms, first_rms)
                                  : std::string()));
    }
    run_stages(stage, int(in_stage), guard);
  };
  // The last round of the current repair known to pass (its partial step,
  // then its watched rounds), while its end does not.
  std::optional<std::size_t> repair_passed;
  for (int repair = 0; final_error > allowed; ++repair) {
    if (first_kept && (repair >= o.topology_repairs || guard.localize_left < descent_meshings(guard))) {
      // The last repair's end is farther: its last round that passes.
      std::size_t good_lost = 0;
      const std::size_t good = last_passing(*repair_passed, good_lost);
      fall_back(good, good_lost);
      break;
    }
    const std::size_t last = history.size() - 1;
    std::size_t lost = last;
    kept = last_passing(kept, lost);
    if (!first_kept) {
      first_kept = kept, first_lost = lost, first_last = last, first_history = history;
      for (const Planned& p : plan) first_values.push_back(*p.values);
    }
    // The step from round `kept` to round `lost`, without the spheres
    // that take the topology farther.
    std::vector<double> step(per_sphere * mesh.spheres.size(), 0.0);
    for (std::size_t i = 0; i < mesh.spheres.size(); ++i)
      for (std::size_t c = 0; c < per_sphere; ++c)
        step[per_sphere * i + c] = history[lost][i][Eigen::Index(c)] - history[kept][i][Eigen::Index(c)];
    const std::size_t held_before = std::size_t(std::count(guard.held.begin(), guard.held.end(), 1));
    const int meshings = guard.localize_left;
    std::optional<MedialMesh> part;
    if (repair < o.topology_repairs)
      part = localize_step(at_round(kept), step, guard, o.max_radius_slope, clearance);
    if (!part) {
      // After a repair, `kept` is its last round that passes.
      fall_back(repair > 0 ? std::optional<std::size_t>(kept) : std::nullopt, lost);
      break;
    }
    std::size_t stage = 0, in_stage = 0;
    lambda = o.initial_damping;
    r.rounds_kept = kept;
    back_to(kept, stage, in_stage);
    // Round `kept` again, taken this far: its objective is the partial
    // step's.
    mesh = std::move(*part);
    history.back() = mesh.spheres;
    now = evaluate(mesh, points, field_of, plan[stage].stage.newton_steps);
    if (!plan[stage].values->empty()) plan[stage].values->back() = plan[stage].stage.objective(now);
    const std::size_t held = std::size_t(std::count(guard.held.begin(), guard.held.end(), 1));
    if (progress)
      progress(fmt::format("medial fit: round {} takes the topology farther from the input's than round {}; "
                           "{} spheres held ({} more, {} meshings), the rest of its step taken (RMS distance "
                           "{:.4g}), the fit resumed untested",
                           lost, kept, held, held - held_before, meshings - guard.localize_left, now.rms));
    Guard holding;
    holding.held = guard.held;
    holding.watch = topology_error, holding.allowed = allowed, holding.watched = o.repair_watch_rounds;
    run_stages(stage, int(in_stage), holding);
    // Where the topology is lost again within the repair's first rounds,
    // holding did not keep it: another search from that round fails the
    // same way on the real shapes (CGAL's femur: the same round again, the
    // 5 meshings left holding no sphere more), so the fit goes back.
    // Its partial step (round `kept`) passed.
    if (holding.reopened) {
      fall_back(kept, *holding.watched_round);
      break;
    }
    repair_passed = holding.watched_round ? *holding.watched_round : kept;
    final_error = holding.watched_round == history.size() - 1 ? holding.watched_error : topology_error(mesh);
  }
}

}  // namespace

bool fit_stalled(const std::vector<double>& values, double stall_fall, int stall_rounds) {
  if (!(stall_fall > 0.0) || stall_rounds < 1 || values.size() <= std::size_t(stall_rounds)) return false;
  const double before = values[values.size() - 1 - std::size_t(stall_rounds)];
  return values.back() > std::pow(1.0 - stall_fall, stall_rounds) * before;
}

MedialMesh fit_start(MedialMesh mesh, const MedialFitOptions& o, const Clearance& clearance) {
  for (Vec4& sphere : mesh.spheres) sphere.w() = std::max(sphere.w(), o.min_radius);
  limit_radius_slope(mesh, o.max_radius_slope, clearance);
  return mesh;
}

MedialMesh fit_medial_mesh(MedialMesh mesh, const std::vector<WeightedPoint>& surface_points,
                           const std::vector<Vec3>& inside_points, const MedialField& field_of,
                           const MedialFitOptions& o, MedialFitReport* report,
                           const std::function<void(std::string_view)>& progress, const TopologyError& topology_error,
                           const Clearance& clearance,
                           const std::vector<std::int32_t>& point_parts) {
  MedialFitReport r;
  FitPoints points;
  points.all = surface_points;
  points.surface = surface_points.size();
  // An inside point weighs as much as an average surface point.
  double area = 0.0;
  for (const WeightedPoint& p : surface_points) area += p.weight;
  const double inside_weight = surface_points.empty() ? 1.0 : area / double(surface_points.size());
  for (const Vec3& p : inside_points) points.all.push_back({p, inside_weight});
  if (mesh.parts.empty()) {
    points.parts.assign(points.all.size(), 0);
  } else {
    if (point_parts.size() != points.all.size())
      throw std::logic_error("fit_medial_mesh: a medial mesh of several parts needs the part of every point");
    points.parts = point_parts;
  }
  // Each centre stays within its medial ball, which is inside the input:
  // nothing in the fit pulls back a sphere that wanders out of it (the
  // input's points see only where the surface misses them, not where a
  // spike of the reconstruction sticks out into empty space).
  const std::vector<Vec4> start = mesh.spheres;
  mesh = fit_start(std::move(mesh), o, clearance);
  // The stages in order (the first stage's rounds: its first-order start's
  // and its Newton phase's together).
  std::vector<Planned> plan;
  const double huber = o.huber_scale * diagonal_of(surface_points);
  Rounds least_squares;
  least_squares.name = "RMS distance (Huber)";
  least_squares.weights = [huber](const Evaluation&) { return huber_weights(huber); };
  least_squares.objective = [](const Evaluation& e) { return e.objective; };
  least_squares.stall_fall = o.stall_fall, least_squares.stall_rounds = o.stall_rounds;
  if (o.first_order_start && o.newton_steps > 0) {
    // First-order distances while the reconstruction is far off, then the
    // Newton steps from where that stalled (MedialFitOptions::first_order_start).
    Rounds first_order = least_squares;
    first_order.name = "RMS distance (Huber), first-order";
    first_order.newton_steps = 0;
    first_order.stall_fall = o.first_order_stall_fall;
    plan.push_back({first_order, &r.first_order, std::min(o.first_order_rounds, o.rounds)});
  }
  least_squares.newton_steps = o.newton_steps;
  plan.push_back({least_squares, &r.rms, o.rounds});
  const std::size_t first_stage = plan.size();  // the first stage's phases come before
  // Then the worst points: the least squares leave a few places (a crease
  // the blend fills, a rim it rounds) far off while the RMS is low, and
  // those make the Hausdorff distance.
  const double p = o.worst_exponent;
  Rounds worst;
  worst.name = fmt::format("L{} mean", p);
  worst.weights = [&points, p](const Evaluation& e) {
    return power_weights(p, std::max(power_mean(points.all, e, p), std::numeric_limits<double>::min()));
  };
  worst.objective = [&points, p](const Evaluation& e) { return power_mean(points.all, e, p); };
  // The worst points are where the field saturates (a crease the blend
  // filled), where the first-order distance falls short most: the second
  // stage measures them with more Newton steps.
  worst.newton_steps = std::max(o.newton_steps, o.worst_newton_steps);
  plan.push_back({worst, &r.worst, o.worst_rounds});

  Evaluation now = evaluate(mesh, points, field_of, plan.front().stage.newton_steps);
  if (progress)
    progress(fmt::format("medial fit: RMS distance {:.4g}, largest {:.4g} before fitting ({} points on the surface, "
                         "{} inside)",
                         now.rms, now.largest, points.surface, inside_points.size()));
  // λ starts small (nearly Gauss–Newton) and grows tenfold while a step
  // raises the objective, shrinks after a step that lowers it.
  double lambda = o.initial_damping;
  const auto evaluate_for = [&](const Rounds& stage) {
    if (now.newton_steps != stage.newton_steps) now = evaluate(mesh, points, field_of, stage.newton_steps);
  };
  std::vector<std::vector<Vec4>> history{mesh.spheres};  // before the fit, then after each round taken
  double first_stage_rms = 0.0;
  // Runs the stages from stage `from` on, the rounds of stage `from` it
  // kept (`kept`) counted against its cap: a first-stage phase records its
  // objective before any round even with no round left (the report's first
  // value); the second stage is skipped without rounds, and its RMS limit
  // is where the first stage ended (when resumed within the second stage:
  // where it ended before).
  const auto run_stages = [&](std::size_t from, int kept, Guard& guard) {
    for (std::size_t i = from; i < plan.size(); ++i) {
      Planned& step = plan[i];
      const bool first = i < first_stage;
      int left = step.cap - (i == from ? kept : 0);
      if (first && i > 0) left -= int(plan[0].values->size()) - 1;  // the first-order start's rounds
      if (!first && left <= 0) continue;
      step.stage.rounds = std::max(left, 0);
      evaluate_for(step.stage);
      // The Newton phase measures other distances than the first-order
      // start whose λ climbed while it stalled
      // (MedialFitOptions::newton_phase_fresh_damping).
      if (o.newton_phase_fresh_damping && first && i > 0 && i > from) lambda = o.initial_damping;
      if (!first) step.stage.rms_limit = (1.0 + o.worst_rms_growth) * first_stage_rms;
      run_rounds(mesh, now, lambda, points, field_of, o, start, step.stage, *step.values, history, guard, clearance,
                 progress);
      if (guard.reopened) return;
      if (i + 1 == first_stage && o.worst_rounds > 0) {
        // The second stage's RMS limit is on its own distances.
        evaluate_for(plan.back().stage);
        first_stage_rms = now.rms;
      }
    }
  };
  Guard unguarded;
  run_stages(0, 0, unguarded);
  // The points see distances, not topology: where the fit ended farther
  // from the input's, undo_topology_loss holds the spheres that took it
  // there or goes back and tests each step.
  FitInProgress fit{mesh, now, lambda, history, plan, points, field_of, run_stages};
  undo_topology_loss(fit, topology_error, o, clearance, r, progress);
  if (report != nullptr) *report = r;
  return mesh;
}

}  // namespace skelconv::reconstruct
