// libFuzzer harness for `skelconv eval`'s point lines
// (skelconv::cli::parse_point_line): each input is one line. Any outcome
// but three finite numbers, a blank line or an InputError is a finding.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "../../src/cli/point_lines.hpp"
#include "skelconv/errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view line(reinterpret_cast<const char*>(data), size);
  try {
    if (const auto point = skelconv::cli::parse_point_line(line)) {
      if (!std::isfinite((*point)[0]) || !std::isfinite((*point)[1]) || !std::isfinite((*point)[2])) std::abort();
    }
  } catch (const skelconv::InputError&) {
    // the documented refusal
  }
  return 0;
}
