// generated/scalis_segment_table.hpp — every generated SCALIS segment kernel, for lookup at run time.
//
// GENERATED FILE: DO NOT EDIT. Regenerate with
//     skelconv-codegen --inverse 1:16 --cauchy 1:16 --compact 2:16 --weights 0:3 --polygon-inverse 3:12 --polygon-cauchy 3:12 --polygon-compact 4:12 --scalis-inverse 2:10 --scalis-cauchy 2:10 --scalis-compact 2:10 --out generated
// Generator: skelconv-codegen 0.1.0 (GiNaC 1.8.6)
// From: codegen/segment_families.cpp (the families) and codegen/segment_moments.cpp
// (recurrence (1) of Hubert & Cani unrolled; docs/mathematics.md §2, Hubert 2012 §3).
// SCALIS segments (docs/mathematics.md §4, Zanni et al. 2013 §3–4, Table 3): the segment kernel of
// degree i with the weight σ^i τ(t)^(i−1), and for Cauchy q = |P − Γ(t)|² + σ²τ(t)²
// (codegen/segment_families.cpp, ScalisKernelSpec). Unnormalised: f = c F / h is
// the runtime's (skelconv/primitives/scalis_segment.hpp).
#pragma once

#include <array>
#include <span>

#include <skelconv/kernels/op_count.hpp>
#include <skelconv/primitives/segment_input.hpp>

#include "generated/scalis_segment_inverse.hpp"
#include "generated/scalis_segment_cauchy.hpp"

