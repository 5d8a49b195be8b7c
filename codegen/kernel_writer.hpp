// codegen/kernel_writer.hpp — writes generated/: one header per family, the
// lookup table and the operation-count table.
#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "polygon_families.hpp"
#include "segment_families.hpp"

namespace skelconv::codegen {

/// What to generate; the command line (main.cpp) fills it.
struct GeneratorRequest {
  std::vector<SegmentKernelSpec> segment_kernels;
  std::vector<PolygonKernelSpec> polygon_kernels;        ///< docs/mathematics.md §3 (polygon_writer.cpp)
  std::vector<ScalisKernelSpec> scalis_segment_kernels;  ///< docs/mathematics.md §4 (scalis_segment_writer.cpp)
  std::vector<int> scalis_compact_degrees;  ///< even; docs/mathematics.md §4 (scalis_compact_writer.cpp)
  std::string command_line;  ///< recorded in every file header (without --out)
};

/// Writes every file of `request` into `folder`. Same request, same bytes.
void write_generated_folder(const GeneratorRequest& request, const std::filesystem::path& folder);

// Shared by the writers of the generated files.
/// f, grad, f_and_grad: the suffixes of the three functions of a kernel.
inline constexpr const char* kFunctionSuffix[] = {"f", "grad", "f_and_grad"};
inline constexpr SegmentOutputs kOutputs[] = {SegmentOutputs::value, SegmentOutputs::gradient,
                                              SegmentOutputs::value_and_gradient};
/// The comment at the top of generated/`file`: what it is and the command that made it.
std::string file_header(const std::string& file, const std::string& what, const GeneratorRequest& request);
/// "12 +, 30 ×, …" and "{12, 30, …}" (an OpCount initializer).
std::string ops_text(const OpCount& o);
std::string ops_initializer(const OpCount& o);
/// One generated function (`which`: 0 f, 1 grad, 2 f_and_grad) of kernel
/// `kernel_name`, reading `const input_type<T>& in`; `prologue` (C++
/// statements) comes before the program's body.
std::string kernel_function_text(const std::string& kernel_name, const std::string& equation,
                                 const std::string& input_type, int which, const EmittedCode& code,
                                 const std::string& prologue = "");
/// The same with the C++ parameter list `parameters` (before `grad`), and
/// `note` (comment lines) after the equation.
std::string kernel_function_text_reading(const std::string& kernel_name, const std::string& equation,
                                         const std::string& parameters, int which, const EmittedCode& code,
                                         const std::string& prologue, const std::string& note);
/// One row of opcounts.csv: one evaluation's generic-path counts `o` and
/// longest-path counts `l`; for a kernel split into a preparation and a
/// per-point evaluation, the per-point counts and the preparation's (once
/// per primitive), else empty cells.
std::string opcount_csv_row(const std::string& kernel_name, const std::string& family, int degree, int weight_degree,
                            int which, const OpCount& o, const OpCount& l, const OpCount* point = nullptr,
                            const OpCount* primitive = nullptr);
void write_file(const std::filesystem::path& path, const std::string& text);

/// How a family's kernels are split into a preparation, once per primitive,
/// and per-point functions (PreparedQuantities): the C++ the split writes.
struct KernelSplit {
  std::string input_type;           ///< the one-point input, e.g. "SegmentInput"
  std::string evaluate_parameters;  ///< the per-point functions' parameters (before `grad`)
  std::string point_type;           ///< the per-point argument's type, e.g. "const SegmentPoint<T>&"
  std::string prepared_what;        ///< the preparation's comment: what it reads
  std::string not_read;             ///< the preparation's comment: the per-point inputs it does not read
  std::string prologue;             ///< C++ statements before the preparation's body
  std::function<bool(const std::string& cpp)> per_primitive_input;
  std::function<std::string(const std::string& cpp)> point_input;  ///< a per-point input's C++ in the evaluation
};
/// One kernel split: <name>_prepared_size, <name>_prepare and <name>_f,
/// _grad, _f_and_grad (per point), with the operation counts.
struct SplitKernel {
  std::string text;
  OpCount ops[3], ops_longest[3];  ///< f, grad, f_and_grad per point: generic path, longest path
  OpCount ops_primitive[3];        ///< what each of them reads from the preparation, once per primitive
  OpCount ops_prepare;             ///< the whole preparation (what any of the three reads)
  std::size_t prepared_size = 0;
};
/// Splits the programs of a kernel's f, ∇f and both (built from fresh
/// symbols of the same names) as `how` says.
SplitKernel split_kernel(const std::string& kernel_name, const std::string& equation,
                         const std::array<StraightLineProgram, 3>& outputs, const KernelSplit& how);
/// The members a split kernel adds to its table's struct (after the one-point
/// functions and their counts), and its entry's values for them and for the
/// one-point functions (generic wrappers, skelconv/primitives/prepared_kernel.hpp).
std::string split_table_members(const KernelSplit& how);
std::string one_point_entries(const std::string& kernel_name);
std::string split_entries(const std::string& kernel_name, const OpCount& ops_prepare);
/// The opcounts.csv rows of a split kernel: one evaluation (the preparation of
/// what the output reads plus the per-point code), then per point and per primitive.
std::string split_csv_rows(const std::string& kernel_name, const std::string& family, int degree,
                           int weight_degree, const SplitKernel& k);

/// Writes generated/polygon_{inverse,cauchy,compact}.hpp and
/// polygon_table.hpp; returns their rows of opcounts.csv.
std::string write_polygon_files(const GeneratorRequest& request, const std::filesystem::path& folder);

/// The programs of the SCALIS segment kernels (f, grad, f_and_grad each),
/// built before the classical kernels are split: GiNaC orders terms by its
/// symbols' serial numbers, and the split makes symbols of its own.
std::vector<std::array<StraightLineProgram, 3>> build_scalis_segment_programs(const GeneratorRequest& request);
/// Splits them and writes generated/scalis_segment_{inverse,cauchy}.hpp,
/// scalis_segment_table.hpp and (write_scalis_compact_file)
/// scalis_segment_compact.hpp; returns their rows of opcounts.csv.
std::string write_scalis_segment_files(const GeneratorRequest& request, const std::filesystem::path& folder,
                                       const std::vector<std::array<StraightLineProgram, 3>>& programs);
std::string write_scalis_compact_file(const GeneratorRequest& request, const std::filesystem::path& folder);

}  // namespace skelconv::codegen
