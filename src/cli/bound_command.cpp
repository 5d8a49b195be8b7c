// Implementation of bound_command.hpp.
#include "bound_command.hpp"

#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <string_view>

#include <fmt/format.h>

#include "exit_status.hpp"
#include "point_lines.hpp"
#include "skelconv/detail/unsigned_zero.hpp"
#include "skelconv/errors.hpp"
#include "skelconv/interval/octree.hpp"
#include "skelconv/skeleton/skeleton_file.hpp"

namespace skelconv::cli {
namespace {

/// Parses one line as `eval` parses its points (point_lines.hpp); nullopt
/// for a blank one.
std::optional<interval::Box> parse_box_line(std::string_view line) {
  const std::optional<std::vector<double>> values = parse_number_line(line, 6, "six numbers \"x0 y0 z0 x1 y1 z1\"");
  if (!values) return std::nullopt;
  return interval::box_from_corners(*values);
}

/// Standard input, its lines bounded as `eval`'s (point_lines.hpp): input
/// without line breaks is refused at once. The number of boxes is not: each
/// costs one enclosure and one output line.
std::string read_box_input() {
  PointInputLimits limits;
  limits.max_points = std::numeric_limits<std::size_t>::max();
  return read_point_input(stdin, limits);
}

std::string bound_lines(const Skeleton& skeleton, std::string_view input, std::optional<double> iso) {
  std::string output;
  std::size_t line_number = 0;
  while (!input.empty()) {
    const std::size_t end = input.find('\n');
    const std::string_view line = input.substr(0, end);
    input.remove_prefix(end == std::string_view::npos ? input.size() : end + 1);
    ++line_number;
    std::optional<interval::Box> box;
    try {
      box = parse_box_line(line);
    } catch (const InputError& error) {
      throw InputError(error.what(), fmt::format("line {}", line_number));
    }
    if (!box) continue;
    const interval::Interval f = interval::enclose(skeleton, *box);
    // An end computed as −(−x − y) under directed rounding can be −0 (a box
    // straddling a compact support): the same number, printed as 0.
    fmt::format_to(std::back_inserter(output), "{:.17g} {:.17g}", detail::unsigned_zero(f.lower()),
                   detail::unsigned_zero(f.upper()));
    if (iso) fmt::format_to(std::back_inserter(output), " {}", interval::classification_name(interval::classify(f, *iso)));
    output += '\n';
  }
  return output;
}

std::string octree_lines(const Skeleton& skeleton, const BoundOptions& options) {
  if (options.box.empty()) throw InputError("--octree needs --box x0 y0 z0 x1 y1 z1", "--box");
  interval::Box box;
  try {
    box = interval::box_from_corners(options.box);
  } catch (const InputError& error) {
    throw InputError(error.what(), "--box");
  }
  const int depth = *options.octree_depth;
  if (depth < 0 || depth > interval::max_octree_depth) {
    throw InputError(fmt::format("must be 0..{}, got {}", interval::max_octree_depth, depth), "--octree");
  }
  const double iso = options.iso.value_or(skeleton.iso());
  std::string output;
  const auto counts = interval::classify_octree(skeleton, box, depth, iso);
  for (std::size_t level = 0; level < counts.size(); ++level) {
    fmt::format_to(std::back_inserter(output), "{} {} {} {}\n", level, counts[level].inside, counts[level].outside,
                   counts[level].undetermined);
  }
  return output;
}

}  // namespace

CLI::App* add_bound_command(CLI::App& app, BoundOptions& options) {
  CLI::App* bound = app.add_subcommand("bound", "Certified enclosures [lo, hi] of the field over boxes (docs/bound.md)");
  bound->add_option("SKELETON", options.skeleton_path, "Skeleton file (JSON)")->required();
  bound->add_option("--iso", options.iso, "Classify each box against this level: inside, outside, undetermined");
  bound->add_option("--octree", options.octree_depth, "Classify the --box by an octree of this depth instead");
  bound->add_option("--box", options.box, "x0 y0 z0 x1 y1 z1: the octree's box")->expected(6);
  bound->footer(R"(
Input (stdin, box mode): one box "x0 y0 z0 x1 y1 z1" (min corner, max corner)
                per line; blank lines are skipped.
Output: "lo hi" per box (%.17g), then "inside"/"outside"/"undetermined" with
                --iso. With --octree DEPTH --box ...: one line "level inside
                outside undetermined" per level 0..DEPTH (iso: --iso or the
                file's). Exit 2 on bad input (nothing on stdout).)");
  return bound;
}

int run_bound(const BoundOptions& options) {
  std::string output;
  return print_all_or_nothing([&] {
    const Skeleton skeleton = load_skeleton_file(options.skeleton_path);
    if (options.iso && !std::isfinite(*options.iso)) throw InputError("must be finite", "--iso");
    // Ignored, it would leave the user waiting on standard input for boxes.
    if (!options.octree_depth && !options.box.empty())
      throw InputError("is the box of --octree DEPTH; without --octree the boxes are read from standard input", "--box");
    return options.octree_depth ? octree_lines(skeleton, options)
                                : bound_lines(skeleton, read_box_input(), options.iso);
  });
}

}  // namespace skelconv::cli
