// python/bindings.hpp — what the files of the `skelconv` Python module share
// (docs/python.md): the numpy array type they read and write, the shape
// check of their arguments, and the function each file registers its part
// of the module with.
//
//   skelconv_module.cpp  the module, Skeleton, field, bound, octree
//   skeleton_nodes.cpp   Segment, Polygon, ScalisSegment, ScalisTriangle,
//                        Point, Blend and Skeleton(...) from Python objects
//   mesh_bindings.cpp    mesh, mesh_topology, skeletonize
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

#include <fmt/format.h>

#include "skelconv/errors.hpp"
#include "skelconv/skeleton/skeleton.hpp"

namespace skelconv::python {

namespace py = pybind11;

/// numpy float64, C order; anything convertible is converted (a list of
/// lists, float32, a strided view).
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// Throws InputError located at `name` unless `array` is (N, columns).
template <class Array>
void require_rows_of(const Array& array, py::ssize_t columns, const char* name) {
  if (array.ndim() == 2 && array.shape(1) == columns) return;
  std::string shape;
  for (py::ssize_t k = 0; k < array.ndim(); ++k) shape += fmt::format("{}{}", k ? ", " : "", array.shape(k));
  if (array.ndim() == 1) shape += ",";
  throw InputError(fmt::format("must be an (N, {}) array of numbers, got shape ({})", columns, shape), name);
}

/// A Skeleton from Python objects (skeleton_nodes.cpp): a dict in the
/// skeleton file's schema, or a list of primitives and blend nodes (dicts or
/// the module's Segment, Blend, ... objects), with the top-level iso.
Skeleton skeleton_from_objects(const py::object& data, const py::object& iso);

void add_skeleton_nodes(py::module_& m);
void add_mesh_bindings(py::module_& m, py::class_<Skeleton>& skeleton);

}  // namespace skelconv::python
