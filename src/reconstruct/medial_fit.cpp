// Implementation of skelconv/reconstruct/medial_fit.hpp.
#include "skelconv/reconstruct/medial_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <fmt/format.h>

#include "skelconv/field/support_box.hpp"

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

/// The primitives of `mesh` that use sphere i: its edges, its triangles and
/// itself if isolated (all spheres kept, so indices stay valid).
MedialMesh incident(const MedialMesh& mesh, std::int32_t i) {
  MedialMesh local;
  local.spheres = mesh.spheres;
  for (const auto& e : mesh.edges)
    if (e[0] == i || e[1] == i) local.edges.push_back(e);
  for (const auto& t : mesh.triangles)
    if (t[0] == i || t[1] == i || t[2] == i) local.triangles.push_back(t);
  for (const std::int32_t j : mesh.isolated)
    if (j == i) local.isolated.push_back(j);
  return local;
}

/// The skeleton's fit to the points: each point's sphere (nearest
/// surface), signed first-order distance δ and slope |∇f|, and the
/// weighted RMS of δ.
struct Evaluation {
  std::vector<double> delta, slope;
  std::vector<bool> clamped;  ///< δ held at ± the radius: no first-order information
  double rms = 0.0;
};

Evaluation evaluate(const MedialMesh& mesh, const std::vector<WeightedPoint>& points, const MedialField& field_of) {
  const Skeleton skeleton = field_of(mesh);
  Evaluation e;
  e.delta.resize(points.size());
  e.slope.resize(points.size());
  e.clamped.resize(points.size());
  double sum = 0.0, total = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const std::size_t i = nearest_sphere(mesh, points[k].point);
    const FieldSample s = skeleton.value_and_gradient(points[k].point);
    const double radius = mesh.spheres[i].w();
    e.slope[k] = s.gradient.norm();
    // Far from the surface the first-order distance means little, and it
    // is infinite where ∇f vanishes (outside every compact support): it is
    // clamped to the sphere's radius, with the sign of f − iso.
    const double excess = s.value - skeleton.iso();
    const double d = e.slope[k] > 0.0 ? excess / e.slope[k] : std::copysign(radius, excess);
    e.delta[k] = std::isfinite(d) ? std::clamp(d, -radius, radius) : std::copysign(radius, excess);
    e.clamped[k] = !(std::abs(d) < radius);
    sum += points[k].weight * e.delta[k] * e.delta[k], total += points[k].weight;
  }
  e.rms = total > 0.0 ? std::sqrt(sum / total) : 0.0;
  return e;
}

/// The Jacobian of the points' distances δ_k in the radii, sparse: for
/// each point the spheres whose primitives reach it, with ∂δ_k/∂r_i =
/// (∂f/∂r_i) / |∇f| from a forward difference of the primitives that use
/// sphere i (the others do not depend on r_i). Points whose δ is clamped
/// (outside every support, or farther than a radius) have no row: the
/// first-order distance says nothing there.
/// The box holding the supports of all primitives of `skeleton`, or none
/// where one has an infinite support.
std::optional<Eigen::AlignedBox3d> support_of(const Skeleton& skeleton) {
  Eigen::AlignedBox3d all;
  for (const Primitive& primitive : skeleton.primitives()) {
    const std::optional<SupportBox> box = support_box(primitive);
    if (!box) return std::nullopt;
    all.extend(Eigen::AlignedBox3d(box->lo, box->hi));
  }
  return all;
}

struct Jacobian {
  std::vector<std::vector<std::pair<std::size_t, double>>> rows;  ///< per point: (sphere, ∂δ/∂r)
};

Jacobian jacobian(const MedialMesh& mesh, const std::vector<WeightedPoint>& points, const Evaluation& e,
                  const MedialField& field_of, const MedialFitOptions& o) {
  Jacobian j;
  j.rows.resize(points.size());
  for (std::size_t i = 0; i < mesh.spheres.size(); ++i) {
    MedialMesh local = incident(mesh, std::int32_t(i));
    if (local.edges.empty() && local.triangles.empty() && local.isolated.empty()) continue;
    const double h = o.relative_step * mesh.spheres[i].w();
    const Skeleton before = field_of(local);
    local.spheres[i].w() += h;
    const Skeleton after = field_of(local);
    const std::optional<Eigen::AlignedBox3d> reach = support_of(after);
    for (std::size_t k = 0; k < points.size(); ++k) {
      if (e.clamped[k]) continue;
      const Vec3& p = points[k].point;
      if (reach && !reach->contains(p)) continue;
      const double difference = after.value(p) - before.value(p);
      if (difference != 0.0) j.rows[k].emplace_back(i, difference / h / e.slope[k]);
    }
  }
  return j;
}

