// bench/counting_scalar.hpp — a double that counts the arithmetic done on it.
//
// Why: the compact SCALIS segment (include/skelconv/scalis_compact.hpp) is
// not generated code, so generated/opcounts.csv has no row for it. Its
// operation count is path dependent (the number of Gauss panels depends on
// P), so it is measured by running the same template on this type: every
// +, −, ×, / and √ executed is tallied, in the units of SPEC §4's Table 4
// (+, ×, / then (√, atan, log)). Conventions: negation, comparisons, abs,
// min/max and frexp are free (sign or exponent manipulation); ldexp is
// counted as a ×. The arithmetic is the double arithmetic, operation for
// operation, so the result is bit-identical to the double instantiation when
// both are compiled without FMA contraction (-ffp-contract=off); the caller
// checks that, which is what shows that no operation escaped the count.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

namespace skelconv::bench {

/// Tally of the operations executed on CountingDouble values.
struct OperationTally {
  std::int64_t add = 0, mul = 0, div = 0, sqrt = 0, atan = 0, log = 0;
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
