// codegen/segment_moments.hpp — the Hubert–Cani recurrences, unrolled.
//
// With q(t) = a t² − 2 b t + c and D = ac − b² (SPEC §2), this builds the
// moments
//
//     M_{k,n} = ∫_{t0}^{t1} t^k q(t)^(-n/2) dt        (J_n = M_{0,n})
//
// as explicit expressions in a few base symbols, for any integer n (n ≤ 0 for
// compact kernels) and k ≥ 0:
//
//  * J_n by recurrence (1) of Hubert & Cani (Hubert 2012 §3.1, eq. 1), taken
//    on a general interval [t0, t1]:
//        (n−2) D J_n + a(3−n) J_{n−2} = [(a t − b) q^(1−n/2)]_{t0}^{t1},
//    upwards from J_1 or J_2 for n ≥ 3, downwards from J_1 or J_0 for n ≤ 0;
//  * M_{1,n} from d/dt q^(1−n/2) = (2−n)(a t − b) q^(−n/2):
//        a M_{1,n} = b J_n + [q^(1−n/2)] / (2−n)      (n ≠ 2)
//        a M_{1,2} = b J_2 + ½ ln(q(t1)/q(t0));
//  * M_{k+2,n} from t² = (q + 2bt − c)/a:
//        a M_{k+2,n} = M_{k,n−2} + 2b M_{k+1,n} − c M_{k,n}.
//
// The base symbols (J_1, J_2, the log ratio, q and √q at the ends) are
// defined by the family (segment_families.cpp), which chooses stable forms
// for them.
#pragma once

#include <ginac/ginac.h>

#include <map>
#include <utility>

namespace skelconv::codegen {

/// q and its neighbours at one end of the interval.
struct QuadraticEnd {
  GiNaC::ex t;      ///< the parameter there (0, 1, or a symbol)
  GiNaC::ex q;      ///< q(t)
  GiNaC::ex root;   ///< √q(t); used only when the kernel index n is odd
  GiNaC::ex slope;  ///< a t − b (half of q'(t))
};

/// The symbols the unrolled recurrences are written in.
struct MomentSymbols {
  GiNaC::ex a, b, c;
  GiNaC::ex D;          ///< ac − b², defined by the family in a stable way
  QuadraticEnd lo, hi;  ///< the interval's ends t0 ≤ t1
  GiNaC::ex J1;         ///< ∫ q^(-1/2)
  GiNaC::ex J2;         ///< ∫ q^(-1)   (infinite-support kernels only)
  GiNaC::ex log_ratio;  ///< ln(q(t1)/q(t0))   (for M_{1,2})
};

class MomentRecurrence {
 public:
  explicit MomentRecurrence(MomentSymbols symbols) : s_(std::move(symbols)) {}

  /// J_n = ∫_{t0}^{t1} q^(-n/2) dt.
  GiNaC::ex J(int n);
  /// M_{k,n} = ∫_{t0}^{t1} t^k q^(-n/2) dt.
  GiNaC::ex M(int k, int n);

 private:
  /// q^(e/2) at one end, written with q and √q only.
  GiNaC::ex half_power(const QuadraticEnd& end, int e) const;
  /// [(a t − b) q^(1−n/2)]_{t0}^{t1}: the right-hand side of recurrence (1).
  GiNaC::ex recurrence_boundary(int n) const;

  MomentSymbols s_;
  std::map<std::pair<int, int>, GiNaC::ex> memo_;
};

}  // namespace skelconv::codegen
