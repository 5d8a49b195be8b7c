// python/skeleton_nodes.cpp — skeletons built from Python values
// (docs/python.md, "Primitives from Python values").
//
//     cauchy = {"family": "cauchy", "degree": 4, "s": 2.0}
//     arm = skelconv.Segment([0, 0, 0], [1, 0, 0], cauchy, weight=[1, 0.5])
//     ball = skelconv.Point([1, 0, 0], {"family": "soft", "R": 1.5})
//     skeleton = skelconv.Skeleton([skelconv.Blend("union", [arm, ball])], iso=0.5)
//
// A primitive or blend node made in Python is its JSON object in the
// skeleton file's schema (docs/cli_skeleton.md, docs/cli_blends.md): each
// class takes the fields of its "type" as arguments. It is checked by the
// file reader when it is made, and a Skeleton is read from the objects by
// the same reader, so every check, default and message is the file's; an
// error is located at the argument ("kernel.R: must be > 0, got -1") where
// the file names its path ("primitives[0].kernel.R: ...").
#include <cmath>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>

#include "bindings.hpp"
#include "skelconv/skeleton/skeleton_file.hpp"

namespace skelconv::python {
namespace {

/// A primitive or blend node: its JSON object, as text (file comment).
struct Node {
  std::string json;
};
struct SegmentNode : Node {};
struct PolygonNode : Node {};
struct ScalisSegmentNode : Node {};
struct ScalisTriangleNode : Node {};
struct PointNode : Node {};
struct BlendNode : Node {};

/// Throws InputError("must be finite, got nan", "a[0]") at the first float
/// of `value` that is nan or ±inf (dicts by key, lists, tuples and numpy
/// arrays by index; nodes were checked when made). json.dumps would write
/// it as NaN or Infinity, which the reader refuses as malformed JSON at a
/// column of text the caller never wrote.
void require_finite_numbers(const py::handle& value, const std::string& where) {
  if (py::isinstance<Node>(value)) return;
  if (py::isinstance<py::float_>(value) || (py::hasattr(value, "dtype") && py::hasattr(value, "item") &&
                                           py::len(value.attr("shape")) == 0)) {
    const double number = value.attr("__float__")().cast<double>();
    if (!std::isfinite(number)) throw InputError(fmt::format("must be finite, got {}", number), where);
    return;
  }
  if (py::isinstance<py::dict>(value)) {
    for (const auto& [key, item] : value.cast<py::dict>()) {
      require_finite_numbers(item, join_location(where, py::str(key).cast<std::string>()));
    }
    return;
  }
  if (py::hasattr(value, "tolist")) return require_finite_numbers(value.attr("tolist")(), where);
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    std::size_t k = 0;
    for (const py::handle item : value) require_finite_numbers(item, fmt::format("{}[{}]", where, k++));
  }
}

/// json.dumps of Python objects: numpy arrays and numpy integers through
/// their tolist(), nodes as their JSON objects. Anything else JSON cannot
/// hold is an InputError, a non-finite number too (require_finite_numbers).
std::string to_json(const py::object& value) {
  require_finite_numbers(value, "");
  const py::module_ json = py::module_::import("json");
  const py::cpp_function convert([json](const py::object& item) -> py::object {
    if (py::isinstance<Node>(item)) return json.attr("loads")(item.cast<const Node&>().json);
    if (py::hasattr(item, "tolist")) return item.attr("tolist")();
    throw InputError(fmt::format("cannot be written as JSON: {}", py::str(py::type::of(item)).cast<std::string>()),
                     "skeleton");
  });
  return json.attr("dumps")(value, py::arg("default") = convert).cast<std::string>();
}

/// The reader's location of a node read as the file's only primitive,
/// "primitives[0].kernel.R", as the node's own: "kernel.R".
std::string node_location(std::string_view where) {
  constexpr std::string_view only = "primitives[0]";
  if (!where.starts_with(only)) return std::string(where);
  where.remove_prefix(only.size());
  if (where.starts_with('.')) where.remove_prefix(1);
  return std::string(where);
}

/// A node of type T from its fields (those given as None are left out, so
/// the file's defaults apply), checked by reading it as a skeleton file of
/// one primitive.
template <class T>
T make_node(std::initializer_list<std::pair<const char*, py::object>> fields) {
  py::dict object;
  for (const auto& [key, value] : fields)
    if (!value.is_none()) object[key] = value;
  T node;
  node.json = to_json(object);
  try {
    parse_skeleton_json(fmt::format("{{\"primitives\": [{}]}}", node.json));
  } catch (const InputError& error) {
    throw InputError(error.problem(), node_location(error.where()));
  }
  return node;
}

constexpr const char* kernel_doc =
    "kernel: a dict as in the skeleton file, e.g. {\"family\": \"cauchy\", \"degree\": 4, \"s\": 2.0} "
    "(docs/cli_skeleton.md)";

}  // namespace

Skeleton skeleton_from_objects(const py::object& data, const py::object& iso) {
  py::dict skeleton;
  if (py::isinstance<py::dict>(data)) {
    skeleton = data.attr("copy")();
  } else if (py::isinstance<Node>(data)) {
    skeleton["primitives"] = py::make_tuple(data);
  } else {
    skeleton["primitives"] = data;
  }
  if (!iso.is_none()) skeleton["iso"] = iso;
  return parse_skeleton_json(to_json(skeleton));
}

