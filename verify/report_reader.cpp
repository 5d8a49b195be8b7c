// verify/report_reader.cpp — see report_reader.hpp.
#include "report_reader.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "report.hpp"
#include "skelconv/kernels/kernel_spec.hpp"

namespace skelconv::verify {
namespace {

using nlohmann::json;

/// A place in a report, for messages: the file and the JSON path.
struct Place {
  const std::string& source;
  std::string path;

  [[noreturn]] void fail(const std::string& problem) const {
    throw ReportError(source + ": " + (path.empty() ? "" : path + ": ") + problem);
  }
  Place operator/(const std::string& key) const { return {source, path.empty() ? key : path + "." + key}; }
  Place operator[](std::size_t index) const { return {source, path + "[" + std::to_string(index) + "]"}; }
};

const json& member(const json& object, const std::string& key, const Place& place) {
  if (!object.is_object()) place.fail("expected an object");
  const auto it = object.find(key);
  if (it == object.end()) (place / key).fail("missing");
  return *it;
}

const json& array_member(const json& object, const std::string& key, const Place& place) {
  const json& value = member(object, key, place);
  if (!value.is_array()) (place / key).fail("expected an array");
  return value;
}

double number(const json& object, const std::string& key, const Place& place) {
  const json& value = member(object, key, place);
  if (!value.is_number()) (place / key).fail("expected a number");
  return value.get<double>();
}

/// A maximum error: a number, or null for an infinite one (JSON has no
/// infinity; the writer turns a non-finite error into null).
double error_value(const json& object, const std::string& key, const Place& place) {
  const json& value = member(object, key, place);
  if (value.is_null()) return std::numeric_limits<double>::infinity();
  return number(object, key, place);
}

std::uint64_t count(const json& object, const std::string& key, const Place& place) {
  const json& value = member(object, key, place);
  if (!value.is_number_unsigned()) (place / key).fail("expected a non-negative integer");
  return value.get<std::uint64_t>();
}

int integer(const json& object, const std::string& key, const Place& place) {
  const json& value = member(object, key, place);
  if (!value.is_number_integer()) (place / key).fail("expected an integer");
  return value.get<int>();
}

std::string text(const json& object, const std::string& key, const Place& place) {
  const json& value = member(object, key, place);
  if (!value.is_string()) (place / key).fail("expected a string");
  return value.get<std::string>();
}

KernelFamily family_of(const std::string& name, const Place& place) {
  const auto family = family_from_name(name);
  if (!family) place.fail("unknown kernel family \"" + name + "\"");
  return *family;
}

Region region_of(const std::string& name, const Place& place) {
  const auto region = region_from_name(name);
  if (!region) place.fail("unknown region \"" + name + "\"");
  return *region;
}

/// A round-trip decimal written by report.cpp's problem_json ("%.17g").
double exact_decimal(const json& value, const Place& place) {
  if (!value.is_string()) place.fail("expected a decimal string");
  const std::string& s = value.get_ref<const std::string&>();
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || !std::isfinite(x)) place.fail("not a finite decimal: \"" + s + "\"");
  return x;
}

template <std::size_t N>
std::array<double, N> decimals(const json& object, const std::string& key, const Place& place) {
  const json& values = array_member(object, key, place);
  if (values.size() != N) (place / key).fail("expected " + std::to_string(N) + " values");
  std::array<double, N> out{};
  for (std::size_t k = 0; k < N; ++k) out[k] = exact_decimal(values[k], (place / key)[k]);
  return out;
}

SweepProblem sample_of(const json& object, KernelFamily family, int degree, const Place& place) {
  SweepProblem pb;
  pb.family = family;
  pb.degree = degree;
  pb.region = region_of(text(object, "region", place), place / "region");
  pb.index = count(object, "index", place);
  pb.a = decimals<3>(object, "A", place);
  pb.b = decimals<3>(object, "B", place);
  pb.p = decimals<3>(object, "P", place);
  pb.w = decimals<4>(object, "w", place);
  pb.s = exact_decimal(member(object, "s", place), place / "s");
  pb.R = exact_decimal(member(object, "R", place), place / "R");
  if (family == KernelFamily::gaussian) {
    pb.gaussian_a = exact_decimal(member(object, "gaussian_a", place), place / "gaussian_a");
    pb.gaussian_b = exact_decimal(member(object, "gaussian_b", place), place / "gaussian_b");
  }
  return pb;
}

PrecisionStats precision_of(const json& object, KernelFamily family, int degree, const Place& place) {
  PrecisionStats stats;
  stats.max_f = error_value(object, "max_rel_f", place);
  stats.max_grad = error_value(object, "max_rel_grad", place);
  stats.max_grad_component = error_value(object, "max_rel_grad_component", place);
  stats.nonfinite = count(object, "nonfinite", place);
  stats.f_above_target = count(object, "f_above_generic_target", place);
  stats.grad_above_target = count(object, "grad_above_generic_target", place);
  if (object.contains("worst_f_sample"))
    stats.worst_f = sample_of(object["worst_f_sample"], family, degree, place / "worst_f_sample");
  if (object.contains("worst_grad_sample"))
    stats.worst_grad = sample_of(object["worst_grad_sample"], family, degree, place / "worst_grad_sample");
  return stats;
}

void read_cell(const json& object, const Place& place, SweepCells& cells) {
  const KernelFamily family = family_of(text(object, "family", place), place / "family");
  const int degree = integer(object, "degree", place);
  const int weight_degree = integer(object, "weight_degree", place);
  const Region region = region_of(text(object, "region", place), place / "region");
  CellStats cell;
  cell.points = count(object, "points", place);
  cell.excluded = count(object, "excluded", place);
  cell.retried = count(object, "retried", place);
  cell.outside_support = count(object, "outside_support", place);
  cell.support_mismatch = count(object, "support_mismatch", place);
  cell.max_reference_error = number(object, "max_reference_error_estimate", place);
  cell.in_double = precision_of(member(object, "double", place), family, degree, place / "double");
  cell.in_extended = precision_of(member(object, "extended", place), family, degree, place / "extended");
  if (!cells.emplace(CellKey{family, degree, weight_degree, region}, cell).second)
    place.fail("a second cell for the same family, degree, weight degree and region");
}

void read_filters(const json& filters, const Place& place, SweepOptions& options) {
  if (const json& family = member(filters, "family", place); !family.is_null())
    options.family = family_of(text(filters, "family", place), place / "family");
  if (const json& degree = member(filters, "degree", place); !degree.is_null())
    options.degree = integer(filters, "degree", place);
  if (const json& region = member(filters, "region", place); !region.is_null())
    options.region = region_of(text(filters, "region", place), place / "region");
}

SweepOptions options_of(const json& settings, const Place& place) {
  SweepOptions options;
  options.commit = text(settings, "commit", place);
  options.seed = count(settings, "seed", place);
  options.counts = {integer(settings, "points_generic", place), integer(settings, "points_other", place)};
  options.chunk_size = integer(settings, "chunk_size", place);
  read_filters(member(settings, "filters", place), place / "filters", options);
  options.shard_index = integer(settings, "shard_index", place);
  options.shard_count = integer(settings, "shard_count", place);
  if (options.shard_count < 1 || options.shard_index < 0 || options.shard_index >= options.shard_count)
    (place / "shard_index").fail("shard " + std::to_string(options.shard_index) + " of " +
                                 std::to_string(options.shard_count) + " does not exist");
  options.threads = integer(settings, "threads", place);
  options.targets = {number(settings, "target_generic_f", place), number(settings, "target_generic_grad", place)};
  options.reference.requested = number(settings, "reference_requested_tolerance", place);
  options.reference.flag_threshold = number(settings, "reference_flag_threshold", place);
  options.reference.max_levels = count(settings, "reference_max_levels", place);
  options.exclusions = {number(settings, "max_excluded_share", place), number(settings, "min_compared_share", place)};
  if (settings.contains("test_perturbation")) {
    const json& perturbation = settings["test_perturbation"];
    const Place at = place / "test_perturbation";
    options.perturbation = TestPerturbation{family_of(text(perturbation, "family", at), at / "family"),
                                            number(perturbation, "relative", at)};
  }
  return options;
}

SweepResult result_of(const json& report, const Place& place) {
  SweepResult result;
  const json& cells = array_member(report, "cells", place);
  for (std::size_t k = 0; k < cells.size(); ++k) read_cell(cells[k], (place / "cells")[k], result.cells);
  const json& summary = member(report, "summary", place);
  const Place at = place / "summary";
  result.samples = count(summary, "samples", at);
  result.items_run = count(summary, "items_run", at);
  result.items_total = count(summary, "items_total", at);
  result.seconds = number(summary, "seconds", at);
  result.kernel_evaluations = count(summary, "reference_kernel_evaluations", at);
  if (summary.contains("merged_shards")) result.merged_shards = integer(summary, "merged_shards", at);
  return result;
}

/// `value` on one line per array element (and per top-level member).
void write_lines(std::ostream& out, const json& report) {
  out << "{\n";
  bool first = true;
  for (const auto& [key, value] : report.items()) {
    out << (first ? "" : ",\n") << json(key).dump() << ": ";
    first = false;
    if (!value.is_array() || value.empty()) {
      out << value.dump();
      continue;
    }
    out << "[\n";
    for (std::size_t k = 0; k < value.size(); ++k) out << "  " << value[k].dump() << (k + 1 < value.size() ? ",\n" : "\n");
    out << "]";
  }
  out << "\n}\n";
}

}  // namespace

