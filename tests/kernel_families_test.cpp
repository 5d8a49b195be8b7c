// The soft-object kernel families (include/skelconv/kernels/:
// soft, wyvill, ferley, gaussian, polynomial): values against their definitions as the
// sources print them (written out here, independently of the traits),
// derivatives against 50-digit central differences, the iso ↔ radius
// relations against the definitions (point) and quadrature (line), and
// the reader's handling of the new JSON kernels.
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <gtest/gtest.h>

#include "extended_difference.hpp"
#include "skelconv/kernels/kernel_list.hpp"
#include "skelconv/primitives/point.hpp"
#include "skelconv/primitives/polygon.hpp"
#include "skelconv/primitives/scalis_segment.hpp"
#include "skelconv/primitives/scalis_triangle.hpp"
#include "skelconv/primitives/segment.hpp"
#include "skelconv/skeleton/skeleton_file.hpp"

namespace skelconv {
namespace {

using test::Extended;

/// The definitions in long double, as printed: the exam notes (soft),
/// Ferley §1.1.1 (Wyvill's polynomial in u = d²/R², Ferley's piecewise
/// kernel with the C¹ slope k = 2/(R − e)), Ferley §1.1.3 (Muraki's b e^(−a d²)).
long double definition(const KernelSpec& k, long double d) {
  const long double u = d * d / (k.R * k.R);
  switch (k.family) {
    case KernelFamily::soft: return d < k.R ? (1 - u) * (1 - u) : 0;
    case KernelFamily::wyvill: return d < k.R ? 1 - 22.0L / 9 * u + 17.0L / 9 * u * u - 4.0L / 9 * u * u * u : 0;
    case KernelFamily::ferley: {
      const long double slope = 2.0L / (k.R - k.e);
      if (d < k.e) return 1 + slope * (k.e - d);
      return d < k.R ? (d - k.R) * (d - k.R) / ((k.e - k.R) * (k.e - k.R)) : 0;
    }
    case KernelFamily::gaussian: return k.b * std::exp(-k.a * d * d);
    case KernelFamily::polynomial: return d < k.R ? std::pow(1 - u, (long double)k.degree) : 0;
    default: return NAN;
  }
}

/// K(0): the trait's value at 0 in long double (a different rounding from
/// max_value's own closed form, e.g. Ferley's (R + e)/(R − e)); +inf for a
/// kernel singular at 0.
template <class K>
long double definition_or_value(const K& k, long double r) {
  if constexpr (K::singular_at_zero) {
    return r == 0 ? INFINITY : k.value(r);
  } else {
    return k.value(r);
  }
}

std::vector<KernelSpec> new_kernels() {
  return {KernelSpec::soft(1.3), KernelSpec::soft(3.7), KernelSpec::wyvill(0.8), KernelSpec::wyvill(2.5),
          KernelSpec::ferley(0.4, 1.5), KernelSpec::ferley(1.0, 1.2), KernelSpec::gaussian(0.7, 1.0),
          KernelSpec::gaussian(3.0, 2.5),   KernelSpec::polynomial(1, 1.3), KernelSpec::polynomial(3, 0.9),
          KernelSpec::polynomial(8, 2.2)};
}

TEST(KernelFamilies, ValuesMatchTheDefinitions) {
  for (const KernelSpec& spec : new_kernels()) {
    const kernels::RadialKernel kernel = kernels::make_radial_kernel(spec);
    for (double d = 0.0; d < 4.0; d += 0.0137) {
      const double value = std::visit([&](const auto& k) { return k.value(d); }, kernel);
      const long double reference = definition(spec, d);
      // A few ulps of u = d²/R² (or of a d² in the exponent) propagate.
      const double exponent = spec.family == KernelFamily::gaussian ? spec.a * d * d : 0.0;
      EXPECT_NEAR(value, double(reference), 1e-15 * (1.0 + exponent) * std::max(1.0L, std::abs(reference)))
          << family_name(spec.family) << " d = " << d;
    }
  }
}

TEST(KernelFamilies, DerivativesMatchExtendedDifferences) {
  for (const KernelSpec& spec : new_kernels()) {
    const kernels::RadialKernel kernel = kernels::make_radial_kernel(spec);
    for (double d = 0.011; d < 4.0; d += 0.0731) {
      std::visit(
          [&](const auto& k) {
            // Skip the corners (Ferley at e is C¹ but not C²; both sides agree there).
            const Extended h(1e-20), x(d);
            const double difference = static_cast<double>((k.value(x + h) - k.value(x - h)) / (2 * h));
            EXPECT_NEAR(k.derivative(d), difference, 1e-13 * std::max(1.0, std::abs(difference)))
                << family_name(spec.family) << " d = " << d;
          },
          kernel);
    }
  }
}

/// One kernel of every family, with parameters away from 1 (so that a
/// misplaced R, s or a shows).
std::vector<KernelSpec> every_family() {
  std::vector<KernelSpec> specs = new_kernels();
  for (int i : {2, 3, 4, 7}) {
    specs.push_back(KernelSpec::inverse(i));
    specs.push_back(KernelSpec::cauchy(i, 2.3));
    specs.push_back(KernelSpec::compact(i, 1.7));
  }
  return specs;
}

// max_slope is the largest |K'|: no sample of the definition's derivative
// (an extended-precision difference of value()) exceeds it, and a fine grid
// comes within its spacing of it.
TEST(KernelFamilies, MaxSlopeIsTheLargestDerivative) {
  for (const KernelSpec& spec : every_family()) {
    const double bound = kernels::max_slope(spec);
    if (spec.family == KernelFamily::inverse) {
      EXPECT_TRUE(std::isinf(bound));
      continue;
    }
    const kernels::RadialKernel kernel = kernels::make_radial_kernel(spec);
    const double length = kernels::length_scale(spec);
    double largest = 0.0;
    for (double d = 1e-3 * length; d < 5.0 * length; d += 1e-3 * length) {
      std::visit(
          [&](const auto& k) {
            const Extended h(1e-20), x(d);
            largest = std::max(largest, std::abs(static_cast<double>((k.value(x + h) - k.value(x - h)) / (2 * h))));
          },
          kernel);
    }
    EXPECT_LE(largest, bound * (1 + 1e-12)) << family_name(spec.family) << " " << spec.degree;
    // The grid's spacing from the maximum (at R for compact i = 2) costs ≤ 1e-3.
    EXPECT_GE(largest, bound * (1 - 3e-3)) << family_name(spec.family) << " " << spec.degree;
  }
}

// max_value is K(0), the largest value (+inf for the singular inverse kernel).
TEST(KernelFamilies, MaxValueIsTheValueAtZero) {
  for (const KernelSpec& spec : every_family()) {
    const kernels::RadialKernel kernel = kernels::make_radial_kernel(spec);
    const double at_zero = std::visit([](const auto& k) { return double(definition_or_value(k, 0.0L)); }, kernel);
    if (std::isinf(at_zero)) {
      EXPECT_TRUE(std::isinf(kernels::max_value(spec))) << family_name(spec.family);
      continue;
    }
    EXPECT_NEAR(kernels::max_value(spec), at_zero, 4e-16 * at_zero) << family_name(spec.family);
  }
}

// scaling_power: every length times λ, the length parameters with them,
// gives λ^p K(r/λ) (radial_kernel.hpp); length_scale scales by λ.
TEST(KernelFamilies, ScalingPowerAndLengthScale) {
  const double lambda = 2.75;
  for (const KernelSpec& spec : every_family()) {
    KernelSpec scaled = spec;
    scaled.R *= lambda;
    scaled.e *= lambda;
    scaled.s /= lambda * lambda;
    scaled.a /= lambda * lambda;
    const kernels::RadialKernel k = kernels::make_radial_kernel(spec);
    const kernels::RadialKernel k_scaled = kernels::make_radial_kernel(scaled);
    const int p = kernels::scaling_power(spec);
    EXPECT_EQ(p, spec.family == KernelFamily::inverse ? -spec.degree : 0) << family_name(spec.family);
    for (double r = 0.0371; r < 3.0; r += 0.0731) {
      const double value = std::visit([&](const auto& kk) { return kk.value(r); }, k);
      const double value_scaled = std::visit([&](const auto& kk) { return kk.value(lambda * r); }, k_scaled);
      // A few ulps of u = r/R, s r², a r², more near a support's edge.
      EXPECT_NEAR(value_scaled, std::pow(lambda, p) * value, 1e-11 * std::abs(value_scaled))
          << family_name(spec.family) << " r = " << r;
    }
    if (p == 0) {
      EXPECT_NEAR(kernels::length_scale(scaled), lambda * kernels::length_scale(spec),
                  1e-15 * kernels::length_scale(scaled));
    }
  }
}

// vanishes_far: the value is exactly 0 far out (a finite support, or an
// underflow) for exactly the families that say so.
TEST(KernelFamilies, VanishesFarAsDeclared) {
  for (const KernelSpec& spec : every_family()) {
    const kernels::RadialKernel kernel = kernels::make_radial_kernel(spec);
    const double far = 1e3 * kernels::length_scale(spec);
    const double value = std::visit([&](const auto& k) { return k.value(far); }, kernel);
    EXPECT_EQ(value == 0.0, kernels::family_facts(spec.family).vanishes_far) << family_name(spec.family);
  }
}

TEST(KernelFamilies, FerleyIsC1AtTheCoating) {
  const kernels::FerleyKernel k(KernelSpec::ferley(0.4, 1.5));
  const double e = 0.4, below = std::nextafter(e, 0.0);
  EXPECT_NEAR(k.value(below), 1.0, 1e-15);
  EXPECT_DOUBLE_EQ(k.value(e), 1.0);
  EXPECT_NEAR(k.derivative(below), k.derivative(e), 1e-14);  // both −2/(R − e)
  EXPECT_DOUBLE_EQ(k.derivative(e), -2.0 / (1.5 - 0.4));
}

TEST(KernelFamilies, SoftRadiusAtIsoOneHalf) {
  // Exam notes 3b: R = r / √(1 − 1/√2) = r √(2 + √2) (since 1/(1 − 1/√2) = 2 + √2).
  const double r = 2.0;
  const double expected = r * std::sqrt(2.0 + std::numbers::sqrt2);
  EXPECT_NEAR(*kernels::SoftKernel::support_for_radius(r, 0.5), expected, 4e-16 * expected);
  const kernels::RadialKernel soft = kernels::make_radial_kernel(KernelSpec::soft(expected));
  EXPECT_NEAR(*kernels::point_iso_radius(soft, 0.5), r, 4e-16 * r);
  // Squared: R² = r² (2 + √2) = 8 + 4√2 for r = 2 (not the notes' 13.616).
  EXPECT_NEAR(expected * expected, 8.0 + 4.0 * std::numbers::sqrt2, 1e-14);
}

TEST(KernelFamilies, PointIsoRadiusSolvesTheDefinition) {
  std::vector<KernelSpec> all = new_kernels();
  for (KernelSpec k : {KernelSpec::inverse(3), KernelSpec::cauchy(4, 2.0), KernelSpec::compact(6, 1.7)}) all.push_back(k);
  for (const KernelSpec& spec : all) {
    const kernels::RadialKernel kernel = kernels::make_radial_kernel(spec);
    for (double c : {0.05, 0.3, 0.5, 0.9, 1.2}) {
      const std::optional<double> rho = kernels::point_iso_radius(kernel, c);
      const double top = std::visit([](const auto& k) { return k.value(1e-300); }, kernel);
      if (!(c < top)) {
        EXPECT_FALSE(rho) << family_name(spec.family) << " c = " << c;
        continue;
      }
      ASSERT_TRUE(rho) << family_name(spec.family) << " c = " << c;
      const long double at_rho = spec.family <= KernelFamily::compact
                                     ? std::visit([&](const auto& k) { return (long double)k.value(*rho); }, kernel)
                                     : definition(spec, *rho);
      EXPECT_NEAR(double(at_rho), c, 1e-13) << family_name(spec.family) << " c = " << c;
    }
    // A weight scales the level: w K(ρ) = c.
    EXPECT_EQ(kernels::point_iso_radius(kernel, 0.6, 2.0), kernels::point_iso_radius(kernel, 0.3));
  }
}

TEST(KernelFamilies, LineIsoRadiusMatchesQuadrature) {
  using boost::math::quadrature::gauss_kronrod;
  for (const KernelSpec& spec : new_kernels()) {
    const kernels::RadialKernel kernel = kernels::make_radial_kernel(spec);
    for (double c : {0.05, 0.4, 1.0}) {
      const std::optional<double> d = kernels::line_iso_radius(kernel, c);
      if (spec.family == KernelFamily::ferley) {
        EXPECT_FALSE(d);  // not derived (ferley.hpp)
        continue;
      }
      if (!d) continue;  // c above the line's peak
      // ∫ K(√(d² + t²)) dt over the line, from the definition.
      const long double half = spec.family == KernelFamily::gaussian ? 12.0L / std::sqrt((long double)spec.a)
                                                                     : std::sqrt(spec.R * spec.R - *d * *d);
      const auto integrand = [&](long double t) { return definition(spec, std::sqrt(*d * *d + t * t)); };
      const long double integral = gauss_kronrod<long double, 61>::integrate(integrand, -half, half, 15, 1e-18L);
      EXPECT_NEAR(double(integral), c, 1e-12) << family_name(spec.family) << " c = " << c;
    }
  }
}

TEST(KernelFamilies, ReaderBuildsPointsAndRejectsThemElsewhere) {
  const Skeleton skeleton = parse_skeleton_json(R"({"primitives": [
      {"type": "point", "center": [0, 0, 0], "kernel": {"family": "ferley", "e": 0.5, "R": 2}},
      {"type": "point", "center": [5, 0, 0], "kernel": {"family": "gaussian", "a": 2, "b": 3}}]})");
  // Ferley at d = 1: ((1 − 2)/(0.5 − 2))² = 4/9; the Gaussian is 3e^(−2·4²) there.
  EXPECT_NEAR(skeleton.value(Vec3(1, 0, 0)), 4.0 / 9.0 + 3.0 * std::exp(-32.0), 1e-15);
  const auto message = [](const std::string& json) {
    try {
      parse_skeleton_json(json);
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message(R"({"primitives": [{"type": "point", "center": [0, 0, 0],
                        "kernel": {"family": "soft", "R": 1, "degree": 4}}]})"),
            "primitives[0].kernel: unknown field \"degree\" for the soft family (allowed: \"family\", \"R\")");
  EXPECT_EQ(message(R"({"primitives": [{"type": "point", "center": [0, 0, 0],
                        "kernel": {"family": "ferley", "e": 1}}]})"),
            "primitives[0].kernel: missing field \"R\"");
  EXPECT_EQ(message(R"({"primitives": [{"type": "point", "center": [0, 0, 0],
                        "kernel": {"family": "gaussian", "a": -1, "b": 1}}]})"),
            "primitives[0].kernel.a: must be > 0, got -1");
  EXPECT_EQ(message(R"({"primitives": [{"type": "scalis_segment", "a": [0, 0, 0], "b": [1, 0, 0],
                        "radius": [1, 1], "kernel": {"family": "wyvill", "R": 1}}]})"),
            "primitives[0].kernel.family: the wyvill family has no closed form on a scalis_segment (it is defined "
            "on points, segments and polygons only); a scalis_segment takes \"inverse\", \"cauchy\", \"compact\"");
  EXPECT_EQ(message(R"({"primitives": [{"type": "polygon", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],
                        "kernel": {"family": "gaussian", "a": 1, "b": 1}}]})"),
            "primitives[0].kernel.family: the gaussian family has no closed form on a polygon (it is defined on "
            "points and segments only); a polygon takes \"inverse\", \"cauchy\", \"compact\", \"soft\", "
            "\"wyvill\"");
}

