// Implementation of skelconv/reconstruct/bspline.hpp.
#include "skelconv/reconstruct/bspline.hpp"

#include "skelconv/errors.hpp"

namespace skelconv::reconstruct {

Vec4 bspline_span_point(const Vec4& v0, const Vec4& v1, const Vec4& v2, const Vec4& v3, double u) {
  return (v0 + 4.0 * v1 + v2 + 3.0 * u * (v2 - v0) + 3.0 * u * u * (v0 - 2.0 * v1 + v2) +
          u * u * u * (v3 - v0 + 3.0 * (v1 - v2))) /
         6.0;
}

std::vector<Vec4> smooth_bspline(const std::vector<Vec4>& control, int samples_per_span) {
  if (samples_per_span < 1) throw InputError("must be ≥ 1", "samples_per_span");
  if (control.size() < 2) return control;
  std::vector<Vec4> v;
  v.push_back(control.front());
  v.push_back(control.front());
  v.insert(v.end(), control.begin(), control.end());
  v.push_back(control.back());
  v.push_back(control.back());
  std::vector<Vec4> curve;
  for (std::size_t s = 0; s + 3 < v.size(); ++s) {
    for (int k = 0; k < samples_per_span; ++k) {
      curve.push_back(bspline_span_point(v[s], v[s + 1], v[s + 2], v[s + 3], double(k) / samples_per_span));
    }
  }
  curve.front() = control.front();  // exact, not merely to rounding
  curve.push_back(control.back());
  return curve;
}

std::vector<Vec4> smooth_closed_bspline(const std::vector<Vec4>& control, int samples_per_span) {
  if (samples_per_span < 1) throw InputError("must be ≥ 1", "samples_per_span");
  const std::size_t m = control.size() - 1;  // distinct points: the last repeats the first
  if (control.size() < 4) return control;
  const auto v = [&](std::size_t k) -> const Vec4& { return control[k % m]; };
  std::vector<Vec4> curve;
  for (std::size_t s = 0; s < m; ++s) {
    for (int k = 0; k < samples_per_span; ++k) {
      curve.push_back(bspline_span_point(v(s + m - 1), v(s), v(s + 1), v(s + 2), double(k) / samples_per_span));
    }
  }
  curve.push_back(curve.front());
  return curve;
}

}  // namespace skelconv::reconstruct
