// Implementation of src/reconstruct/medial_step.hpp.
#include "medial_step.hpp"

#include <Eigen/SparseCholesky>

namespace skelconv::detail {

std::size_t tie_lowered_radii(std::vector<std::size_t>& tied_to, const std::vector<std::size_t>& bounded_by,
                              const std::vector<std::uint8_t>& held) {
  std::size_t made = 0;
  for (std::size_t v = 0; v < tied_to.size(); ++v) {
    const std::size_t p = bounded_by[v];
    if (p == v || tied_to[v] != v || (!held.empty() && held[v] != 0)) continue;
    // Ties point from a radius to the one it follows; a loop would leave a
    // radius defined by itself.
    std::size_t root = p;
    while (tied_to[root] != root && root != v) root = tied_to[root];
    if (root == v) continue;
    tied_to[v] = p, ++made;
  }
  return made;
}

Eigen::SparseMatrix<double> radius_ties(const reconstruct::MedialMesh& mesh, const std::vector<std::size_t>& tied_to,
                                        double slope, const std::vector<std::uint8_t>& fixed) {
  const std::size_t spheres = mesh.spheres.size();
  const Eigen::Index n = Eigen::Index(unknowns_per_sphere * spheres);
  const auto is_fixed = [&fixed](std::size_t unknown) { return !fixed.empty() && fixed[unknown] != 0; };
  const auto radius_of = [](std::size_t sphere) { return unknowns_per_sphere * sphere + 3; };
  // Each tied radius's row: (free unknown, coefficient), its neighbour's
  // row expanded first (ties form a forest, tie_lowered_radii).
  std::vector<std::vector<std::pair<std::size_t, double>>> rows(spheres);
  std::vector<std::uint8_t> done(spheres, 0);
  const auto row = [&](const auto& self, std::size_t v) -> const std::vector<std::pair<std::size_t, double>>& {
    if (done[v]) return rows[v];
    done[v] = 1;
    const std::size_t p = tied_to[v];
    if (p == v) {
      if (!is_fixed(radius_of(v))) rows[v] = {{radius_of(v), 1.0}};
      return rows[v];
    }
    std::vector<std::pair<std::size_t, double>> r = self(self, p);
    const Vec3 along = mesh.spheres[v].head<3>() - mesh.spheres[p].head<3>();
    if (along.norm() > 0.0) {
      const Vec3 u = slope * along / along.norm();
      for (std::size_t c = 0; c < 3; ++c) {
        if (!is_fixed(unknowns_per_sphere * v + c)) r.emplace_back(unknowns_per_sphere * v + c, u[Eigen::Index(c)]);
        if (!is_fixed(unknowns_per_sphere * p + c)) r.emplace_back(unknowns_per_sphere * p + c, -u[Eigen::Index(c)]);
      }
    }
    rows[v] = std::move(r);
    return rows[v];
  };
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t v = 0; v < spheres; ++v) {
    for (std::size_t c = 0; c < 3; ++c) {
      const std::size_t i = unknowns_per_sphere * v + c;
      if (!is_fixed(i)) entries.emplace_back(Eigen::Index(i), Eigen::Index(i), 1.0);
    }
    for (const auto& [column, coefficient] : row(row, v))
      entries.emplace_back(Eigen::Index(radius_of(v)), Eigen::Index(column), coefficient);
  }
  Eigen::SparseMatrix<double> z(n, n);
  z.setFromTriplets(entries.begin(), entries.end());  // sums an unknown met twice along a chain
  return z;
}

Eigen::VectorXd damped_solution(const NormalEquations& equations, double lambda, const std::vector<std::uint8_t>& fixed,
                                const Eigen::SparseMatrix<double>* ties) {
  const Eigen::Index n = equations.gradient.size();
  Eigen::SparseMatrix<double> normal;
  Eigen::VectorXd gradient, diagonal;
  std::vector<std::uint8_t> out(std::size_t(n), 0);  // unknowns not solved for: held at 0, or tied
  if (ties == nullptr) {
    normal = equations.normal, gradient = equations.gradient, diagonal = equations.diagonal;
    for (Eigen::Index i = 0; i < n; ++i) out[std::size_t(i)] = !fixed.empty() && fixed[std::size_t(i)] != 0;
    normal.prune([&out](Eigen::Index row, Eigen::Index column, double) {
      return !out[std::size_t(row)] && !out[std::size_t(column)];
    });
  } else {
    const Eigen::SparseMatrix<double> transposed = ties->transpose();
    normal = transposed * equations.normal * *ties, gradient = transposed * equations.gradient;
    diagonal = normal.diagonal();
    for (Eigen::Index i = 0; i < n; ++i) out[std::size_t(i)] = ties->col(i).nonZeros() == 0;
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    if (out[std::size_t(i)])
      normal.coeffRef(i, i) = 1.0, gradient[i] = 0.0;
    else
      normal.coeffRef(i, i) += lambda * (diagonal[i] + equations.floor);
  }
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
  if (solver.info() != Eigen::Success) return Eigen::VectorXd::Zero(n);
  const Eigen::VectorXd solution = solver.solve(-gradient);
  return ties == nullptr ? solution : Eigen::VectorXd(*ties * solution);
}

}  // namespace skelconv::detail
