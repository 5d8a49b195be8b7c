// Implementation of eval_command.hpp.
#include "eval_command.hpp"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "count_option.hpp"
#include "thread_option.hpp"
#include "exit_status.hpp"
#include "point_lines.hpp"
#include "progress_lines.hpp"
#include "tolerance_option.hpp"
#include "skelconv/detail/unsigned_zero.hpp"
#include "skelconv/errors.hpp"
#include "skelconv/field/batch.hpp"
#include "skelconv/skeleton/skeleton_file.hpp"

namespace skelconv::cli {
namespace {

constexpr const char* eval_footer = R"(
Input (stdin):  one point "x y z" per line, numbers separated by blanks;
                blank lines are skipped. At most --max-points points and
                4096 characters a line.
Output (stdout): one line "f gx gy gz" per point: the field f of the
                skeleton (the sum of the top-level primitives and blend
                nodes) and its gradient, printed with %.17g; the surface
                is where f equals the file's "iso" (default 1).
                Points are evaluated on every core (--threads), with the
                same output bytes whatever the thread count.
Progress (stderr): in a run longer than a second, about one line a second,
                "skelconv eval: read N points, T s" (then parsed,
                evaluated, formatted); none with --quiet.
                On an inverse-kernel segment or polygon itself f and the
                gradient are printed as "inf".
On any error nothing is written to stdout and one "skelconv: error: ..." line
to stderr; exit status 2 for bad input, 1 if a value cannot be computed in
double precision. Schema of SKELETON.json: see docs/cli.md.)";

/// Lines between two looks at the clock while the points are parsed.
constexpr std::size_t lines_between_clock_reads = 1 << 16;

/// The points of `input`, one per non-blank line, with their line numbers,
/// up to the first bad line (whose InputError, located at "line N", is
/// returned instead of thrown: a point before it may fail first).
struct PointList {
  std::vector<Vec3> points;
  std::vector<std::size_t> line_numbers;
  std::exception_ptr bad_line;
};

PointList read_points(std::string_view input, ProgressLines& progress) {
  PointList list;
  std::size_t line_number = 0;
  while (!input.empty()) {
    const std::size_t end = input.find('\n');
    const std::string_view line = input.substr(0, end);
    input.remove_prefix(end == std::string_view::npos ? input.size() : end + 1);
    ++line_number;
    if (line_number % lines_between_clock_reads == 0 && progress.due())
      progress.print(fmt::format("parsed {} points", list.points.size()));
    try {
      if (const std::optional<Vec3> point = parse_point_line(line)) {
        list.points.push_back(*point);
        list.line_numbers.push_back(line_number);
      }
    } catch (const InputError& error) {
      list.bad_line = std::make_exception_ptr(InputError(error.what(), fmt::format("line {}", line_number)));
      break;
    }
  }
  return list;
}

/// Evaluates every point line of `input` (all cores, field/batch.hpp),
/// returning the output text. Throws InputError / EvaluationError located
/// at "line N", the first failing line whatever the thread count.
std::string evaluate_lines(const Skeleton& skeleton, std::string_view input, unsigned threads, double tolerance,
                           ProgressLines& progress) {
  const PointList list = read_points(input, progress);
  BatchOptions options;
  options.threads = threads;
  options.tolerance = tolerance;
  if (!progress.quiet()) {
    // Asked after every block (one thread at a time), timed by `progress`
    // with the other phases' lines.
    options.progress_interval = 0.0;
    options.progress = [&](std::size_t evaluated) {
      if (progress.due()) progress.print(fmt::format("evaluated {} of {} points", evaluated, list.points.size()));
    };
  }
  const BatchResult result = evaluate_batch(skeleton, list.points, options);
  if (result.failure) rethrow_located(result.failure->error, fmt::format("line {}", list.line_numbers[result.failure->index]));
  if (list.bad_line) std::rethrow_exception(list.bad_line);
  std::string output;
  for (std::size_t k = 0; k < result.samples.size(); ++k) {
    const FieldSample& sample = result.samples[k];
    // A zero prints as 0 whatever its sign (detail/unsigned_zero.hpp).
    fmt::format_to(std::back_inserter(output), "{:.17g} {:.17g} {:.17g} {:.17g}\n", detail::unsigned_zero(sample.value),
                   detail::unsigned_zero(sample.gradient.x()), detail::unsigned_zero(sample.gradient.y()),
                   detail::unsigned_zero(sample.gradient.z()));
    if ((k + 1) % lines_between_clock_reads == 0 && progress.due())
      progress.print(fmt::format("formatted {} of {} output lines", k + 1, result.samples.size()));
  }
  return output;
}

}  // namespace

CLI::App* add_eval_command(CLI::App& app, EvalOptions& options) {
  CLI::App* eval = app.add_subcommand("eval", "Evaluate the field and its gradient at points read from stdin");
  eval->add_option("SKELETON", options.skeleton_path, "Skeleton file (JSON)")->required();
  add_thread_option(eval, options.threads,
                    "Threads evaluating the points (0: every core, at most 1024); the output is the same for any "
                    "value");
  eval->add_option("--max-points", options.limits.max_points,
                   "Refuse more points than this (default 10000000): the points and their output lines are held "
                   "in memory until the last one is evaluated")
      ->check(count_option());
  eval->add_option("--tolerance", options.tolerance,
                   "Relative tolerance of the field (default 0: exact to rounding); > 0 lets Cauchy segments far "
                   "from a point take short quadrature rules within it (docs/field.md, \"Tolerance\")")
      ->check(tolerance_range());
  eval->add_flag("--quiet", options.quiet, "No progress line on stderr");
  eval->footer(eval_footer);
  return eval;
}

int run_eval(const EvalOptions& options) {
  return print_all_or_nothing([&] {
    const Skeleton skeleton = load_skeleton_file(options.skeleton_path);
    // From here: a skeleton file that takes seconds to read (10⁵ points)
    // is not the points' time.
    ProgressLines progress("eval", options.quiet);
    const std::string input = read_point_input(stdin, options.limits, [&](std::size_t points) {
      if (progress.due()) progress.print(fmt::format("read {} points", points));
    });
    return evaluate_lines(skeleton, input, options.threads, options.tolerance, progress);
  });
}

}  // namespace skelconv::cli
