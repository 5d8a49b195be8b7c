// tools/counting_scalar.hpp — a double that counts the arithmetic done on it.
//
// Why: the compact SCALIS segment (include/skelconv/primitives/scalis_compact.hpp) is
// not generated code, so generated/opcounts.csv has no row for it. Its
// operation count is path dependent (the number of Gauss panels depends on
// P), so it is measured by running the same template on this type: every
// +, −, ×, / and √ executed is tallied, in the units of docs/mathematics.md §4's Table 4
// (+, ×, / then (√, atan, log)). Conventions: negation, comparisons, abs,
// min/max and frexp are free (sign or exponent manipulation); ldexp is
// counted as a ×. The arithmetic is the double arithmetic, operation for
// operation, so the result is bit-identical to the double instantiation when
// both are compiled without FMA contraction (-ffp-contract=off); the caller
// checks that, which is what shows that no operation escaped the count.
//
// The generator (codegen/helper_costs.cpp) also runs the hand-written helpers
// that generated code calls (skelconv/detail/gauss_moments.hpp,
// stable_recurrence.hpp, polygon_angle_integrals.hpp) once on this type, so
// that their cost in generated/opcounts.csv is what they execute. For them:
// atan2 counts in `atan`, log in `log`, cos (no column of Table 4) in
// `other`; pow(x, n) for an integer n as the multiplications of binary
// powering (what libstdc++'s std::pow(double, int) does), and 1/x for n < 0
// as one division more; ceil is free (rounding, like abs).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

namespace skelconv::bench {

/// Tally of the operations executed on CountingDouble values.
struct OperationTally {
  std::int64_t add = 0, mul = 0, div = 0, sqrt = 0, atan = 0, log = 0, other = 0;
};

inline OperationTally& operation_tally() {
  static OperationTally tally;
  return tally;
}

struct CountingDouble {
  double value = 0;

  CountingDouble() = default;
  CountingDouble(double v) : value(v) {}  // NOLINT: implicit, so that literals mix in as in the template code

  CountingDouble& operator+=(CountingDouble o) { return ++operation_tally().add, value += o.value, *this; }
  CountingDouble& operator-=(CountingDouble o) { return ++operation_tally().add, value -= o.value, *this; }
  CountingDouble& operator*=(CountingDouble o) { return ++operation_tally().mul, value *= o.value, *this; }
  CountingDouble& operator/=(CountingDouble o) { return ++operation_tally().div, value /= o.value, *this; }
  friend CountingDouble operator+(CountingDouble a, CountingDouble b) { return a += b; }
  friend CountingDouble operator-(CountingDouble a, CountingDouble b) { return a -= b; }
  friend CountingDouble operator*(CountingDouble a, CountingDouble b) { return a *= b; }
  friend CountingDouble operator/(CountingDouble a, CountingDouble b) { return a /= b; }
  friend CountingDouble operator-(CountingDouble a) { return CountingDouble(-a.value); }
  friend CountingDouble operator+(CountingDouble a) { return a; }

  friend bool operator<(CountingDouble a, CountingDouble b) { return a.value < b.value; }
  friend bool operator>(CountingDouble a, CountingDouble b) { return a.value > b.value; }
  friend bool operator<=(CountingDouble a, CountingDouble b) { return a.value <= b.value; }
  friend bool operator>=(CountingDouble a, CountingDouble b) { return a.value >= b.value; }
  friend bool operator==(CountingDouble a, CountingDouble b) { return a.value == b.value; }
  friend bool operator!=(CountingDouble a, CountingDouble b) { return a.value != b.value; }

  friend CountingDouble sqrt(CountingDouble a) { return ++operation_tally().sqrt, CountingDouble(std::sqrt(a.value)); }
  friend CountingDouble abs(CountingDouble a) { return CountingDouble(std::abs(a.value)); }
  friend CountingDouble frexp(CountingDouble a, int* e) { return CountingDouble(std::frexp(a.value, e)); }
  friend CountingDouble ldexp(CountingDouble a, int e) { return ++operation_tally().mul, CountingDouble(std::ldexp(a.value, e)); }
  friend CountingDouble ceil(CountingDouble a) { return CountingDouble(std::ceil(a.value)); }
  friend CountingDouble log(CountingDouble a) { return ++operation_tally().log, CountingDouble(std::log(a.value)); }
  friend CountingDouble cos(CountingDouble a) { return ++operation_tally().other, CountingDouble(std::cos(a.value)); }
  friend CountingDouble sin(CountingDouble a) { return ++operation_tally().other, CountingDouble(std::sin(a.value)); }
  friend CountingDouble atan2(CountingDouble y, CountingDouble x) {
    return ++operation_tally().atan, CountingDouble(std::atan2(y.value, x.value));
  }
  // A fused multiply-add counts as the × and the + it fuses (op_count.hpp has
  // no column of its own for it); it is exact to one rounding, as std::fma.
  friend CountingDouble fma(CountingDouble a, CountingDouble b, CountingDouble c) {
    ++operation_tally().mul, ++operation_tally().add;
    return CountingDouble(std::fma(a.value, b.value, c.value));
  }
  friend CountingDouble pow(CountingDouble a, int n) {
    // Binary powering: one × per bit after the leading one, one per further set bit.
    const unsigned magnitude = n < 0 ? static_cast<unsigned>(-n) : static_cast<unsigned>(n);
    for (unsigned k = magnitude; k > 1; k >>= 1) operation_tally().mul += (k & 1u) ? 2 : 1;
    if (n < 0) ++operation_tally().div;
    return CountingDouble(std::pow(a.value, n));
  }
  explicit operator double() const { return value; }
  explicit operator int() const { return static_cast<int>(value); }
};

}  // namespace skelconv::bench

template <>
class std::numeric_limits<skelconv::bench::CountingDouble> : public std::numeric_limits<double> {
 public:
  static skelconv::bench::CountingDouble infinity() { return std::numeric_limits<double>::infinity(); }
  static skelconv::bench::CountingDouble quiet_NaN() { return std::numeric_limits<double>::quiet_NaN(); }
  static skelconv::bench::CountingDouble epsilon() { return std::numeric_limits<double>::epsilon(); }
  static skelconv::bench::CountingDouble max() { return std::numeric_limits<double>::max(); }
  static skelconv::bench::CountingDouble min() { return std::numeric_limits<double>::min(); }
  static skelconv::bench::CountingDouble lowest() { return std::numeric_limits<double>::lowest(); }
};
