// Implementation of thickness_fit.hpp.
#include "thickness_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "skelconv/errors.hpp"
#include "skelconv/kernels/kernel_list.hpp"
#include "skelconv/primitives/segment.hpp"

namespace skelconv::detail {
namespace {

/// Levenberg–Marquardt damping: start, growth on a rejected step, floor.
constexpr double damping_start = 1e-4, damping_growth = 10.0, damping_floor = 1e-12;
/// Damping increases tried per iteration before the fit declares a local
/// minimum (a factor 10¹² over the current damping).
constexpr int damping_attempts = 12;

double relative_departure(const ThicknessSample& s) { return (s.thickness - s.target) / s.target; }

double fit_cost(const std::vector<ThicknessSample>& samples, const Eigen::VectorXd& x, double lambda) {
  double sum = 0;
  for (const ThicknessSample& s : samples) {
    if (s.target > 0) sum += relative_departure(s) * relative_departure(s);
  }
  return sum + lambda * x.squaredNorm();
}

/// ∂e_j/∂x_k with e_j = (r_j − t_j)/t_j (file comment of the header); a row
/// stays 0 where the field does not decrease outwards (no direction there)
/// or where the target is 0.
Eigen::MatrixXd departure_jacobian(const LinearThicknessModel& model, const std::vector<ThicknessSample>& samples,
                                   const Skeleton& field, const Vec3& normal) {
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(Eigen::Index(samples.size()), Eigen::Index(model.basis.size()));
  for (std::size_t j = 0; j < samples.size(); ++j) {
    if (!(samples[j].target > 0)) continue;
    const Vec3 q = samples[j].foot + samples[j].thickness * normal;
    const double slope = normal.dot(field.gradient(q));
    if (!(slope < 0)) continue;
    for (std::size_t k = 0; k < model.basis.size(); ++k) {
      jacobian(Eigen::Index(j), Eigen::Index(k)) = -model.basis[k].value(q) / (slope * samples[j].target);
    }
  }
  return jacobian;
}

/// One Levenberg–Marquardt iteration: damps the Gauss–Newton step until the
/// projected step lowers fit_cost; false when no damping does.
bool improve(const LinearThicknessModel& model, ThicknessFitResult& out, const ThicknessFitSettings& s,
             double& damping) {
  const Eigen::MatrixXd jac = departure_jacobian(model, out.after, model.build(out.x), s.normal);
  Eigen::VectorXd residual = Eigen::VectorXd::Zero(jac.rows());
  for (Eigen::Index j = 0; j < jac.rows(); ++j) {
    if (out.after[std::size_t(j)].target > 0) residual(j) = relative_departure(out.after[std::size_t(j)]);
  }
  Eigen::MatrixXd normal_matrix = jac.transpose() * jac;
  normal_matrix.diagonal().array() += s.regularisation;
  const Eigen::VectorXd gradient = jac.transpose() * residual + s.regularisation * out.x;
  const double cost = fit_cost(out.after, out.x, s.regularisation);
  // Active set: an unknown on its bound whose descent direction points out
  // of the bounds takes no step; the others solve the reduced system (a
  // projected full step would let one bound stall every unknown).
  std::vector<Eigen::Index> active;
  for (Eigen::Index k = 0; k < out.x.size(); ++k) {
    if (!(out.x(k) <= model.lower[std::size_t(k)] && gradient(k) > 0)) active.push_back(k);
  }
  const auto n = Eigen::Index(active.size());
  Eigen::MatrixXd reduced(n, n);
  Eigen::VectorXd reduced_gradient(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    reduced_gradient(i) = gradient(active[std::size_t(i)]);
    for (Eigen::Index j = 0; j < n; ++j) reduced(i, j) = normal_matrix(active[std::size_t(i)], active[std::size_t(j)]);
  }
  for (int attempt = 0; attempt < damping_attempts; ++attempt) {
    Eigen::MatrixXd damped = reduced;
    damped.diagonal() += damping * reduced.diagonal();
    const Eigen::VectorXd step = damped.ldlt().solve(-reduced_gradient);
    Eigen::VectorXd x = out.x;
    for (Eigen::Index i = 0; i < n; ++i) x(active[std::size_t(i)]) += step(i);
    for (Eigen::Index k = 0; k < x.size(); ++k) x(k) = std::max(x(k), model.lower[std::size_t(k)]);
    std::vector<ThicknessSample> trial = out.after;
    measure_thickness(trial, model.build(x), s);
    if (fit_cost(trial, x, s.regularisation) < cost) {
      out.x = std::move(x), out.after = std::move(trial);
      damping = std::max(damping / damping_growth, damping_floor);
      return true;
    }
    damping *= damping_growth;
  }
  return false;
}

/// Points farther than this fraction of the skeleton's size from the plane
/// through the first non-collinear nodes make the graph non-planar.
constexpr double planarity_ratio = 1e-9;

}  // namespace

void require_fit_options(int ramp_nodes, double samples_per_thickness, double regularisation,
                         double point_support_ratio) {
  if (ramp_nodes < 1 || ramp_nodes > 100) {
    throw InputError(fmt::format("must be in [1, 100], got {}", ramp_nodes), "ramp_nodes");
  }
  if (!(samples_per_thickness >= 1 && samples_per_thickness <= 100)) {
    throw InputError("must be in [1, 100]", "samples_per_thickness");
  }
  if (!(regularisation >= 0 && regularisation < std::numeric_limits<double>::infinity()))
    throw InputError(fmt::format("must be a finite number >= 0, got {}", regularisation), "regularisation");
  if (!(point_support_ratio >= 1 && point_support_ratio <= 4)) {
    throw InputError(fmt::format("must be in [1, 4], got {:.6g}", point_support_ratio), "point_support_ratio");
  }
}

std::size_t node_of(std::vector<Vec3>& nodes, const Vec3& p, double merge) {
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    if ((nodes[k] - p).norm() <= merge) return k;
  }
  nodes.push_back(p);
  return nodes.size() - 1;
}

