// The properties the contour formulas for polygons must have
// (docs/mathematics.md §3), and the paper's cases (Hubert 2012 §6.4, §7, §8.2; figs 6–9).
//
// Reference values come from 2-D quadrature of the definition in binary128
// (verify/polygon_reference.hpp) or from a closed form printed in the paper
// written out here independently of the generator; the other checks compare
// the field with itself under an exact identity (partition, orientation,
// extra vertices, z → 0), with tolerances set by double rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "extended_precision.hpp"
#include "polygon_reference.hpp"
#include "skelconv/primitives/polygon_field.hpp"

namespace {

using skelconv::KernelFamily;
using skelconv::PolygonInput;
using skelconv::verify::extended;
using V = std::array<double, 3>;

struct Kernel {
  KernelFamily family;
  int degree;
  double s = 0.8, R = 2.0;
};

// One of each family at a low and a high degree.
const Kernel kKernels[] = {{KernelFamily::inverse, 3},  {KernelFamily::inverse, 4},  {KernelFamily::inverse, 11},
                           {KernelFamily::cauchy, 3},   {KernelFamily::cauchy, 6},   {KernelFamily::cauchy, 12},
                           {KernelFamily::compact, 4},  {KernelFamily::compact, 12}};

const V kUp = {0, 0, 1};

double field(const std::vector<V>& polygon, const V& normal, const Kernel& k, const V& p, V* grad = nullptr) {
  const PolygonInput<double> in{polygon, normal, k.family, k.degree, k.s, k.R};
  V g;
  const double f = skelconv::polygon_f_and_grad(in, p, g);
  if (grad) *grad = g;
  return f;
}

/// |x − y| ≤ tolerance · scale, for f and each gradient component (scaled by |∇f|).
void expect_same_field(double f, const V& g, double f_ref, const V& g_ref, double tolerance, const char* what) {
  EXPECT_LE(std::abs(f - f_ref), tolerance * std::abs(f_ref)) << what << ": f " << f << " vs " << f_ref;
  const double g_norm = std::sqrt(g_ref[0] * g_ref[0] + g_ref[1] * g_ref[1] + g_ref[2] * g_ref[2]);
  for (int c = 0; c < 3; ++c)
    EXPECT_LE(std::abs(g[c] - g_ref[c]), tolerance * g_norm) << what << ": ∇f[" << c << "] " << g[c] << " vs " << g_ref[c];
}

/// The binary128 reference for one kernel at one point.
skelconv::verify::PolygonReference<extended> reference(const std::vector<V>& polygon, const Kernel& k, const V& p) {
  std::vector<skelconv::verify::Vec3<extended>> vertices;
  for (const V& v : polygon) vertices.push_back(skelconv::verify::widen(v));
  skelconv::verify::PolygonReferenceIntegrator<extended> integrator(vertices);
  const auto refs = integrator.evaluate(skelconv::verify::widen(p), k.family, {k.degree}, extended(k.s),
                                        extended(k.R), extended(1e-22));
  EXPECT_TRUE(refs.at(0).trusted);
  return refs.at(0);
}

void expect_matches_reference(const std::vector<V>& polygon, const V& normal, const Kernel& k, const V& p,
                              double tolerance) {
  V g;
  const double f = field(polygon, normal, k, p, &g);
  const auto ref = reference(polygon, k, p);
  const V g_ref = {static_cast<double>(ref.gradient[0]), static_cast<double>(ref.gradient[1]),
                   static_cast<double>(ref.gradient[2])};
  expect_same_field(f, g, static_cast<double>(ref.value), g_ref, tolerance, "vs quadrature");
}

// A non-convex pentagon in the plane z = 0, counter-clockwise, its
// partition into three triangles and into a quadrilateral and a triangle.
const std::vector<V> kPentagon = {{0, 0, 0}, {2, 0, 0}, {2.2, 1.5, 0}, {1, 0.7, 0}, {0.2, 1.8, 0}};
const std::vector<std::vector<V>> kPentagonTriangles = {
    {{0, 0, 0}, {2, 0, 0}, {1, 0.7, 0}}, {{2, 0, 0}, {2.2, 1.5, 0}, {1, 0.7, 0}}, {{0, 0, 0}, {1, 0.7, 0}, {0.2, 1.8, 0}}};
const std::vector<std::vector<V>> kPentagonHalves = {{{0, 0, 0}, {2, 0, 0}, {2.2, 1.5, 0}, {1, 0.7, 0}},
                                                     {{0, 0, 0}, {1, 0.7, 0}, {0.2, 1.8, 0}}};

// Points off the plane, near it, in it (outside), near an edge.
const V kPoints[] = {{0.9, 0.5, 0.8}, {2.5, -0.4, -0.6}, {0.6, 0.4, 1e-5}, {1.5, 1.4, 2e-6},
                     {3.0, 0.5, 0.0}, {1.0, -1e-4, 0.3},  {-0.7, 2.5, 0.05}};

TEST(PolygonPartition, TrianglesAndSubPolygonsAddUpToThePolygon) {
  for (const Kernel& k : kKernels)
    for (const V& p : kPoints) {
      V g;
      const double f = field(kPentagon, kUp, k, p, &g);
      for (const auto& parts : {kPentagonTriangles, kPentagonHalves}) {
        double f_sum = 0;
        V g_sum = {0, 0, 0};
        for (const auto& part : parts) {
          V g_part;
          f_sum += field(part, kUp, k, p, &g_part);
          for (int c = 0; c < 3; ++c) g_sum[c] += g_part[c];
        }
        expect_same_field(f_sum, g_sum, f, g, 1e-12, "partition");
      }
    }
}

TEST(PolygonPartition, ExtraCollinearVerticesChangeNothing) {
  std::vector<V> refined;
  for (std::size_t m = 0; m < kPentagon.size(); ++m) {
    const V& a = kPentagon[m];
    const V& b = kPentagon[(m + 1) % kPentagon.size()];
    refined.push_back(a);
    refined.push_back({a[0] + 0.375 * (b[0] - a[0]), a[1] + 0.375 * (b[1] - a[1]), 0});  // exact in binary
  }
  for (const Kernel& k : kKernels)
    for (const V& p : kPoints) {
      V g, g_refined;
      const double f = field(kPentagon, kUp, k, p, &g);
      const double f_refined = field(refined, kUp, k, p, &g_refined);
      expect_same_field(f_refined, g_refined, f, g, 1e-12, "collinear vertices");
    }
}

TEST(PolygonOrientation, ReversedVerticesAndNormalGiveTheSameField) {
  std::vector<V> reversed(kPentagon.rbegin(), kPentagon.rend());
  const V down = {0, 0, -1};
  for (const Kernel& k : kKernels)
    for (const V& p : kPoints) {
      V g, g_reversed;
      const double f = field(kPentagon, kUp, k, p, &g);
      const double f_reversed = field(reversed, down, k, p, &g_reversed);
      expect_same_field(f_reversed, g_reversed, f, g, 1e-13, "orientation");
    }
}

// f is even in z and smooth at z = 0 wherever it is finite there (P̄ outside;
// for Cauchy and compact kernels also inside), so f(z) − f(0) = O(z²) and
// ∂f/∂z = O(z): the in-plane form and the off-plane forms must meet.
TEST(PolygonPlane, TheInPlaneFormIsTheLimitOfTheOffPlaneForms) {
  const V outside[] = {{3.0, 0.5, 0}, {1.2, 1.6, 0}, {-0.5, -0.5, 0}};
  const V inside[] = {{0.9, 0.5, 0}, {1.9, 0.4, 0}};
  for (const Kernel& k : kKernels) {
    std::vector<V> points(std::begin(outside), std::end(outside));
    if (k.family != KernelFamily::inverse) points.insert(points.end(), std::begin(inside), std::end(inside));
    for (const V& p0 : points) {
      V g0;
      const double f0 = field(kPentagon, kUp, k, p0, &g0);
      EXPECT_EQ(g0[2], 0.0);
      for (double z : {1e-9, 1e-7}) {
        V g;
        const double f = field(kPentagon, kUp, k, {p0[0], p0[1], z}, &g);
        EXPECT_LE(std::abs(f - f0), 1e-12 * std::abs(f0)) << "z = " << z;
        EXPECT_LE(std::abs(g[0] - g0[0]) + std::abs(g[1] - g0[1]), 1e-11 * std::hypot(g0[0], g0[1]));
      }
    }
  }
}

TEST(PolygonQuadrature, EveryFamilyMatchesTheDefinitionOnANonConvexPolygon) {
  for (const Kernel& k : kKernels)
    for (const V& p : {V{0.9, 0.5, 0.8}, V{2.5, -0.4, -0.6}, V{0.6, 0.4, 1e-4}, V{3.0, 0.5, 1e-3}})
      expect_matches_reference(kPentagon, kUp, k, p, 1e-12);
}

// Hubert 2012 §7, fig. 8: for a triangle the field is a sum of three "step
// functions", one per edge: the field of the fan triangle (P̄, Q_m, Q_{m+1}),
// signed. Each part is checked against quadrature over its fan triangle.
TEST(PolygonPaperCases, EquilateralTriangleIsASumOfThreeStepFunctions) {
  const double r3 = std::sqrt(3.0);
  const std::vector<V> triangle = {{2, 0, 0}, {-1, r3, 0}, {-1, -r3, 0}};
  const Kernel cauchy4{KernelFamily::cauchy, 4, 1.0};
  for (const V& p : {V{0.3, 0.2, 0.5}, V{-0.5, 0.9, 1.5}, V{2.5, 1.0, 0.4}}) {
    const PolygonInput<double> in{triangle, kUp, cauchy4.family, cauchy4.degree, cauchy4.s, cauchy4.R};
    const std::vector<double> parts = skelconv::polygon_edge_fields(in, p);
    ASSERT_EQ(parts.size(), 3u);
    EXPECT_NEAR(parts[0] + parts[1] + parts[2], skelconv::polygon_f(in, p), 1e-14 * std::abs(skelconv::polygon_f(in, p)));
    const V foot = {p[0], p[1], 0};
    for (int m = 0; m < 3; ++m) {
      const V& a = triangle[m];
      const V& b = triangle[(m + 1) % 3];
      // The fan triangle's orientation about +z gives the sign of its part.
      const double orientation = (a[0] - foot[0]) * (b[1] - foot[1]) - (a[1] - foot[1]) * (b[0] - foot[0]);
      const auto ref = reference({foot, a, b}, cauchy4, p);
      const double expected = orientation > 0 ? static_cast<double>(ref.value) : -static_cast<double>(ref.value);
      EXPECT_NEAR(parts[m], expected, 1e-12 * std::abs(expected)) << "edge " << m;
    }
  }
}

// Hubert 2012 §6.4 (figs 6–7): with p^4 the field is the simplest contour sum,
//     C^{p^4}(P) = 1/(2 z²) Σ_m ((Q_m Q_{m+1} × Q_m P)·n) D^{p^2}_{[Q_m Q_{m+1}]}(P),
//     D^{p^2}_{[AB]}(P) = (atan((a − b)/√(ac − b²)) + atan(b/√(ac − b²))) / √(ac − b²),
// written out here from the paper (not from the generator), for a regular
// pentagon and a non-convex polygon, and checked against quadrature too.
// §6.4 prints the wedge as Q_m P ∧ Q_m Q_{m+1}, the opposite order to §6.3
// and docs/mathematics.md §3: with counter-clockwise vertices that gives −f (this test saw
// it), so we use the order of §6.3.
double hubert_p4(const std::vector<V>& polygon, const V& p) {
  long double sum = 0;
  const long double z = p[2];
  for (std::size_t m = 0; m < polygon.size(); ++m) {
    const V& A = polygon[m];
    const V& B = polygon[(m + 1) % polygon.size()];
    const long double ab[3] = {B[0] - A[0], B[1] - A[1], B[2] - A[2]};
    const long double ap[3] = {p[0] - A[0], p[1] - A[1], p[2] - A[2]};
    const long double a = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
    const long double b = ab[0] * ap[0] + ab[1] * ap[1] + ab[2] * ap[2];
    const long double c = ap[0] * ap[0] + ap[1] * ap[1] + ap[2] * ap[2];
    const long double root = std::sqrt(a * c - b * b);
    const long double D_p2 = (std::atan((a - b) / root) + std::atan(b / root)) / root;
    const long double wedge_n = ab[0] * ap[1] - ab[1] * ap[0];  // (Q_m Q_{m+1} × Q_m P)·n, n = +z
    sum += wedge_n * D_p2;
  }
  return static_cast<double>(sum / (2 * z * z));
}

TEST(PolygonPaperCases, PentagonAndNonConvexPolygonWithP4MatchTheClosedFormOfSection6_4) {
  std::vector<V> pentagon;
  for (int k = 0; k < 5; ++k)
    pentagon.push_back({std::cos(2 * std::numbers::pi * k / 5), std::sin(2 * std::numbers::pi * k / 5), 0});
  const Kernel p4{KernelFamily::inverse, 4};
  for (const std::vector<V>* polygon : std::initializer_list<const std::vector<V>*>{&pentagon, &kPentagon})
    for (const V& p : {V{0.1, 0.2, 0.7}, V{1.5, 1.5, 0.4}, V{-0.3, 0.9, -1.2}}) {
      const double f = field(*polygon, kUp, p4, p);
      EXPECT_NEAR(f, hubert_p4(*polygon, p), 1e-12 * std::abs(f));
      expect_matches_reference(*polygon, kUp, p4, p, 1e-12);
    }
}

// Hubert 2012 §8.2, fig. 9: two parallel squares at distance 2 with R = 1.
// The compact field vanishes exactly on the middle plane and each square
// sees none of the other; the cubic inverse field bulges in between.
TEST(PolygonPaperCases, ParallelPolygonsAtDistanceTwoWithRadiusOne) {
  const std::vector<V> lower = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  const std::vector<V> upper = {{-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 2}};
  const Kernel compact4{KernelFamily::compact, 4, 1.0, 1.0};
  for (const V& p : {V{0, 0, 1}, V{0.5, -0.3, 1}, V{2, 0, 1}}) {
    V g_lower, g_upper;
    EXPECT_EQ(field(lower, kUp, compact4, p, &g_lower), 0.0);
    EXPECT_EQ(field(upper, kUp, compact4, p, &g_upper), 0.0);
    EXPECT_EQ(g_lower, (V{0, 0, 0}));
    EXPECT_EQ(g_upper, (V{0, 0, 0}));
  }
  for (const V& p : {V{0.2, 0.1, 0.4}, V{0.9, -0.8, 0.7}}) {
    EXPECT_EQ(field(upper, kUp, compact4, p), 0.0);  // 1.3 or more from the upper square
    expect_matches_reference(lower, kUp, compact4, p, 1e-12);
  }
  // Centre of the square, 0.4 above it: the support disc of radius √(1 − 0.16)
  // lies inside the square, f = π R² w³/3 with w = 1 − z²/R² (Hubert §8.1).
  const double w = 1 - 0.16;
  EXPECT_NEAR(field(lower, kUp, compact4, {0, 0, 0.4}), std::numbers::pi * w * w * w / 3, 1e-15);
  const Kernel cubic{KernelFamily::inverse, 3};
  const V middle = {0, 0, 1};
  const double f_middle = field(lower, kUp, cubic, middle) + field(upper, kUp, cubic, middle);
  EXPECT_GT(f_middle, 0.0);
  expect_matches_reference(lower, kUp, cubic, middle, 1e-12);
}

}  // namespace
