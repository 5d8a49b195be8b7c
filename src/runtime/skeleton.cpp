// Implementation of skelconv/skeleton.hpp.
#include "skelconv/skeleton.hpp"

#include <fmt/format.h>

#include "input_checks.hpp"

namespace skelconv {
namespace {

// FieldSample has no operator+=; sum its parts.
FieldSample& operator+=(FieldSample& total, const FieldSample& term) {
  total.value += term.value;
  total.gradient += term.gradient;
  return total;
}

/// Calls `evaluate(primitive)` for every primitive, adding up the results;
/// a primitive's error is rethrown with its index as location, so a message
/// reads like the skeleton file: "primitives[2]: ...".
template <class Result, class Evaluate>
Result sum_over(const std::vector<Primitive>& primitives, const Vec3& p, Result total, Evaluate evaluate) {
  // Checked once here, so that a bad point is not blamed on primitives[0].
  detail::require_finite_query_point(p);
  for (std::size_t k = 0; k < primitives.size(); ++k) {
    try {
      total += std::visit(evaluate, primitives[k]);
    } catch (const InputError& error) {
      throw error.inside(fmt::format("primitives[{}]", k));
    } catch (const EvaluationError& error) {
      throw error.inside(fmt::format("primitives[{}]", k));
    }
  }
  return total;
}

}  // namespace

double Skeleton::value(const Vec3& p) const {
  return sum_over(primitives_, p, 0.0, [&](const auto& primitive) { return primitive.value(p); });
}

Vec3 Skeleton::gradient(const Vec3& p) const {
  return sum_over(primitives_, p, Vec3(Vec3::Zero()), [&](const auto& primitive) { return primitive.gradient(p); });
}

FieldSample Skeleton::value_and_gradient(const Vec3& p) const {
  return sum_over(primitives_, p, FieldSample{},
                  [&](const auto& primitive) { return primitive.value_and_gradient(p); });
}

}  // namespace skelconv
