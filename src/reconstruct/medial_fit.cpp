// Implementation of skelconv/reconstruct/medial_fit.hpp.
#include "skelconv/reconstruct/medial_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

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
  std::vector<std::vector<std::size_t>> owned;  ///< point indices per sphere
  std::vector<double> delta, slope;
  double rms = 0.0;
};

Evaluation evaluate(const MedialMesh& mesh, const std::vector<WeightedPoint>& points, const MedialField& field_of) {
  const Skeleton skeleton = field_of(mesh);
  Evaluation e;
  e.owned.resize(mesh.spheres.size());
  e.delta.resize(points.size());
  e.slope.resize(points.size());
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
    e.owned[i].push_back(k);
    sum += points[k].weight * e.delta[k] * e.delta[k], total += points[k].weight;
  }
  e.rms = total > 0.0 ? std::sqrt(sum / total) : 0.0;
  return e;
}

/// Each sphere's Gauss–Newton step on its own points (the header), clamped
/// to [−r/2, +r]; 0 where the radius barely moves the surface.
std::vector<double> newton_steps(const MedialMesh& mesh, const std::vector<WeightedPoint>& points, const Evaluation& e,
                                 const MedialField& field_of, const MedialFitOptions& o) {
  std::vector<double> step(mesh.spheres.size(), 0.0);
  for (std::size_t i = 0; i < mesh.spheres.size(); ++i) {
    if (e.owned[i].empty()) continue;
    const double radius = mesh.spheres[i].w();
    // ∂δ/∂r_i on the sphere's own points, by a forward difference of the
    // primitives that use sphere i (the others do not depend on r_i).
    MedialMesh local = incident(mesh, std::int32_t(i));
    const Skeleton before = field_of(local);
    local.spheres[i].w() *= 1.0 + o.relative_step;
    const Skeleton after = field_of(local);
    double mean_delta = 0.0, mean_slope = 0.0, weight = 0.0;
    for (const std::size_t k : e.owned[i]) {
      const Vec3& p = points[k].point;
      const double derivative = (after.value(p) - before.value(p)) / (o.relative_step * radius);
      const double w = points[k].weight;
      mean_delta += w * e.delta[k], weight += w;
      mean_slope += w * (e.slope[k] > 0.0 ? derivative / e.slope[k] : 0.0);
    }
    mean_delta /= weight, mean_slope /= weight;
    // A radius that barely moves the surface (or moves it the wrong way: a
    // primitive much wider than its triangle or segment, whose field falls
    // as its radius grows) is left alone this round.
    if (mean_slope > o.minimum_slope) step[i] = std::clamp(-mean_delta / mean_slope, -0.5 * radius, radius);
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
  for (int round = 1; round <= o.rounds; ++round) {
    const std::vector<double> step = newton_steps(mesh, points, now, field_of, o);
    // The steps ignore how the spheres share points, so a full step can
    // overshoot: halve it until the RMS distance falls; none does: done.
    bool better = false;
    for (double scale = 1.0; scale >= 1.0 / 16 && !better; scale /= 2) {
      MedialMesh trial = mesh;
      for (std::size_t i = 0; i < step.size(); ++i) trial.spheres[i].w() += scale * step[i];
      Evaluation next = evaluate(trial, points, field_of);
      if (next.rms < now.rms) mesh = std::move(trial), now = std::move(next), better = true;
    }
    if (!better) {
      if (progress) progress(fmt::format("medial fit, round {}: no step lowers the RMS distance; stopped", round));
      break;
    }
    r.rms.push_back(now.rms);
    if (progress)
      progress(fmt::format("medial fit, round {} of {}: first-order RMS distance {:.4g}", round, o.rounds, now.rms));
  }
  if (report != nullptr) *report = r;
  return mesh;
}

}  // namespace skelconv::reconstruct