namespace skelconv::generated {

/// One generated SCALIS segment kernel: F, ∇F and both (unnormalised), with their operation counts.
template <class T>
struct ScalisSegmentKernel {
  KernelFamily family;
  int degree;
  T (*f)(const ScalisSegmentInput<T>&);
  std::array<T, 3> (*grad)(const ScalisSegmentInput<T>&);
  T (*f_and_grad)(const ScalisSegmentInput<T>&, std::array<T, 3>&);
  const char* name;
  const char* equation;
  OpCount ops_f, ops_grad, ops_f_and_grad;
};

/// Every generated SCALIS segment kernel, sorted by family and degree.
template <class T>
std::span<const ScalisSegmentKernel<T>> scalis_segment_kernels() {
  static const ScalisSegmentKernel<T> table[] = {
      {KernelFamily::inverse, 2, &scalis_segment_inverse_i2_f<T>, &scalis_segment_inverse_i2_grad<T>, &scalis_segment_inverse_i2_f_and_grad<T>, "scalis_segment_inverse_i2",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|²)^(−2/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {35, 48, 3, 2, 1, 1, 0}, {47, 75, 6, 2, 1, 0, 0}, {49, 84, 6, 2, 1, 1, 0}},
      {KernelFamily::inverse, 3, &scalis_segment_inverse_i3_f<T>, &scalis_segment_inverse_i3_grad<T>, &scalis_segment_inverse_i3_f_and_grad<T>, "scalis_segment_inverse_i3",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−3), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|²)^(−3/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {39, 66, 6, 3, 0, 1, 0}, {53, 109, 5, 3, 0, 0, 0}, {58, 130, 7, 3, 0, 1, 0}},
      {KernelFamily::inverse, 4, &scalis_segment_inverse_i4_f<T>, &scalis_segment_inverse_i4_grad<T>, &scalis_segment_inverse_i4_f_and_grad<T>, "scalis_segment_inverse_i4",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−4), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|²)^(−4/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {45, 83, 5, 2, 1, 1, 0}, {63, 137, 6, 2, 1, 0, 0}, {69, 162, 6, 2, 1, 1, 0}},
      {KernelFamily::inverse, 5, &scalis_segment_inverse_i5_f<T>, &scalis_segment_inverse_i5_grad<T>, &scalis_segment_inverse_i5_f_and_grad<T>, "scalis_segment_inverse_i5",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−5), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|²)^(−5/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {51, 115, 6, 3, 0, 1, 0}, {71, 183, 5, 3, 0, 0, 0}, {80, 221, 7, 3, 0, 1, 0}},
      {KernelFamily::inverse, 6, &scalis_segment_inverse_i6_f<T>, &scalis_segment_inverse_i6_grad<T>, &scalis_segment_inverse_i6_f_and_grad<T>, "scalis_segment_inverse_i6",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−6), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|²)^(−6/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {59, 137, 5, 2, 1, 1, 0}, {83, 210, 6, 2, 1, 0, 0}, {93, 250, 6, 2, 1, 1, 0}},
      {KernelFamily::inverse, 7, &scalis_segment_inverse_i7_f<T>, &scalis_segment_inverse_i7_grad<T>, &scalis_segment_inverse_i7_f_and_grad<T>, "scalis_segment_inverse_i7",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−7), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|²)^(−7/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {67, 178, 6, 3, 0, 1, 0}, {93, 271, 5, 3, 0, 0, 0}, {106, 322, 7, 3, 0, 1, 0}},
      {KernelFamily::inverse, 8, &scalis_segment_inverse_i8_f<T>, &scalis_segment_inverse_i8_grad<T>, &scalis_segment_inverse_i8_f_and_grad<T>, "scalis_segment_inverse_i8",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−8), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|²)^(−8/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {77, 204, 5, 2, 1, 1, 0}, {107, 296, 6, 2, 1, 0, 0}, {121, 351, 6, 2, 1, 1, 0}},
      {KernelFamily::inverse, 9, &scalis_segment_inverse_i9_f<T>, &scalis_segment_inverse_i9_grad<T>, &scalis_segment_inverse_i9_f_and_grad<T>, "scalis_segment_inverse_i9",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−9), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|²)^(−9/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {87, 260, 6, 3, 0, 1, 0}, {119, 368, 5, 3, 0, 0, 0}, {136, 436, 7, 3, 0, 1, 0}},
      {KernelFamily::inverse, 10, &scalis_segment_inverse_i10_f<T>, &scalis_segment_inverse_i10_grad<T>, &scalis_segment_inverse_i10_f_and_grad<T>, "scalis_segment_inverse_i10",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−10), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|²)^(−10/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {99, 286, 5, 2, 1, 1, 0}, {135, 399, 6, 2, 1, 0, 0}, {153, 469, 6, 2, 1, 1, 0}},
      {KernelFamily::cauchy, 2, &scalis_segment_cauchy_i2_f<T>, &scalis_segment_cauchy_i2_grad<T>, &scalis_segment_cauchy_i2_f_and_grad<T>, "scalis_segment_cauchy_i2",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−2/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|² + σ²τ²)^(−2/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {47, 70, 3, 2, 1, 1, 0}, {63, 106, 8, 2, 1, 0, 0}, {65, 115, 8, 2, 1, 1, 0}},
      {KernelFamily::cauchy, 3, &scalis_segment_cauchy_i3_f<T>, &scalis_segment_cauchy_i3_grad<T>, &scalis_segment_cauchy_i3_f_and_grad<T>, "scalis_segment_cauchy_i3",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−3/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|² + σ²τ²)^(−3/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {50, 84, 6, 5, 0, 1, 0}, {68, 136, 7, 3, 0, 0, 0}, {73, 158, 9, 5, 0, 1, 0}},
      {KernelFamily::cauchy, 4, &scalis_segment_cauchy_i4_f<T>, &scalis_segment_cauchy_i4_grad<T>, &scalis_segment_cauchy_i4_f_and_grad<T>, "scalis_segment_cauchy_i4",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−4/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|² + σ²τ²)^(−4/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {57, 103, 5, 2, 1, 1, 0}, {79, 166, 8, 2, 1, 0, 0}, {85, 191, 8, 2, 1, 1, 0}},
      {KernelFamily::cauchy, 5, &scalis_segment_cauchy_i5_f<T>, &scalis_segment_cauchy_i5_grad<T>, &scalis_segment_cauchy_i5_f_and_grad<T>, "scalis_segment_cauchy_i5",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−5/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|² + σ²τ²)^(−5/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {62, 133, 6, 5, 0, 1, 0}, {86, 210, 7, 3, 0, 0, 0}, {95, 249, 9, 5, 0, 1, 0}},
      {KernelFamily::cauchy, 6, &scalis_segment_cauchy_i6_f<T>, &scalis_segment_cauchy_i6_grad<T>, &scalis_segment_cauchy_i6_f_and_grad<T>, "scalis_segment_cauchy_i6",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−6/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|² + σ²τ²)^(−6/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {71, 157, 5, 2, 1, 1, 0}, {99, 239, 8, 2, 1, 0, 0}, {109, 279, 8, 2, 1, 1, 0}},
      {KernelFamily::cauchy, 7, &scalis_segment_cauchy_i7_f<T>, &scalis_segment_cauchy_i7_grad<T>, &scalis_segment_cauchy_i7_f_and_grad<T>, "scalis_segment_cauchy_i7",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−7/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|² + σ²τ²)^(−7/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {78, 196, 6, 5, 0, 1, 0}, {108, 298, 7, 3, 0, 0, 0}, {121, 350, 9, 5, 0, 1, 0}},
      {KernelFamily::cauchy, 8, &scalis_segment_cauchy_i8_f<T>, &scalis_segment_cauchy_i8_grad<T>, &scalis_segment_cauchy_i8_f_and_grad<T>, "scalis_segment_cauchy_i8",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−8/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|² + σ²τ²)^(−8/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {89, 224, 5, 2, 1, 1, 0}, {123, 325, 8, 2, 1, 0, 0}, {137, 380, 8, 2, 1, 1, 0}},
      {KernelFamily::cauchy, 9, &scalis_segment_cauchy_i9_f<T>, &scalis_segment_cauchy_i9_grad<T>, &scalis_segment_cauchy_i9_f_and_grad<T>, "scalis_segment_cauchy_i9",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−9/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|² + σ²τ²)^(−9/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {98, 278, 6, 5, 0, 1, 0}, {134, 395, 7, 3, 0, 0, 0}, {151, 464, 9, 5, 0, 1, 0}},
      {KernelFamily::cauchy, 10, &scalis_segment_cauchy_i10_f<T>, &scalis_segment_cauchy_i10_grad<T>, &scalis_segment_cauchy_i10_f_and_grad<T>, "scalis_segment_cauchy_i10",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−10/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|² + σ²τ²)^(−10/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {111, 306, 5, 2, 1, 1, 0}, {151, 428, 8, 2, 1, 0, 0}, {169, 498, 8, 2, 1, 1, 0}},
  };
  return table;
}

/// The SCALIS segment kernel for (family, degree), or nullptr if it was not generated.
template <class T>
const ScalisSegmentKernel<T>* find_scalis_segment_kernel(KernelFamily family, int degree) {
  for (const ScalisSegmentKernel<T>& k : scalis_segment_kernels<T>())
    if (k.family == family && k.degree == degree) return &k;
  return nullptr;
}

}  // namespace skelconv::generated
