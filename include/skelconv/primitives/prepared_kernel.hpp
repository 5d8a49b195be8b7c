// skelconv/primitives/prepared_kernel.hpp — one point of a generated kernel
// that is split into a preparation, once per primitive, and an evaluation at
// each point (generated/segment_table.hpp, generated/scalis_segment_table.hpp).
// The tables' one-point functions (`f`, `grad`, `f_and_grad`) are these
// wrappers, for the callers that evaluate a primitive at one point: the
// verifier, the tests, the benchmarks.
#pragma once

#include <array>
#include <cstddef>

#include "skelconv/primitives/scalis_segment_input.hpp"
#include "skelconv/primitives/segment_input.hpp"

namespace skelconv::generated {

/// What an evaluation reads at each point: P and the compact clip for a
/// segment, P for a SCALIS segment.
template <class T>
SegmentPoint<T> point_of(const SegmentInput<T>& in) {
  return {in.p, in.t0, in.t1};
}
template <class T>
const std::array<T, 3>& point_of(const ScalisSegmentInput<T>& in) {
  return in.p;
}

/// f, ∇f or both at the point of `in`: `prepare` into N values, then `evaluate`.
template <class T, std::size_t N, auto prepare, auto evaluate, class Input>
T prepared_f(const Input& in) {
  std::array<T, N> pre;
  prepare(in, pre.data());
  return evaluate(pre.data(), point_of(in));
}
template <class T, std::size_t N, auto prepare, auto evaluate, class Input>
std::array<T, 3> prepared_grad(const Input& in) {
  std::array<T, N> pre;
  prepare(in, pre.data());
  return evaluate(pre.data(), point_of(in));
}
template <class T, std::size_t N, auto prepare, auto evaluate, class Input>
T prepared_f_and_grad(const Input& in, std::array<T, 3>& grad) {
  std::array<T, N> pre;
  prepare(in, pre.data());
  return evaluate(pre.data(), point_of(in), grad);
}

}  // namespace skelconv::generated
