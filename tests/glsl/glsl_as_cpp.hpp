// tests/glsl/glsl_as_cpp.hpp — the part of GLSL that generated/glsl/ uses,
// in C++ and IEEE single precision, so that check_glsl_numeric.py --backend
// cpu can compile the generated files themselves (after three rewrites: `out`
// and `inout` parameters become references, a float[N](...) array
// initialiser a braced list, a swizzle of the page's row texels a method or
// an index) and run them, and the page's segment_input(), without a GPU.
//
// What this measures is the forms' rounding in float: every operation
// rounded once to float (x86-64 SSE, no excess precision; the script
// compiles with -ffp-contract=off so that no multiply-add is fused), sqrt
// correctly rounded, log/exp/atan2 glibc's (< 1 ulp). A GPU's own sqrt,
// division and transcendental functions are allowed several ulps by the
// GLSL ES 3.00 specification; the --backend chromium run (SwiftShader)
// measures those.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

struct vec3 {
  float v[3];
  vec3() : v{0, 0, 0} {}
  explicit vec3(float a) : v{a, a, a} {}
  vec3(float a, float b, float c) : v{a, b, c} {}
  float& operator[](int i) { return v[i]; }
  float operator[](int i) const { return v[i]; }
};
struct vec4 {
  float v[4];
  vec4() : v{0, 0, 0, 0} {}
  vec4(float a, float b, float c, float d) : v{a, b, c, d} {}
  vec3 xyz() const { return {v[0], v[1], v[2]}; }  // the swizzle .xyz
  float& operator[](int i) { return v[i]; }
  float operator[](int i) const { return v[i]; }
};

inline vec3 operator+(const vec3& a, const vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline vec3 operator-(const vec3& a, const vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline vec3 operator*(float s, const vec3& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline vec3 operator*(const vec3& a, float s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline vec3& operator+=(vec3& a, const vec3& b) { return a = a + b; }
inline vec3& operator*=(vec3& a, float s) { return a = a * s; }
inline float dot(const vec3& a, const vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline float length(const vec3& a) { return std::sqrt(dot(a, a)); }
inline vec3 cross(const vec3& a, const vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline float sqrt(float x) { return std::sqrt(x); }
inline float log(float x) { return std::log(x); }
inline float exp(float x) { return std::exp(x); }
inline float sin(float x) { return std::sin(x); }
inline float cos(float x) { return std::cos(x); }
inline float sinh(float x) { return std::sinh(x); }
inline float cosh(float x) { return std::cosh(x); }
inline float abs(float x) { return std::fabs(x); }
inline float atan(float y, float x) { return std::atan2(y, x); }
inline float sign(float x) { return x > 0 ? 1.0f : (x < 0 ? -1.0f : 0.0f); }
inline float min(float a, float b) { return b < a ? b : a; }
inline float max(float a, float b) { return a < b ? b : a; }
inline float clamp(float x, float lo, float hi) { return min(max(x, lo), hi); }
inline float uintBitsToFloat(std::uint32_t bits) {
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}
