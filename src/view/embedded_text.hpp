// src/view/embedded_text.hpp — files of the repository carried by the
// program (cmake/embed_text.cmake writes their definitions at build time).
#pragma once

namespace skelconv::detail {

extern const char view_template_html[];    ///< src/view/view_template.html
extern const char view_march_glsl[];       ///< src/view/view_march.glsl
extern const char segment_inverse_glsl[];  ///< generated/glsl/segment_inverse.glsl
extern const char segment_cauchy_glsl[];   ///< generated/glsl/segment_cauchy.glsl
extern const char segment_compact_glsl[];  ///< generated/glsl/segment_compact.glsl
extern const char scalis_segment_inverse_glsl[];  ///< generated/glsl/scalis_segment_inverse.glsl
extern const char scalis_segment_cauchy_glsl[];   ///< generated/glsl/scalis_segment_cauchy.glsl
extern const char point_glsl[];                   ///< generated/glsl/point.glsl

}  // namespace skelconv::detail
