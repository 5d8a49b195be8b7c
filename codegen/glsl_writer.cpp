// codegen/glsl_writer.cpp — see glsl_writer.hpp. Segment and SCALIS
// segment kernels; the point kernels are glsl_point_writer.cpp's.
//
// The GLSL functions are the programs' Forms::fast emission (the generic
// alternative of every stable-form choice, unconditionally, as the filter's
// fast forms), translated token by token from the C++ statements the
// emitter writes: one printer of expressions for both targets, so the two
// cannot drift apart. Generic forms only because the other alternatives
// call C++ helpers (Gauss rules, downward recurrences, the exact cross
// product) that have no GLSL version yet. In single precision these forms
// are NOT accurate everywhere in the generic region: the upward recurrence
// and the cancellations the C++ target's stable rewrites avoid cost far more
// than float's 6e-8 (tests/glsl/check_glsl_numeric.py measures them per
// family, degree and side of P; docs/view.md lists them).
#include "glsl_writer.hpp"

#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace skelconv::codegen {

namespace {

// GLSL ES 3.00 source for WebGL: ASCII only is the portable choice (WebGL 1
// validators refuse any non-ASCII byte, even in comments), so the header's
// mathematics is transliterated.
std::string glsl_ascii(const std::string& text) {
  static const std::pair<const char*, const char*> kMap[] = {
      {"—", "-"}, {"−", "-"}, {"×", "*"}, {"∫", "int"}, {"Γ", "Gamma"}, {"∇", "grad "}, {"§", "sec. "},
      {"τ", "tau"}, {"σ", "sigma"}, {"√", "sqrt"}, {"²", "^2"}, {"³", "^3"}, {"α", "alpha"}, {"β", "beta"},
      {"–", "-"}, {"≥", ">="}, {"≤", "<="}, {"·", "."}, {"∞", "inf"}, {"ℓ", "l"}};
  std::string out = text;
  for (const auto& [from, to] : kMap) {
    const std::string f = from;
    for (size_t at = out.find(f); at != std::string::npos; at = out.find(f, at)) out.replace(at, f.size(), to);
  }
  for (char& c : out)
    if (static_cast<unsigned char>(c) >= 0x80) c = '?';
  return out;
}

// C++ statements of the emitter (straight_line_program.cpp) to GLSL: the
// scalar type T becomes float; `const` goes (in GLSL ES 3.00 a const needs a
// constant initialiser); `in` is a GLSL keyword, so the input is `si`;
// std::atan2(y, x) is GLSL's atan(y, x); asinh is skelconv_asinh (below);
// the other calls (sqrt, log, min, max) have the same names.
std::string to_glsl(const std::string& cpp_body) {
  std::istringstream lines(cpp_body);
  std::ostringstream out;
  static const std::regex const_decl(R"(\bconst T )"), decl(R"(^(\s*)T )"), cast(R"(\bT\()"),
      input(R"(\bin\.)"), std_prefix(R"(\bstd::)"), atan2(R"(\batan2\()"), asinh(R"(\basinh\()");
  for (std::string line; std::getline(lines, line);) {
    if (line.find("using std::") != std::string::npos) continue;
    line = std::regex_replace(line, const_decl, "float ");
    line = std::regex_replace(line, decl, "$1float ");
    line = std::regex_replace(line, cast, "float(");
    line = std::regex_replace(line, input, "si.");
    line = std::regex_replace(line, std_prefix, "");
    line = std::regex_replace(line, atan2, "atan(");
    line = std::regex_replace(line, asinh, "skelconv_asinh(");
    out << glsl_ascii(line) << '\n';
  }
  return out.str();
}

// The input block every segment file declares once (the guard lets a
// shader concatenate several families): the fields of SegmentInput that the
// kernels read (skelconv/primitives/segment_input.hpp).
constexpr const char* kGlslSegmentInput =
    "#ifndef SKELCONV_SEGMENT_INPUT\n"
    "#define SKELCONV_SEGMENT_INPUT\n"
    "// The segment AB, the query point p, the weight w(t) = sum_k w[k] t^k,\n"
    "// the Cauchy sharpness s, the compact support radius R and the part\n"
    "// [t0, t1] of AB inside the ball of radius R around p (compact only; the\n"
    "// caller clips, as skelconv/detail/clip.hpp does).\n"
    "struct SegmentInput {\n"
    "  vec3 a;\n  vec3 b;\n  vec3 p;\n  vec4 w;\n  float s;\n  float R;\n  float t0;\n  float t1;\n"
    "};\n"
    "#endif\n\n";

// The same for the SCALIS segment files: ScalisSegmentInput
// (skelconv/primitives/scalis_segment_input.hpp).
constexpr const char* kGlslScalisInput =
    "#ifndef SKELCONV_SCALIS_SEGMENT_INPUT\n"
    "#define SKELCONV_SCALIS_SEGMENT_INPUT\n"
    "// The segment AB, the query point p, the radii tau0 at A and tau1 at B\n"
    "// (>= 0, not both 0) and the kernel scale sigma (SPEC sec. 4).\n"
    "struct ScalisSegmentInput {\n"
    "  vec3 a;\n  vec3 b;\n  vec3 p;\n  float tau0;\n  float tau1;\n  float sigma;\n"
    "};\n"
    "#endif\n\n";

// The helpers every file may call, under their own guard.
constexpr const char* kGlslHelpers =
    "#ifndef SKELCONV_GLSL_HELPERS\n"
    "#define SKELCONV_GLSL_HELPERS\n"
    "// asinh without the losses of log(x + sqrt(x^2 + 1)), the form GPU\n"
    "// libraries may use: odd symmetry (no cancellation for x < 0), log1p of\n"
    "// u = |x| + x^2 / (1 + sqrt(1 + x^2)) by Kahan's log(1 + u) u / ((1 + u) - 1)\n"
    "// (no loss for small |x|), and log(2|x|) where x^2 would overflow (|x| >\n"
    "// 1e18: there sqrt(1 + x^2) = |x| in float).\n"
    "float skelconv_asinh(float x) {\n"
    "  float ax = abs(x);\n"
    "  if (ax > 1e18) return sign(x) * (log(ax) + 0.69314718);\n"
    "  float u = ax + ax * ax / (1.0 + sqrt(1.0 + ax * ax));\n"
    "  float w = 1.0 + u;\n"
    "  float l = w == 1.0 ? u : log(w) * u / (w - 1.0);\n"
    "  return sign(x) * l;\n"
    "}\n"
    "#endif\n\n";

// The GLSL form of the SCALIS prologue (scalis_segment_writer.cpp's
// kScalisPrologue): the ends ordered so that tau_lo <= tau_hi.
constexpr const char* kGlslScalisPrologue =
    "  // Ends ordered so that tau_lo <= tau_hi (delta tau >= 0: no cancellation in the weight).\n"
    "  bool swap_ends = si.tau1 < si.tau0;\n"
    "  vec3 end_a = swap_ends ? si.b : si.a;\n"
    "  vec3 end_b = swap_ends ? si.a : si.b;\n"
    "  float tau_lo = swap_ends ? si.tau1 : si.tau0;\n"
    "  float tau_hi = swap_ends ? si.tau0 : si.tau1;\n";

// Kernels left out of a file (their generic path calls a helper), as a
// comment wrapped at about 80 columns.
std::string left_out_text(const std::string& names_text) {
  std::ostringstream os;
  std::istringstream names(names_text);
  os << "// Left out (their generic path calls a Gauss rule or a loop):\n//";
  size_t column = 2;
  for (std::string n; names >> n; column += n.size() + 1) {
    if (column + n.size() + 1 > 80) {
      os << "\n//";
      column = 2;
    }
    os << ' ' << n;
  }
  os << '\n';
  return os.str();
}

// One function: `which` 0 for f, 2 for f and grad f; `input` the input
// struct's name, `prologue` GLSL statements before the program's.
std::string glsl_function_text(const std::string& kernel, const std::string& equation, const std::string& input,
                               const char* prologue, int which, const EmittedCode& code) {
  std::ostringstream os;
  const std::string name = kernel + "_" + kFunctionSuffix[which];
  os << "// " << (which == 0 ? "the field" : "the field and its gradient") << ", where\n"
     << "//     " << glsl_ascii(equation) << "\n"
     << "// Operations: " << glsl_ascii(ops_text(code.ops)) << " (generic form).\n";
  if (which == 0)
    os << "float " << name << "(" << input << " si) {\n";
  else
    os << "float " << name << "(" << input << " si, out vec3 grad) {\n";
  os << "  float f;\n" << prologue << to_glsl(code.body) << "  return f;\n}\n\n";
  return os.str();
}

// f and (f, grad f): a ray marcher needs the first per step and the second
// per hit; grad f alone is the second's gradient.
constexpr int kGlslEmitted[] = {0, 2};

// generated/glsl/scalis_segment_<family>.glsl: the SCALIS segment kernels
// (SPEC sec. 4), unnormalised F as the C++ target's (f = c F / h is the
// caller's), the program's fast forms after the GLSL prologue.
void write_glsl_scalis(const GeneratorRequest& request, const std::filesystem::path& folder) {
  std::map<KernelFamily, std::string> bodies, left_out;
  for (const ScalisKernelSpec& spec : request.scalis_segment_kernels) {
    std::string text;
    bool available = true;
    for (int which : kGlslEmitted) {
      const EmittedCode code = build_scalis_segment_program(spec, kOutputs[which]).emit(Forms::fast);
      if (!code.fast_available) {
        available = false;
        break;
      }
      text += glsl_function_text(spec.name(), spec.equation(), "ScalisSegmentInput", kGlslScalisPrologue, which, code);
    }
    (available ? bodies : left_out)[spec.family] += available ? text : " " + spec.name();
  }
  for (const auto& [family, body] : bodies) {
    const std::string file = "scalis_segment_" + std::string(family_name(family)) + ".glsl";
    std::ostringstream os;
    os << glsl_ascii(file_header("glsl/" + file,
                                 "SCALIS segment kernels of the " + std::string(family_name(family)) +
                                     " family in GLSL (float; ES 3.00 and 4.50), generic forms only.",
                                 request))
       << "// Unnormalised, as generated/scalis_segment_" << family_name(family)
       << ".hpp: f = c F / h is the caller's\n// (skelconv/primitives/scalis_segment.hpp).\n";
    if (left_out.count(family)) os << left_out_text(left_out[family]);
    os << "\n" << kGlslScalisInput << kGlslHelpers << body;
    write_file(folder / file, os.str());
  }
}

}  // namespace

