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
#include <skelconv/primitives/prepared_kernel.hpp>
#include <skelconv/primitives/segment_input.hpp>

#include "generated/scalis_segment_inverse.hpp"
#include "generated/scalis_segment_cauchy.hpp"

namespace skelconv::generated {

/// One generated SCALIS segment kernel: F, ∇F and both (unnormalised), with their operation counts.
/// Split in two like SegmentKernel (segment_table.hpp): `prepare` once per segment,
/// `f_at`, `grad_at`, `f_and_grad_at` at each point P (in the input's frame); `f`,
/// `grad` and `f_and_grad` do both for one point. The ops_* counts are per point;
/// ops_prepare is the preparation's, once per segment.
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
  OpCount ops_prepare{};
  std::size_t prepared_size = 0;
  void (*prepare)(const ScalisSegmentInput<T>&, T*) = nullptr;
  T (*f_at)(const T*, const std::array<T, 3>&) = nullptr;
  std::array<T, 3> (*grad_at)(const T*, const std::array<T, 3>&) = nullptr;
  T (*f_and_grad_at)(const T*, const std::array<T, 3>&, std::array<T, 3>&) = nullptr;
};

/// Every generated SCALIS segment kernel, sorted by family and degree.
template <class T>
std::span<const ScalisSegmentKernel<T>> scalis_segment_kernels() {
  static const ScalisSegmentKernel<T> table[] = {
      {KernelFamily::inverse, 2,
       &prepared_f<T, scalis_segment_inverse_i2_prepared_size, &scalis_segment_inverse_i2_prepare<T>, &scalis_segment_inverse_i2_f<T>>,
       &prepared_grad<T, scalis_segment_inverse_i2_prepared_size, &scalis_segment_inverse_i2_prepare<T>, &scalis_segment_inverse_i2_grad<T>>,
       &prepared_f_and_grad<T, scalis_segment_inverse_i2_prepared_size, &scalis_segment_inverse_i2_prepare<T>, &scalis_segment_inverse_i2_f_and_grad<T>>,
       "scalis_segment_inverse_i2",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|²)^(−2/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {29, 42, 2, 1, 1, 1, 0}, {40, 66, 4, 1, 1, 0, 0}, {42, 75, 4, 1, 1, 1, 0},
       {7, 7, 1, 1, 0, 0, 0}, scalis_segment_inverse_i2_prepared_size, &scalis_segment_inverse_i2_prepare<T>, &scalis_segment_inverse_i2_f<T>, &scalis_segment_inverse_i2_grad<T>, &scalis_segment_inverse_i2_f_and_grad<T>},
      {KernelFamily::inverse, 3,
       &prepared_f<T, scalis_segment_inverse_i3_prepared_size, &scalis_segment_inverse_i3_prepare<T>, &scalis_segment_inverse_i3_f<T>>,
       &prepared_grad<T, scalis_segment_inverse_i3_prepared_size, &scalis_segment_inverse_i3_prepare<T>, &scalis_segment_inverse_i3_grad<T>>,
       &prepared_f_and_grad<T, scalis_segment_inverse_i3_prepared_size, &scalis_segment_inverse_i3_prepare<T>, &scalis_segment_inverse_i3_f_and_grad<T>>,
       "scalis_segment_inverse_i3",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−3), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|²)^(−3/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {33, 56, 4, 2, 0, 1, 0}, {45, 95, 3, 2, 0, 0, 0}, {50, 116, 4, 2, 0, 1, 0},
       {8, 12, 2, 1, 0, 0, 0}, scalis_segment_inverse_i3_prepared_size, &scalis_segment_inverse_i3_prepare<T>, &scalis_segment_inverse_i3_f<T>, &scalis_segment_inverse_i3_grad<T>, &scalis_segment_inverse_i3_f_and_grad<T>},
      {KernelFamily::inverse, 4,
       &prepared_f<T, scalis_segment_inverse_i4_prepared_size, &scalis_segment_inverse_i4_prepare<T>, &scalis_segment_inverse_i4_f<T>>,
       &prepared_grad<T, scalis_segment_inverse_i4_prepared_size, &scalis_segment_inverse_i4_prepare<T>, &scalis_segment_inverse_i4_grad<T>>,
       &prepared_f_and_grad<T, scalis_segment_inverse_i4_prepared_size, &scalis_segment_inverse_i4_prepare<T>, &scalis_segment_inverse_i4_f_and_grad<T>>,
       "scalis_segment_inverse_i4",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−4), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|²)^(−4/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {39, 71, 4, 1, 1, 1, 0}, {54, 119, 4, 1, 1, 0, 0}, {60, 144, 4, 1, 1, 1, 0},
       {9, 16, 1, 1, 0, 0, 0}, scalis_segment_inverse_i4_prepared_size, &scalis_segment_inverse_i4_prepare<T>, &scalis_segment_inverse_i4_f<T>, &scalis_segment_inverse_i4_grad<T>, &scalis_segment_inverse_i4_f_and_grad<T>},
      {KernelFamily::inverse, 5,
       &prepared_f<T, scalis_segment_inverse_i5_prepared_size, &scalis_segment_inverse_i5_prepare<T>, &scalis_segment_inverse_i5_f<T>>,
       &prepared_grad<T, scalis_segment_inverse_i5_prepared_size, &scalis_segment_inverse_i5_prepare<T>, &scalis_segment_inverse_i5_grad<T>>,
       &prepared_f_and_grad<T, scalis_segment_inverse_i5_prepared_size, &scalis_segment_inverse_i5_prepare<T>, &scalis_segment_inverse_i5_f_and_grad<T>>,
       "scalis_segment_inverse_i5",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−5), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|²)^(−5/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {45, 100, 4, 2, 0, 1, 0}, {61, 160, 3, 2, 0, 0, 0}, {70, 198, 4, 2, 0, 1, 0},
       {10, 21, 2, 1, 0, 0, 0}, scalis_segment_inverse_i5_prepared_size, &scalis_segment_inverse_i5_prepare<T>, &scalis_segment_inverse_i5_f<T>, &scalis_segment_inverse_i5_grad<T>, &scalis_segment_inverse_i5_f_and_grad<T>},
      {KernelFamily::inverse, 6,
       &prepared_f<T, scalis_segment_inverse_i6_prepared_size, &scalis_segment_inverse_i6_prepare<T>, &scalis_segment_inverse_i6_f<T>>,
       &prepared_grad<T, scalis_segment_inverse_i6_prepared_size, &scalis_segment_inverse_i6_prepare<T>, &scalis_segment_inverse_i6_grad<T>>,
       &prepared_f_and_grad<T, scalis_segment_inverse_i6_prepared_size, &scalis_segment_inverse_i6_prepare<T>, &scalis_segment_inverse_i6_f_and_grad<T>>,
       "scalis_segment_inverse_i6",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−6), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|²)^(−6/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {53, 120, 4, 1, 1, 1, 0}, {72, 183, 4, 1, 1, 0, 0}, {82, 223, 4, 1, 1, 1, 0},
       {11, 25, 1, 1, 0, 0, 0}, scalis_segment_inverse_i6_prepared_size, &scalis_segment_inverse_i6_prepare<T>, &scalis_segment_inverse_i6_f<T>, &scalis_segment_inverse_i6_grad<T>, &scalis_segment_inverse_i6_f_and_grad<T>},
      {KernelFamily::inverse, 7,
       &prepared_f<T, scalis_segment_inverse_i7_prepared_size, &scalis_segment_inverse_i7_prepare<T>, &scalis_segment_inverse_i7_f<T>>,
       &prepared_grad<T, scalis_segment_inverse_i7_prepared_size, &scalis_segment_inverse_i7_prepare<T>, &scalis_segment_inverse_i7_grad<T>>,
       &prepared_f_and_grad<T, scalis_segment_inverse_i7_prepared_size, &scalis_segment_inverse_i7_prepare<T>, &scalis_segment_inverse_i7_f_and_grad<T>>,
       "scalis_segment_inverse_i7",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−7), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|²)^(−7/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {61, 158, 4, 2, 0, 1, 0}, {81, 239, 3, 2, 0, 0, 0}, {94, 290, 4, 2, 0, 1, 0},
       {12, 30, 2, 1, 0, 0, 0}, scalis_segment_inverse_i7_prepared_size, &scalis_segment_inverse_i7_prepare<T>, &scalis_segment_inverse_i7_f<T>, &scalis_segment_inverse_i7_grad<T>, &scalis_segment_inverse_i7_f_and_grad<T>},
      {KernelFamily::inverse, 8,
       &prepared_f<T, scalis_segment_inverse_i8_prepared_size, &scalis_segment_inverse_i8_prepare<T>, &scalis_segment_inverse_i8_f<T>>,
       &prepared_grad<T, scalis_segment_inverse_i8_prepared_size, &scalis_segment_inverse_i8_prepare<T>, &scalis_segment_inverse_i8_grad<T>>,
       &prepared_f_and_grad<T, scalis_segment_inverse_i8_prepared_size, &scalis_segment_inverse_i8_prepare<T>, &scalis_segment_inverse_i8_f_and_grad<T>>,
       "scalis_segment_inverse_i8",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−8), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|²)^(−8/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {71, 183, 4, 1, 1, 1, 0}, {94, 261, 4, 1, 1, 0, 0}, {108, 316, 4, 1, 1, 1, 0},
       {13, 33, 1, 1, 0, 0, 0}, scalis_segment_inverse_i8_prepared_size, &scalis_segment_inverse_i8_prepare<T>, &scalis_segment_inverse_i8_f<T>, &scalis_segment_inverse_i8_grad<T>, &scalis_segment_inverse_i8_f_and_grad<T>},
      {KernelFamily::inverse, 9,
       &prepared_f<T, scalis_segment_inverse_i9_prepared_size, &scalis_segment_inverse_i9_prepare<T>, &scalis_segment_inverse_i9_f<T>>,
       &prepared_grad<T, scalis_segment_inverse_i9_prepared_size, &scalis_segment_inverse_i9_prepare<T>, &scalis_segment_inverse_i9_grad<T>>,
       &prepared_f_and_grad<T, scalis_segment_inverse_i9_prepared_size, &scalis_segment_inverse_i9_prepare<T>, &scalis_segment_inverse_i9_f_and_grad<T>>,
       "scalis_segment_inverse_i9",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−9), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|²)^(−9/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {81, 236, 4, 2, 0, 1, 0}, {105, 328, 3, 2, 0, 0, 0}, {122, 396, 4, 2, 0, 1, 0},
       {14, 38, 2, 1, 0, 0, 0}, scalis_segment_inverse_i9_prepared_size, &scalis_segment_inverse_i9_prepare<T>, &scalis_segment_inverse_i9_f<T>, &scalis_segment_inverse_i9_grad<T>, &scalis_segment_inverse_i9_f_and_grad<T>},
      {KernelFamily::inverse, 10,
       &prepared_f<T, scalis_segment_inverse_i10_prepared_size, &scalis_segment_inverse_i10_prepare<T>, &scalis_segment_inverse_i10_f<T>>,
       &prepared_grad<T, scalis_segment_inverse_i10_prepared_size, &scalis_segment_inverse_i10_prepare<T>, &scalis_segment_inverse_i10_grad<T>>,
       &prepared_f_and_grad<T, scalis_segment_inverse_i10_prepared_size, &scalis_segment_inverse_i10_prepare<T>, &scalis_segment_inverse_i10_f_and_grad<T>>,
       "scalis_segment_inverse_i10",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (d/σ)^(−10), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|²)^(−10/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {93, 260, 4, 1, 1, 1, 0}, {120, 355, 4, 1, 1, 0, 0}, {138, 425, 4, 1, 1, 1, 0},
       {15, 42, 1, 1, 0, 0, 0}, scalis_segment_inverse_i10_prepared_size, &scalis_segment_inverse_i10_prepare<T>, &scalis_segment_inverse_i10_f<T>, &scalis_segment_inverse_i10_grad<T>, &scalis_segment_inverse_i10_f_and_grad<T>},
      {KernelFamily::cauchy, 2,
       &prepared_f<T, scalis_segment_cauchy_i2_prepared_size, &scalis_segment_cauchy_i2_prepare<T>, &scalis_segment_cauchy_i2_f<T>>,
       &prepared_grad<T, scalis_segment_cauchy_i2_prepared_size, &scalis_segment_cauchy_i2_prepare<T>, &scalis_segment_cauchy_i2_grad<T>>,
       &prepared_f_and_grad<T, scalis_segment_cauchy_i2_prepared_size, &scalis_segment_cauchy_i2_prepare<T>, &scalis_segment_cauchy_i2_f_and_grad<T>>,
       "scalis_segment_cauchy_i2",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−2/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^2 |AB| ∫_0^1 τ^1 (|P − Γ|² + σ²τ²)^(−2/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {40, 49, 2, 1, 1, 1, 0}, {55, 81, 4, 1, 1, 0, 0}, {57, 90, 4, 1, 1, 1, 0},
       {8, 23, 2, 1, 0, 0, 0}, scalis_segment_cauchy_i2_prepared_size, &scalis_segment_cauchy_i2_prepare<T>, &scalis_segment_cauchy_i2_f<T>, &scalis_segment_cauchy_i2_grad<T>, &scalis_segment_cauchy_i2_f_and_grad<T>},
      {KernelFamily::cauchy, 3,
       &prepared_f<T, scalis_segment_cauchy_i3_prepared_size, &scalis_segment_cauchy_i3_prepare<T>, &scalis_segment_cauchy_i3_f<T>>,
       &prepared_grad<T, scalis_segment_cauchy_i3_prepared_size, &scalis_segment_cauchy_i3_prepare<T>, &scalis_segment_cauchy_i3_grad<T>>,
       &prepared_f_and_grad<T, scalis_segment_cauchy_i3_prepared_size, &scalis_segment_cauchy_i3_prepare<T>, &scalis_segment_cauchy_i3_f_and_grad<T>>,
       "scalis_segment_cauchy_i3",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−3/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^3 |AB| ∫_0^1 τ^2 (|P − Γ|² + σ²τ²)^(−3/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {43, 64, 4, 2, 0, 1, 0}, {59, 110, 3, 2, 0, 0, 0}, {64, 132, 4, 2, 0, 1, 0},
       {9, 24, 3, 2, 0, 0, 0}, scalis_segment_cauchy_i3_prepared_size, &scalis_segment_cauchy_i3_prepare<T>, &scalis_segment_cauchy_i3_f<T>, &scalis_segment_cauchy_i3_grad<T>, &scalis_segment_cauchy_i3_f_and_grad<T>},
      {KernelFamily::cauchy, 4,
       &prepared_f<T, scalis_segment_cauchy_i4_prepared_size, &scalis_segment_cauchy_i4_prepare<T>, &scalis_segment_cauchy_i4_f<T>>,
       &prepared_grad<T, scalis_segment_cauchy_i4_prepared_size, &scalis_segment_cauchy_i4_prepare<T>, &scalis_segment_cauchy_i4_grad<T>>,
       &prepared_f_and_grad<T, scalis_segment_cauchy_i4_prepared_size, &scalis_segment_cauchy_i4_prepare<T>, &scalis_segment_cauchy_i4_f_and_grad<T>>,
       "scalis_segment_cauchy_i4",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−4/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^4 |AB| ∫_0^1 τ^3 (|P − Γ|² + σ²τ²)^(−4/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {50, 78, 4, 1, 1, 1, 0}, {69, 134, 4, 1, 1, 0, 0}, {75, 159, 4, 1, 1, 1, 0},
       {10, 30, 2, 1, 0, 0, 0}, scalis_segment_cauchy_i4_prepared_size, &scalis_segment_cauchy_i4_prepare<T>, &scalis_segment_cauchy_i4_f<T>, &scalis_segment_cauchy_i4_grad<T>, &scalis_segment_cauchy_i4_f_and_grad<T>},
      {KernelFamily::cauchy, 5,
       &prepared_f<T, scalis_segment_cauchy_i5_prepared_size, &scalis_segment_cauchy_i5_prepare<T>, &scalis_segment_cauchy_i5_f<T>>,
       &prepared_grad<T, scalis_segment_cauchy_i5_prepared_size, &scalis_segment_cauchy_i5_prepare<T>, &scalis_segment_cauchy_i5_grad<T>>,
       &prepared_f_and_grad<T, scalis_segment_cauchy_i5_prepared_size, &scalis_segment_cauchy_i5_prepare<T>, &scalis_segment_cauchy_i5_f_and_grad<T>>,
       "scalis_segment_cauchy_i5",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−5/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^5 |AB| ∫_0^1 τ^4 (|P − Γ|² + σ²τ²)^(−5/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {55, 108, 4, 2, 0, 1, 0}, {75, 175, 3, 2, 0, 0, 0}, {84, 214, 4, 2, 0, 1, 0},
       {11, 33, 3, 2, 0, 0, 0}, scalis_segment_cauchy_i5_prepared_size, &scalis_segment_cauchy_i5_prepare<T>, &scalis_segment_cauchy_i5_f<T>, &scalis_segment_cauchy_i5_grad<T>, &scalis_segment_cauchy_i5_f_and_grad<T>},
      {KernelFamily::cauchy, 6,
       &prepared_f<T, scalis_segment_cauchy_i6_prepared_size, &scalis_segment_cauchy_i6_prepare<T>, &scalis_segment_cauchy_i6_f<T>>,
       &prepared_grad<T, scalis_segment_cauchy_i6_prepared_size, &scalis_segment_cauchy_i6_prepare<T>, &scalis_segment_cauchy_i6_grad<T>>,
       &prepared_f_and_grad<T, scalis_segment_cauchy_i6_prepared_size, &scalis_segment_cauchy_i6_prepare<T>, &scalis_segment_cauchy_i6_f_and_grad<T>>,
       "scalis_segment_cauchy_i6",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−6/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^6 |AB| ∫_0^1 τ^5 (|P − Γ|² + σ²τ²)^(−6/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {64, 127, 4, 1, 1, 1, 0}, {87, 198, 4, 1, 1, 0, 0}, {97, 238, 4, 1, 1, 1, 0},
       {12, 39, 2, 1, 0, 0, 0}, scalis_segment_cauchy_i6_prepared_size, &scalis_segment_cauchy_i6_prepare<T>, &scalis_segment_cauchy_i6_f<T>, &scalis_segment_cauchy_i6_grad<T>, &scalis_segment_cauchy_i6_f_and_grad<T>},
      {KernelFamily::cauchy, 7,
       &prepared_f<T, scalis_segment_cauchy_i7_prepared_size, &scalis_segment_cauchy_i7_prepare<T>, &scalis_segment_cauchy_i7_f<T>>,
       &prepared_grad<T, scalis_segment_cauchy_i7_prepared_size, &scalis_segment_cauchy_i7_prepare<T>, &scalis_segment_cauchy_i7_grad<T>>,
       &prepared_f_and_grad<T, scalis_segment_cauchy_i7_prepared_size, &scalis_segment_cauchy_i7_prepare<T>, &scalis_segment_cauchy_i7_f_and_grad<T>>,
       "scalis_segment_cauchy_i7",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−7/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^7 |AB| ∫_0^1 τ^6 (|P − Γ|² + σ²τ²)^(−7/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {71, 166, 4, 2, 0, 1, 0}, {95, 254, 3, 2, 0, 0, 0}, {108, 306, 4, 2, 0, 1, 0},
       {13, 42, 3, 2, 0, 0, 0}, scalis_segment_cauchy_i7_prepared_size, &scalis_segment_cauchy_i7_prepare<T>, &scalis_segment_cauchy_i7_f<T>, &scalis_segment_cauchy_i7_grad<T>, &scalis_segment_cauchy_i7_f_and_grad<T>},
      {KernelFamily::cauchy, 8,
       &prepared_f<T, scalis_segment_cauchy_i8_prepared_size, &scalis_segment_cauchy_i8_prepare<T>, &scalis_segment_cauchy_i8_f<T>>,
       &prepared_grad<T, scalis_segment_cauchy_i8_prepared_size, &scalis_segment_cauchy_i8_prepare<T>, &scalis_segment_cauchy_i8_grad<T>>,
       &prepared_f_and_grad<T, scalis_segment_cauchy_i8_prepared_size, &scalis_segment_cauchy_i8_prepare<T>, &scalis_segment_cauchy_i8_f_and_grad<T>>,
       "scalis_segment_cauchy_i8",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−8/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^8 |AB| ∫_0^1 τ^7 (|P − Γ|² + σ²τ²)^(−8/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {82, 190, 4, 1, 1, 1, 0}, {109, 276, 4, 1, 1, 0, 0}, {123, 331, 4, 1, 1, 1, 0},
       {14, 47, 2, 1, 0, 0, 0}, scalis_segment_cauchy_i8_prepared_size, &scalis_segment_cauchy_i8_prepare<T>, &scalis_segment_cauchy_i8_f<T>, &scalis_segment_cauchy_i8_grad<T>, &scalis_segment_cauchy_i8_f_and_grad<T>},
      {KernelFamily::cauchy, 9,
       &prepared_f<T, scalis_segment_cauchy_i9_prepared_size, &scalis_segment_cauchy_i9_prepare<T>, &scalis_segment_cauchy_i9_f<T>>,
       &prepared_grad<T, scalis_segment_cauchy_i9_prepared_size, &scalis_segment_cauchy_i9_prepare<T>, &scalis_segment_cauchy_i9_grad<T>>,
       &prepared_f_and_grad<T, scalis_segment_cauchy_i9_prepared_size, &scalis_segment_cauchy_i9_prepare<T>, &scalis_segment_cauchy_i9_f_and_grad<T>>,
       "scalis_segment_cauchy_i9",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−9/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^9 |AB| ∫_0^1 τ^8 (|P − Γ|² + σ²τ²)^(−9/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {91, 244, 4, 2, 0, 1, 0}, {119, 343, 3, 2, 0, 0, 0}, {136, 412, 4, 2, 0, 1, 0},
       {15, 50, 3, 2, 0, 0, 0}, scalis_segment_cauchy_i9_prepared_size, &scalis_segment_cauchy_i9_prepare<T>, &scalis_segment_cauchy_i9_f<T>, &scalis_segment_cauchy_i9_grad<T>, &scalis_segment_cauchy_i9_f_and_grad<T>},
      {KernelFamily::cauchy, 10,
       &prepared_f<T, scalis_segment_cauchy_i10_prepared_size, &scalis_segment_cauchy_i10_prepare<T>, &scalis_segment_cauchy_i10_f<T>>,
       &prepared_grad<T, scalis_segment_cauchy_i10_prepared_size, &scalis_segment_cauchy_i10_prepare<T>, &scalis_segment_cauchy_i10_grad<T>>,
       &prepared_f_and_grad<T, scalis_segment_cauchy_i10_prepared_size, &scalis_segment_cauchy_i10_prepare<T>, &scalis_segment_cauchy_i10_f_and_grad<T>>,
       "scalis_segment_cauchy_i10",
       "F(P) = ∫_0^1 K(|P − Γ(t)|/τ(t)) |AB| dt/τ(t), K(d) = (1 + (d/σ)²)^(−10/2), τ(t) = τ0 + (τ1 − τ0) t  [= σ^10 |AB| ∫_0^1 τ^9 (|P − Γ|² + σ²τ²)^(−10/2) dt; docs/mathematics.md §4, Zanni 2013 eq. 13, Table 3]", {104, 267, 4, 1, 1, 1, 0}, {135, 370, 4, 1, 1, 0, 0}, {153, 440, 4, 1, 1, 1, 0},
       {16, 56, 2, 1, 0, 0, 0}, scalis_segment_cauchy_i10_prepared_size, &scalis_segment_cauchy_i10_prepare<T>, &scalis_segment_cauchy_i10_f<T>, &scalis_segment_cauchy_i10_grad<T>, &scalis_segment_cauchy_i10_f_and_grad<T>},
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
