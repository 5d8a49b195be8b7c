// skelconv/errors.hpp — the exceptions the runtime throws.
//
// Both carry a *location* ("where") separate from the *problem*, so that a
// layer that knows more context can prepend it without re-parsing text:
// Segment's constructor says `kernel.R: must be > 0, got -1`, and the JSON
// reader turns that into `primitives[2].kernel.R: must be > 0, got -1`.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace skelconv {

/// Joins two location paths: ("primitives[2]", "kernel.R") gives
/// "primitives[2].kernel.R"; an index ("[1]") is appended without a dot.
std::string join_location(std::string_view outer, std::string_view inner);

/// Common base: what() is "where: problem", or just "problem" when where is
/// empty.
class LocatedError : public std::runtime_error {
 public:
  LocatedError(std::string problem, std::string where);

  /// The location, e.g. "primitives[2].kernel.R"; may be empty.
  const std::string& where() const noexcept { return where_; }
  /// The problem without the location, e.g. "must be > 0, got -1".
  const std::string& problem() const noexcept { return problem_; }

 private:
  std::string problem_;
  std::string where_;
};

/// The user's input is invalid: a bad skeleton (file or C++ arguments), a bad
/// query point. The CLI reports these with exit code 2.
struct InputError : LocatedError {
  explicit InputError(std::string problem, std::string where = {})
      : LocatedError(std::move(problem), std::move(where)) {}

  /// The same error, located inside `outer`.
  InputError inside(std::string_view outer) const {
    return InputError(problem(), join_location(outer, where()));
  }
};

/// Valid input, but the field could not be evaluated in double precision:
/// a generated kernel returned NaN or infinity where the field is finite
/// (e.g. a point so close to an inverse-kernel segment, or coordinates so
/// large, that intermediate quantities overflow). The runtime never returns
/// NaN; it throws this instead.
struct EvaluationError : LocatedError {
  explicit EvaluationError(std::string problem, std::string where = {})
      : LocatedError(std::move(problem), std::move(where)) {}

  /// The same error, located inside `outer`.
  EvaluationError inside(std::string_view outer) const {
    return EvaluationError(problem(), join_location(outer, where()));
  }
};

}  // namespace skelconv