/// The Levenberg–Marquardt step of all radii together on Σ w δ²:
/// (JᵀWJ + λ (diag JᵀWJ + μ)) Δr = −JᵀWδ, μ a trace-relative floor that
/// keeps a sphere no point sees at Δr = 0; each step clamped to [−r/2, r].
std::vector<double> joint_step(const MedialMesh& mesh, const std::vector<WeightedPoint>& points, const Evaluation& e,
                               const Jacobian& j, double lambda) {
  const Eigen::Index n = Eigen::Index(mesh.spheres.size());
  // J and the weighted residual as sparse matrices, JᵀWJ as their product:
  // its size is that of the sphere pairs sharing a point, never the sum over
  // points of their squared row lengths (spheres crowded about one centre,
  // as a ball's medial mesh is, would make that quadratic in the spheres).
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd weighted_delta(Eigen::Index(points.size()));
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double root = std::sqrt(points[k].weight);
    weighted_delta[Eigen::Index(k)] = root * e.delta[k];
    for (const auto& [i, d] : j.rows[k]) entries.emplace_back(Eigen::Index(k), Eigen::Index(i), root * d);
  }
  Eigen::SparseMatrix<double> scaled(Eigen::Index(points.size()), n);  // W^½ J
  scaled.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SparseMatrix<double> transposed = scaled.transpose();
  Eigen::SparseMatrix<double> normal = transposed * scaled;
  const Eigen::VectorXd gradient = transposed * weighted_delta;
  const Eigen::VectorXd diagonal = normal.diagonal();
  const double floor = 1e-9 * std::max(diagonal.sum(), std::numeric_limits<double>::min()) / double(std::max<Eigen::Index>(n, 1));
  for (Eigen::Index i = 0; i < n; ++i) normal.coeffRef(i, i) += lambda * (diagonal[i] + floor);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
  const Eigen::VectorXd solution = solver.info() == Eigen::Success ? Eigen::VectorXd(solver.solve(-gradient))
                                                                    : Eigen::VectorXd::Zero(n);
  std::vector<double> step(mesh.spheres.size(), 0.0);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double radius = mesh.spheres[std::size_t(i)].w();
    if (std::isfinite(solution[i])) step[std::size_t(i)] = std::clamp(solution[i], -0.5 * radius, radius);
  }
  return step;
}

}  // namespace

MedialMesh fit_medial_radii(MedialMesh mesh, const std::vector<WeightedPoint>& points, const MedialField& field_of,
                            const MedialFitOptions& o, MedialFitReport* report,
                            const std::function<void(std::string_view)>& progress) {
  MedialFitReport r;
  Evaluation now = evaluate(mesh, points, field_of);
  r.rms.push_back(now.rms);
  if (progress) progress(fmt::format("medial fit: first-order RMS distance {:.4g} before fitting", now.rms));
  // λ starts small (nearly Gauss–Newton) and grows tenfold while a step
  // raises the RMS distance, shrinks after a step that lowers it.
  double lambda = o.initial_damping;
  for (int round = 1; round <= o.rounds; ++round) {
    const Jacobian j = jacobian(mesh, points, now, field_of, o);
    bool better = false;
    for (int attempt = 0; attempt < o.damping_attempts && !better; ++attempt, lambda *= 10.0) {
      const std::vector<double> step = joint_step(mesh, points, now, j, lambda);
      MedialMesh trial = mesh;
      for (std::size_t i = 0; i < step.size(); ++i) trial.spheres[i].w() += step[i];
      Evaluation next = evaluate(trial, points, field_of);
      if (next.rms < now.rms) mesh = std::move(trial), now = std::move(next), better = true;
    }
    if (!better) {
      if (progress) progress(fmt::format("medial fit, round {}: no step lowers the RMS distance; stopped", round));
      break;
    }
    lambda = std::max(lambda / 30.0, o.initial_damping);  // the loop's last ×10, then ÷3
    r.rms.push_back(now.rms);
    if (progress)
      progress(fmt::format("medial fit, round {} of {}: first-order RMS distance {:.4g}", round, o.rounds, now.rms));
  }
  if (report != nullptr) *report = r;
  return mesh;
}

}  // namespace skelconv::reconstruct
