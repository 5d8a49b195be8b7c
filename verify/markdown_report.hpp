// verify/markdown_report.hpp — a sweep's report as Markdown, for a person
// (a CI job summary, a pull request): one table per family, degree × region,
// the worst relative error of f and of |∇f| in double over the weight degrees.
#pragma once

#include <iosfwd>

#include "sweep.hpp"

namespace skelconv::verify {

/// Marks: ❌ a generic cell above its (asserted) target; ⚠ a cell of another
/// region above the generic targets (reported only: those regions have no
/// target, the mark says where the digits go).
void write_markdown_report(std::ostream& out, const SweepOptions& options, const SweepResult& result);

}  // namespace skelconv::verify
