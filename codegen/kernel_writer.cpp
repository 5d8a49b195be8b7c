// codegen/kernel_writer.cpp — see kernel_writer.hpp.
#include "kernel_writer.hpp"

#include <ginac/version.h>

#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>

namespace skelconv::codegen {

namespace {
constexpr const char* kGenericSuffix = "f_and_grad_generic";
}  // namespace

std::string file_header(const std::string& file, const std::string& what, const GeneratorRequest& request) {
  std::ostringstream os;
  os << "// generated/" << file << " — " << what << "\n"
     << "//\n"
     << "// GENERATED FILE: DO NOT EDIT. Regenerate with\n"
     << "//     " << request.command_line << " --out generated\n"
     << "// Generator: skelconv-codegen " << SKELCONV_VERSION << " (GiNaC " << GINACLIB_MAJOR_VERSION << '.'
     << GINACLIB_MINOR_VERSION << '.' << GINACLIB_MICRO_VERSION << ")\n"
     << "// From: codegen/segment_families.cpp (the families) and codegen/segment_moments.cpp\n"
     << "// (recurrence (1) of Hubert & Cani unrolled; docs/mathematics.md §2, Hubert 2012 §3).\n";
  return os.str();
}

std::string ops_text(const OpCount& o) {
  std::ostringstream os;
  os << o.add << " +, " << o.mul << " ×, " << o.div << " /, " << o.sqrt << " sqrt, " << o.atan << " atan, "
     << o.log << " log/asinh";
  if (o.other) os << ", " << o.other << " other";
  return os.str();
}

std::string ops_initializer(const OpCount& o) {
  std::ostringstream os;
  os << '{' << o.add << ", " << o.mul << ", " << o.div << ", " << o.sqrt << ", " << o.atan << ", " << o.log << ", "
     << o.other << '}';
  return os.str();
}

namespace {

struct EmittedKernel {
  SegmentKernelSpec spec;
  SplitKernel split;
};

// A segment kernel's inputs that are the same at every point: all but P
// and the compact clip [t0, t1] (which depends on P).
bool per_primitive_input(const std::string& cpp) {
  return cpp.rfind("in.p[", 0) != 0 && cpp != "in.t0" && cpp != "in.t1";
}
// The per-point inputs, read from the evaluation's SegmentPoint: in.p[0] → point.p[0].
std::string point_input(const std::string& cpp) { return "point" + cpp.substr(2); }

// The classical segments' split: everything but P and the compact clip is
// the segment's.
KernelSplit classical_split() {
  return {"SegmentInput",
          "const T* pre, const SegmentPoint<T>& point",
          "const SegmentPoint<T>&",
          "A, B, the weight, the kernel's parameter",
          "in.p, in.t0 and in.t1 are",
          "",
          per_primitive_input,
          point_input};
}

// The preparation of one kernel: what its f, ∇f and both read that depends
// on the primitive alone, into pre[0 .. size).
std::string prepare_function_text(const std::string& name, const KernelSplit& how, std::size_t size,
                                  const EmittedCode& code) {
  std::ostringstream os;
  os << "/// How many values " << name << "_prepare writes.\n"
     << "inline constexpr std::size_t " << name << "_prepared_size = " << size << ";\n\n"
     << "/// What " << name << "_f, _grad and _f_and_grad read that depends on the segment\n"
     << "/// alone (" << how.prepared_what << "), into pre[0 .. " << size << "): computed once per\n"
     << "/// segment; " << how.not_read << " not read.\n"
     << "/// Operations: " << ops_text(code.ops) << ".\n"
     << "template <class T>\n"
     << "void " << name << "_prepare(const " << how.input_type << "<T>& in, T* pre) {\n"
     << "  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;\n"
     << how.prologue << code.body << "}\n\n";
  return os.str();
}

// f and ∇f on the generic forms only: straight-line code whose operations
// bench/summarize.py splits by section (preamble, conditions, forms, result);
// returns false where the full function would take another form,
// and the caller must then call <name>_f_and_grad.
std::string generic_function_text(const SegmentKernelSpec& spec, const EmittedCode& code) {
  const std::string name = spec.name() + "_" + kGenericSuffix;
  std::ostringstream os;
  os << "/// The field and its gradient on the generic forms only (no helper loops), where\n"
     << "///     " << spec.equation() << "\n"
     << "/// Returns false where " << spec.name() << "_f_and_grad takes another form: its values\n"
     << "/// then are not to be used.\n"
     << "/// Operations: " << ops_text(code.ops) << ".\n"
     << "template <class T>\n"
     << "bool " << name << "(const SegmentInput<T>& in, T& f, std::array<T, 3>& grad) {\n"
     << "  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;\n"
     << code.body << "  return " << code.generic_applies << ";\n}\n\n";
  return os.str();
}

}  // namespace

std::string kernel_function_text(const std::string& kernel_name, const std::string& equation,
                                 const std::string& input_type, int which, const EmittedCode& code,
                                 const std::string& prologue) {
  return kernel_function_text_reading(kernel_name, equation, "const " + input_type + "<T>& in", which, code, prologue,
                                      "");
}

std::string kernel_function_text_reading(const std::string& kernel_name, const std::string& equation,
                                         const std::string& parameters, int which, const EmittedCode& code,
                                         const std::string& prologue, const std::string& note) {
  const std::string name = kernel_name + "_" + kFunctionSuffix[which];
  std::ostringstream os;
  static const char* kWhat[] = {"the field", "its gradient ∇_P f", "the field and its gradient"};
  os << "/// " << kWhat[which] << ", where\n"
     << "///     " << equation << "\n"
     << note
     << "/// Operations: " << ops_text(code.ops) << " (generic form).\n";
  if (!(code.ops_longest == code.ops)) os << "/// Longest path: " << ops_text(code.ops_longest) << ".\n";
  os
     << "template <class T>\n";
  switch (which) {
    case 0: os << "T " << name << "(" << parameters << ") {\n"; break;
    case 1: os << "std::array<T, 3> " << name << "(" << parameters << ") {\n"; break;
    default: os << "T " << name << "(" << parameters << ", std::array<T, 3>& grad) {\n"; break;
  }
  os << "  using std::asinh, std::atan2, std::log, std::max, std::min, std::sqrt;\n";
  if (which != 1) os << "  T f;\n";
  if (which == 1) os << "  std::array<T, 3> grad;\n";
  os << prologue << code.body;
  os << (which == 1 ? "  return grad;\n" : "  return f;\n") << "}\n\n";
  return os.str();
}

SplitKernel split_kernel(const std::string& kernel_name, const std::string& equation,
                         const std::array<StraightLineProgram, 3>& outputs, const KernelSplit& how) {
  SplitKernel k;
  // f and ∇f first: it reads the most, so its quantities come first in pre[].
  PreparedQuantities prepared(how.per_primitive_input);
  EmittedCode code[3];
  for (const int which : {2, 0, 1}) code[which] = prepared.per_point_part(outputs[which], how.point_input).emit();
  const EmittedCode preparation = prepared.prepare_program().emit();
  k.ops_prepare = preparation.ops;
  k.prepared_size = prepared.size();
  k.text = prepare_function_text(kernel_name, how, prepared.size(), preparation);
  for (int which = 0; which < 3; ++which) {
    k.ops[which] = code[which].ops;
    k.ops_longest[which] = code[which].ops_longest;
    k.ops_primitive[which] = prepared.prepare_program(&code[which].inputs_read).emit().ops;
    k.text += kernel_function_text_reading(
        kernel_name, equation, how.evaluate_parameters, which, code[which],
        prepared.read_fields_text(code[which].inputs_read),
        "/// At one point, from the segment's pre[] (" + kernel_name + "_prepare); operations per point.\n");
  }
  return k;
}

std::string split_table_members(const KernelSplit& how) {
  const std::string point = how.point_type;
  return "  OpCount ops_prepare{};\n"
         "  std::size_t prepared_size = 0;\n"
         "  void (*prepare)(const " + how.input_type + "<T>&, T*) = nullptr;\n"
         "  T (*f_at)(const T*, " + point + ") = nullptr;\n"
         "  std::array<T, 3> (*grad_at)(const T*, " + point + ") = nullptr;\n"
         "  T (*f_and_grad_at)(const T*, " + point + ", std::array<T, 3>&) = nullptr;\n";
}

std::string one_point_entries(const std::string& n) {
  const std::string size = n + "_prepared_size";
  auto at_one_point = [&](const char* wrapper, int which) {
    return "&" + std::string(wrapper) + "<T, " + size + ", &" + n + "_prepare<T>, &" + n + "_" +
           kFunctionSuffix[which] + "<T>>";
  };
  return at_one_point("prepared_f", 0) + ",\n       " + at_one_point("prepared_grad", 1) + ",\n       " +
         at_one_point("prepared_f_and_grad", 2);
}

std::string split_entries(const std::string& n, const OpCount& ops_prepare) {
  return ops_initializer(ops_prepare) + ", " + n + "_prepared_size, &" + n + "_prepare<T>, &" + n + "_f<T>, &" + n +
         "_grad<T>, &" + n + "_f_and_grad<T>";
}

std::string split_csv_rows(const std::string& kernel_name, const std::string& family, int degree,
                           int weight_degree, const SplitKernel& k) {
  std::string rows;
  for (int which = 0; which < 3; ++which) {
    OpCount one = k.ops[which], longest = k.ops_longest[which];
    one += k.ops_primitive[which];
    longest += k.ops_primitive[which];
    rows += opcount_csv_row(kernel_name, family, degree, weight_degree, which, one, longest, &k.ops[which],
                            &k.ops_primitive[which]);
  }
  return rows;
}

std::string opcount_csv_row(const std::string& kernel_name, const std::string& family, int degree, int weight_degree,
                            int which, const OpCount& o, const OpCount& l, const OpCount* point,
                            const OpCount* primitive) {
  std::ostringstream csv;
  auto cells = [&](const OpCount* c) {
    if (c)
      csv << ',' << c->add << ',' << c->mul << ',' << c->div << ',' << c->sqrt << ',' << c->atan << ',' << c->log
          << ',' << c->other;
    else
      csv << ",,,,,,,";
  };
  csv << kernel_name << '_' << kFunctionSuffix[which] << ',' << family << ',' << degree << ',' << weight_degree << ','
      << kFunctionSuffix[which];
  cells(&o);
  cells(&l);
  cells(point);
  cells(primitive);
  csv << '\n';
  return csv.str();
}

// A file whose bytes are already `text` is left alone: its time stamp stays,
// so that a build after regenerating recompiles only what includes a file
// that changed (a formula change in one family rebuilds that family).
void write_file(const std::filesystem::path& path, const std::string& text) {
  {
    std::ifstream existing(path, std::ios::binary);
    if (existing) {
      const std::string old_text{std::istreambuf_iterator<char>(existing), std::istreambuf_iterator<char>()};
      if (old_text == text) return;
    }
  }
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

void write_generated_folder(const GeneratorRequest& request, const std::filesystem::path& folder) {
  std::filesystem::create_directories(folder);
  std::vector<EmittedKernel> kernels;
  std::map<KernelFamily, std::string> family_bodies;

  // The programs first, in the order of the kernels, and the split into a
  // preparation and a per-point part after the other writers: GiNaC orders
  // terms by its symbols' serial numbers, and the split makes symbols of
  // its own, which would otherwise reorder the polygon and SCALIS code.
  struct Programs {
    std::array<StraightLineProgram, 3> outputs;  // f, grad, f_and_grad
    std::string generic_text;
  };
  std::vector<Programs> programs;
  for (const SegmentKernelSpec& spec : request.segment_kernels) {
    Programs& p = programs.emplace_back();
    for (int which = 0; which < 3; ++which) p.outputs[which] = build_segment_program(spec, kOutputs[which]);
    p.generic_text = generic_function_text(
        spec, build_segment_program(spec, SegmentOutputs::value_and_gradient).emit(Forms::generic_only));
  }

  // Polygon edges and SCALIS segments: their own headers and tables
  // (polygon_writer.cpp, scalis_segment_writer.cpp); the SCALIS kernels are
  // split after the classical ones.
  const std::string polygon_csv_rows = write_polygon_files(request, folder);
  const std::vector<std::array<StraightLineProgram, 3>> scalis_programs = build_scalis_segment_programs(request);

  const KernelSplit split = classical_split();
  for (std::size_t i = 0; i < request.segment_kernels.size(); ++i) {
    const SegmentKernelSpec& spec = request.segment_kernels[i];
    EmittedKernel k{spec, split_kernel(spec.name(), spec.equation(), programs[i].outputs, split)};
    family_bodies[spec.family] += k.split.text + programs[i].generic_text;
    kernels.push_back(k);
  }
  const std::string scalis_csv_rows = write_scalis_segment_files(request, folder, scalis_programs);

  // One header per family: its functions, then its part of the lookup
  // table (segment_<family>_kernels<T>(), declared in segment_table.hpp).
  // A formula change in one family changes that family's header only, so
  // only the files that instantiate that family recompile (the double table
  // of the runtime, the binary128 table of the verifier, one file each).
  // The table holds f, ∇f and both; the generic-only functions are not in
  // it (only the benchmarks call them, by name), so instantiating the table
  // does not compile them.
  for (const auto& [family, body] : family_bodies) {
    const std::string file = "segment_" + std::string(family_name(family)) + ".hpp";
    std::ostringstream os;
    os << file_header(file, "segment kernels of the " + std::string(family_name(family)) + " family.", request)
       << "#pragma once\n\n#include <algorithm>\n#include <array>\n#include <cmath>\n#include <span>\n\n"
       << "#include <skelconv/detail/exact_cross.hpp>\n#include <skelconv/detail/gauss_moments.hpp>\n#include <skelconv/primitives/segment_input.hpp>\n"
       << "#include <skelconv/detail/stable_recurrence.hpp>\n#include <skelconv/detail/support_gap.hpp>\n\n"
       << "#include \"generated/segment_table.hpp\"\n\n"
       << "namespace skelconv::generated {\n\n"
       << body
       << "/// The " << family_name(family) << " family's kernels, sorted by degree and weight degree.\n"
       << "template <class T>\nstd::span<const SegmentKernel<T>> segment_" << family_name(family) << "_kernels() {\n"
       << "  static const SegmentKernel<T> table[] = {\n";
    for (const EmittedKernel& k : kernels) {
      if (k.spec.family != family) continue;
      const std::string n = k.spec.name();
      os << "      {KernelFamily::" << family_name(k.spec.family) << ", " << k.spec.degree << ", "
         << k.spec.weight_degree << ",\n       " << one_point_entries(n) << ",\n       \""
         << n << "\",\n       \"" << k.spec.equation() << "\", " << ops_initializer(k.split.ops[0]) << ", "
         << ops_initializer(k.split.ops[1]) << ", " << ops_initializer(k.split.ops[2]) << ",\n       "
         << split_entries(n, k.split.ops_prepare) << "},\n";
    }
    os << "  };\n  return table;\n}\n\n"
       << "}  // namespace skelconv::generated\n";
    write_file(folder / file, os.str());
  }

  // The lookup table's types and declarations, with no formula in it: one
  // function per family, each defined at the end of the family's header and
  // instantiated in a translation unit of its own (double in the runtime,
  // binary128 in the verifier), so that the families compile in parallel
  // and a file that only looks kernels up never parses the formulas.
  std::ostringstream table;
  table << file_header("segment_table.hpp", "the lookup table of the generated segment kernels (declarations).", request)
        << "#pragma once\n\n#include <array>\n#include <span>\n#include <vector>\n\n"
        << "#include <skelconv/kernels/kernel_family.hpp>\n#include <skelconv/kernels/op_count.hpp>\n"
        << "#include <skelconv/primitives/prepared_kernel.hpp>\n#include <skelconv/primitives/segment_input.hpp>\n\n"
        << "namespace skelconv::generated {\n\n"
        << "/// One generated kernel: f, ∇f and both, with their operation counts.\n"
        << "/// A generated kernel is split in two: `prepare` computes what depends on the\n"
        << "/// segment alone into an array of `prepared_size` values, once per segment, and\n"
        << "/// `f_at`, `grad_at`, `f_and_grad_at` read it at each point. `f`, `grad` and\n"
        << "/// `f_and_grad` do both for one point (prepared_f, prepared_kernel.hpp). The ops_* counts are\n"
        << "/// per point; ops_prepare is the preparation's, once per segment. The derived\n"
        << "/// Gaussian entry (derived_segment_kernels.hpp) is not split: no `prepare`.\n"
        << "template <class T>\nstruct SegmentKernel {\n"
        << "  KernelFamily family;\n  int degree;\n  int weight_degree;\n"
        << "  T (*f)(const SegmentInput<T>&);\n"
        << "  std::array<T, 3> (*grad)(const SegmentInput<T>&);\n"
        << "  T (*f_and_grad)(const SegmentInput<T>&, std::array<T, 3>&);\n"
        << "  const char* name;\n  const char* equation;\n"
        << "  OpCount ops_f, ops_grad, ops_f_and_grad;\n"
        << split_table_members(split) << "};\n\n";
  for (const auto& [family, body] : family_bodies)
    table << "/// The " << family_name(family) << " family's kernels (defined in generated/segment_"
          << family_name(family) << ".hpp).\n"
          << "template <class T>\nstd::span<const SegmentKernel<T>> segment_" << family_name(family) << "_kernels();\n\n";
  table << "/// Every generated kernel, sorted by family, degree and weight degree.\n"
        << "template <class T>\nstd::span<const SegmentKernel<T>> segment_kernels() {\n"
        << "  static const std::vector<SegmentKernel<T>> table = [] {\n"
        << "    std::vector<SegmentKernel<T>> all;\n";
  for (const auto& [family, body] : family_bodies)
    table << "    for (const SegmentKernel<T>& k : segment_" << family_name(family) << "_kernels<T>()) all.push_back(k);\n";
  table << "    return all;\n  }();\n  return table;\n}\n\n"
        << "/// The kernel for (family, degree, weight degree), or nullptr if it was not generated.\n"
        << "template <class T>\n"
        << "const SegmentKernel<T>* find_segment_kernel(KernelFamily family, int degree, int weight_degree) {\n"
        << "  for (const SegmentKernel<T>& k : segment_kernels<T>())\n"
        << "    if (k.family == family && k.degree == degree && k.weight_degree == weight_degree) return &k;\n"
        << "  return nullptr;\n}\n\n"
        << "}  // namespace skelconv::generated\n";
  write_file(folder / "segment_table.hpp", table.str());

  // The operation counts, machine-readable.
  std::ostringstream csv;
  // One evaluation (the first two groups) is the preparation of what the
  // output reads plus the per-point code; point_* is the per-point code
  // alone and primitive_* that preparation, once per primitive. Rows
  // without the split (polygon edges) leave the last two empty.
  csv << "function,family,degree,weight_degree,outputs,add,mul,div,sqrt,atan,log,other,"
         "longest_add,longest_mul,longest_div,longest_sqrt,longest_atan,longest_log,longest_other,"
         "point_add,point_mul,point_div,point_sqrt,point_atan,point_log,point_other,"
         "primitive_add,primitive_mul,primitive_div,primitive_sqrt,primitive_atan,primitive_log,primitive_other\n";
  for (const EmittedKernel& k : kernels)
    csv << split_csv_rows(k.spec.name(), std::string(family_name(k.spec.family)), k.spec.degree, k.spec.weight_degree,
                          k.split);
  csv << polygon_csv_rows << scalis_csv_rows;
  write_file(folder / "opcounts.csv", csv.str());
}

}  // namespace skelconv::codegen
