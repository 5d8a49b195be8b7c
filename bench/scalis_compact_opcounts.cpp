// bench/scalis_compact_opcounts.cpp — operation counts of the compact SCALIS
// segment (include/skelconv/primitives/scalis_compact.hpp) as executed: the
// support by hand-written code, the integral by the generated closed form
// (even degrees; generated/opcounts.csv has those rows) or by Gauss panels.
//
//   skelconv_scalis_compact_opcounts [--points N]
//
// Runs scalis_compact_F on bench::CountingDouble (tools/counting_scalar.hpp)
// at N generic points per degree 2..10 (random segments, radii and σ; P inside
// the support, F > 0) and prints, per degree, the count (+, ×, / (√)) at the
// median point (by +×/ total) and the range over the points, for f alone and
// for f and ∇f together (∇f alone costs what f and ∇f cost: it is the same
// call). Every counted result is compared bit for bit with the double
// instantiation; a difference (an operation that escaped the count) exits 1.
// The runtime multiplies F by c/h afterwards (one more ×, not counted here).
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "tools/counting_scalar.hpp"
#include "skelconv/primitives/scalis_compact.hpp"

namespace {

using skelconv::ScalisSegmentInput;
using skelconv::bench::CountingDouble;
using skelconv::bench::operation_tally;
using skelconv::bench::OperationTally;

std::int64_t arithmetic(const OperationTally& t) { return t.add + t.mul + t.div; }

std::string format(const OperationTally& t) {
  char text[96];
  std::snprintf(text, sizeof text, "%lld, %lld, %lld (%lld, 0, 0)", static_cast<long long>(t.add),
                static_cast<long long>(t.mul), static_cast<long long>(t.div), static_cast<long long>(t.sqrt));
  return text;
}

/// Counts one call; returns false if the counted result differs from double.
bool count_call(int degree, const ScalisSegmentInput<double>& in, bool with_grad, OperationTally& tally) {
  const ScalisSegmentInput<CountingDouble> counted = skelconv::convert_scalar<CountingDouble>(in);
  std::array<double, 3> grad{};
  std::array<CountingDouble, 3> counted_grad{};
  const double expected = skelconv::scalis_compact_F(degree, in, with_grad ? &grad : nullptr);
  operation_tally() = OperationTally{};
  const CountingDouble value = skelconv::scalis_compact_F(degree, counted, with_grad ? &counted_grad : nullptr);
  tally = operation_tally();
  bool same = value.value == expected;
  for (int c = 0; c < 3; ++c) same = same && counted_grad[c].value == grad[c];
  return same;
}

struct Summary {
  OperationTally median, fewest, most;
};

Summary summarise(std::vector<OperationTally> tallies) {
  std::sort(tallies.begin(), tallies.end(),
            [](const OperationTally& x, const OperationTally& y) { return arithmetic(x) < arithmetic(y); });
  return {tallies[tallies.size() / 2], tallies.front(), tallies.back()};
}

}  // namespace

int main(int argc, char** argv) {
  int points = 1000;
  for (int j = 1; j < argc; ++j) {
    if (std::strcmp(argv[j], "--points") == 0 && j + 1 < argc) {
      points = std::atoi(argv[++j]);
    } else {
      std::fprintf(stderr, "usage: %s [--points N]  (N >= 1)\n", argv[0]);
      return 2;
    }
  }
  if (points < 1) {
    std::fprintf(stderr, "--points must be at least 1\n");
    return 2;
  }
  std::mt19937_64 random(20130601);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::printf("| compact degree | f: median point | f: range of +×/ | f and ∇f: median point | f and ∇f: range of +×/ |\n");
  std::printf("|---|---|---|---|---|\n");
  for (int degree = 2; degree <= 10; ++degree) {
    std::vector<OperationTally> f_tallies, both_tallies;
    while (static_cast<int>(f_tallies.size()) < points) {
      ScalisSegmentInput<double> in;
      for (int c = 0; c < 3; ++c) {
        in.a[c] = 2 * unit(random) - 1;
        in.b[c] = 2 * unit(random) - 1;
      }
      in.tau0 = 0.1 + 0.4 * unit(random);
      in.tau1 = 0.1 + 0.4 * unit(random);
      in.sigma = 1.2 + 1.8 * unit(random);
      const double reach = in.sigma * std::max(in.tau0, in.tau1);
      for (int c = 0; c < 3; ++c) {
        const double lo = std::min(in.a[c], in.b[c]) - reach, hi = std::max(in.a[c], in.b[c]) + reach;
        in.p[c] = lo + (hi - lo) * unit(random);
      }
      if (!(skelconv::scalis_compact_F(degree, in, nullptr) > 0)) continue;  // outside the support
      OperationTally f, both;
      if (!count_call(degree, in, false, f) || !count_call(degree, in, true, both)) {
        std::fprintf(stderr, "degree %d: the counted evaluation differs from double: an operation escaped the count\n",
                     degree);
        return 1;
      }
      f_tallies.push_back(f);
      both_tallies.push_back(both);
    }
    const Summary f = summarise(f_tallies), both = summarise(both_tallies);
    std::printf("| %d | %s | %lld–%lld | %s | %lld–%lld |\n", degree, format(f.median).c_str(),
                static_cast<long long>(arithmetic(f.fewest)), static_cast<long long>(arithmetic(f.most)),
                format(both.median).c_str(), static_cast<long long>(arithmetic(both.fewest)),
                static_cast<long long>(arithmetic(both.most)));
  }
  return 0;
}
