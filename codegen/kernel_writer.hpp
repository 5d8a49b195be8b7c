// codegen/kernel_writer.hpp — writes generated/: one header per family, the
// lookup table and the operation-count table.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "polygon_families.hpp"
#include "segment_families.hpp"

namespace skelconv::codegen {

/// What to generate; the command line (main.cpp) fills it.
struct GeneratorRequest {
  std::vector<SegmentKernelSpec> segment_kernels;
  std::vector<PolygonKernelSpec> polygon_kernels;
  std::string command_line;  ///< recorded in every file header (without --out)
};

/// Writes every file of `request` into `folder`. Same request, same bytes.
void write_generated_folder(const GeneratorRequest& request, const std::filesystem::path& folder);

}  // namespace skelconv::codegen
