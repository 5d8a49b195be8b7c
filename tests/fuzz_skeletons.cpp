// skelconv_fuzz_skeletons — a seeded mutation fuzzer over skeleton files
// (no crash, no NaN and no non-finite output for accepted input).
//
//   skelconv_fuzz_skeletons SKELCONV_BINARY GOOD_DIR [--iterations N] [--seed S]
//
// Each iteration takes one of GOOD_DIR/*.json (in name order, round robin),
// applies 1–3 random mutations to its JSON tree, writes it to a temporary
// file and runs `skelconv eval` on it with a fixed set of query points.
// The mutations, drawn from a std::mt19937_64 seeded with S (so a failure
// is reproduced by the same command):
//   - a number replaced by an extreme: 0, −0, ±1e-310 (subnormal),
//     ±5e-324, ±1e-300, ±1e300, ±1.7976931348623157e308, a negative of
//     itself, itself × 2^±400, a huge integer, or the strings "NaN" / "inf";
//   - a key dropped from an object;
//   - an array truncated (or emptied), or an element duplicated;
//   - a value replaced by a value of another type (string, null, object).
// The run must end with exit status 0, 1 or 2 (no signal, no other code);
// with 0, every output line must be four numbers, each finite, or the
// singular marker "inf inf inf inf" (a point on an inverse skeleton); with
// 1 or 2, stdout must be empty and stderr one "skelconv: error:" line.
// Any violation is printed with the mutated file kept, and the exit status
// is 1. ctest runs 60 iterations (seconds); the `long` label runs
// many more (tests/CMakeLists.txt).
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

/// The query points: a coarse grid over the box the good skeletons occupy,
/// plus points far away and near the origin.
std::string query_points() {
  std::string text;
  for (double x : {-0.7, 0.45, 1.6, 2.9})
    for (double y : {-0.6, 0.35, 1.3})
      for (double z : {-0.45, 0.25, 1.15}) text += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
  text += "1e6 -2e6 3e5\n1e-9 2e-9 -1e-9\n0 0 0\n";
  return text;
}

/// Pointers (as JSON pointers) to every value in the tree, of every kind.
void collect(const json& value, const json::json_pointer& at, std::vector<json::json_pointer>& out) {
  out.push_back(at);
  if (value.is_object()) {
    for (auto it = value.begin(); it != value.end(); ++it) collect(it.value(), at / it.key(), out);
  } else if (value.is_array()) {
    for (std::size_t k = 0; k < value.size(); ++k) collect(value[k], at / k, out);
  }
}

class Mutator {
 public:
  explicit Mutator(std::uint64_t seed) : random_(seed) {}

  void mutate(json& root) {
    const int count = 1 + int(pick(3));
    for (int m = 0; m < count; ++m) mutate_once(root);
  }

 private:
  std::size_t pick(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(random_); }

  json extreme_number(const json& old) {
    const double x = old.is_number() ? old.get<double>() : 1.0;
    switch (pick(16)) {
      case 0: return 0.0;
      case 1: return -0.0;
      case 2: return 1e-310;
      case 3: return -1e-310;
      case 4: return 5e-324;
      case 5: return 1e-300;
      case 6: return 1e300;
      case 7: return -1e300;
      case 8: return 1.7976931348623157e308;
      case 9: return -x;
      case 10: return std::ldexp(x, 400);
      case 11: return std::ldexp(x, -400);
      case 12: return 123456789012345678;
      case 13: return "NaN";
      case 14: return "inf";
      default: return x * 1e-8 + 1e-12;  // nearly what it was
    }
  }

  void mutate_once(json& root) {
    std::vector<json::json_pointer> places;
    collect(root, json::json_pointer(), places);
    const json::json_pointer at = places[pick(places.size())];
    json& value = root[at];
    switch (pick(6)) {
      case 0:
      case 1:
      case 2: {  // numbers are what most checks are about: mutate one
        std::vector<json::json_pointer> numbers;
        for (const auto& p : places)
          if (root[p].is_number()) numbers.push_back(p);
        if (numbers.empty()) return;
        json& number = root[numbers[pick(numbers.size())]];
        number = extreme_number(number);
        return;
      }
      case 3:  // drop a key
        if (value.is_object() && !value.empty()) {
          auto it = value.begin();
          std::advance(it, long(pick(value.size())));
          value.erase(it);
        }
        return;
      case 4:  // truncate or grow an array
        if (value.is_array() && !value.empty()) {
          if (pick(3) == 0) {
            value.push_back(value[pick(value.size())]);
          } else {
            json shorter = json::array();
            for (std::size_t k = 0, n = pick(value.size()); k < n; ++k) shorter.push_back(value[k]);
            value = shorter;
          }
        }
        return;
      default: {  // another type
        const json others[] = {"text", nullptr, json::object(), json::array(), true, 3};
        if (!at.empty()) value = others[pick(std::size(others))];
        return;
      }
    }
  }