/// The unit normal of the plane holding every node (any unit vector normal
/// to the line for a collinear graph). InputError if there is none.
Vec3 plane_normal(const std::vector<Vec3>& nodes, const std::vector<SegmentGraph::Edge>& edges, double size) {
  const Vec3 o = nodes[0];
  const Vec3 d = (nodes[edges[0].b] - nodes[edges[0].a]).normalized();
  Vec3 normal = Vec3::Zero();
  for (const Vec3& p : nodes) {
    const Vec3 c = d.cross(p - o);
    if (c.norm() > planarity_ratio * size) {
      normal = c.normalized();
      break;
    }
  }
  if (normal.isZero()) {  // collinear: the axis least aligned with the line gives a normal
    Eigen::Index axis = 0;
    d.cwiseAbs().minCoeff(&axis);
    normal = d.cross(Vec3::Unit(axis)).normalized();
  }
  for (const SegmentGraph::Edge& e : edges) {
    for (std::size_t n : {e.a, e.b}) {
      if (std::abs(normal.dot(nodes[n] - o)) > planarity_ratio * size) {
        throw InputError("the segments are not in one plane: the correction measures the thickness along the "
                         "plane's normal",
                         e.location);
      }
    }
  }
  return normal;
}

void require_correction_family(KernelFamily family, const std::string& where) {
  if (kernels::family_facts(family).thickness_correction) return;
  std::string families;
  for (KernelFamily other : all_kernel_families) {
    if (!kernels::family_facts(other).thickness_correction) continue;
    families += fmt::format("{}\"{}\"", families.empty() ? "" : " or ", family_name(other));
  }
  throw InputError(fmt::format("the thickness correction needs the {} kernel (its finite support keeps the correction "
                               "local), got \"{}\"",
                               families, family_name(family)),
                   where + ".kernel.family");
}

double long_segment_weight(const KernelSpec& kernel, double iso, double tau) {
  const Segment line(Vec3(-kernel.R, 0, 0), Vec3(kernel.R, 0, 0), kernel, {1.0});
  return iso / line.value(Vec3(0, tau, 0));
}

void measure_thickness(std::vector<ThicknessSample>& samples, const Skeleton& field, const ThicknessFitSettings& s) {
  for (ThicknessSample& x : samples) x.thickness = thickness_along(field, x.foot, s.normal, s.iso, s.reach);
}

double worst_departure(const std::vector<ThicknessSample>& samples) {
  double worst = 0;
  for (const ThicknessSample& s : samples) {
    if (s.target > 0) worst = std::max(worst, std::abs(relative_departure(s)));
  }
  return worst;
}

ThicknessFitResult fit_thickness(const LinearThicknessModel& model, const Eigen::VectorXd& x0,
                                 std::vector<ThicknessSample> samples, const ThicknessFitSettings& settings) {
  ThicknessFitResult out;
  out.x = x0;
  out.after = std::move(samples);
  measure_thickness(out.after, model.build(out.x), settings);
  double damping = damping_start;
  if (settings.progress) settings.progress(0, worst_departure(out.after));
  while (!model.basis.empty() && worst_departure(out.after) > settings.tolerance &&
         out.iterations < settings.max_iterations) {
    ++out.iterations;
    const bool improved = improve(model, out, settings, damping);
    if (settings.progress) settings.progress(out.iterations, worst_departure(out.after));
    if (!improved) break;
  }
  out.converged = worst_departure(out.after) <= settings.tolerance;
  return out;
}

}  // namespace skelconv::detail
