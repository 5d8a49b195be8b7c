// python/skelconv_module.cpp — the `skelconv` Python module (docs/python.md).
//
//     import numpy as np, skelconv
//     skeleton = skelconv.load_skeleton_file("skel.json")   # or parse_skeleton_json(text),
//                                                           # or skelconv.Skeleton({...})
//     f, grad = skeleton.field(np.array([[0.5, 0.2, 0.0]]))  # f: (N,), grad: (N, 3)
//
// Each call crosses into C++ once: the points are copied into the library's
// batch path (field/batch.hpp, every core) with the GIL released, and the
// results come back as numpy arrays. Errors are the library's: InputError
// and EvaluationError become skelconv.InputError (a ValueError) and
// skelconv.EvaluationError (an ArithmeticError) with the message the CLI
// prints after "skelconv: error: "; a failing point is located at
// "points[k]" where the CLI says "line N".
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstddef>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "skelconv/skelconv.hpp"

namespace py = pybind11;

namespace skelconv::python {
namespace {

/// numpy float64, C order; anything convertible is converted (a list of
/// lists, float32, a strided view).
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// Throws InputError located at `name` unless `array` is (N, columns).
void require_rows_of(const DoubleArray& array, py::ssize_t columns, const char* name) {
  if (array.ndim() == 2 && array.shape(1) == columns) return;
  std::string shape;
  for (py::ssize_t k = 0; k < array.ndim(); ++k) shape += fmt::format("{}{}", k ? ", " : "", array.shape(k));
  if (array.ndim() == 1) shape += ",";
  throw InputError(fmt::format("must be an (N, {}) array of numbers, got shape ({})", columns, shape), name);
}

/// f (N,) and ∇f (N, 3) at the rows of `points`, through evaluate_batch.
py::tuple field(const Skeleton& skeleton, const DoubleArray& points, unsigned threads) {
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
    failure = evaluate_batch_into(skeleton, {in, 3 * n}, {f, n}, {g, 3 * n}, options);
  }
  if (failure) rethrow_located(failure->error, fmt::format("points[{}]", failure->index));
  return py::make_tuple(values, gradients);
}

/// Sound enclosures [lo, hi] of f over the boxes (rows x0 y0 z0 x1 y1 z1),
/// as `skelconv bound` (docs/bound.md).
py::tuple bound(const Skeleton& skeleton, const DoubleArray& boxes) {
  require_rows_of(boxes, 6, "boxes");
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
        out_lo[k] = f.lower();
        out_hi[k] = f.upper();
      } catch (...) {
        rethrow_located(std::current_exception(), fmt::format("boxes[{}]", k));
      }
    }
  }
  return py::make_tuple(lo, hi);
}

/// A TriangleMesh as numpy arrays: vertices (V, 3), triangles (T, 3) int32
/// (counter-clockwise seen from outside), normals (V, 3).
py::tuple mesh_arrays(const TriangleMesh& mesh) {
  const auto v = static_cast<py::ssize_t>(mesh.vertices.size());
  const auto t = static_cast<py::ssize_t>(mesh.triangles.size());
  DoubleArray vertices({v, py::ssize_t(3)}), normals({v, py::ssize_t(3)});
  py::array_t<std::int32_t> triangles({t, py::ssize_t(3)});
  for (py::ssize_t k = 0; k < v; ++k) {
    for (int c = 0; c < 3; ++c) {
      vertices.mutable_at(k, c) = mesh.vertices[k][c];
      normals.mutable_at(k, c) = mesh.normals.empty() ? 0.0 : mesh.normals[k][c];
    }
  }
  for (py::ssize_t k = 0; k < t; ++k)
    for (int c = 0; c < 3; ++c) triangles.mutable_at(k, c) = mesh.triangles[k][c];
  return py::make_tuple(vertices, triangles, normals);
}

/// The surface f = iso (default: the skeleton's iso), as `skelconv mesh`.
py::tuple mesh(const Skeleton& skeleton, std::optional<double> iso, const std::string& method,
               std::optional<double> size, std::optional<double> distance) {
  if (method != "cgal" && method != "grid")
    throw InputError(fmt::format("{} not in {{cgal,grid}}", method), "method");
  MeshOptions options;
  options.iso = iso.value_or(skeleton.iso());
  options.method = method == "grid" ? MeshMethod::grid : MeshMethod::cgal;
  options.size = size;
  options.distance = distance;
  TriangleMesh result;
  {
    py::gil_scoped_release release;
    result = mesh_iso_surface(skeleton_field(skeleton), options);
  }
  return mesh_arrays(result);
}

/// A Skeleton from Python objects: the skeleton file's schema (docs/cli_skeleton.md)
/// as dicts and lists (numpy arrays allowed), or just the list of
/// primitives. Read by the same JSON reader, so the same checks and messages.
Skeleton skeleton_from_objects(const py::object& data) {
  const py::module_ json = py::module_::import("json");
  const py::object skeleton_dict = py::isinstance<py::dict>(data) ? data : py::object(py::dict(py::arg("primitives") = data));
  const py::cpp_function to_list([](const py::object& value) -> py::object {
    if (py::hasattr(value, "tolist")) return value.attr("tolist")();
    throw InputError(fmt::format("cannot be written as JSON: {}", py::str(py::type::of(value)).cast<std::string>()),
                     "skeleton");
  });
  const std::string text = json.attr("dumps")(skeleton_dict, py::arg("default") = to_list).cast<std::string>();
  return parse_skeleton_json(text);
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

  py::class_<Skeleton>(m, "Skeleton", "A skeleton: primitives and blend nodes, and the field they define.")
      .def(py::init<>(), "An empty skeleton (f = 0).")
      .def(py::init(&skeleton_from_objects), py::arg("data"),
           "From Python objects: a dict with the skeleton file's schema ({\"primitives\": [...], \"iso\": 1}) "
           "or the list of primitives; numbers may be numpy arrays.")
      .def("__len__", &Skeleton::size, "The number of primitives.")
      .def_property_readonly("iso", &Skeleton::iso, "The level of the surface (the file's \"iso\", default 1).")
      .def("field", &field, py::arg("points"), py::arg("threads") = 0u,
           "f (N,) and grad f (N, 3) at the rows of an (N, 3) array, on `threads` cores (0: all).")
      .def(
          "value_and_gradient",
          [](const Skeleton& skeleton, const std::array<double, 3>& p) {
            const FieldSample sample = skeleton.value_and_gradient(to_vec3(p));
            return py::make_tuple(sample.value, DoubleArray(3, sample.gradient.data()));
          },
          py::arg("point"), "f and grad f (3,) at one point.")
      .def("bound", &bound, py::arg("boxes"),
           "Sound enclosures (lo (N,), hi (N,)) of f over the boxes, rows x0 y0 z0 x1 y1 z1 (docs/bound.md).")
      .def("mesh", &mesh, py::arg("iso") = py::none(), py::arg("method") = "cgal", py::arg("size") = py::none(),
           py::arg("distance") = py::none(),
           "The surface f = iso: (vertices (V, 3), triangles (T, 3) int32, normals (V, 3)) (docs/mesh.md).");

  m.def("parse_skeleton_json", &parse_skeleton_json, py::arg("text"), "A Skeleton from the JSON text of a skeleton file.");
  m.def(
      "load_skeleton_file", [](const std::filesystem::path& path) { return load_skeleton_file(path); }, py::arg("path"),
      "A Skeleton from a skeleton file (docs/cli.md).");
}