void add_skeleton_nodes(py::module_& m) {
  py::class_<Node>(m, "Node",
                   "A primitive or blend node of a skeleton: one JSON object of the skeleton file, checked when made.")
      .def_property_readonly(
          "data", [](const Node& node) { return py::module_::import("json").attr("loads")(node.json); },
          "The node as a dict in the skeleton file's schema (a copy).")
      .def("__repr__", [](const py::object& self) {
        return fmt::format("skelconv.{}({})", py::type::of(self).attr("__name__").cast<std::string>(),
                           self.cast<const Node&>().json);
      });

  py::class_<SegmentNode, Node>(m, "Segment",
                                "A convolution segment from a to b with weight polynomial w(t) = sum w_k t^k "
                                "(docs/cli_skeleton.md, type \"segment\").")
      .def(py::init([](py::object a, py::object b, py::object kernel, py::object weight) {
             return make_node<SegmentNode>(
                 {{"type", py::str("segment")}, {"a", a}, {"b", b}, {"kernel", kernel}, {"weight", weight}});
           }),
           py::arg("a"), py::arg("b"), py::arg("kernel"), py::arg("weight") = py::none(),
           (std::string("a, b: end points [x, y, z]; ") + kernel_doc +
            "; weight: [w0 .. w3], default [1].")
               .c_str());

  py::class_<PolygonNode, Node>(m, "Polygon",
                                "A planar polygon of uniform weight (docs/cli_skeleton.md, type \"polygon\").")
      .def(py::init([](py::object vertices, py::object kernel) {
             return make_node<PolygonNode>({{"type", py::str("polygon")}, {"vertices", vertices}, {"kernel", kernel}});
           }),
           py::arg("vertices"), py::arg("kernel"),
           (std::string("vertices: (n, 3), n >= 3, in one plane; ") + kernel_doc + ".").c_str());

  py::class_<ScalisSegmentNode, Node>(m, "ScalisSegment",
                                      "A SCALIS segment: radius varying linearly from a to b, f = iso at that "
                                      "distance (docs/cli_skeleton.md, type \"scalis_segment\").")
      .def(py::init([](py::object a, py::object b, py::object radius, py::object kernel, py::object iso) {
             return make_node<ScalisSegmentNode>({{"type", py::str("scalis_segment")},
                                                  {"a", a},
                                                  {"b", b},
                                                  {"radius", radius},
                                                  {"kernel", kernel},
                                                  {"iso", iso}});
           }),
           py::arg("a"), py::arg("b"), py::arg("radius"), py::arg("kernel"), py::arg("iso") = py::none(),
           "a, b: end points; radius: [tau0, tau1]; kernel: {\"family\": ..., \"degree\": ..., \"sigma\": ...}; "
           "iso: default 1.");

  py::class_<ScalisTriangleNode, Node>(m, "ScalisTriangle",
                                       "A SCALIS triangle: radius interpolated between its vertices "
                                       "(docs/cli_skeleton.md, type \"scalis_triangle\").")
      .def(py::init([](py::object vertices, py::object radius, py::object kernel, py::object iso) {
             return make_node<ScalisTriangleNode>({{"type", py::str("scalis_triangle")},
                                                   {"vertices", vertices},
                                                   {"radius", radius},
                                                   {"kernel", kernel},
                                                   {"iso", iso}});
           }),
           py::arg("vertices"), py::arg("radius"), py::arg("kernel"), py::arg("iso") = py::none(),
           "vertices: (3, 3); radius: [tau0, tau1, tau2]; kernel: {\"family\": ..., \"degree\": ..., \"sigma\": ...}; "
           "iso: default 1.");

  py::class_<PointNode, Node>(m, "Point",
                              "A point primitive f = w K(|P - center|) (docs/cli_blends.md, type \"point\").")
      .def(py::init([](py::object center, py::object kernel, py::object weight) {
             return make_node<PointNode>(
                 {{"type", py::str("point")}, {"center", center}, {"kernel", kernel}, {"weight", weight}});
           }),
           py::arg("center"), py::arg("kernel"), py::arg("weight") = py::none(),
           (std::string("center: [x, y, z]; ") + kernel_doc +
            ", or a soft-object family (soft, wyvill, ferley, gaussian, polynomial); weight: default 1.")
               .c_str());

  py::class_<BlendNode, Node>(m, "Blend",
                              "A blend node over its children (primitives or blend nodes): \"sum\", \"union\" or "
                              "\"super_elliptic\" (docs/cli_blends.md).")
      .def(py::init([](py::object kind, py::object children, py::object weights, py::object t, py::object r,
                       py::object iso, py::object angle_weighted) {
             return make_node<BlendNode>({{"blend", kind},
                                          {"children", children},
                                          {"weights", weights},
                                          {"t", t},
                                          {"r", r},
                                          {"iso", iso},
                                          {"angle_weighted", angle_weighted}});
           }),
           py::arg("kind"), py::arg("children"), py::arg("weights") = py::none(), py::arg("t") = py::none(),
           py::arg("r") = py::none(), py::arg("iso") = py::none(), py::arg("angle_weighted") = py::none(),
           "kind: \"sum\" (weights: one per child), \"union\" (max), \"super_elliptic\" (t, r: one per child or "
           "one for all, iso: default the skeleton's, angle_weighted: two children); children: a list of nodes.");
}

}  // namespace skelconv::python
