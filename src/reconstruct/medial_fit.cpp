// Implementation of skelconv/reconstruct/medial_fit.hpp.
#include "skelconv/reconstruct/medial_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <fmt/format.h>

#include "skelconv/field/support_box.hpp"
#include "skelconv/reconstruct/medial_derivatives.hpp"

namespace skelconv::reconstruct {
namespace {

/// The sphere of `mesh` whose surface is nearest to p.
std::size_t nearest_sphere(const MedialMesh& mesh, const Vec3& p) {
  std::size_t best = 0;
  double best_gap = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < mesh.spheres.size(); ++i) {
    const Vec4& s = mesh.spheres[i];
    const double gap = std::abs((p - s.head<3>()).norm() - s.w());
    if (gap < best_gap) best_gap = gap, best = i;
  }
  return best;
}

/// The skeleton's fit to the points: each point's signed first-order
/// distance δ and slope |∇f|, and the weighted RMS of δ.
struct Evaluation {
  Skeleton skeleton;
  std::vector<double> delta, slope;
  std::vector<bool> clamped;  ///< δ held at ± the radius: no first-order information
  double rms = 0.0;
};

Evaluation evaluate(const MedialMesh& mesh, const std::vector<WeightedPoint>& points, const MedialField& field_of) {
  Evaluation e;
  e.skeleton = field_of(mesh);
  e.delta.resize(points.size());
  e.slope.resize(points.size());
  e.clamped.resize(points.size());
  double sum = 0.0, total = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const std::size_t i = nearest_sphere(mesh, points[k].point);
    const FieldSample s = e.skeleton.value_and_gradient(points[k].point);
    const double radius = mesh.spheres[i].w();
    e.slope[k] = s.gradient.norm();
    // Far from the surface the first-order distance means little, and it
    // is infinite where ∇f vanishes (outside every compact support): it is
    // clamped to the radius of the sphere whose surface is nearest, with
    // the sign of f − iso.
    const double excess = s.value - e.skeleton.iso();
    const double d = e.slope[k] > 0.0 ? excess / e.slope[k] : std::copysign(radius, excess);
    e.delta[k] = std::isfinite(d) ? std::clamp(d, -radius, radius) : std::copysign(radius, excess);
    e.clamped[k] = !(std::abs(d) < radius);
    sum += points[k].weight * e.delta[k] * e.delta[k], total += points[k].weight;
  }
  e.rms = total > 0.0 ? std::sqrt(sum / total) : 0.0;
  return e;
}

/// Unknowns per sphere: its centre (x, y, z) and its radius.
constexpr std::size_t per_sphere = 4;

/// The Jacobian of the points' distances δ_k in the spheres' centres and
/// radii, sparse: ∂δ_k/∂θ = (∂f/∂θ) / |∇f|, summed over the primitives whose
/// support holds the point (medial_derivatives.hpp), each derivative put on
/// the spheres the primitive was made of (field_of's order: edges,
/// triangles, isolated spheres; a triangle's radius is the mean of its
/// spheres'). Points whose δ is clamped (outside every support, or farther
/// than a radius) have no row: the first-order distance says nothing there.
/// Without `centres`, the centres' columns stay empty.
struct Jacobian {
  std::vector<std::vector<std::pair<std::size_t, double>>> rows;  ///< per point: (unknown, ∂δ/∂θ)
};

Jacobian jacobian(const MedialMesh& mesh, const std::vector<WeightedPoint>& points, const Evaluation& e, bool centres) {
  const std::vector<Primitive>& primitives = e.skeleton.primitives();
  if (primitives.size() != mesh.edges.size() + mesh.triangles.size() + mesh.isolated.size())
    throw std::logic_error("fit_medial_mesh: the field's primitives are not the medial mesh's edges, triangles and "
                           "isolated spheres");
  Jacobian j;
  j.rows.resize(points.size());
  const auto add = [&](std::size_t k, std::int32_t sphere, const Vec3& centre, double radius) {
    const std::size_t column = per_sphere * std::size_t(sphere);
    if (centres)
      for (std::size_t c = 0; c < 3; ++c)
        if (centre[Eigen::Index(c)] != 0.0) j.rows[k].emplace_back(column + c, centre[Eigen::Index(c)] / e.slope[k]);
    if (radius != 0.0) j.rows[k].emplace_back(column + 3, radius / e.slope[k]);
  };
  for (std::size_t q = 0; q < primitives.size(); ++q) {
    const std::optional<SupportBox> box = support_box(primitives[q]);
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Vec3& p = points[k].point;
      if (e.clamped[k] || (box && !box->contains(p))) continue;
      if (q < mesh.edges.size()) {
        const auto& edge = mesh.edges[q];
        const PrimitiveDerivatives<2> d = derivatives(std::get<ScalisSegment>(primitives[q]), p);
        for (std::size_t v = 0; v < 2; ++v) add(k, edge[v], d.vertex[v], d.radius[v]);
      } else if (q < mesh.edges.size() + mesh.triangles.size()) {
        const auto& triangle = mesh.triangles[q - mesh.edges.size()];
        const PrimitiveDerivatives<3> d = derivatives(std::get<ScalisTriangle>(primitives[q]), p);
        for (std::size_t v = 0; v < 3; ++v) add(k, triangle[v], d.vertex[v], d.radius[0] / 3.0);
      } else {
        const std::int32_t sphere = mesh.isolated[q - mesh.edges.size() - mesh.triangles.size()];
        const PrimitiveDerivatives<1> d =
            derivatives(std::get<PointPrimitive>(primitives[q]), mesh.spheres[std::size_t(sphere)].w(), p);
        add(k, sphere, d.vertex[0], d.radius[0]);
      }
    }
  }
  return j;
}

