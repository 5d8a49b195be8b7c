// codegen/polygon_writer.cpp — writes the polygon edge kernels (docs/mathematics.md §3):
// generated/polygon_{inverse,cauchy,compact}.hpp and generated/polygon_table.hpp.
// See kernel_writer.hpp and polygon_families.hpp.
#include <map>
#include <sstream>

#include "kernel_writer.hpp"

namespace skelconv::codegen {

namespace {

const char* const kPolygonSources =
    "// Polygons (docs/mathematics.md §3, Hubert 2012 §5–8): the terms of one edge of the contour sum\n"
    "// (codegen/polygon_families.cpp), on the segment forms of the edge;\n"
    "// skelconv/primitives/polygon_field.hpp adds them up.\n";

// One polygon edge function: writes the PolygonEdgeTerms its outputs need.
std::string polygon_function_text(const PolygonKernelSpec& spec, int which, const EmittedCode& code) {
  const std::string name = spec.name() + "_" + kFunctionSuffix[which];
  static const char* kWhat[] = {"f", "∇f", "f and ∇f"};
  std::ostringstream os;
  os << "/// The terms of one edge for " << kWhat[which] << " (skelconv/primitives/polygon_field.hpp adds them up), where\n"
     << "///     " << spec.equation() << "\n"
     << "/// Operations per edge: " << ops_text(code.ops) << " (generic form).\n";
  if (!(code.ops_longest == code.ops)) os << "/// Longest path: " << ops_text(code.ops_longest) << ".\n";
  os << "template <class T>\n"
     << "void " << name << "(const PolygonEdgeInput<T>& in, PolygonEdgeTerms<T>& out) {\n"
     << "  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;\n"
     << code.body << "}\n\n";
  return os.str();
}

struct EmittedPolygonKernel {
  PolygonKernelSpec spec;
  OpCount ops[3], ops_longest[3];
};

}  // namespace

std::string write_polygon_files(const GeneratorRequest& request, const std::filesystem::path& folder) {
  if (request.polygon_kernels.empty()) return "";
  std::vector<EmittedPolygonKernel> kernels;
  std::map<KernelFamily, std::string> family_bodies;
  for (const PolygonKernelSpec& spec : request.polygon_kernels) {
    EmittedPolygonKernel k{spec, {}, {}};
    for (int which = 0; which < 3; ++which) {
      const EmittedCode code = build_polygon_edge_program(spec, kOutputs[which]).emit();
      k.ops[which] = code.ops;
      k.ops_longest[which] = code.ops_longest;
      family_bodies[spec.family] += polygon_function_text(spec, which, code);
    }
    kernels.push_back(k);
  }
  for (const auto& [family, body] : family_bodies) {
    const std::string file = "polygon_" + std::string(family_name(family)) + ".hpp";
    std::ostringstream os;
    os << file_header(file, "polygon edge kernels of the " + std::string(family_name(family)) + " family.", request)
       << kPolygonSources << "#pragma once\n\n#include <algorithm>\n#include <array>\n#include <cmath>\n\n"
       << "#include <skelconv/detail/exact_cross.hpp>\n#include <skelconv/detail/gauss_moments.hpp>\n#include <skelconv/detail/polygon_angle_integrals.hpp>\n"
       << "#include <skelconv/primitives/polygon_edge_input.hpp>\n#include <skelconv/primitives/segment_input.hpp>\n"
       << "#include <skelconv/detail/stable_recurrence.hpp>\n#include <skelconv/detail/support_gap.hpp>\n\n"
       << "namespace skelconv::generated {\n\n"
       << body << "}  // namespace skelconv::generated\n";
    write_file(folder / file, os.str());
  }

  std::ostringstream table;
  table << file_header("polygon_table.hpp", "every generated polygon edge kernel, for lookup at run time.", request)
        << kPolygonSources << "#pragma once\n\n#include <span>\n\n";
  for (const auto& [family, body] : family_bodies)
    table << "#include \"generated/polygon_" << family_name(family) << ".hpp\"\n";
  table << "\nnamespace skelconv::generated {\n\n"
        << "/// One generated polygon edge kernel: the edge terms for f, ∇f and both, with their\n"
        << "/// operation counts per edge.\n"
        << "template <class T>\nstruct PolygonEdgeKernel {\n"
        << "  KernelFamily family;\n  int degree;\n"
        << "  void (*f)(const PolygonEdgeInput<T>&, PolygonEdgeTerms<T>&);\n"
        << "  void (*grad)(const PolygonEdgeInput<T>&, PolygonEdgeTerms<T>&);\n"
        << "  void (*f_and_grad)(const PolygonEdgeInput<T>&, PolygonEdgeTerms<T>&);\n"
        << "  const char* name;\n  const char* equation;\n"
        << "  OpCount ops_f, ops_grad, ops_f_and_grad;\n};\n\n"
        << "/// Every generated polygon edge kernel, sorted by family and degree.\n"
        << "template <class T>\nstd::span<const PolygonEdgeKernel<T>> polygon_edge_kernels() {\n"
        << "  static const PolygonEdgeKernel<T> table[] = {\n";
  for (const EmittedPolygonKernel& k : kernels) {
    const std::string n = k.spec.name();
    table << "      {KernelFamily::" << family_name(k.spec.family) << ", " << k.spec.degree << ", &" << n << "_f<T>, &"
          << n << "_grad<T>, &" << n << "_f_and_grad<T>, \"" << n << "\",\n       \"" << k.spec.equation() << "\", "
          << ops_initializer(k.ops[0]) << ", " << ops_initializer(k.ops[1]) << ", " << ops_initializer(k.ops[2])
          << "},\n";
  }
  table << "  };\n  return table;\n}\n\n"
        << "/// The edge kernel for (family, degree), or nullptr if it was not generated.\n"
        << "template <class T>\n"
        << "const PolygonEdgeKernel<T>* find_polygon_edge_kernel(KernelFamily family, int degree) {\n"
        << "  for (const PolygonEdgeKernel<T>& k : polygon_edge_kernels<T>())\n"
        << "    if (k.family == family && k.degree == degree) return &k;\n"
        << "  return nullptr;\n}\n\n"
        << "}  // namespace skelconv::generated\n";
  write_file(folder / "polygon_table.hpp", table.str());

  // Rows of opcounts.csv (family "polygon_<family>", weight degree 0; counts per edge).
  std::ostringstream csv;
  for (const EmittedPolygonKernel& k : kernels)
    for (int which = 0; which < 3; ++which)
      csv << opcount_csv_row(k.spec.name(), "polygon_" + std::string(family_name(k.spec.family)), k.spec.degree, 0,
                             which, k.ops[which], k.ops_longest[which]);
  return csv.str();
}

}  // namespace skelconv::codegen
