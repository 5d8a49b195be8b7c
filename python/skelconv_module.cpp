// python/skelconv_module.cpp — the `skelconv` Python module (docs/python.md).
//
//     import numpy as np, skelconv
//     skeleton = skelconv.load_skeleton_file("skel.json")   # or parse_skeleton_json(text),
//                                                           # or skelconv.Skeleton([...primitives...])
//     f, grad = skeleton.field(np.array([[0.5, 0.2, 0.0]]))  # f: (N,), grad: (N, 3)
//
// Each call crosses into C++ once: the points are copied into the library's
// batch path (field/batch.hpp, every core) with the GIL released, and the
// results come back as numpy arrays. Errors are the library's: InputError
// and EvaluationError become skelconv.InputError (a ValueError) and
// skelconv.EvaluationError (an ArithmeticError) with the message the CLI
// prints after "skelconv: error: "; a failing point is located at
// "points[k]" where the CLI says "line N".
//
// This file: the module, Skeleton, its field and its enclosures (`skelconv
// eval`, `skelconv bound`); skeleton_nodes.cpp: skeletons from Python
// values; mesh_bindings.cpp: meshing and reconstruction.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "skelconv/detail/unsigned_zero.hpp"
#include "skelconv/skelconv.hpp"

namespace skelconv::python {
namespace {

/// f (N,) and ∇f (N, 3) at the rows of `points`, through evaluate_batch.
py::tuple field(const Skeleton& skeleton, const DoubleArray& points, unsigned threads, double tolerance) {
  require_rows_of(points, 3, "points");
  const auto n = static_cast<std::size_t>(points.shape(0));
  DoubleArray values(static_cast<py::ssize_t>(n));
  DoubleArray gradients({static_cast<py::ssize_t>(n), py::ssize_t(3)});
  const double* in = points.data();
  double* f = values.mutable_data();
  double* g = gradients.mutable_data();
  std::optional<BatchFailure> failure;
  {
    py::gil_scoped_release release;
    BatchOptions options;
    options.threads = threads;
    options.tolerance = tolerance;
    failure = evaluate_batch_into(skeleton, {in, 3 * n}, {f, n}, {g, 3 * n}, options);
  }
  if (failure) rethrow_located(failure->error, fmt::format("points[{}]", failure->index));
  // A zero as +0, as `skelconv eval` prints it (detail/unsigned_zero.hpp).
  for (std::size_t k = 0; k < n; ++k) f[k] = detail::unsigned_zero(f[k]);
  for (std::size_t k = 0; k < 3 * n; ++k) g[k] = detail::unsigned_zero(g[k]);
  return py::make_tuple(values, gradients);
}

/// Throws InputError ("iso") for a given iso that is not finite, as `skelconv bound --iso`.
void require_finite_iso(std::optional<double> iso) {
  if (iso && !std::isfinite(*iso)) throw InputError("must be finite", "iso");
}

/// Sound enclosures [lo, hi] of f over the boxes (rows x0 y0 z0 x1 y1 z1),
/// as `skelconv bound` (docs/bound.md); with `iso`, also each box's
/// classification against it ("inside", "outside", "undetermined"), as
/// `skelconv bound --iso`.
py::tuple bound(const Skeleton& skeleton, const DoubleArray& boxes, std::optional<double> iso) {
  require_rows_of(boxes, 6, "boxes");
  require_finite_iso(iso);
  const auto n = static_cast<std::size_t>(boxes.shape(0));
  DoubleArray lo(static_cast<py::ssize_t>(n)), hi(static_cast<py::ssize_t>(n));
  const double* in = boxes.data();
  double* out_lo = lo.mutable_data();
  double* out_hi = hi.mutable_data();
  {
    py::gil_scoped_release release;
    for (std::size_t k = 0; k < n; ++k) {
      try {
        const interval::Interval f = interval::enclose(skeleton, interval::box_from_corners({in + 6 * k, 6}));
        // −0 (directed rounding at a box straddling a compact support) as 0, as `skelconv bound` prints it.
        out_lo[k] = detail::unsigned_zero(f.lower());
        out_hi[k] = detail::unsigned_zero(f.upper());
      } catch (...) {
        rethrow_located(std::current_exception(), fmt::format("boxes[{}]", k));
      }
    }
  }
  if (!iso) return py::make_tuple(lo, hi);
  py::list names;
  for (std::size_t k = 0; k < n; ++k) {
    const interval::Interval f(out_lo[k], out_hi[k]);
    names.append(interval::classification_name(interval::classify(f, *iso)));
  }
  return py::make_tuple(lo, hi, py::module_::import("numpy").attr("array")(names, py::arg("dtype") = "U12"));
}

/// Cells of an octree over `box` classified against iso (default the
/// skeleton's), as `skelconv bound --octree DEPTH --box ...`: an
/// (depth + 1, 3) int64 array, row d = inside, outside, undetermined cells
/// of level d.
py::array_t<std::int64_t> octree(const Skeleton& skeleton, const std::array<double, 6>& corners, int depth,
                                 std::optional<double> iso) {
  require_finite_iso(iso);
  interval::Box box;
  try {
    box = interval::box_from_corners(corners);
  } catch (const InputError& error) {
    throw InputError(error.what(), "box");
  }
  if (depth < 0 || depth > interval::max_octree_depth)
    throw InputError(fmt::format("must be 0..{}, got {}", interval::max_octree_depth, depth), "depth");
  std::vector<interval::LevelCounts> counts;
  {
    py::gil_scoped_release release;
    counts = interval::classify_octree(skeleton, box, depth, iso.value_or(skeleton.iso()));
  }
  py::array_t<std::int64_t> result({static_cast<py::ssize_t>(counts.size()), py::ssize_t(3)});
  for (std::size_t level = 0; level < counts.size(); ++level) {
    const auto row = static_cast<py::ssize_t>(level);
    result.mutable_at(row, 0) = static_cast<std::int64_t>(counts[level].inside);
    result.mutable_at(row, 1) = static_cast<std::int64_t>(counts[level].outside);
    result.mutable_at(row, 2) = static_cast<std::int64_t>(counts[level].undetermined);
  }
  return result;
}

}  // namespace
}  // namespace skelconv::python