// The C++ constructors refuse a family where its trait has no field, as the
// reader does (not with an empty list of supported degrees).
TEST(KernelFamilies, ConstructorsRejectThemElsewhere) {
  const KernelSpec ferley = KernelSpec::ferley(0.5, 1.0), gaussian = KernelSpec::gaussian(1.0, 1.0);
  const auto located_at_family = [](const char* family, auto&& construct) {
    try {
      construct();
    } catch (const InputError& error) {
      return error.where() == "kernel.family" &&
             error.problem().starts_with(std::string("the ") + family + " family has no closed form on a");
    }
    return false;
  };
  EXPECT_TRUE(located_at_family("ferley", [&] { Segment(Vec3(0, 0, 0), Vec3(1, 0, 0), ferley); }));
  EXPECT_TRUE(located_at_family("ferley", [&] { Polygon({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, ferley); }));
  EXPECT_TRUE(located_at_family("gaussian", [&] { Polygon({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, gaussian); }));
  const ScalisKernel scalis{KernelFamily::soft, 4, 2.0};
  EXPECT_TRUE(located_at_family("soft", [&] { ScalisSegment(Vec3(0, 0, 0), Vec3(1, 0, 0), 0.1, 0.2, scalis); }));
  EXPECT_TRUE(located_at_family(
      "soft", [&] { ScalisTriangle({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {0.1, 0.1, 0.1}, scalis); }));
}


// ---- The polynomial family (1 − r²/R²)^k on points ---------------------------

/// The field of tests/data/good/polynomial_points.json written out from the
/// definition, in 50 digits: 2 (1 − |P|²/1.5²)³ + (1 − |P − (1.2, 0, 0)|²/0.8²)¹.
Extended polynomial_points_definition(const std::array<Extended, 3>& p) {
  const auto term = [&](double cx, double R, int k, double w) {
    const Extended q = (p[0] - cx) * (p[0] - cx) + p[1] * p[1] + p[2] * p[2];
    const Extended base = 1 - q / (Extended(R) * R);
    return base > 0 ? Extended(w) * boost::multiprecision::pow(base, k) : Extended(0);
  };
  return term(0.0, 1.5, 3, 2.0) + term(1.2, 0.8, 1, 1.0);
}

// The skeleton file's field and gradient against the definition (value in
// 50 digits, gradient by 50-digit central differences, extended_difference.hpp).
TEST(KernelFamilies, PolynomialPointsFromAFileMatchTheDefinition) {
  const Skeleton skeleton = parse_skeleton_json(R"({"primitives": [
      {"type": "point", "center": [0, 0, 0], "kernel": {"family": "polynomial", "degree": 3, "R": 1.5}, "weight": 2},
      {"type": "point", "center": [1.2, 0, 0], "kernel": {"family": "polynomial", "degree": 1, "R": 0.8}}]})");
  int inside_both = 0;
  for (double x = -1.7; x < 2.2; x += 0.113) {
    for (double y : {0.0, 0.31, -0.77}) {
      const std::array<double, 3> p{x, y, 0.2};
      const FieldSample sample = skeleton.value_and_gradient(Vec3(p[0], p[1], p[2]));
      const double reference =
          static_cast<double>(polynomial_points_definition({Extended(p[0]), Extended(p[1]), Extended(p[2])}));
      // A few ulps of u = r²/R² through a cube and a sum of two terms ≤ 2.
      EXPECT_NEAR(sample.value, reference, 2e-15) << "x = " << x << " y = " << y;
      // The k = 1 term's gradient jumps at its sphere r = R; stay off it.
      const double r1 = std::hypot(x - 1.2, y, 0.2);
      if (std::abs(r1 - 0.8) < 1e-6) continue;
      const std::array<double, 3> g = test::extended_gradient(polynomial_points_definition, p);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(sample.gradient[c], g[c], 1e-14) << "x = " << x << " axis " << c;
      inside_both += reference > 0 && r1 < 0.8 && std::hypot(x, y, 0.2) < 1.5;
    }
  }
  EXPECT_GT(inside_both, 5);  // the sample reaches the overlap of the two supports
}

// (1 − r²/R²)^k is the compact kernel of degree 2k (docs/mathematics.md §1), whose point
// field is checked against its own definition (point_primitive_test.cpp):
// the two families agree to the last bits everywhere.
TEST(KernelFamilies, PolynomialIsCompactOfTwiceTheDegree) {
  for (int k = 1; k <= 8; ++k) {
    const PointPrimitive polynomial(Vec3(0.1, -0.2, 0.3), KernelSpec::polynomial(k, 1.7), 1.3);
    const PointPrimitive compact(Vec3(0.1, -0.2, 0.3), KernelSpec::compact(2 * k, 1.7), 1.3);
    for (double x = -2.0; x < 2.0; x += 0.0917) {
      const Vec3 p(x, 0.4 * x, 0.25);
      const FieldSample a = polynomial.value_and_gradient(p), b = compact.value_and_gradient(p);
      EXPECT_NEAR(a.value, b.value, 1e-15) << "k = " << k << " x = " << x;
      EXPECT_NEAR((a.gradient - b.gradient).norm(), 0.0, 1e-14) << "k = " << k << " x = " << x;
    }
  }
}

// Bad polynomial kernels: one message, at the JSON path of the bad key.
TEST(KernelFamilies, PolynomialBadInputIsLocated) {
  const auto message = [](const std::string& kernel) {
    try {
      parse_skeleton_json(R"({"primitives": [{"type": "point", "center": [0, 0, 0], "kernel": )" + kernel + "}]}");
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message(R"({"family": "polynomial", "degree": 2, "R": -1})"),
            "primitives[0].kernel.R: must be > 0, got -1");
  EXPECT_EQ(message(R"({"family": "polynomial", "degree": 0, "R": 1})"),
            "primitives[0].kernel.degree: unsupported degree 0 for the polynomial family on a point; supported: 1..8");
  EXPECT_EQ(message(R"({"family": "polynomial", "degree": 9, "R": 1})"),
            "primitives[0].kernel.degree: unsupported degree 9 for the polynomial family on a point; supported: 1..8");
  EXPECT_EQ(message(R"({"family": "polynomial", "R": 1})"), "primitives[0].kernel: missing field \"degree\"");
  EXPECT_EQ(message(R"({"family": "polynomial", "degree": 2, "R": 1, "s": 2})"),
            "primitives[0].kernel: unknown field \"s\" for the polynomial family (allowed: \"family\", \"degree\", "
            "\"R\")");
  try {
    parse_skeleton_json(R"({"primitives": [{"type": "segment", "a": [0, 0, 0], "b": [1, 0, 0],
                            "kernel": {"family": "polynomial", "degree": 2, "R": 1}}]})");
    ADD_FAILURE() << "a polynomial segment was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "primitives[0].kernel.family");
    EXPECT_TRUE(error.problem().starts_with("the polynomial family has no closed form on a segment (it is defined on "
                                            "points only)"))
        << error.what();
  }
}

