// skelconv/kernels/op_count.hpp — floating-point operation counts of generated code.
//
// The generator (codegen/straight_line_program.cpp) counts the operations of
// the C++ it writes, after common-subexpression elimination, so a count is
// what one call executes on its longest path. The rules:
//  * a + b and a − b count one `add`; unary minus is free (a sign flip);
//  * a × b counts one `mul`, also when one side is a constant;
//    x^k for integer k is written as products of memoised powers and counted
//    as those products; a rational constant is folded, never divided;
//  * a / b counts one `div`; 1/x shared by several uses counts once;
//  * sqrt, atan2 (or atan), log and asinh count one call each in their
//    column; x^(k/2) is sqrt(x) times an integer power;
//  * comparisons and selections between forms are not counted;
//  * a call of a hand-written helper (a Gauss rule, a Miller recurrence,
//    Gauss panels: skelconv/detail/gauss_moments.hpp, stable_recurrence.hpp,
//    polygon_angle_integrals.hpp) counts what the helper executes, measured
//    by running it on a counting scalar (codegen/helper_costs.hpp); a loop
//    whose length depends on P counts at its longest.
// Table 4 of Zanni 2013 (docs/mathematics.md §4) counts +, ×, / and (√, atan, ln); asinh is
// a log in disguise and goes in the log column.
#pragma once

namespace skelconv {

struct OpCount {
  int add = 0;    ///< additions and subtractions
  int mul = 0;    ///< multiplications (including by constants)
  int div = 0;    ///< divisions
  int sqrt = 0;   ///< square roots
  int atan = 0;   ///< atan / atan2
  int log = 0;    ///< log, asinh
  int other = 0;  ///< any other call: cos, in the polygon helpers' angle rule

  constexpr int total() const { return add + mul + div + sqrt + atan + log + other; }
  constexpr OpCount& operator+=(const OpCount& o) {
    add += o.add; mul += o.mul; div += o.div; sqrt += o.sqrt;
    atan += o.atan; log += o.log; other += o.other;
    return *this;
  }
  friend constexpr OpCount operator+(OpCount a, const OpCount& b) { return a += b; }
  friend constexpr bool operator==(const OpCount&, const OpCount&) = default;
};

}  // namespace skelconv