PYBIND11_MODULE(skelconv, m) {
  using namespace skelconv;
  using namespace skelconv::python;
  m.doc() = "Closed-form convolution and SCALIS fields of skeleton primitives (docs/python.md).";
  m.attr("__version__") = SKELCONV_VERSION;

  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<EvaluationError>(m, "EvaluationError", PyExc_ArithmeticError);

  add_skeleton_nodes(m);

  py::class_<Skeleton> skeleton(m, "Skeleton", "A skeleton: primitives and blend nodes, and the field they define.");
  skeleton.def(py::init<>(), "An empty skeleton (f = 0).")
      .def(py::init(&skeleton_from_objects), py::arg("data"), py::arg("iso") = py::none(),
           "From Python values: a list of primitives and blend nodes (Segment, Point, Blend, ... or dicts in the "
           "skeleton file's schema), or a dict of the whole file ({\"primitives\": [...], \"iso\": 1}); numbers "
           "may be numpy arrays. iso: the level of the surface (default the dict's, else 1). Read by the file "
           "reader: the same checks and messages.")
      .def("__len__", &Skeleton::size, "The number of primitives.")
      .def_property_readonly("iso", &Skeleton::iso, "The level of the surface (the file's \"iso\", default 1).")
      .def("field", &field, py::arg("points"), py::arg("threads") = 0u,
           py::arg("tolerance") = Skeleton::default_tolerance,
           "f (N,) and grad f (N, 3) at the rows of an (N, 3) array, on `threads` cores (0: all), as "
           "`skelconv eval --tolerance`: within `tolerance` (default 1e-12) of f relative to f on lists of "
           "Cauchy segments, classical or SCALIS, 0 for the exact field (docs/field.md, \"Tolerance\").")
      .def(
          "value_and_gradient",
          [](const Skeleton& skeleton, const std::array<double, 3>& p) {
            const FieldSample sample = skeleton.value_and_gradient(to_vec3(p));
            return py::make_tuple(sample.value, DoubleArray(3, sample.gradient.data()));
          },
          py::arg("point"), "f and grad f (3,) at one point.")
      .def("bound", &bound, py::arg("boxes"), py::arg("iso") = py::none(),
           "Sound enclosures (lo (N,), hi (N,)) of f over the boxes, rows x0 y0 z0 x1 y1 z1, as `skelconv bound` "
           "(docs/bound.md). With iso: (lo, hi, labels), labels[k] \"inside\" (lo > iso), \"outside\" (hi < iso) "
           "or \"undetermined\".")
      .def("octree", &octree, py::arg("box"), py::arg("depth"), py::arg("iso") = py::none(),
           "Classifies an octree of the box [x0, y0, z0, x1, y1, z1] against iso (default the skeleton's), as "
           "`skelconv bound --octree DEPTH --box ...`: an (depth + 1, 3) int64 array, row d = the inside, "
           "outside and undetermined cells of level d (those of level d + 1 split the undetermined ones).");
  add_mesh_bindings(m, skeleton);

  m.def("parse_skeleton_json", &parse_skeleton_json, py::arg("text"), "A Skeleton from the JSON text of a skeleton file.");
  m.def(
      "load_skeleton_file", [](const std::filesystem::path& path) { return load_skeleton_file(path); }, py::arg("path"),
      "A Skeleton from a skeleton file (docs/cli.md).");
}