// ---- Soft, Wyvill and Gaussian on segments and polygons ----------------------

/// The families with a segment field, with the iso levels tried around them.
std::vector<KernelSpec> segment_kernels() {
  return {KernelSpec::soft(1.3), KernelSpec::wyvill(2.5), KernelSpec::gaussian(0.7, 1.0), KernelSpec::gaussian(30.0, 2.5)};
}

/// Half-length of a segment that is "infinite" for the kernel: twice the
/// support, or where the Gaussian is below e^(−200) of its peak.
double long_half_length(const KernelSpec& k) {
  return k.family == KernelFamily::gaussian ? std::sqrt(200.0 / k.a) : 2.0 * k.R;
}

// The iso ↔ radius relation around a long segment, on the Segment primitive
// itself: f = c at distance line_iso_radius(c) from its middle.
TEST(KernelFamilies, LineIsoRadiusOnALongSegment) {
  for (const KernelSpec& spec : segment_kernels()) {
    const kernels::RadialKernel kernel = kernels::make_radial_kernel(spec);
    const double h = long_half_length(spec);
    const Segment segment(Vec3(-h, 0.25, -1), Vec3(h, 0.25, -1), spec);
    for (double c : {0.05, 0.4, 1.0}) {
      const std::optional<double> d = kernels::line_iso_radius(kernel, c);
      if (!d) continue;  // above the line's peak
      EXPECT_NEAR(segment.value(Vec3(0.1, 0.25 + *d * 0.6, -1 + *d * 0.8)), c, 2e-13 * c)
          << family_name(spec.family) << " c = " << c;
    }
  }
}

