// generated/segment_table.hpp — the lookup table of the generated segment kernels (declarations).
//
// GENERATED FILE: DO NOT EDIT. Regenerate with
//     skelconv-codegen --inverse 1:16 --cauchy 1:16 --compact 2:16 --weights 0:3 --polygon-inverse 3:12 --polygon-cauchy 3:12 --polygon-compact 4:12 --scalis-inverse 2:10 --scalis-cauchy 2:10 --scalis-compact 2:10 --out generated
// Generator: skelconv-codegen 0.1.0 (GiNaC 1.8.6)
// From: codegen/segment_families.cpp (the families) and codegen/segment_moments.cpp
// (recurrence (1) of Hubert & Cani unrolled; docs/mathematics.md §2, Hubert 2012 §3).
#pragma once

#include <array>
#include <span>
#include <vector>

#include <skelconv/kernels/kernel_family.hpp>
#include <skelconv/kernels/op_count.hpp>
#include <skelconv/primitives/prepared_kernel.hpp>
#include <skelconv/primitives/segment_input.hpp>

namespace skelconv::generated {

/// One generated kernel: f, ∇f and both, with their operation counts.
/// A generated kernel is split in two: `prepare` computes what depends on the
/// segment alone into an array of `prepared_size` values, once per segment, and
/// `f_at`, `grad_at`, `f_and_grad_at` read it at each point. `f`, `grad` and
/// `f_and_grad` do both for one point (prepared_f, prepared_kernel.hpp). The ops_* counts are
/// per point; ops_prepare is the preparation's, once per segment. The derived
/// Gaussian entry (derived_segment_kernels.hpp) is not split: no `prepare`.
template <class T>
struct SegmentKernel {
  KernelFamily family;
  int degree;
  int weight_degree;
  T (*f)(const SegmentInput<T>&);
  std::array<T, 3> (*grad)(const SegmentInput<T>&);
  T (*f_and_grad)(const SegmentInput<T>&, std::array<T, 3>&);
  const char* name;
  const char* equation;
  OpCount ops_f, ops_grad, ops_f_and_grad;
  OpCount ops_prepare{};
  std::size_t prepared_size = 0;
  void (*prepare)(const SegmentInput<T>&, T*) = nullptr;
  T (*f_at)(const T*, const SegmentPoint<T>&) = nullptr;
  std::array<T, 3> (*grad_at)(const T*, const SegmentPoint<T>&) = nullptr;
  T (*f_and_grad_at)(const T*, const SegmentPoint<T>&, std::array<T, 3>&) = nullptr;
};

/// The inverse family's kernels (defined in generated/segment_inverse.hpp).
template <class T>
std::span<const SegmentKernel<T>> segment_inverse_kernels();

/// The cauchy family's kernels (defined in generated/segment_cauchy.hpp).
template <class T>
std::span<const SegmentKernel<T>> segment_cauchy_kernels();

/// The compact family's kernels (defined in generated/segment_compact.hpp).
template <class T>
std::span<const SegmentKernel<T>> segment_compact_kernels();

/// Every generated kernel, sorted by family, degree and weight degree.
template <class T>
std::span<const SegmentKernel<T>> segment_kernels() {
  static const std::vector<SegmentKernel<T>> table = [] {
    std::vector<SegmentKernel<T>> all;
    for (const SegmentKernel<T>& k : segment_inverse_kernels<T>()) all.push_back(k);
    for (const SegmentKernel<T>& k : segment_cauchy_kernels<T>()) all.push_back(k);
    for (const SegmentKernel<T>& k : segment_compact_kernels<T>()) all.push_back(k);
    return all;
  }();
  return table;
}

/// The kernel for (family, degree, weight degree), or nullptr if it was not generated.
template <class T>
const SegmentKernel<T>* find_segment_kernel(KernelFamily family, int degree, int weight_degree) {
  for (const SegmentKernel<T>& k : segment_kernels<T>())
    if (k.family == family && k.degree == degree && k.weight_degree == weight_degree) return &k;
  return nullptr;
}

}  // namespace skelconv::generated
