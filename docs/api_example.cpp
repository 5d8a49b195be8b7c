// docs/api_example.cpp — the complete example of docs/api.md. ctest builds it
// against an installed skelconv (tests/package/) and compares its output
// with `skelconv eval` on the same skeleton and points.
//
//     api_example [SKELETON.json]
//
// prints "x y z f gx gy gz" for eleven points on a line, then f at one point
// of a segment in float, double, long double and 50-digit Boost.Multiprecision.
#include <skelconv/primitives/generic.hpp>  // opt-in: other scalar types (compiles the generated kernels used)
#include <skelconv/skelconv.hpp>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cstdio>
#include <exception>
#include <vector>

namespace {

// f of a Cauchy i = 4 segment with w = 1 computed in T, by that kernel's
// generated function (only it is compiled for T).
template <class T>
double segment_value_in(const skelconv::Segment& segment, const std::array<T, 3>& p) {
  const std::optional<skelconv::SegmentInput<T>> input = skelconv::segment_input(segment, p);
  if (!input) return 0.0;  // outside a compact kernel's support
  std::array<T, 3> gradient;
  std::array<T, skelconv::generated::segment_cauchy_i4_w0_prepared_size> prepared;  // depends on the segment alone
  skelconv::generated::segment_cauchy_i4_w0_prepare<T>(*input, prepared.data());
  return static_cast<double>(skelconv::generated::segment_cauchy_i4_w0_f_and_grad<T>(
      prepared.data(), skelconv::generated::point_of(*input), gradient));
}

}  // namespace

int main(int argc, char** argv) {
  try {
    // A skeleton from a file, or from JSON text (docs/cli.md has the schema).
    const skelconv::Skeleton skeleton =
        argc > 1 ? skelconv::load_skeleton_file(argv[1])
                 : skelconv::parse_skeleton_json(R"({"primitives": [
                     {"type": "segment", "a": [0, 0, 0], "b": [1, 0, 0],
                      "kernel": {"family": "cauchy", "degree": 4, "s": 2}}]})");

    // Many points at once: on every core, the same bytes whatever the thread count.
    std::vector<skelconv::Vec3> points;
    for (int k = 0; k <= 10; ++k) points.emplace_back(-0.25 + 0.15 * k, 0.3, 0.2);
    const skelconv::BatchResult batch = skelconv::evaluate_batch(skeleton, points);
    if (batch.failure) std::rethrow_exception(batch.failure->error);  // the first failing point's error
    for (std::size_t k = 0; k < points.size(); ++k) {
      const skelconv::FieldSample& s = batch.samples[k];
      std::printf("%.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", points[k].x(), points[k].y(), points[k].z(), s.value,
                  s.gradient.x(), s.gradient.y(), s.gradient.z());
    }

    // One point, and a sound enclosure of f over a box (docs/bound.md).
    const skelconv::FieldSample one = skeleton.value_and_gradient(skelconv::Vec3(0.5, 0.3, 0.2));
    const skelconv::interval::Interval range =
        skelconv::interval::enclose(skeleton, skelconv::interval::Box{{0.4, 0.2, 0.1}, {0.6, 0.4, 0.3}});
    std::printf("f(0.5, 0.3, 0.2) = %.17g in [%.17g, %.17g]\n", one.value, range.lower(), range.upper());

    // A primitive built in C++, and its closed form in other scalar types.
    const skelconv::Segment segment({0, 0, 0}, {1, 0, 0}, skelconv::KernelSpec{skelconv::KernelFamily::cauchy, 4, 2.0});
    using Big = boost::multiprecision::cpp_bin_float_50;
    std::printf("float %.9g, double %.17g, long double %.17g, cpp_bin_float_50 %.17g\n",
                segment_value_in<float>(segment, {0.5f, 0.3f, 0.2f}),
                segment_value_in<double>(segment, {0.5, 0.3, 0.2}),
                segment_value_in<long double>(segment, {0.5L, 0.3L, 0.2L}),
                segment_value_in<Big>(segment, {Big("0.5"), Big("0.3"), Big("0.2")}));
    return 0;
  } catch (const skelconv::InputError& error) {  // bad input: a located message
    std::fprintf(stderr, "error: %s\n", error.what());
    return 2;
  } catch (const skelconv::EvaluationError& error) {  // a value that cannot be computed
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  }
}
