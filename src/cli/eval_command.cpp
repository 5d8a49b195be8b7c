// Implementation of eval_command.hpp.
#include "eval_command.hpp"

#include <cstdio>
#include <iterator>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include "exit_status.hpp"
#include "point_lines.hpp"
#include "skelconv/errors.hpp"
#include "skelconv/skeleton_file.hpp"

namespace skelconv::cli {
namespace {

constexpr const char* eval_footer = R"(
Input (stdin):  one point "x y z" per line, numbers separated by blanks;
                blank lines are skipped.
Output (stdout): one line "f gx gy gz" per point: the field f = sum of the
                primitives' fields and its gradient, printed with %.17g.
                On an inverse-kernel segment or polygon itself f and the
                gradient are printed as "inf".
On any error nothing is written to stdout and one "skelconv: error: ..." line
to stderr; exit status 2 for bad input, 1 if a value cannot be computed in
double precision. Schema of SKELETON.json: see docs/cli.md.)";

/// All of stdin. Throws InputError if it cannot be read.
std::string read_standard_input() {
  std::string text;
  char chunk[1 << 16];
  std::size_t count = 0;
  while ((count = std::fread(chunk, 1, sizeof chunk, stdin)) > 0) text.append(chunk, count);
  if (std::ferror(stdin)) throw InputError("cannot read standard input");
  return text;
}

/// Evaluates every point line of `input`, returning the output text.
/// Throws InputError / EvaluationError located at "line N".
std::string evaluate_lines(const Skeleton& skeleton, std::string_view input) {
  std::string output;
  std::size_t line_number = 0;
  while (!input.empty()) {
    const std::size_t end = input.find('\n');
    const std::string_view line = input.substr(0, end);
    input.remove_prefix(end == std::string_view::npos ? input.size() : end + 1);
    ++line_number;

    const std::string where = fmt::format("line {}", line_number);
    std::optional<Vec3> point;
    try {
      point = parse_point_line(line);
      if (!point) continue;  // blank line
      const FieldSample sample = skeleton.value_and_gradient(*point);
      fmt::format_to(std::back_inserter(output), "{:.17g} {:.17g} {:.17g} {:.17g}\n", sample.value,
                     sample.gradient.x(), sample.gradient.y(), sample.gradient.z());
    } catch (const InputError& error) {
      throw InputError(error.what(), where);
    } catch (const EvaluationError& error) {
      throw EvaluationError(error.what(), where);
    }
  }
  return output;
}

}  // namespace

CLI::App* add_eval_command(CLI::App& app, EvalOptions& options) {
  CLI::App* eval = app.add_subcommand("eval", "Evaluate the field and its gradient at points read from stdin");
  eval->add_option("SKELETON", options.skeleton_path, "Skeleton file (JSON)")->required();
  eval->footer(eval_footer);
  return eval;
}

int run_eval(const EvalOptions& options) {
  std::string output;
  try {
    const Skeleton skeleton = load_skeleton_file(options.skeleton_path);
    output = evaluate_lines(skeleton, read_standard_input());
  } catch (const InputError& error) {
    report_error(error.what());
    return exit_bad_input;
  } catch (const EvaluationError& error) {
    report_error(error.what());
    return exit_evaluation_failed;
  }
  // Only now, with every point evaluated, does anything reach stdout.
  if (std::fwrite(output.data(), 1, output.size(), stdout) != output.size() || std::fflush(stdout) != 0) {
    report_error("cannot write to standard output");
    return exit_evaluation_failed;
  }
  return exit_success;
}

}  // namespace skelconv::cli
