// generated/polygon_table.hpp — every generated polygon edge kernel, for lookup at run time.
//
// GENERATED FILE: DO NOT EDIT. Regenerate with
//     skelconv-codegen --inverse 1:16 --cauchy 1:16 --compact 2:16 --weights 0:3 --polygon-inverse 3:12 --polygon-cauchy 3:12 --polygon-compact 4:12 --scalis-inverse 2:10 --scalis-cauchy 2:10 --scalis-compact 2:10 --out generated
// Generator: skelconv-codegen 0.1.0 (GiNaC 1.8.6)
// From: codegen/segment_families.cpp (the families) and codegen/segment_moments.cpp
// (recurrence (1) of Hubert & Cani unrolled; docs/mathematics.md §2, Hubert 2012 §3).
// Polygons (docs/mathematics.md §3, Hubert 2012 §5–8): the terms of one edge of the contour sum
// (codegen/polygon_families.cpp), on the segment forms of the edge;
// skelconv/primitives/polygon_field.hpp adds them up.
#pragma once

#include <span>

#include "generated/polygon_inverse.hpp"
#include "generated/polygon_cauchy.hpp"
#include "generated/polygon_compact.hpp"

namespace skelconv::generated {

/// One generated polygon edge kernel: the edge terms for f, ∇f and both, with their
/// operation counts per edge.
template <class T>
struct PolygonEdgeKernel {
  KernelFamily family;
  int degree;
  void (*f)(const PolygonEdgeInput<T>&, PolygonEdgeTerms<T>&);
  void (*grad)(const PolygonEdgeInput<T>&, PolygonEdgeTerms<T>&);
  void (*f_and_grad)(const PolygonEdgeInput<T>&, PolygonEdgeTerms<T>&);
  const char* name;
  const char* equation;
  OpCount ops_f, ops_grad, ops_f_and_grad;
};

/// Every generated polygon edge kernel, sorted by family and degree.
template <class T>
std::span<const PolygonEdgeKernel<T>> polygon_edge_kernels() {
  static const PolygonEdgeKernel<T> table[] = {
      {KernelFamily::inverse, 3, &polygon_edge_inverse_i3_f<T>, &polygon_edge_inverse_i3_grad<T>, &polygon_edge_inverse_i3_f_and_grad<T>, "polygon_edge_inverse_i3",
       "C(P) = ∬_Ω |P − Q|^(−3) dQ", {43, 50, 1, 3, 2, 0, 0}, {72, 78, 5, 3, 2, 0, 0}, {72, 78, 5, 3, 2, 0, 0}},
      {KernelFamily::inverse, 4, &polygon_edge_inverse_i4_f<T>, &polygon_edge_inverse_i4_grad<T>, &polygon_edge_inverse_i4_f_and_grad<T>, "polygon_edge_inverse_i4",
       "C(P) = ∬_Ω |P − Q|^(−4) dQ", {70, 69, 2, 1, 2, 0, 0}, {73, 76, 5, 1, 2, 0, 0}, {73, 76, 5, 1, 2, 0, 0}},
      {KernelFamily::inverse, 5, &polygon_edge_inverse_i5_f<T>, &polygon_edge_inverse_i5_grad<T>, &polygon_edge_inverse_i5_f_and_grad<T>, "polygon_edge_inverse_i5",
       "C(P) = ∬_Ω |P − Q|^(−5) dQ", {72, 78, 5, 3, 2, 0, 0}, {75, 91, 7, 3, 2, 0, 0}, {75, 91, 7, 3, 2, 0, 0}},
      {KernelFamily::inverse, 6, &polygon_edge_inverse_i6_f<T>, &polygon_edge_inverse_i6_grad<T>, &polygon_edge_inverse_i6_f_and_grad<T>, "polygon_edge_inverse_i6",
       "C(P) = ∬_Ω |P − Q|^(−6) dQ", {73, 76, 5, 1, 2, 0, 0}, {76, 91, 5, 1, 2, 0, 0}, {76, 91, 5, 1, 2, 0, 0}},
      {KernelFamily::inverse, 7, &polygon_edge_inverse_i7_f<T>, &polygon_edge_inverse_i7_grad<T>, &polygon_edge_inverse_i7_f_and_grad<T>, "polygon_edge_inverse_i7",
       "C(P) = ∬_Ω |P − Q|^(−7) dQ", {75, 91, 7, 3, 2, 0, 0}, {78, 110, 5, 3, 2, 0, 0}, {78, 110, 5, 3, 2, 0, 0}},
      {KernelFamily::inverse, 8, &polygon_edge_inverse_i8_f<T>, &polygon_edge_inverse_i8_grad<T>, &polygon_edge_inverse_i8_f_and_grad<T>, "polygon_edge_inverse_i8",
       "C(P) = ∬_Ω |P − Q|^(−8) dQ", {76, 91, 5, 1, 2, 0, 0}, {79, 104, 5, 1, 2, 0, 0}, {79, 104, 5, 1, 2, 0, 0}},
      {KernelFamily::inverse, 9, &polygon_edge_inverse_i9_f<T>, &polygon_edge_inverse_i9_grad<T>, &polygon_edge_inverse_i9_f_and_grad<T>, "polygon_edge_inverse_i9",
       "C(P) = ∬_Ω |P − Q|^(−9) dQ", {78, 110, 5, 3, 2, 0, 0}, {81, 125, 5, 3, 2, 0, 0}, {81, 125, 5, 3, 2, 0, 0}},
      {KernelFamily::inverse, 10, &polygon_edge_inverse_i10_f<T>, &polygon_edge_inverse_i10_grad<T>, &polygon_edge_inverse_i10_f_and_grad<T>, "polygon_edge_inverse_i10",
       "C(P) = ∬_Ω |P − Q|^(−10) dQ", {79, 104, 5, 1, 2, 0, 0}, {82, 117, 5, 1, 2, 0, 0}, {82, 117, 5, 1, 2, 0, 0}},
      {KernelFamily::inverse, 11, &polygon_edge_inverse_i11_f<T>, &polygon_edge_inverse_i11_grad<T>, &polygon_edge_inverse_i11_f_and_grad<T>, "polygon_edge_inverse_i11",
       "C(P) = ∬_Ω |P − Q|^(−11) dQ", {81, 125, 5, 3, 2, 0, 0}, {84, 140, 5, 3, 2, 0, 0}, {84, 140, 5, 3, 2, 0, 0}},
      {KernelFamily::inverse, 12, &polygon_edge_inverse_i12_f<T>, &polygon_edge_inverse_i12_grad<T>, &polygon_edge_inverse_i12_f_and_grad<T>, "polygon_edge_inverse_i12",
       "C(P) = ∬_Ω |P − Q|^(−12) dQ", {82, 117, 5, 1, 2, 0, 0}, {85, 130, 5, 1, 2, 0, 0}, {85, 130, 5, 1, 2, 0, 0}},
      {KernelFamily::cauchy, 3, &polygon_edge_cauchy_i3_f<T>, &polygon_edge_cauchy_i3_grad<T>, &polygon_edge_cauchy_i3_f_and_grad<T>, "polygon_edge_cauchy_i3",
       "C(P) = ∬_Ω (1 + s |P − Q|²)^(−3/2) dQ", {44, 59, 1, 3, 2, 0, 0}, {73, 87, 5, 3, 2, 0, 0}, {73, 87, 5, 3, 2, 0, 0}},
      {KernelFamily::cauchy, 4, &polygon_edge_cauchy_i4_f<T>, &polygon_edge_cauchy_i4_grad<T>, &polygon_edge_cauchy_i4_f_and_grad<T>, "polygon_edge_cauchy_i4",
       "C(P) = ∬_Ω (1 + s |P − Q|²)^(−4/2) dQ", {71, 79, 2, 1, 2, 0, 0}, {74, 86, 5, 1, 2, 0, 0}, {74, 86, 5, 1, 2, 0, 0}},
      {KernelFamily::cauchy, 5, &polygon_edge_cauchy_i5_f<T>, &polygon_edge_cauchy_i5_grad<T>, &polygon_edge_cauchy_i5_f_and_grad<T>, "polygon_edge_cauchy_i5",
       "C(P) = ∬_Ω (1 + s |P − Q|²)^(−5/2) dQ", {73, 87, 5, 3, 2, 0, 0}, {76, 100, 7, 3, 2, 0, 0}, {76, 100, 7, 3, 2, 0, 0}},
      {KernelFamily::cauchy, 6, &polygon_edge_cauchy_i6_f<T>, &polygon_edge_cauchy_i6_grad<T>, &polygon_edge_cauchy_i6_f_and_grad<T>, "polygon_edge_cauchy_i6",
       "C(P) = ∬_Ω (1 + s |P − Q|²)^(−6/2) dQ", {74, 86, 5, 1, 2, 0, 0}, {77, 101, 5, 1, 2, 0, 0}, {77, 101, 5, 1, 2, 0, 0}},
      {KernelFamily::cauchy, 7, &polygon_edge_cauchy_i7_f<T>, &polygon_edge_cauchy_i7_grad<T>, &polygon_edge_cauchy_i7_f_and_grad<T>, "polygon_edge_cauchy_i7",
       "C(P) = ∬_Ω (1 + s |P − Q|²)^(−7/2) dQ", {76, 100, 7, 3, 2, 0, 0}, {79, 119, 5, 3, 2, 0, 0}, {79, 119, 5, 3, 2, 0, 0}},
      {KernelFamily::cauchy, 8, &polygon_edge_cauchy_i8_f<T>, &polygon_edge_cauchy_i8_grad<T>, &polygon_edge_cauchy_i8_f_and_grad<T>, "polygon_edge_cauchy_i8",
       "C(P) = ∬_Ω (1 + s |P − Q|²)^(−8/2) dQ", {77, 101, 5, 1, 2, 0, 0}, {80, 114, 5, 1, 2, 0, 0}, {80, 114, 5, 1, 2, 0, 0}},
      {KernelFamily::cauchy, 9, &polygon_edge_cauchy_i9_f<T>, &polygon_edge_cauchy_i9_grad<T>, &polygon_edge_cauchy_i9_f_and_grad<T>, "polygon_edge_cauchy_i9",
       "C(P) = ∬_Ω (1 + s |P − Q|²)^(−9/2) dQ", {79, 119, 5, 3, 2, 0, 0}, {82, 134, 5, 3, 2, 0, 0}, {82, 134, 5, 3, 2, 0, 0}},
      {KernelFamily::cauchy, 10, &polygon_edge_cauchy_i10_f<T>, &polygon_edge_cauchy_i10_grad<T>, &polygon_edge_cauchy_i10_f_and_grad<T>, "polygon_edge_cauchy_i10",
       "C(P) = ∬_Ω (1 + s |P − Q|²)^(−10/2) dQ", {80, 114, 5, 1, 2, 0, 0}, {83, 127, 5, 1, 2, 0, 0}, {83, 127, 5, 1, 2, 0, 0}},
      {KernelFamily::cauchy, 11, &polygon_edge_cauchy_i11_f<T>, &polygon_edge_cauchy_i11_grad<T>, &polygon_edge_cauchy_i11_f_and_grad<T>, "polygon_edge_cauchy_i11",
       "C(P) = ∬_Ω (1 + s |P − Q|²)^(−11/2) dQ", {82, 134, 5, 3, 2, 0, 0}, {85, 149, 5, 3, 2, 0, 0}, {85, 149, 5, 3, 2, 0, 0}},
      {KernelFamily::cauchy, 12, &polygon_edge_cauchy_i12_f<T>, &polygon_edge_cauchy_i12_grad<T>, &polygon_edge_cauchy_i12_f_and_grad<T>, "polygon_edge_cauchy_i12",
       "C(P) = ∬_Ω (1 + s |P − Q|²)^(−12/2) dQ", {83, 127, 5, 1, 2, 0, 0}, {86, 140, 5, 1, 2, 0, 0}, {86, 140, 5, 1, 2, 0, 0}},
      {KernelFamily::compact, 4, &polygon_edge_compact_i4_f<T>, &polygon_edge_compact_i4_grad<T>, &polygon_edge_compact_i4_f_and_grad<T>, "polygon_edge_compact_i4",
       "C(P) = ∬_Ω (1 − |P − Q|²/R²)^(4/2) dQ", {87, 144, 3, 0, 2, 0, 0}, {86, 142, 3, 0, 2, 0, 0}, {88, 147, 3, 0, 2, 0, 0}},
      {KernelFamily::compact, 6, &polygon_edge_compact_i6_f<T>, &polygon_edge_compact_i6_grad<T>, &polygon_edge_compact_i6_f_and_grad<T>, "polygon_edge_compact_i6",
       "C(P) = ∬_Ω (1 − |P − Q|²/R²)^(6/2) dQ", {95, 161, 3, 0, 2, 0, 0}, {94, 158, 3, 0, 2, 0, 0}, {97, 164, 3, 0, 2, 0, 0}},
      {KernelFamily::compact, 8, &polygon_edge_compact_i8_f<T>, &polygon_edge_compact_i8_grad<T>, &polygon_edge_compact_i8_f_and_grad<T>, "polygon_edge_compact_i8",
       "C(P) = ∬_Ω (1 − |P − Q|²/R²)^(8/2) dQ", {103, 176, 3, 0, 2, 0, 0}, {102, 174, 3, 0, 2, 0, 0}, {106, 181, 3, 0, 2, 0, 0}},
      {KernelFamily::compact, 10, &polygon_edge_compact_i10_f<T>, &polygon_edge_compact_i10_grad<T>, &polygon_edge_compact_i10_f_and_grad<T>, "polygon_edge_compact_i10",
       "C(P) = ∬_Ω (1 − |P − Q|²/R²)^(10/2) dQ", {111, 192, 3, 0, 2, 0, 0}, {110, 191, 3, 0, 2, 0, 0}, {115, 198, 3, 0, 2, 0, 0}},
      {KernelFamily::compact, 12, &polygon_edge_compact_i12_f<T>, &polygon_edge_compact_i12_grad<T>, &polygon_edge_compact_i12_f_and_grad<T>, "polygon_edge_compact_i12",
       "C(P) = ∬_Ω (1 − |P − Q|²/R²)^(12/2) dQ", {119, 208, 3, 0, 2, 0, 0}, {118, 206, 3, 0, 2, 0, 0}, {124, 215, 3, 0, 2, 0, 0}},
  };
  return table;
}

/// The edge kernel for (family, degree), or nullptr if it was not generated.
template <class T>
const PolygonEdgeKernel<T>* find_polygon_edge_kernel(KernelFamily family, int degree) {
  for (const PolygonEdgeKernel<T>& k : polygon_edge_kernels<T>())
    if (k.family == family && k.degree == degree) return &k;
  return nullptr;
}

}  // namespace skelconv::generated
