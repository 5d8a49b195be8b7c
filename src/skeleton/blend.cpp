// Implementation of validate_blend (skelconv/skeleton/blend.hpp).
#include "skelconv/skeleton/blend.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "../detail/input_checks.hpp"
#include "skelconv/errors.hpp"

namespace skelconv {
namespace {

void require_positive(double value, const std::string& where) {
  detail::require_positive_parameter(value, where.c_str());
}

/// A per-child list: exactly one entry per child (or, when `one_for_all`,
/// a single entry), each checked by `check(value, where)`.
template <class Check>
void require_per_child(const std::vector<double>& values, std::size_t child_count, const char* name,
                       bool one_for_all, Check check) {
  if (values.size() != child_count && !(one_for_all && values.size() == 1)) {
    throw InputError(fmt::format("must have one entry per child ({}){}, got {}", child_count,
                                 one_for_all ? " or be a single number" : "", values.size()),
                     name);
  }
  if (one_for_all && values.size() == 1) return check(values[0], std::string(name));
  for (std::size_t k = 0; k < values.size(); ++k) check(values[k], fmt::format("{}[{}]", name, k));
}

}  // namespace

void validate_blend(const Blend& blend, std::size_t child_count) {
  if (child_count == 0) {
    throw InputError(fmt::format("a {} blend needs at least one child", blend_name(blend.kind)), "children");
  }
  switch (blend.kind) {
    case BlendKind::sum:
      if (!blend.weights.empty()) {
        require_per_child(blend.weights, child_count, "weights", false, [](double w, const std::string& where) {
          if (!std::isfinite(w)) throw InputError(fmt::format("must be finite, got {}", w), where);
          if (w == 0.0) throw InputError("must be non-zero: a zero weight removes the child", where);
        });
      }
      break;
    case BlendKind::union_max:
      break;
    case BlendKind::super_elliptic:
      require_positive(blend.t, "t");
      if (blend.r.empty()) throw InputError("needs at least one band width", "r");
      require_per_child(blend.r, child_count, "r", true, [](double r, const std::string& where) { require_positive(r, where); });
      require_positive(blend.iso, "iso");
      if (blend.angle_weighted && child_count != 2) {
        throw InputError(fmt::format("the angle-weighted super_elliptic blend is binary: it needs exactly 2 "
                                     "children, got {}",
                                     child_count),
                         "angle_weighted");
      }
      break;
  }
}

}  // namespace skelconv
