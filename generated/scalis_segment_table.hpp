// generated/scalis_segment_table.hpp — every generated SCALIS segment kernel, for lookup at run time.
//
// GENERATED FILE: DO NOT EDIT. Regenerate with
//     skelconv-codegen --inverse 1:16 --cauchy 1:16 --compact 2:16 --weights 0:3 --polygon-inverse 3:12 --polygon-cauchy 3:12 --polygon-compact 4:12 --scalis-inverse 2:10 --scalis-cauchy 2:10 --out generated
// Generator: skelconv-codegen 0.1.0 (GiNaC 1.8.6)
// From: codegen/segment_families.cpp (the families) and codegen/segment_moments.cpp
// (recurrence (1) of Hubert & Cani unrolled; SPEC §2, Hubert 2012 §3).
// SCALIS segments (SPEC §4, Zanni et al. 2013 §3–4, Table 3): the segment kernel of
// degree i with the weight σ^i τ(t)^(i−1), and for Cauchy q = |P − Γ(t)|² + σ²τ(t)²
// (codegen/segment_families.cpp, ScalisKernelSpec). Unnormalised: f = c F / h is
// the runtime's (skelconv/scalis_segment.hpp).
#pragma once

#include <array>
#include <span>

#include <skelconv/op_count.hpp>
#include <skelconv/segment_input.hpp>

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
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|²)^(−2/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]", {32, 42, 3, 2, 1, 1, 0}, {44, 69, 6, 2, 1, 0, 0}, {46, 78, 6, 2, 1, 1, 0}},
      {KernelFamily::inverse, 3, &scalis_segment_inverse_i3_f<T>, &scalis_segment_inverse_i3_grad<T>, &scalis_segment_inverse_i3_f_and_grad<T>, "scalis_segment_inverse_i3",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−3), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]", {36, 60, 6, 3, 0, 1, 0}, {50, 103, 5, 3, 0, 0, 0}, {55, 124, 7, 3, 0, 1, 0}},
      {KernelFamily::inverse, 4, &scalis_segment_inverse_i4_f<T>, &scalis_segment_inverse_i4_grad<T>, &scalis_segment_inverse_i4_f_and_grad<T>, "scalis_segment_inverse_i4",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−4), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]", {42, 77, 5, 2, 1, 1, 0}, {60, 131, 6, 2, 1, 0, 0}, {66, 156, 6, 2, 1, 1, 0}},
      {KernelFamily::inverse, 5, &scalis_segment_inverse_i5_f<T>, &scalis_segment_inverse_i5_grad<T>, &scalis_segment_inverse_i5_f_and_grad<T>, "scalis_segment_inverse_i5",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−5), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]", {48, 109, 6, 3, 0, 1, 0}, {68, 177, 5, 3, 0, 0, 0}, {77, 215, 7, 3, 0, 1, 0}},
      {KernelFamily::inverse, 6, &scalis_segment_inverse_i6_f<T>, &scalis_segment_inverse_i6_grad<T>, &scalis_segment_inverse_i6_f_and_grad<T>, "scalis_segment_inverse_i6",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−6), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]", {56, 131, 5, 2, 1, 1, 0}, {80, 204, 6, 2, 1, 0, 0}, {90, 244, 6, 2, 1, 1, 0}},
      {KernelFamily::inverse, 7, &scalis_segment_inverse_i7_f<T>, &scalis_segment_inverse_i7_grad<T>, &scalis_segment_inverse_i7_f_and_grad<T>, "scalis_segment_inverse_i7",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−7), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]", {64, 172, 6, 3, 0, 1, 0}, {90, 265, 5, 3, 0, 0, 0}, {103, 316, 7, 3, 0, 1, 0}},
      {KernelFamily::inverse, 8, &scalis_segment_inverse_i8_f<T>, &scalis_segment_inverse_i8_grad<T>, &scalis_segment_inverse_i8_f_and_grad<T>, "scalis_segment_inverse_i8",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−8), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]", {74, 198, 5, 2, 1, 1, 0}, {104, 290, 6, 2, 1, 0, 0}, {118, 345, 6, 2, 1, 1, 0}},
      {KernelFamily::inverse, 9, &scalis_segment_inverse_i9_f<T>, &scalis_segment_inverse_i9_grad<T>, &scalis_segment_inverse_i9_f_and_grad<T>, "scalis_segment_inverse_i9",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−9), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]", {84, 254, 6, 3, 0, 1, 0}, {116, 362, 5, 3, 0, 0, 0}, {133, 430, 7, 3, 0, 1, 0}},
      {KernelFamily::inverse, 10, &scalis_segment_inverse_i10_f<T>, &scalis_segment_inverse_i10_grad<T>, &scalis_segment_inverse_i10_f_and_grad<T>, "scalis_segment_inverse_i10",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−10), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]", {96, 280, 5, 2, 1, 1, 0}, {132, 393, 6, 2, 1, 0, 0}, {150, 463, 6, 2, 1, 1, 0}},
      {KernelFamily::cauchy, 2, &scalis_segment_cauchy_i2_f<T>, &scalis_segment_cauchy_i2_grad<T>, &scalis_segment_cauchy_i2_f_and_grad<T>, "scalis_segment_cauchy_i2",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−2/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|² + σ²τ²)^(−2/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]", {44, 64, 3, 2, 1, 1, 0}, {56, 89, 6, 2, 1, 0, 0}, {58, 98, 6, 2, 1, 1, 0}},
      {KernelFamily::cauchy, 3, &scalis_segment_cauchy_i3_f<T>, &scalis_segment_cauchy_i3_grad<T>, &scalis_segment_cauchy_i3_f_and_grad<T>, "scalis_segment_cauchy_i3",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−3/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|² + σ²τ²)^(−3/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]", {47, 78, 6, 5, 0, 1, 0}, {61, 119, 5, 3, 0, 0, 0}, {66, 141, 7, 5, 0, 1, 0}},
      {KernelFamily::cauchy, 4, &scalis_segment_cauchy_i4_f<T>, &scalis_segment_cauchy_i4_grad<T>, &scalis_segment_cauchy_i4_f_and_grad<T>, "scalis_segment_cauchy_i4",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−4/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|² + σ²τ²)^(−4/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]", {54, 97, 5, 2, 1, 1, 0}, {72, 149, 6, 2, 1, 0, 0}, {78, 174, 6, 2, 1, 1, 0}},
      {KernelFamily::cauchy, 5, &scalis_segment_cauchy_i5_f<T>, &scalis_segment_cauchy_i5_grad<T>, &scalis_segment_cauchy_i5_f_and_grad<T>, "scalis_segment_cauchy_i5",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−5/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|² + σ²τ²)^(−5/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]", {59, 127, 6, 5, 0, 1, 0}, {79, 193, 5, 3, 0, 0, 0}, {88, 232, 7, 5, 0, 1, 0}},
      {KernelFamily::cauchy, 6, &scalis_segment_cauchy_i6_f<T>, &scalis_segment_cauchy_i6_grad<T>, &scalis_segment_cauchy_i6_f_and_grad<T>, "scalis_segment_cauchy_i6",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−6/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|² + σ²τ²)^(−6/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]", {68, 151, 5, 2, 1, 1, 0}, {92, 222, 6, 2, 1, 0, 0}, {102, 262, 6, 2, 1, 1, 0}},
      {KernelFamily::cauchy, 7, &scalis_segment_cauchy_i7_f<T>, &scalis_segment_cauchy_i7_grad<T>, &scalis_segment_cauchy_i7_f_and_grad<T>, "scalis_segment_cauchy_i7",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−7/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|² + σ²τ²)^(−7/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]", {75, 190, 6, 5, 0, 1, 0}, {101, 281, 5, 3, 0, 0, 0}, {114, 333, 7, 5, 0, 1, 0}},
      {KernelFamily::cauchy, 8, &scalis_segment_cauchy_i8_f<T>, &scalis_segment_cauchy_i8_grad<T>, &scalis_segment_cauchy_i8_f_and_grad<T>, "scalis_segment_cauchy_i8",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−8/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|² + σ²τ²)^(−8/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]", {86, 218, 5, 2, 1, 1, 0}, {116, 308, 6, 2, 1, 0, 0}, {130, 363, 6, 2, 1, 1, 0}},
      {KernelFamily::cauchy, 9, &scalis_segment_cauchy_i9_f<T>, &scalis_segment_cauchy_i9_grad<T>, &scalis_segment_cauchy_i9_f_and_grad<T>, "scalis_segment_cauchy_i9",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−9/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|² + σ²τ²)^(−9/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]", {95, 272, 6, 5, 0, 1, 0}, {127, 378, 5, 3, 0, 0, 0}, {144, 447, 7, 5, 0, 1, 0}},
      {KernelFamily::cauchy, 10, &scalis_segment_cauchy_i10_f<T>, &scalis_segment_cauchy_i10_grad<T>, &scalis_segment_cauchy_i10_f_and_grad<T>, "scalis_segment_cauchy_i10",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−10/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|² + σ²τ²)^(−10/2) dt; SPEC §4, Zanni 2013 eq. 13, Table 3]", {108, 300, 5, 2, 1, 1, 0}, {144, 411, 6, 2, 1, 0, 0}, {162, 481, 6, 2, 1, 1, 0}},
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
