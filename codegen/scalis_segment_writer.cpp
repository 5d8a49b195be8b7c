// codegen/scalis_segment_writer.cpp — writes the SCALIS segment kernels
// (docs/mathematics.md §4): generated/scalis_segment_{inverse,cauchy}.hpp and
// generated/scalis_segment_table.hpp, and through scalis_compact_writer.cpp
// the compact family's closed forms. See kernel_writer.hpp.
#include <map>
#include <sstream>

#include "kernel_writer.hpp"

namespace skelconv::codegen {

namespace {

// The ends ordered so that τ grows from end_a to end_b: Δτ ≥ 0 keeps every
// coefficient of the weight τ(t)^(i−1) non-negative (docs/mathematics.md §4). F and ∇_P F
// do not depend on the direction of the segment.
constexpr const char* kScalisPrologue =
    "  // Ends ordered so that tau_lo <= tau_hi (Δτ ≥ 0: no cancellation in the weight).\n"
    "  const bool swap_ends = in.tau1 < in.tau0;\n"
    "  const std::array<T, 3>& end_a = swap_ends ? in.b : in.a;\n"
    "  const std::array<T, 3>& end_b = swap_ends ? in.a : in.b;\n"
    "  const T& tau_lo = swap_ends ? in.tau1 : in.tau0;\n"
    "  const T& tau_hi = swap_ends ? in.tau0 : in.tau1;\n";

std::string scalis_family_name(KernelFamily family) { return "scalis_" + std::string(family_name(family)); }

// The SCALIS segments' split: everything but P is the segment's; the
// preparation orders the ends (kScalisPrologue) once.
KernelSplit scalis_split() {
  return {"ScalisSegmentInput",
          "const T* pre, const std::array<T, 3>& p",
          "const std::array<T, 3>&",
          "A, B, the radii, σ",
          "in.p is",
          kScalisPrologue,
          [](const std::string& cpp) { return cpp.rfind("in.p[", 0) != 0; },
          [](const std::string& cpp) { return cpp.substr(3); }};  // in.p[0] → p[0]
}

struct EmittedScalisKernel {
  ScalisKernelSpec spec;
  SplitKernel split;
};

}  // namespace

std::vector<std::array<StraightLineProgram, 3>> build_scalis_segment_programs(const GeneratorRequest& request) {
  std::vector<std::array<StraightLineProgram, 3>> programs;
  for (const ScalisKernelSpec& spec : request.scalis_segment_kernels) {
    std::array<StraightLineProgram, 3>& p = programs.emplace_back();
    for (int which = 0; which < 3; ++which) p[which] = build_scalis_segment_program(spec, kOutputs[which]);
  }
  return programs;
}

std::string write_scalis_segment_files(const GeneratorRequest& request, const std::filesystem::path& folder,
                                       const std::vector<std::array<StraightLineProgram, 3>>& programs) {
  const std::string compact_rows = request.scalis_compact_degrees.empty() ? "" : write_scalis_compact_file(request, folder);
  if (request.scalis_segment_kernels.empty()) return compact_rows;
  std::vector<EmittedScalisKernel> kernels;
  std::map<KernelFamily, std::string> family_bodies;
  const KernelSplit split = scalis_split();
  for (std::size_t i = 0; i < request.scalis_segment_kernels.size(); ++i) {
    const ScalisKernelSpec& spec = request.scalis_segment_kernels[i];
    EmittedScalisKernel k{spec, split_kernel(spec.name(), spec.equation(), programs[i], split)};
    family_bodies[spec.family] += k.split.text;
    kernels.push_back(k);
  }

  const std::string from =
      "// SCALIS segments (docs/mathematics.md §4, Zanni et al. 2013 §3–4, Table 3): the segment kernel of\n"
      "// degree i with the weight σ^i τ(t)^(i−1), and for Cauchy q = |P − Γ(t)|² + σ²τ(t)²\n"
      "// (codegen/segment_families.cpp, ScalisKernelSpec). Unnormalised: f = c F / h is\n"
      "// the runtime's (skelconv/primitives/scalis_segment.hpp).\n";
  for (const auto& [family, body] : family_bodies) {
    const std::string file = "scalis_segment_" + std::string(family_name(family)) + ".hpp";
    std::ostringstream os;
    os << file_header(file, "SCALIS segment kernels of the " + std::string(family_name(family)) + " family.",
                      request)
       << from << "#pragma once\n\n#include <algorithm>\n#include <array>\n#include <cmath>\n\n"
       << "#include <skelconv/detail/exact_cross.hpp>\n#include <skelconv/detail/gauss_moments.hpp>\n#include <skelconv/primitives/scalis_segment_input.hpp>\n"
       << "#include <skelconv/detail/stable_recurrence.hpp>\n\n"
       << "namespace skelconv::generated {\n\n"
       << body << "}  // namespace skelconv::generated\n";
    write_file(folder / file, os.str());
  }

  std::ostringstream table;
  table << file_header("scalis_segment_table.hpp", "every generated SCALIS segment kernel, for lookup at run time.",
                       request)
        << from << "#pragma once\n\n#include <array>\n#include <span>\n\n#include <skelconv/kernels/op_count.hpp>\n"
        << "#include <skelconv/primitives/prepared_kernel.hpp>\n#include <skelconv/primitives/segment_input.hpp>\n\n";
  for (const auto& [family, body] : family_bodies)
    table << "#include \"generated/scalis_segment_" << family_name(family) << ".hpp\"\n";
  table << "\nnamespace skelconv::generated {\n\n"
        << "/// One generated SCALIS segment kernel: F, ∇F and both (unnormalised), with their operation counts.\n"
        << "/// Split in two like SegmentKernel (segment_table.hpp): `prepare` once per segment,\n"
        << "/// `f_at`, `grad_at`, `f_and_grad_at` at each point P (in the input's frame); `f`,\n"
        << "/// `grad` and `f_and_grad` do both for one point. The ops_* counts are per point;\n"
        << "/// ops_prepare is the preparation's, once per segment.\n"
        << "template <class T>\nstruct ScalisSegmentKernel {\n"
        << "  KernelFamily family;\n  int degree;\n"
        << "  T (*f)(const ScalisSegmentInput<T>&);\n"
        << "  std::array<T, 3> (*grad)(const ScalisSegmentInput<T>&);\n"
        << "  T (*f_and_grad)(const ScalisSegmentInput<T>&, std::array<T, 3>&);\n"
        << "  const char* name;\n  const char* equation;\n"
        << "  OpCount ops_f, ops_grad, ops_f_and_grad;\n"
        << split_table_members(split) << "};\n\n"
        << "/// Every generated SCALIS segment kernel, sorted by family and degree.\n"
        << "template <class T>\nstd::span<const ScalisSegmentKernel<T>> scalis_segment_kernels() {\n"
        << "  static const ScalisSegmentKernel<T> table[] = {\n";
  for (const EmittedScalisKernel& k : kernels) {
    const std::string n = k.spec.name();
    table << "      {KernelFamily::" << family_name(k.spec.family) << ", " << k.spec.degree << ",\n       "
          << one_point_entries(n) << ",\n       \"" << n << "\",\n       \"" << k.spec.equation() << "\", "
          << ops_initializer(k.split.ops[0]) << ", " << ops_initializer(k.split.ops[1]) << ", "
          << ops_initializer(k.split.ops[2]) << ",\n       " << split_entries(n, k.split.ops_prepare) << "},\n";
  }
  table << "  };\n  return table;\n}\n\n"
        << "/// The SCALIS segment kernel for (family, degree), or nullptr if it was not generated.\n"
        << "template <class T>\n"
        << "const ScalisSegmentKernel<T>* find_scalis_segment_kernel(KernelFamily family, int degree) {\n"
        << "  for (const ScalisSegmentKernel<T>& k : scalis_segment_kernels<T>())\n"
        << "    if (k.family == family && k.degree == degree) return &k;\n"
        << "  return nullptr;\n}\n\n"
        << "}  // namespace skelconv::generated\n";
  write_file(folder / "scalis_segment_table.hpp", table.str());

  // Rows of opcounts.csv (same columns as the segment rows; weight degree i − 1).
  std::ostringstream csv;
  for (const EmittedScalisKernel& k : kernels)
    csv << split_csv_rows(k.spec.name(), scalis_family_name(k.spec.family), k.spec.degree, k.spec.degree - 1,
                          k.split);
  return csv.str() + compact_rows;
}

}  // namespace skelconv::codegen
