// skelconv/canal/uniform_spline.hpp — the interpolating curve through points
// P_0 … P_n of a vector space at the uniform parameters t_k = k/n, as the
// canal-surfaces paper's Algorithm 1 (§3, step 4) needs it in the hyperplane:
//
//   n = 1 (two points)    the segment, linear in t;
//   n = 2 (three points)  the unique quadratic through them;
//   n ≥ 3                 the C² cubic spline with "not-a-knot" end
//                         conditions: the third derivative is continuous at
//                         t_1 and t_{n−1}, so the first two and the last two
//                         pieces are one cubic each. For n = 3 this is the
//                         unique cubic through the four points, so the
//                         sequence linear, quadratic, cubic, spline has no
//                         jump in kind; and the spline reproduces every cubic
//                         polynomial exactly (natural end conditions, M = 0,
//                         would not, and lose an order of accuracy at the ends).
//
// All three are stored the same way: the points and the second derivatives
// M_k at the knots (M ≡ 0 for the segment, M ≡ the constant second
// derivative for the quadratic). On [t_k, t_{k+1}], with h = 1/n and
// s = (t − t_k)/h,
//     X(t) = (1 − s) P_k + s P_{k+1} + h²/6 [((1 − s)³ − (1 − s)) M_k + (s³ − s) M_{k+1}],
// which returns P_k and P_{k+1} exactly (to the last bit) at s = 0 and 1.
// Not-a-knot on uniform knots gives M_1 = Δ²P_1/h² and M_{n−1} = Δ²P_{n−1}/h²
// directly, M_0 = 2M_1 − M_2 and M_n = 2M_{n−1} − M_{n−2}, and the interior
// equations M_{k−1} + 4M_k + M_{k+1} = 6 Δ²P_k/h² (k = 2 … n−2) form a
// diagonally dominant tridiagonal system, solved by the Thomas algorithm.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/Core>

namespace skelconv::canal {

template <class Point>
class UniformSpline {
 public:
  using Scalar = typename Point::Scalar;

  /// At least two points. Throws std::invalid_argument otherwise.
  explicit UniformSpline(std::vector<Point> points) : points_(std::move(points)) {
    if (points_.size() < 2) throw std::invalid_argument("UniformSpline needs at least two points");
    second_derivatives_.assign(points_.size(), zero());
    const std::size_t n = points_.size() - 1;
    if (n == 2) {
      second_derivatives_.assign(3, second_difference(1) * Scalar(n * n));
    } else if (n >= 3) {
      solve_not_a_knot();
    }
  }

  /// Number of pieces n (points − 1).
  std::size_t pieces() const { return points_.size() - 1; }
  const std::vector<Point>& points() const { return points_; }

  /// X(t) for t in [0, 1] (clamped outside: the end pieces are extended).
  Point value(Scalar t) const {
    const Local local = locate(t);
    const Scalar u = Scalar(1) - local.s, s = local.s, h2 = local.h * local.h / Scalar(6);
    return u * points_[local.k] + s * points_[local.k + 1] +
           h2 * ((u * u * u - u) * second_derivatives_[local.k] + (s * s * s - s) * second_derivatives_[local.k + 1]);
  }

  /// X′(t), derivative with respect to t.
  Point derivative(Scalar t) const {
    const Local local = locate(t);
    const Scalar u = Scalar(1) - local.s, s = local.s, h = local.h;
    return (points_[local.k + 1] - points_[local.k]) / h +
           (h / Scalar(6)) * ((Scalar(1) - Scalar(3) * u * u) * second_derivatives_[local.k] +
                              (Scalar(3) * s * s - Scalar(1)) * second_derivatives_[local.k + 1]);
  }

  /// X″(t) (linear on each piece, continuous at the knots).
  Point second_derivative(Scalar t) const {
    const Local local = locate(t);
    return (Scalar(1) - local.s) * second_derivatives_[local.k] + local.s * second_derivatives_[local.k + 1];
  }

 private:
  struct Local {
    std::size_t k;  ///< piece index
    Scalar s;       ///< position in the piece, 0 … 1 (beyond when extrapolating)
    Scalar h;       ///< piece length 1/n
  };

  Local locate(Scalar t) const {
    using std::floor;
    const std::size_t n = pieces();
    const Scalar scaled = t * Scalar(n);
    const Scalar clamped = std::clamp(floor(scaled), Scalar(0), Scalar(n - 1));
    const std::size_t k = std::size_t(clamped);
    return {k, scaled - Scalar(k), Scalar(1) / Scalar(n)};
  }

  Point zero() const { return Point::Zero(points_.front().rows()); }

  /// Δ²P_k = P_{k+1} − 2 P_k + P_{k−1}.
  Point second_difference(std::size_t k) const { return points_[k + 1] - Scalar(2) * points_[k] + points_[k - 1]; }

  void solve_not_a_knot() {
    const std::size_t n = pieces();
    const Scalar inverse_h2 = Scalar(n * n);
    std::vector<Point>& m = second_derivatives_;
    m[1] = second_difference(1) * inverse_h2;
    m[n - 1] = second_difference(n - 1) * inverse_h2;
    // Interior unknowns m[2] … m[n−2]: m[k−1] + 4 m[k] + m[k+1] = 6 Δ²P_k/h².
    if (n >= 4) {
      const std::size_t first = 2, last = n - 2;
      std::vector<Scalar> diagonal(n, Scalar(4));
      std::vector<Point> rhs(n, zero());
      for (std::size_t k = first; k <= last; ++k) rhs[k] = Scalar(6) * inverse_h2 * second_difference(k);
      rhs[first] -= m[1];
      rhs[last] -= m[n - 1];
      for (std::size_t k = first + 1; k <= last; ++k) {  // forward elimination (sub- and super-diagonal 1)
        const Scalar factor = Scalar(1) / diagonal[k - 1];
        diagonal[k] -= factor;
        rhs[k] -= factor * rhs[k - 1];
      }
      m[last] = rhs[last] / diagonal[last];
      for (std::size_t k = last; k-- > first;) m[k] = (rhs[k] - m[k + 1]) / diagonal[k];
    }
    m[0] = Scalar(2) * m[1] - m[2];
    m[n] = Scalar(2) * m[n - 1] - m[n - 2];
  }

  std::vector<Point> points_;
  std::vector<Point> second_derivatives_;
};

}  // namespace skelconv::canal
