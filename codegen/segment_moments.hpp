// codegen/segment_moments.hpp — the Hubert–Cani recurrences, unrolled.
//
// With q(t) = a t² − 2 b t + c and D = ac − b² (docs/mathematics.md §2), this builds the
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
// Recurrence (1) has two stable directions (the theory of minimal solutions
// of three-term recurrences, as in Miller's algorithm):
//  * upwards from J_1, J_2 when P projects onto the segment, or sits far
//    from its line compared with its distance beyond the nearer end: there
//    J_n shrinks no faster than the homogeneous solution;
//  * downwards, where P projects beyond an end and lies close to the line:
//    there the upward recurrence divides a cancelling difference by D → 0
//    (it loses every digit on the line), while going down multiplies errors
//    by about ρ = D / (a q_near) < 1 at every step. The highest J_n a kernel
//    needs comes from skelconv::J_downward (include/skelconv/
//    stable_recurrence.hpp, Miller's algorithm with an adaptive start),
//    the lower ones from the recurrence taken downwards.
// Compact kernels (n ≤ 0) mirror this: downwards from J_0, J_1 when the
// vertex of q lies inside the clipped interval, and upwards from
// skelconv::J_upward_compact at the lowest index when it lies outside.
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

/// How recurrence (1) is run (J_0 and J_1 always come from their own forms).
struct RecurrenceDirection {
  enum class Mode {
    from_base,       ///< up from J_1, J_2 for n ≥ 3; down from J_0, J_1 for n ≤ −1
    down_from_top,   ///< J_anchor = J_downward(…), then down to n ≥ 2
    up_from_bottom,  ///< J_anchor = J_upward_compact(…), then up to n ≤ −1
  } mode = Mode::from_base;
  int anchor = 0;
};

class MomentRecurrence {
 public:
  explicit MomentRecurrence(MomentSymbols symbols, RecurrenceDirection direction = {})
      : s_(std::move(symbols)), direction_(direction) {}

  /// J_n = ∫_{t0}^{t1} q^(-n/2) dt.
  GiNaC::ex J(int n);
  /// M_{k,n} = ∫_{t0}^{t1} t^k q^(-n/2) dt.
  GiNaC::ex M(int k, int n);

 private:
  /// q^(e/2) at one end, written with q and √q only.
  GiNaC::ex half_power(const QuadraticEnd& end, int e) const;
  /// [(a t − b) q^(1−n/2)]_{t0}^{t1}: the right-hand side of recurrence (1).
  GiNaC::ex recurrence_boundary(int n) const;
  /// J_m from J_{m−2} by recurrence (1) at index m.
  GiNaC::ex lower_index_to_up(int m);
  /// J_{m−2} from J_m by recurrence (1) at index m.
  GiNaC::ex up_index_to_lower(int m);

  MomentSymbols s_;
  RecurrenceDirection direction_;
  std::map<std::pair<int, int>, GiNaC::ex> memo_;
  std::map<int, GiNaC::ex> J_memo_;
};

}  // namespace skelconv::codegen