  std::mt19937_64 random_;
};

/// The output of an accepted run: four numbers per line, finite, or the
/// singular marker. Returns a description of the first bad line, or "".
std::string check_output(const std::string& out, std::size_t expected_lines) {
  std::istringstream lines(out);
  std::string line;
  std::size_t count = 0;
  while (std::getline(lines, line)) {
    ++count;
    if (line == "inf inf inf inf") continue;
    std::istringstream fields(line);
    std::string field;
    int n = 0;
    while (fields >> field) {
      ++n;
      char* end = nullptr;
      const double x = std::strtod(field.c_str(), &end);
      if (*end != '\0' || !std::isfinite(x)) return "line " + std::to_string(count) + " holds '" + field + "': " + line;
    }
    if (n != 4) return "line " + std::to_string(count) + " does not hold 4 numbers: " + line;
  }
  if (count != expected_lines) return std::to_string(count) + " lines for " + std::to_string(expected_lines) + " points";
  return "";
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: skelconv_fuzz_skeletons SKELCONV_BINARY GOOD_DIR [--iterations N] [--seed S]\n";
    return 2;
  }
  const std::string binary = argv[1];
  const fs::path good_dir = argv[2];
  long iterations = 300;
  std::uint64_t seed = 16;
  for (int k = 3; k + 1 < argc; k += 2) {
    const std::string option = argv[k];
    if (option == "--iterations") iterations = std::stol(argv[k + 1]);
    else if (option == "--seed") seed = std::stoull(argv[k + 1]);
  }

  std::vector<fs::path> seeds;
  for (const auto& entry : fs::directory_iterator(good_dir))
    if (entry.path().extension() == ".json") seeds.push_back(entry.path());
  std::sort(seeds.begin(), seeds.end());
  if (seeds.empty()) {
    std::cerr << "no .json files in " << good_dir << "\n";
    return 2;
  }

  const fs::path work = fs::temp_directory_path() / ("skelconv_fuzz_" + std::to_string(::getpid()));
  fs::create_directories(work);
  const std::string points = query_points();
  const std::size_t point_count = std::size_t(std::count(points.begin(), points.end(), '\n'));
  std::ofstream(work / "points.txt") << points;

  Mutator mutator(seed);
  long failures = 0, accepted = 0, refused_input = 0, refused_value = 0;
  for (long iteration = 0; iteration < iterations; ++iteration) {
    const fs::path& source = seeds[std::size_t(iteration) % seeds.size()];
    json skeleton = json::parse(read_file(source));
    mutator.mutate(skeleton);
    const fs::path file = work / "mutated.json";
    std::ofstream(file) << skeleton.dump();
    const std::string command = "'" + binary + "' eval '" + file.string() + "' < '" + (work / "points.txt").string() +
                                "' > '" + (work / "out.txt").string() + "' 2> '" + (work / "err.txt").string() + "'";
    const int status = std::system(command.c_str());
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    const std::string out = read_file(work / "out.txt"), err = read_file(work / "err.txt");

    std::string problem;
    if (code == 0) {
      ++accepted;
      problem = check_output(out, point_count);
    } else if (code == 1 || code == 2) {
      ++(code == 1 ? refused_value : refused_input);
      if (!out.empty()) problem = "exit " + std::to_string(code) + " with output on stdout";
      else if (err.rfind("skelconv: error: ", 0) != 0 || std::count(err.begin(), err.end(), '\n') != 1)
        problem = "exit " + std::to_string(code) + " without one error line: " + err;
    } else {
      problem = "exit status " + std::to_string(code) + " (a crash or an unexpected code): " + err;
    }
    if (!problem.empty()) {
      ++failures;
      const fs::path kept = work / ("failure_" + std::to_string(iteration) + ".json");
      fs::copy_file(file, kept, fs::copy_options::overwrite_existing);
      std::cout << "FAIL iteration " << iteration << " (from " << source.filename().string() << ", kept in "
                << kept.string() << "): " << problem << "\n";
    }
  }
  std::cout << "[ fuzz ] seed " << seed << ", " << iterations << " mutated files: " << accepted << " accepted, "
            << refused_input << " refused as bad input (exit 2), " << refused_value
            << " refused as not computable (exit 1), " << failures << " failures\n";
  if (failures == 0) fs::remove_all(work);
  return failures == 0 ? 0 : 1;
}
