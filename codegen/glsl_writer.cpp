// codegen/glsl_writer.cpp — see glsl_writer.hpp. Segment and SCALIS
// segment kernels; the point kernels are glsl_point_writer.cpp's.
//
// Each kernel is its definition integral by the Gauss-Legendre rule of
// glsl_rule.cpp, not the C++ target's closed forms: in float those cancel
// (glsl_rule.cpp gives the measurements); the rule's integrand is positive.
#include "glsl_writer.hpp"

#include "glsl_rule.hpp"

#include <map>
#include <sstream>
#include <string>

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
    "// (>= 0, not both 0) and the kernel scale sigma (docs/mathematics.md sec. 4).\n"
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

// generated/glsl/scalis_segment_<family>.glsl: the SCALIS segment kernels
// (docs/mathematics.md sec. 4), unnormalised F as the C++ target's (f = c F / h is the
// caller's).
void write_glsl_scalis(const GeneratorRequest& request, const std::filesystem::path& folder) {
  std::map<KernelFamily, std::string> bodies;
  for (const ScalisKernelSpec& spec : request.scalis_segment_kernels)
    bodies[spec.family] += glsl_scalis_rule_functions(spec);
  for (const auto& [family, body] : bodies) {
    const std::string file = "scalis_segment_" + std::string(family_name(family)) + ".glsl";
    std::ostringstream os;
    os << glsl_ascii(file_header("glsl/" + file,
                                 "SCALIS segment kernels of the " + std::string(family_name(family)) +
                                     " family in GLSL (float; ES 3.00 and 4.50), by a Gauss-Legendre rule.",
                                 request))
       << "// Unnormalised, as generated/scalis_segment_" << family_name(family)
       << ".hpp: f = c F / h is the caller's\n// (skelconv/primitives/scalis_segment.hpp).\n"
       << "\n" << kGlslScalisInput << kGlslHelpers << glsl_rule_block() << glsl_ascii(body);
    write_file(folder / file, os.str());
  }
}

}  // namespace

void write_glsl_folder(const GeneratorRequest& request, const std::filesystem::path& folder) {
  std::filesystem::create_directories(folder);
  std::map<KernelFamily, std::string> bodies;
  for (const SegmentKernelSpec& spec : request.segment_kernels) bodies[spec.family] += glsl_segment_rule_functions(spec);
  for (const auto& [family, body] : bodies) {
    const std::string file = "glsl/segment_" + std::string(family_name(family)) + ".glsl";
    std::ostringstream os;
    os << glsl_ascii(file_header(file,
                                 "segment kernels of the " + std::string(family_name(family)) +
                                     " family in GLSL (float; ES 3.00 and 4.50), by a Gauss-Legendre rule.",
                                 request))
       << "\n" << kGlslSegmentInput << kGlslHelpers << glsl_rule_block() << glsl_ascii(body);
    write_file(folder / ("segment_" + std::string(family_name(family)) + ".glsl"), os.str());
  }
  write_glsl_scalis(request, folder);
  write_glsl_points(request, folder);
}

}  // namespace skelconv::codegen
