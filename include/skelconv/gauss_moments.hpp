// skelconv/gauss_moments.hpp — segment moments by a fixed Gauss–Legendre rule,
// where the recurrences cancel and the rule is exact (to rounding).
//
// Generated segment kernels need M_{k,m} = ∫_{t0}^{t1} t^k q(t)^(−m/2) dt with
// q = a t² − 2 b t + c (SPEC §2). Two places where recurrence (1) and the
// moment relations lose digits are better served by an N-point
// Gauss–Legendre rule, whose positive weights and positive integrand leave
// nothing to cancel:
//
//  * compact kernels of even degree i: t^k q^(i/2) is a polynomial of degree
//    ≤ i + k, integrated exactly by N points when 2N − 1 ≥ i + k (the
//    generator takes the smallest of Boost's tabulated N = 7, 10, 15);
//  * inverse and Cauchy kernels with P far from the segment's line compared
//    with its length (D ≥ 2 a², i.e. the complex roots t* ± i√D/a of q at
//    least √2 from the real axis in units of |AB|): the moment relations
//    lose a factor ~ D/a² per step there (the kernel is nearly flat), while
//    the rule's error, for an integrand with a pole of order m/2 outside the
//    Bernstein ellipse of parameter ρ ≥ 5.8, is below N^(m/2) ρ^(−2N) ≈ 1e-19
//    with N = 20 (Trefethen, Approximation Theory and Approximation
//    Practice, ch. 19). The verifier checks both claims against quadrature
//    of the definition.
//
// Nodes and weights are Boost.Math's, tabulated to the precision of T
// (double, long double, float128, …).
#pragma once

#include <boost/math/quadrature/gauss.hpp>

#include <cmath>

namespace skelconv {

/// Writes M_{k,m} for k = 0…k_max and m = m_lo, m_lo + 2, …, m_hi (m may be
/// negative: q^(|m|/2) for compact kernels, where q ≥ 0 on [t0, t1]) to
/// out[((m − m_lo)/2)(k_max + 1) + k], with the N-point Gauss–Legendre rule.
template <class T, unsigned N>
void segment_moments_gauss(int m_lo, int m_hi, int k_max, const T& a, const T& b, const T& c, const T& t0,
                           const T& t1, T* out) {
  using std::max;
  using std::sqrt;
  using Rule = boost::math::quadrature::gauss<T, N>;
  const int levels = (m_hi - m_lo) / 2 + 1;
  const int per_level = k_max + 1;
  for (int i = 0; i < levels * per_level; ++i) out[i] = T(0);
  const T half_width = (t1 - t0) / 2;
  const T middle = (t0 + t1) / 2;
  // One node t with Gauss weight g adds g t^k q^(−m/2) to every moment.
  auto add_node = [&](const T& x, const T& g) {
    const T t = middle + half_width * x;
    const T q = max(T(0), c + t * (a * t - 2 * b));
    // q^(−m_hi/2) from integer powers of q (even m) or of √q (odd m), then
    // × q per level down to m_lo: no division by a q that may be 0 at a
    // clipped end.
    const bool even = m_hi % 2 == 0;
    const T root = even ? q : sqrt(q);
    const T base = m_hi <= 0 ? root : T(1) / root;
    const int power = (m_hi <= 0 ? -m_hi : m_hi) / (even ? 2 : 1);
    T level_value = T(1);
    for (int j = 0; j < power; ++j) level_value *= base;
    for (int l = levels - 1; l >= 0; --l) {
      T term = g * level_value;
      for (int k = 0; k <= k_max; ++k) {
        out[l * per_level + k] += term;
        term *= t;
      }
      level_value *= q;
    }
  };
  const auto& x = Rule::abscissa();
  const auto& g = Rule::weights();
  unsigned first = 0;
  if (N % 2 == 1) {
    add_node(T(0), g[0]);
    first = 1;
  }
#pragma GCC unroll 16
  for (unsigned j = first; j < x.size(); ++j) {
    add_node(x[j], g[j]);
    add_node(-x[j], g[j]);
  }
  for (int i = 0; i < levels * per_level; ++i) out[i] *= half_width;
}

}  // namespace skelconv
