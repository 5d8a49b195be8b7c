// skelconv/kernels/derived_segment_kernels.hpp — segment kernels that are not in the
// generated table but follow from a kernel trait (skelconv/kernels/):
//
//  * a trait with `compact_levels` (soft = k_R^4, Wyvill = 5/9 k_R^4 +
//    4/9 k_R^6) gets Σ_j c_j × the generated compact segment function of
//    degree i_j: the same closed forms, exactly combined (the field is
//    linear in K). The compact clip [t0, t1] of the input applies to every
//    level (they share R).
//  * a trait with a `SegmentClosedForm<T, W>` (the Gaussian) gets its
//    hand-written closed form.
//
// Entries have the generated table's type (generated::SegmentKernel), with
// degree 0 (these families have no degree), so the runtime (Segment), the
// verifier and the benchmarks take them from find_any_segment_kernel() like
// generated ones. A combination is split like its levels (their
// preparations side by side); the Gaussian is not (no `prepare`: it reads
// the whole SegmentInput at each point). Operation counts: a combination
// adds its levels' counts plus one multiplication per level and one
// addition between levels; the hand-written Gaussian is not counted (zeros).
//
// Adding a family here is adding its trait to kernels::RadialKernel with
// one of those two members: the table below is built from that list.
#pragma once

#include <array>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "generated/segment_table.hpp"
#include "skelconv/kernels/kernel_list.hpp"

namespace skelconv {

namespace detail {

/// "w0", "(w0 + w1 t)", … as in the generated equations.
inline std::string weight_text(int weight_degree) {
  if (weight_degree == 0) return "w0";
  std::string s = "(w0";
  for (int k = 1; k <= weight_degree; ++k)
    s += " + w" + std::to_string(k) + (k == 1 ? " t" : " t^" + std::to_string(k));
  return s + ")";
}

/// Σ_j c_j k_R^(i_j) for weight degree W, on the generated compact functions.
template <class Kernel, class T, int W>
struct CompactCombination {
  static constexpr std::size_t count = Kernel::compact_levels.size();
  using Level = generated::SegmentKernel<T>;

