// python/mesh_bindings.cpp — meshes as numpy arrays (docs/python.md):
// Skeleton.mesh (`skelconv mesh`), mesh_topology (what `skelconv mesh`
// prints about its mesh) and skeletonize (`skelconv skeletonize`), each a
// call of the library functions the command calls, with the GIL released
// while they run.
//
// Options are the command's, as keyword arguments: --max-triangles is
// max_triangles. The library locates an error in an option at the option's
// name ("--prune-angle: must be in [0, 180) degrees, got 200"); here it is
// located at the argument's ("prune_angle: ...").
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "bindings.hpp"
#include "skelconv/mesh/implicit_field.hpp"
#include "skelconv/mesh/mesh_iso_surface.hpp"
#include "skelconv/mesh/mesh_topology.hpp"
#include "skelconv/mesh/missed_parts.hpp"
#include "skelconv/mesh/triangle_mesh.hpp"
#include "skelconv/reconstruct/mesh_check.hpp"
#include "skelconv/reconstruct/reconstruct.hpp"
#include "skelconv/reconstruct/sample_noise.hpp"
#include "skelconv/reconstruct/surface_samples.hpp"
#include "skelconv/skeleton/skeleton_file.hpp"

namespace skelconv::python {
namespace {

/// numpy int32, C order (the triangles' vertex indices).
using IndexArray = py::array_t<std::int32_t, py::array::c_style | py::array::forcecast>;

/// Runs `work`; an InputError located at a command-line option ("--iso")
/// is rethrown located at the keyword argument of the same name ("iso").
template <class Work>
auto with_argument_names(Work&& work) {
  try {
    return work();
  } catch (const InputError& error) {
    const std::string& where = error.where();
    if (!where.starts_with("--")) throw;
    std::string name = where.substr(2);
    for (char& c : name)
      if (c == '-') c = '_';
    throw InputError(error.problem(), name);
  }
}

/// A TriangleMesh as numpy arrays: vertices (V, 3), triangles (T, 3) int32
/// (counter-clockwise seen from outside), normals (V, 3).
py::tuple mesh_arrays(const TriangleMesh& mesh) {
  const auto v = static_cast<py::ssize_t>(mesh.vertices.size());
  const auto t = static_cast<py::ssize_t>(mesh.triangles.size());
  DoubleArray vertices({v, py::ssize_t(3)}), normals({v, py::ssize_t(3)});
  IndexArray triangles({t, py::ssize_t(3)});
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

/// A TriangleMesh (without normals) from arrays: vertices (V, 3), finite;
/// triangles (T, 3) of indices in [0, V), as the mesh reader requires of a
/// file (mesh_reader.hpp).
TriangleMesh triangle_mesh(const DoubleArray& vertices, const IndexArray& triangles) {
  require_rows_of(vertices, 3, "vertices");
  require_rows_of(triangles, 3, "triangles");
  TriangleMesh mesh;
  const auto v = static_cast<std::size_t>(vertices.shape(0));
  mesh.vertices.resize(v);
  for (std::size_t k = 0; k < v; ++k) {
    for (int c = 0; c < 3; ++c) mesh.vertices[k][c] = vertices.at(k, c);
    if (!mesh.vertices[k].allFinite()) throw InputError("not finite", fmt::format("vertices[{}]", k));
  }
  mesh.triangles.resize(static_cast<std::size_t>(triangles.shape(0)));
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
    for (int c = 0; c < 3; ++c) {
      const std::int32_t index = triangles.at(k, c);
      if (index < 0 || std::size_t(index) >= v)
        throw InputError(fmt::format("vertex index {} outside [0, {})", index, v), fmt::format("triangles[{}]", k));
      mesh.triangles[k][c] = index;
    }
  }
  return mesh;
}

/// The surface f = iso (default: the skeleton's iso), as `skelconv mesh`.
py::tuple mesh(const Skeleton& skeleton, std::optional<double> iso, const std::string& method,
               std::optional<double> size, std::optional<double> distance, std::optional<std::size_t> max_triangles,
               double tolerance) {
  if (method != "cgal" && method != "grid")
    throw InputError(fmt::format("{} not in {{cgal,grid}}", method), "method");
  MeshOptions options;
  options.iso = iso.value_or(skeleton.iso());
  options.method = method == "grid" ? MeshMethod::grid : MeshMethod::cgal;
  options.size = size;
  options.distance = distance;
  if (max_triangles) options.max_triangles = *max_triangles;
  MeshReport report;
  const TriangleMesh result = with_argument_names([&] {
    py::gil_scoped_release release;
    return mesh_iso_surface(skeleton_field(skeleton, 4, tolerance), options, &report);
  });
  // The command's warning for the parts a grid lost (skelconv/mesh/missed_parts.hpp),
  // as a Python warning: the mesh is returned, and the caller's warning
  // filters decide (an "error" filter raises it).
  if (!report.missed_parts.empty()) {
    const std::string message = fmt::format("size={:g}: {}", report.size, missed_parts_problem(skeleton, report));
    if (PyErr_WarnEx(PyExc_RuntimeWarning, message.c_str(), 1) != 0) throw py::error_already_set();
  }
  return mesh_arrays(result);
}

/// The counts `skelconv mesh` prints about its mesh.
py::dict topology(const DoubleArray& vertices, const IndexArray& triangles) {
  const MeshTopology t = mesh_topology(triangle_mesh(vertices, triangles));
  py::dict result;
  result["triangles"] = t.triangles;
  result["vertices"] = t.vertices;
  result["edges"] = t.edges;
  result["components"] = t.components;
  result["euler_characteristic"] = t.euler_characteristic;
  result["closed"] = t.closed;
  result["manifold"] = t.manifold;
  return result;
}

/// "auto", "curve" or "medial": the names of `skelconv skeletonize --method`.
reconstruct::SkeletonMethod skeleton_method(const std::string& name) {
  if (name == "auto") return reconstruct::SkeletonMethod::automatic;
  if (name == "curve") return reconstruct::SkeletonMethod::curve;
  if (name == "medial") return reconstruct::SkeletonMethod::medial;
  throw InputError(fmt::format("{} not in {{auto,curve,medial}}", name), "method");
}

/// The skeleton `skelconv skeletonize` writes for the closed mesh
/// (vertices, triangles), as a Skeleton: the same merge of coincident
/// vertices, checks of the mesh (or repair: `--repair`), removal of the
/// vertices of no triangle, noise,
/// reconstruction and skeleton file.
Skeleton skeletonize(const DoubleArray& vertices, const IndexArray& triangles,
                     const reconstruct::ReconstructOptions& options, double noise, std::size_t max_triangles,
                     bool repair) {
  TriangleMesh input = triangle_mesh(vertices, triangles);
  const std::string text = with_argument_names([&] {
    py::gil_scoped_release release;
    reconstruct::merge_coincident_vertices(input);
    reconstruct::check_mesh_size(input, max_triangles);
    if (repair) reconstruct::check_closed_mesh_repairing(input);
    else reconstruct::check_closed_mesh_offering_repair(input, "repair=True");
    reconstruct::remove_unused_vertices(input);
    const TriangleMesh samples = reconstruct::with_sample_noise(input, noise);
    return reconstruct::skeleton_file_text(reconstruct::reconstruct(samples, options).stages.back(), options);
  });
  return parse_skeleton_json(text);
}

}  // namespace

void add_mesh_bindings(py::module_& m, py::class_<Skeleton>& skeleton) {
  skeleton.def("mesh", &mesh, py::arg("iso") = py::none(), py::arg("method") = "cgal", py::arg("size") = py::none(),
               py::arg("distance") = py::none(), py::arg("max_triangles") = py::none(),
               py::arg("tolerance") = Skeleton::default_tolerance,
               "The surface f = iso, as `skelconv mesh` (docs/mesh.md): returns (vertices (V, 3), triangles (T, 3) "
               "int32, counter-clockwise seen from outside, normals (V, 3) unit, outward).\n"
               "iso: default the skeleton's; method: \"cgal\" (closed manifold) or \"grid\" (OpenVDB, faster); "
               "size: largest facet circumradius (default box diagonal / 50); distance: largest facet-to-surface "
               "distance (default size / 10); max_triangles: refuse a size whose mesh would have more triangles "
               "(default 4000000); tolerance: the field's relative tolerance (default 1e-12, 0: exact; "
               "docs/field.md, \"Tolerance\").");

  m.def("mesh_topology", &topology, py::arg("vertices"), py::arg("triangles"),
        "What `skelconv mesh` prints about a mesh: a dict of triangles, vertices (used by a triangle), edges, "
        "components, euler_characteristic, closed, manifold.");

  m.def(
      "skeletonize",
      [](const DoubleArray& vertices, const IndexArray& triangles, const std::string& method, std::size_t budget,
         std::optional<double> medial_prune_angle, std::optional<double> medial_prune_span,
         std::optional<double> prune_angle, std::optional<double> prune_span,
         std::optional<double> epsilon, bool bezier_junctions, double noise, std::optional<std::size_t> max_triangles,
         bool repair) {
        // The library's defaults are the command's; an argument given replaces one.
        reconstruct::ReconstructOptions options;
        options.method = skeleton_method(method);
        options.medial.budget = budget;
        options.medial.prune_angle_degrees = medial_prune_angle.value_or(options.medial.prune_angle_degrees);
        options.medial.prune_span = medial_prune_span.value_or(options.medial.prune_span);
        options.prune_angle_degrees = prune_angle.value_or(options.prune_angle_degrees);
        options.prune_span = prune_span.value_or(options.prune_span);
        options.epsilon = epsilon.value_or(options.epsilon);
        options.junction_triangles = bezier_junctions;
        // As the command's --max-triangles (skeletonize_command.hpp says why).
        const std::size_t limit = max_triangles.value_or(2 * reconstruct::SamplingOptions{}.max_samples);
        return skeletonize(vertices, triangles, options, noise, limit, repair);
      },
      py::arg("vertices"), py::arg("triangles"), py::arg("method") = "auto",
      py::arg("budget") = reconstruct::MedialOptions{}.budget, py::arg("medial_prune_angle") = py::none(),
      py::arg("medial_prune_span") = py::none(),
      py::arg("prune_angle") = py::none(), py::arg("prune_span") = py::none(), py::arg("epsilon") = py::none(),
      py::arg("bezier_junctions") = false, py::arg("noise") = 0.0, py::arg("max_triangles") = py::none(),
      py::arg("repair") = false,
      "The skeleton of SCALIS primitives whose surface approximates a closed mesh, as `skelconv skeletonize` "
      "(docs/reconstruction.md): vertices (V, 3), triangles (T, 3) counter-clockwise seen from outside. "
      "method: \"auto\" (both, the closer one), \"curve\" or \"medial\"; budget: the result's primitives at most (auto and medial: auto keeps no curve skeleton of more); "
      "repair: as --repair, close holes, split non-manifold edges and join crossing parts instead of refusing; "
      "the other options are the command's (--prune-angle is prune_angle; None: the command's default).");
}

}  // namespace skelconv::python