SweepReport report_from_json(const json& report, const std::string& source) {
  const Place root{source, ""};
  if (!report.is_object() || !report.contains("tool") || report["tool"] != "skelconv-verify")
    root.fail("not a skelconv-verify report (its \"tool\" is not \"skelconv-verify\")");
  SweepReport out;
  out.source = source;
  out.options = options_of(member(report, "settings", root), root / "settings");
  out.options.progress = false;
  out.result = result_of(report, root);
  return out;
}

SweepReport read_report(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw ReportError(path + ": cannot open");
  json report;
  try {
    report = json::parse(file);
  } catch (const json::parse_error& e) {
    throw ReportError(path + ": not JSON (" + e.what() + ")");
  }
  return report_from_json(report, path);
}

void write_report(const SweepReport& report, const std::string& path, bool with_samples) {
  json document = json_report(report.options, report.result);
  if (!with_samples)
    for (json& cell : document["cells"])
      for (const char* precision : {"double", "extended"})
        cell[precision].erase("worst_f_sample"), cell[precision].erase("worst_grad_sample");
  const std::string temporary = path + ".partial";
  {
    std::ofstream file(temporary);
    write_lines(file, document);
    if (!file.flush()) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw ReportError(path + ": cannot write");
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) throw ReportError(path + ": cannot write (" + error.message() + ")");
}

}  // namespace skelconv::verify