  static const std::array<const Level*, count>& levels() {
    static const std::array<const Level*, count> table = [] {
      std::array<const Level*, count> out{};
      for (std::size_t j = 0; j < count; ++j)
        out[j] = generated::find_segment_kernel<T>(KernelFamily::compact, Kernel::compact_levels[j].degree, W);
      return out;
    }();
    return table;
  }
  static T coefficient(std::size_t j) {
    return T(Kernel::compact_levels[j].numerator) / T(Kernel::compact_levels[j].denominator);
  }
  static T f(const SegmentInput<T>& in) {
    T sum(0);
    for (std::size_t j = 0; j < count; ++j) sum += coefficient(j) * levels()[j]->f(in);
    return sum;
  }
  static std::array<T, 3> grad(const SegmentInput<T>& in) {
    std::array<T, 3> sum{};
    for (std::size_t j = 0; j < count; ++j) {
      const std::array<T, 3> g = levels()[j]->grad(in);
      for (int i = 0; i < 3; ++i) sum[i] += coefficient(j) * g[i];
    }
    return sum;
  }
  static T f_and_grad(const SegmentInput<T>& in, std::array<T, 3>& grad_out) {
    T sum(0);
    grad_out = {};
    for (std::size_t j = 0; j < count; ++j) {
      std::array<T, 3> g{};
      sum += coefficient(j) * levels()[j]->f_and_grad(in, g);
      for (int i = 0; i < 3; ++i) grad_out[i] += coefficient(j) * g[i];
    }
    return sum;
  }
  // Split like the generated kernels: the levels' preparations one after
  // the other in pre[], each level's per-point function reading its own.
  static std::size_t prepared_size() {
    std::size_t size = 0;
    for (const Level* level : levels()) size += level->prepared_size;
    return size;
  }
  static void prepare(const SegmentInput<T>& in, T* pre) {
    for (const Level* level : levels()) {
      level->prepare(in, pre);
      pre += level->prepared_size;
    }
  }
  static T f_at(const T* pre, const SegmentPoint<T>& point) {
    T sum(0);
    for (std::size_t j = 0; j < count; ++j) {
      sum += coefficient(j) * levels()[j]->f_at(pre, point);
      pre += levels()[j]->prepared_size;
    }
    return sum;
  }
  static std::array<T, 3> grad_at(const T* pre, const SegmentPoint<T>& point) {
    std::array<T, 3> sum{};
    for (std::size_t j = 0; j < count; ++j) {
      const std::array<T, 3> g = levels()[j]->grad_at(pre, point);
      for (int i = 0; i < 3; ++i) sum[i] += coefficient(j) * g[i];
      pre += levels()[j]->prepared_size;
    }
    return sum;
  }
  static T f_and_grad_at(const T* pre, const SegmentPoint<T>& point, std::array<T, 3>& grad_out) {
    T sum(0);
    grad_out = {};
    for (std::size_t j = 0; j < count; ++j) {
      std::array<T, 3> g{};
      sum += coefficient(j) * levels()[j]->f_and_grad_at(pre, point, g);
      for (int i = 0; i < 3; ++i) grad_out[i] += coefficient(j) * g[i];
      pre += levels()[j]->prepared_size;
    }
    return sum;
  }
  static std::string equation() {
    std::string sum;
    for (const kernels::CompactLevel& level : Kernel::compact_levels) {
      if (!sum.empty()) sum += " + ";
      if (level.numerator != level.denominator)
        sum += std::to_string(level.numerator) + "/" + std::to_string(level.denominator) + " ";
      sum += "(1 − |P − Γ(t)|²/R²)^(" + std::to_string(level.degree) + "/2)";
    }
    return "f(P) = |AB| ∫_t0^t1 " + weight_text(W) + " [" + sum + "] dt";
  }
  static OpCount ops(OpCount Level::*which) {
    OpCount total;
    for (std::size_t j = 0; j < count; ++j) {
      total += levels()[j]->*which;
      total.mul += 1;
      if (j > 0) total.add += 1;
    }
    return total;
  }
};

/// The hand-written closed form of a trait, for weight degree W.
template <class Kernel, class T, int W>
struct ClosedFormEntry {
  using Form = typename Kernel::template SegmentClosedForm<T, W>;
  static std::string equation() {
    return "f(P) = " + std::string(Kernel::segment_equation) + ", w(t) = " + weight_text(W);
  }
};

/// Stable storage for the entries' names and equations (the table keeps
/// const char*).
inline const char* keep(std::string text) {
  static std::mutex mutex;  // the double and binary128 tables may be built on two threads
  static std::vector<std::unique_ptr<std::string>> texts;
  const std::lock_guard lock(mutex);
  texts.push_back(std::make_unique<std::string>(std::move(text)));
  return texts.back()->c_str();
}

template <class Kernel, class T, int W>
void add_entry(std::vector<generated::SegmentKernel<T>>& out) {
  const char* name = keep("segment_" + std::string(Kernel::name) + "_w" + std::to_string(W));
  if constexpr (requires { Kernel::compact_levels; }) {
    using C = CompactCombination<Kernel, T, W>;
    using L = generated::SegmentKernel<T>;
    OpCount ops_prepare;
    for (const L* level : C::levels()) ops_prepare += level->ops_prepare;
    out.push_back({Kernel::family, 0, W, &C::f, &C::grad, &C::f_and_grad, name, keep(C::equation()),
                   C::ops(&L::ops_f), C::ops(&L::ops_grad), C::ops(&L::ops_f_and_grad), ops_prepare,
                   C::prepared_size(), &C::prepare, &C::f_at, &C::grad_at, &C::f_and_grad_at});
  } else if constexpr (requires { typename Kernel::template SegmentClosedForm<T, W>; }) {
    using E = ClosedFormEntry<Kernel, T, W>;
    using Form = typename E::Form;
    out.push_back({Kernel::family, 0, W, &Form::f, &Form::grad, &Form::f_and_grad, name,
                   keep(E::equation()), OpCount{}, OpCount{}, OpCount{}});
  }
}

template <class Kernel, class T>
void add_family(std::vector<generated::SegmentKernel<T>>& out) {
  if constexpr ((Kernel::primitives & kernels::on_segments) != 0 && !Kernel::has_degree) {
    [&]<int... W>(std::integer_sequence<int, W...>) {
      (add_entry<Kernel, T, W>(out), ...);
    }(std::make_integer_sequence<int, max_weight_degree + 1>{});
  }
}

}  // namespace detail

/// Every derived segment kernel (file comment), in the order of
/// kernels::RadialKernel, then by weight degree.
template <class T>
std::span<const generated::SegmentKernel<T>> derived_segment_kernels() {
  static const std::vector<generated::SegmentKernel<T>> table = [] {
    std::vector<generated::SegmentKernel<T>> out;
    [&]<std::size_t... index>(std::index_sequence<index...>) {
      (detail::add_family<std::variant_alternative_t<index, kernels::RadialKernel>, T>(out), ...);
    }(std::make_index_sequence<std::variant_size_v<kernels::RadialKernel>>{});
    return out;
  }();
  return table;
}

/// The generated kernel of (family, degree, weight degree), or else the
/// derived one of (family, weight degree) for a family without a degree;
/// nullptr when there is neither.
template <class T>
const generated::SegmentKernel<T>* find_any_segment_kernel(KernelFamily family, int degree, int weight_degree) {
  if (kernels::family_facts(family).has_degree) return generated::find_segment_kernel<T>(family, degree, weight_degree);
  for (const auto& k : derived_segment_kernels<T>())
    if (k.family == family && k.weight_degree == weight_degree) return &k;
  return nullptr;
}

}  // namespace skelconv
