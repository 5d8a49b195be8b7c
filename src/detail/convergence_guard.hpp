// src/detail/convergence_guard.hpp — where the runtime calls generated code
// (Segment, Polygon, ScalisSegment), a helper that reached its iteration cap
// (skelconv::NotConvergedError, skelconv/not_converged.hpp) becomes an
// EvaluationError naming the evaluator and the point: the CLI reports it as
// "could not be computed" (exit status 1), and no unconverged value escapes.
// Internal to skelconv_runtime.
#pragma once

#include <utility>

#include <fmt/format.h>

#include "input_checks.hpp"
#include "skelconv/errors.hpp"
#include "skelconv/not_converged.hpp"

namespace skelconv::detail {

/// Returns evaluate(); rethrows its NotConvergedError as EvaluationError
/// ("<evaluator> did not converge at P = (…): <helper's message>"). A C
/// string: a string_view would measure it at every evaluation.
template <class Evaluate>
[[gnu::always_inline]] inline decltype(auto) evaluate_converged(const char* evaluator, const Vec3& p, Evaluate&& evaluate) {
  try {
    return std::forward<Evaluate>(evaluate)();
  } catch (const NotConvergedError& error) {
    throw EvaluationError(fmt::format("{} did not converge at P = {}: {}", evaluator, format_point(p), error.what()));
  }
}

}  // namespace skelconv::detail