void write_glsl_folder(const GeneratorRequest& request, const std::filesystem::path& folder) {
  std::filesystem::create_directories(folder);
  std::map<KernelFamily, std::string> bodies, left_out;
  for (const SegmentKernelSpec& spec : request.segment_kernels) {
    std::string text;
    bool available = true;
    for (int which : kGlslEmitted) {
      const EmittedCode code = build_segment_program(spec, kOutputs[which]).emit(Forms::fast);
      if (!code.fast_available) {
        available = false;
        break;
      }
      text += glsl_function_text(spec.name(), spec.equation(), "SegmentInput", "", which, code);
    }
    if (available)
      bodies[spec.family] += text;
    else
      left_out[spec.family] += " " + spec.name();
  }
  for (const auto& [family, body] : bodies) {
    const std::string file = "glsl/segment_" + std::string(family_name(family)) + ".glsl";
    std::ostringstream os;
    os << glsl_ascii(file_header(file,
                            "segment kernels of the " + std::string(family_name(family)) +
                                " family in GLSL (float; ES 3.00 and 4.50), generic forms only.",
                            request));
    if (left_out.count(family)) os << left_out_text(left_out[family]);
    os << "\n" << kGlslSegmentInput << kGlslHelpers << body;
    write_file(folder / ("segment_" + std::string(family_name(family)) + ".glsl"), os.str());
  }
  write_glsl_scalis(request, folder);
  write_glsl_points(request, folder);
}

}  // namespace skelconv::codegen