// Additivity: the field of [A, B] is the sum of those of [A, M] and [M, B]
// (the integral splits; M = A + 0.37 AB), for f and ∇f, at points in every
// position (beside, beyond either end, far).
TEST(KernelFamilies, SegmentFieldsAreAdditive) {
  const Vec3 a(0.2, -0.1, 0.3), b(1.4, 0.5, -0.2), m = a + 0.37 * (b - a);
  for (const KernelSpec& spec : segment_kernels()) {
    const Segment whole(a, b, spec), first(a, m, spec), second(m, b, spec);
    for (const Vec3& p : {Vec3(0.7, 0.4, 0.1), Vec3(-0.4, -0.3, 0.5), Vec3(1.9, 0.8, -0.3), Vec3(0.5, 0.2, 0.05),
                          Vec3(0.9, 0.15, 0.08)}) {
      const FieldSample w = whole.value_and_gradient(p), s1 = first.value_and_gradient(p),
                        s2 = second.value_and_gradient(p);
      const double scale = std::abs(s1.value) + std::abs(s2.value);
      EXPECT_NEAR(w.value, s1.value + s2.value, 1e-14 * scale + 1e-300) << family_name(spec.family);
      const double gscale = s1.gradient.norm() + s2.gradient.norm();
      EXPECT_LE((w.gradient - s1.gradient - s2.gradient).norm(), 1e-13 * gscale + 1e-300) << family_name(spec.family);
    }
  }
}