/// The normal equations of the Levenberg–Marquardt step of all unknowns
/// together on the Huber cost Σ w ρ(δ) (ρ = δ² up to `huber`, linear
/// beyond: a point the sum of primitives cannot reach, in a crease, does not
/// drag its neighbours), as reweighted least squares: JᵀWJ and JᵀWδ with W
/// the weights times ψ(δ)/δ. They do not depend on the damping λ, so a round
/// builds them once for all its attempts.
struct NormalEquations {
  Eigen::SparseMatrix<double> normal;  ///< JᵀWJ
  Eigen::VectorXd gradient, diagonal;  ///< JᵀWδ, diag JᵀWJ
  double floor = 0.0;  ///< μ, a trace-relative floor that keeps an unknown no point sees at 0
};

NormalEquations normal_equations(const std::vector<WeightedPoint>& points, const Evaluation& e, const Jacobian& j,
                                 double huber, Eigen::Index n) {
  // J and the weighted residual as sparse matrices, JᵀWJ as their product:
  // its size is that of the unknown pairs sharing a point, never the sum over
  // points of their squared row lengths (spheres crowded about one centre,
  // as a ball's medial mesh is, would make that quadratic in the spheres).
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd weighted_delta(Eigen::Index(points.size()));
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double magnitude = std::abs(e.delta[k]);
    const double robust = magnitude > huber ? huber / magnitude : 1.0;
    const double root = std::sqrt(points[k].weight * robust);
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
/// sphere's starting ball (`start`).
std::vector<double> joint_step(const MedialMesh& mesh, const NormalEquations& equations, double lambda,
                               double min_radius, const std::vector<Vec4>& start) {
  const Eigen::Index n = Eigen::Index(per_sphere * mesh.spheres.size());
  Eigen::SparseMatrix<double> normal = equations.normal;
  for (Eigen::Index i = 0; i < n; ++i) normal.coeffRef(i, i) += lambda * (equations.diagonal[i] + equations.floor);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
  const Eigen::VectorXd solution = solver.info() == Eigen::Success
                                       ? Eigen::VectorXd(solver.solve(-equations.gradient))
                                       : Eigen::VectorXd::Zero(n);
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
  }
  return step;
}

double diagonal_of(const std::vector<WeightedPoint>& points) {
  if (points.empty()) return 0.0;
  Vec3 lo = points.front().point, hi = lo;
  for (const WeightedPoint& p : points) lo = lo.cwiseMin(p.point), hi = hi.cwiseMax(p.point);
  return (hi - lo).norm();
}

}  // namespace

MedialMesh fit_medial_mesh(MedialMesh mesh, const std::vector<WeightedPoint>& points, const MedialField& field_of,
                           const MedialFitOptions& o, MedialFitReport* report,
                           const std::function<void(std::string_view)>& progress) {
  MedialFitReport r;
  // Each centre stays within its medial ball, which is inside the input:
  // nothing in the fit pulls back a sphere that wanders out of it (the
  // input's points see only where the surface misses them, not where a
  // spike of the reconstruction sticks out into empty space).
  const std::vector<Vec4> start = mesh.spheres;
  for (Vec4& sphere : mesh.spheres) sphere.w() = std::max(sphere.w(), o.min_radius);
  Evaluation now = evaluate(mesh, points, field_of);
  r.rms.push_back(now.rms);
  if (progress) progress(fmt::format("medial fit: first-order RMS distance {:.4g} before fitting", now.rms));
  const double huber = o.huber_scale * diagonal_of(points);
  // λ starts small (nearly Gauss–Newton) and grows tenfold while a step
  // raises the RMS distance, shrinks after a step that lowers it.
  double lambda = o.initial_damping;
  for (int round = 1; round <= o.rounds; ++round) {
    const NormalEquations equations =
        normal_equations(points, now, jacobian(mesh, points, now, o.fit_centres), huber,
                         Eigen::Index(per_sphere * mesh.spheres.size()));
    bool better = false;
    for (int attempt = 0; attempt < o.damping_attempts && !better; ++attempt, lambda *= 10.0) {
      const std::vector<double> step = joint_step(mesh, equations, lambda, o.min_radius, start);
      MedialMesh trial = mesh;
      for (std::size_t i = 0; i < trial.spheres.size(); ++i)
        for (std::size_t c = 0; c < per_sphere; ++c) trial.spheres[i][Eigen::Index(c)] += step[per_sphere * i + c];
      Evaluation next = evaluate(trial, points, field_of);
      // Kept only if the RMS distance falls: the fit never ends worse than
      // it started, whatever the robust weights made of the step.
      if (next.rms < now.rms) mesh = std::move(trial), now = std::move(next), better = true;
    }
    if (!better) {
      if (progress) progress(fmt::format("medial fit, round {}: no step lowers the RMS distance; stopped", round));
      break;
    }
    lambda = std::max(lambda / 30.0, o.initial_damping);  // the loop's last ×10, then ÷3
    r.rms.push_back(now.rms);
    if (progress)
      progress(fmt::format("medial fit, round {} of {}: first-order RMS distance {:.4g}, damping {:.2g}", round,
                           o.rounds, now.rms, lambda));
  }
  if (report != nullptr) *report = r;
  return mesh;
}

}  // namespace skelconv::reconstruct
