// Replays the inputs of a libFuzzer harness without libFuzzer: main() calls
// the harness's LLVMFuzzerTestOneInput on every file of the folders named on
// the command line (tests/data/fuzz/NAME/: the seeds and every input a fuzzer
// once found). A finding aborts, as under libFuzzer, and fails the ctest; a
// folder without a file fails too (a replay of nothing proves nothing).
//   skelconv_fuzz_replay_NAME FOLDER...
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FOLDER...\n", argv[0]);
    return 2;
  }
  for (int k = 1; k < argc; ++k) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(argv[k]))
      if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());  // the same order on every run
    if (files.empty()) {
      std::fprintf(stderr, "fuzz replay: no input in %s\n", argv[k]);
      return 1;
    }
    for (const auto& file : files) {
      std::ifstream in(file, std::ios::binary);
      const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
      LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
      std::printf("fuzz replay: %s (%zu bytes)\n", file.filename().c_str(), bytes.size());
    }
    std::printf("fuzz replay: %zu inputs of %s replayed\n", files.size(), argv[k]);
  }
  return 0;
}