// Polygons: soft and Wyvill against the definition integral ∬ K(|P − Q|) dQ
// over a square inside the support. There K(|P − Q|) is a polynomial of
// degree ≤ 6 in each coordinate of Q, so the 8 × 8 Gauss–Legendre product
// rule (exact to degree 15 per coordinate) is exact up to rounding.
TEST(KernelFamilies, PolygonCombinationsMatchTheDefinitionIntegral) {
  static constexpr std::array<long double, 8> x{-0.9602898564975362316835609L, -0.7966664774136267395915539L,
                                                -0.5255324099163289858177390L, -0.1834346424956498049394761L,
                                                0.1834346424956498049394761L,  0.5255324099163289858177390L,
                                                0.7966664774136267395915539L,  0.9602898564975362316835609L};
  static constexpr std::array<long double, 8> w{0.1012285362903762591525314L, 0.2223810344533744705443560L,
                                                0.3137066458778872873379622L, 0.3626837833783619829651504L,
                                                0.3626837833783619829651504L, 0.3137066458778872873379622L,
                                                0.2223810344533744705443560L, 0.1012285362903762591525314L};
  for (const KernelSpec& spec : {KernelSpec::soft(2.0), KernelSpec::wyvill(1.7)}) {
    const Polygon square({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}, spec);
    for (const Vec3& p : {Vec3(0.3, 0.4, 0.2), Vec3(0.5, 0.5, -0.01), Vec3(1.1, -0.2, 0.3)}) {
      long double f = 0, g[3] = {0, 0, 0};
      for (int i = 0; i < 8; ++i) {
        for (int j = 0; j < 8; ++j) {
          const long double qx = (1 + x[i]) / 2, qy = (1 + x[j]) / 2, weight = w[i] * w[j] / 4;
          const long double d[3] = {p.x() - qx, p.y() - qy, (long double)p.z()};
          const long double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
          f += weight * definition(spec, r);
          // ∇_P K(|P − Q|) = K'(r)/r (P − Q), K'(r)/r by a central difference of
          // the definition in u = r² (K is a polynomial in u: exact to ~1e-12).
          const long double du = 1e-6L, u = r * r;
          const long double slope = (definition(spec, std::sqrt(u + du)) - definition(spec, std::sqrt(u - du))) / (2 * du);
          for (int c = 0; c < 3; ++c) g[c] += weight * 2 * slope * d[c];
        }
      }
      const FieldSample s = square.value_and_gradient(p);
      EXPECT_NEAR(s.value, double(f), 1e-13 * double(f)) << family_name(spec.family);
      const double gnorm = std::sqrt(double(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]));
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.gradient[c], double(g[c]), 1e-9 * gnorm) << family_name(spec.family);
    }
  }
}

}  // namespace
}  // namespace skelconv
