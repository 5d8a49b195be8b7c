// skelconv/not_converged.hpp — what a numerical helper throws when it reaches
// its iteration cap before its own convergence criterion holds.
//
// The helpers behind the generated kernels (stable_recurrence.hpp's Miller
// runs, scalis_compact.hpp's Gauss panel bisection) stop at a fixed cap so
// that a call always ends. A result taken at the cap is not converged, so it
// must not be returned as if it were: the helper throws this instead. It is
// header-only (the helpers are templates used without the runtime library);
// the runtime turns it into skelconv::EvaluationError naming the kernel and
// the point (errors.hpp), which the CLI reports with exit status 1.
#pragma once

#include <stdexcept>
#include <string>

namespace skelconv {

struct NotConvergedError : std::runtime_error {
  explicit NotConvergedError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace skelconv
