// Implementation of skelconv/skeleton/skeleton_file.hpp.
//
// Reading happens in two passes:
//   1. nlohmann::json::parse builds the document. A callback follows the
//      parser's position so that the two problems nlohmann reports without a
//      location (a number overflowing double) or not at all (a duplicate key:
//      it keeps the last one) are reported with their JSON path.
//   2. read_skeleton walks the document, checking presence, types and
//      allowed keys with the path of each value, then builds the primitives;
//      the primitive constructors check the geometry and kernel values
//      (a primitive constructor's InputError is relocated under
//      "primitives[k]").
#include "skelconv/skeleton/skeleton_file.hpp"

#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <set>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "skelconv/errors.hpp"
#include "skelconv/kernels/kernel_list.hpp"
#include "skelconv/skeleton/text_file.hpp"
#include "../detail/input_checks.hpp"

namespace skelconv {
namespace {

using Json = nlohmann::json;

/// A name from the file (a key, a type, a family) as messages quote it: at
/// most 40 bytes, cut before a UTF-8 continuation byte, then "...", as
/// values are (excerpt below): a 5,000-character type was quoted whole.
std::string shown_name(std::string_view name) {
  constexpr std::size_t max_length = 40;
  if (name.size() <= max_length) return std::string(name);
  std::size_t end = max_length - 3;
  while (end > 0 && (static_cast<unsigned char>(name[end]) & 0xC0) == 0x80) --end;
  return std::string(name.substr(0, end)) + "...";
}

// ---------------------------------------------------------------------------
// Pass 1: parsing, with the parser's position tracked as a JSON path.

/// Follows nlohmann's parse events and knows, at any moment, the path of the
/// value being parsed ("primitives[0].a[1]").
class ParsePathTracker {
 public:
  /// The parse callback; always keeps the value. Throws InputError on a
  /// duplicate key.
  bool on_event(Json::parse_event_t event, const Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start:
        detail::require_json_nesting(levels_.size(), current_path());
        levels_.push_back({true, {}, 0, {}});
        break;
      case Json::parse_event_t::array_start:
        detail::require_json_nesting(levels_.size(), current_path());
        levels_.push_back({false, {}, 0, {}});
        break;
      case Json::parse_event_t::key: {
        Level& object = levels_.back();
        object.key = parsed.get<std::string>();
        if (!object.keys_seen.insert(object.key).second) {
          throw InputError(fmt::format("duplicate field \"{}\"", shown_name(object.key)), path(levels_.size() - 1));
        }
        break;
      }
      case Json::parse_event_t::object_end:
      case Json::parse_event_t::array_end:
        levels_.pop_back();
        value_done();
        break;
      case Json::parse_event_t::value:
        value_done();
        break;
    }
    return true;
  }

  /// Path of the value being parsed now.
  std::string current_path() const { return path(levels_.size()); }

 private:
  struct Level {
    bool is_object;
    std::string key;          // object: key of the current member
    std::size_t index;        // array: index of the current element
    std::set<std::string> keys_seen;
  };

  // A value inside an array is complete: the next one has the next index.
  void value_done() {
    if (!levels_.empty() && !levels_.back().is_object) ++levels_.back().index;
  }

  // Path through the first `depth` levels.
  std::string path(std::size_t depth) const {
    std::string text;
    for (std::size_t k = 0; k < depth; ++k) {
      const Level& level = levels_[k];
      text = level.is_object ? join_location(text, level.key) : fmt::format("{}[{}]", text, level.index);
    }
    return text;
  }

  std::vector<Level> levels_;
};

/// nlohmann's what() without its "[json.exception.parse_error.101] " tag.
std::string without_exception_tag(const char* what) {
  std::string_view text(what);
  if (text.starts_with("[json.exception.")) {
    if (const std::size_t end = text.find("] "); end != std::string_view::npos) text.remove_prefix(end + 2);
  }
  return std::string(text);
}

Json parse_json(std::string_view text) {
  detail::require_no_nul_byte(text);
  ParsePathTracker tracker;
  const Json::parser_callback_t callback = [&tracker](int /*depth*/, Json::parse_event_t event, Json& parsed) {
    return tracker.on_event(event, parsed);
  };
  try {
    return Json::parse(text.begin(), text.end(), callback);
  } catch (const Json::parse_error& error) {
    throw InputError("malformed JSON: " + without_exception_tag(error.what()));
  } catch (const Json::out_of_range& error) {
    // The only out_of_range the parser throws: "number overflow parsing '1e999'".
    throw InputError(without_exception_tag(error.what()) + " (too large for double precision)",
                     tracker.current_path());
  }
}

// ---------------------------------------------------------------------------
// Pass 2: reading the document. Each reader takes the value and its path.

/// A short rendering of a JSON value for messages: `"abc"`, `[1,2]`, `null`.
std::string excerpt(const Json& value) {
  std::string text = value.dump();
  constexpr std::size_t max_length = 40;
  if (text.size() > max_length) text = text.substr(0, max_length - 3) + "...";
  return text;
}

/// "a string", "an array", ... for "must be X, got <a string> "abc"".
std::string describe(const Json& value) {
  switch (value.type()) {
    case Json::value_t::object: return "an object";
    case Json::value_t::array: return "an array " + excerpt(value);
    case Json::value_t::string: return "a string " + excerpt(value);
    case Json::value_t::boolean: return "a boolean " + excerpt(value);
    case Json::value_t::null: return "null";
    default: return excerpt(value);
  }
}

std::string quoted_list(std::span<const std::string_view> names) {
  std::string text;
  for (std::string_view name : names) text += fmt::format("{}\"{}\"", text.empty() ? "" : ", ", name);
  return text;
}
std::string quoted_list(std::initializer_list<std::string_view> names) {
  return quoted_list(std::span<const std::string_view>(names.begin(), names.size()));
}

void require_object(const Json& value, const std::string& path) {
  if (!value.is_object()) throw InputError("must be an object, got " + describe(value), path);
}

/// Rejects every key not in `allowed`; `context` ends the message, e.g.
/// " for the inverse family".
void reject_unknown_keys(const Json& object, const std::string& path, std::span<const std::string_view> allowed,
                         std::string_view context = "") {
  for (const auto& [key, value] : object.items()) {
    bool known = false;
    for (std::string_view name : allowed) known = known || key == name;
    if (!known) {
      throw InputError(fmt::format("unknown field \"{}\"{} (allowed: {})", shown_name(key), context, quoted_list(allowed)), path);
    }
  }
}
void reject_unknown_keys(const Json& object, const std::string& path,
                         std::initializer_list<std::string_view> allowed, std::string_view context = "") {
  reject_unknown_keys(object, path, std::span<const std::string_view>(allowed.begin(), allowed.size()), context);
}

const Json& require_field(const Json& object, const std::string& path, const char* key) {
  const auto found = object.find(key);
  if (found == object.end()) throw InputError(fmt::format("missing field \"{}\"", key), path);
  return *found;
}

double read_number(const Json& value, const std::string& path) {
  if (!value.is_number()) throw InputError("must be a number, got " + describe(value), path);
  const double number = value.get<double>();
  if (!std::isfinite(number)) throw InputError(fmt::format("must be a finite number, got {}", number), path);
  return number;
}

int read_integer(const Json& value, const std::string& path) {
  const double number = read_number(value, path);
  if (number != std::floor(number)) throw InputError("must be an integer, got " + excerpt(value), path);
  if (std::abs(number) > 1e9) throw InputError("is out of range, got " + excerpt(value), path);
  return int(number);
}

std::string read_string(const Json& value, const std::string& path) {
  if (!value.is_string()) throw InputError("must be a string, got " + describe(value), path);
  return value.get<std::string>();
}

std::vector<double> read_numbers(const Json& value, const std::string& path) {
  if (!value.is_array()) throw InputError("must be an array of numbers, got " + describe(value), path);
  std::vector<double> numbers;
  for (std::size_t k = 0; k < value.size(); ++k) {
    numbers.push_back(read_number(value[k], fmt::format("{}[{}]", path, k)));
  }
  return numbers;
}

Vec3 read_point(const Json& value, const std::string& path) {
  if (!value.is_array() || value.size() != 3) {
    throw InputError("must be a point [x, y, z] (an array of 3 numbers), got " + describe(value), path);
  }
  const std::vector<double> xyz = read_numbers(value, path);
  return {xyz[0], xyz[1], xyz[2]};
}

/// "\"inverse\", \"cauchy\", ..." — every family name, for messages.
std::string family_names() {
  std::string text;
  for (KernelFamily family : all_kernel_families) {
    text += fmt::format("{}\"{}\"", text.empty() ? "" : ", ", family_name(family));
  }
  return text;
}

/// The "family" field of the kernel object at `path`.
KernelFamily read_family(const Json& kernel, const std::string& path) {
  const std::string family_text = read_string(require_field(kernel, path, "family"), path + ".family");
  const std::optional<KernelFamily> family = family_from_name(family_text);
  if (!family) {
    throw InputError(fmt::format("unknown family \"{}\" (supported: {})", shown_name(family_text), family_names()),
                     path + ".family");
  }
  return *family;
}

/// {"family": ..., "degree": ... (families with a degree), and the family's
/// parameters (its trait's list: "s", "R", "e", "a", "b")}.
KernelSpec read_kernel(const Json& value, const std::string& path) {
  require_object(value, path);
  KernelSpec kernel;
  kernel.family = read_family(value, path);
  const kernels::FamilyFacts facts = kernels::family_facts(kernel.family);
  std::vector<std::string_view> allowed{"family"};
  if (facts.has_degree) allowed.push_back("degree");
  allowed.insert(allowed.end(), facts.parameters.begin(), facts.parameters.end());
  reject_unknown_keys(value, path, allowed, fmt::format(" for the {} family", facts.name));
  for (std::string_view key : facts.parameters) {
    const std::string name(key);
    *kernel_parameter(kernel, key) = read_number(require_field(value, path, name.c_str()), path + "." + name);
  }
  if (facts.has_degree) kernel.degree = read_integer(require_field(value, path, "degree"), path + ".degree");
  return kernel;
}

/// detail::require_convolution_family, located at `path`.family.
void require_family_on(KernelFamily family, std::string_view what, const std::string& path) {
  try {
    detail::require_convolution_family(family, what);
  } catch (const InputError& error) {
    throw InputError(error.problem(), path + ".family");
  }
}

/// read_kernel for a primitive that is not a point.
KernelSpec read_convolution_kernel(const Json& value, const std::string& path, std::string_view what) {
  require_object(value, path);
  require_family_on(read_family(value, path), what, path);
  return read_kernel(value, path);
}

/// Runs a primitive's constructor, locating its InputError (whose where()
/// is relative to the primitive: "kernel.R") under the primitive's path.
template <class Construct>
Primitive construct_located(const std::string& path, Construct construct) {
  try {
    return construct();
  } catch (const InputError& error) {
    throw error.inside(path);
  }
}

/// {"type": "segment", "a": P, "b": P, "weight": [w0, ...] (optional), "kernel": K}.
Primitive read_segment(const Json& value, const std::string& path) {
  reject_unknown_keys(value, path, {"type", "a", "b", "weight", "kernel"}, " for a segment");
  const Vec3 a = read_point(require_field(value, path, "a"), path + ".a");
  const Vec3 b = read_point(require_field(value, path, "b"), path + ".b");
  std::vector<double> weight{1.0};
  if (const auto found = value.find("weight"); found != value.end()) weight = read_numbers(*found, path + ".weight");
  const KernelSpec kernel = read_convolution_kernel(require_field(value, path, "kernel"), path + ".kernel", "segment");
  return construct_located(path, [&] { return Segment(a, b, kernel, weight); });
}

/// {"type": "polygon", "vertices": [P, P, P, ...], "kernel": K}.
Primitive read_polygon(const Json& value, const std::string& path) {
  reject_unknown_keys(value, path, {"type", "vertices", "kernel"}, " for a polygon");
  const std::string vertices_path = path + ".vertices";
  const Json& vertices_json = require_field(value, path, "vertices");
  if (!vertices_json.is_array()) {
    throw InputError("must be an array of points [[x, y, z], ...], got " + describe(vertices_json), vertices_path);
  }
  std::vector<Vec3> vertices;
  for (std::size_t k = 0; k < vertices_json.size(); ++k) {
    vertices.push_back(read_point(vertices_json[k], fmt::format("{}[{}]", vertices_path, k)));
  }
  const KernelSpec kernel = read_convolution_kernel(require_field(value, path, "kernel"), path + ".kernel", "polygon");
  return construct_located(path, [&] { return Polygon(vertices, kernel); });
}

// --- SCALIS segment (docs/mathematics.md §4) ---------------------------------------------

/// {"family": "inverse" | "cauchy" | "compact", "degree": i, "sigma": σ}.
ScalisKernel read_scalis_kernel(const Json& value, const std::string& path, std::string_view what) {
  require_object(value, path);
  ScalisKernel kernel;
  kernel.family = read_family(value, path);
  require_family_on(kernel.family, what, path);
  reject_unknown_keys(value, path, {"family", "degree", "sigma"}, " for a SCALIS kernel");
  kernel.degree = read_integer(require_field(value, path, "degree"), path + ".degree");
  kernel.sigma = read_number(require_field(value, path, "sigma"), path + ".sigma");
  return kernel;
}

/// The "radius" field of a SCALIS primitive: exactly `count` numbers, the
/// radii at `at` (named as in the message, e.g. "[tau0, tau1] at a and b").
std::vector<double> read_scalis_radii(const Json& value, const std::string& path, std::size_t count,
                                      const char* names_and_places) {
  const Json& radius_value = require_field(value, path, "radius");
  if (!radius_value.is_array() || radius_value.size() != count) {
    throw InputError(fmt::format("must be the radii {} (an array of {} numbers), got {}", names_and_places, count,
                                 describe(radius_value)),
                     path + ".radius");
  }
  return read_numbers(radius_value, path + ".radius");
}

/// The optional "iso" field of a SCALIS primitive (default 1).
double read_iso(const Json& value, const std::string& path) {
  const auto found = value.find("iso");
  return found == value.end() ? 1.0 : read_number(*found, path + ".iso");
}

/// {"type": "scalis_segment", "a": P, "b": P, "radius": [τ0, τ1], "kernel": K, "iso": c (optional, 1)}.
Primitive read_scalis_segment(const Json& value, const std::string& path) {
  reject_unknown_keys(value, path, {"type", "a", "b", "radius", "kernel", "iso"}, " for a scalis_segment");
  const Vec3 a = read_point(require_field(value, path, "a"), path + ".a");
  const Vec3 b = read_point(require_field(value, path, "b"), path + ".b");
  const std::vector<double> radius = read_scalis_radii(value, path, 2, "[tau0, tau1] at a and b");
  const ScalisKernel kernel =
      read_scalis_kernel(require_field(value, path, "kernel"), path + ".kernel", "scalis_segment");
  const double iso = read_iso(value, path);
  return construct_located(path, [&] { return ScalisSegment(a, b, radius[0], radius[1], kernel, iso); });
}

// --- SCALIS triangle (docs/mathematics.md §4, Zanni §5.2) ----------------------------------

/// {"type": "scalis_triangle", "vertices": [P, P, P], "radius": [τ0, τ1, τ2], "kernel": K, "iso": c (optional, 1)}.
Primitive read_scalis_triangle(const Json& value, const std::string& path) {
  reject_unknown_keys(value, path, {"type", "vertices", "radius", "kernel", "iso"}, " for a scalis_triangle");
  const std::string vertices_path = path + ".vertices";
  const Json& vertices_json = require_field(value, path, "vertices");
  if (!vertices_json.is_array() || vertices_json.size() != 3) {
    throw InputError("must be the 3 vertices [[x, y, z], [x, y, z], [x, y, z]] (an array of 3 points), got " +
                         describe(vertices_json),
                     vertices_path);
  }
  std::array<Vec3, 3> vertices;
  for (std::size_t k = 0; k < 3; ++k)
    vertices[k] = read_point(vertices_json[k], fmt::format("{}[{}]", vertices_path, k));
  const std::vector<double> radius = read_scalis_radii(value, path, 3, "[tau0, tau1, tau2] at the vertices");
  const ScalisKernel kernel =
      read_scalis_kernel(require_field(value, path, "kernel"), path + ".kernel", "scalis_triangle");
  const double iso = read_iso(value, path);
  return construct_located(
      path, [&] { return ScalisTriangle(vertices, {radius[0], radius[1], radius[2]}, kernel, iso); });
}

// --- Point (skelconv/primitives/point.hpp) ---------------------------------

/// {"type": "point", "center": P, "kernel": K, "weight": w (optional, 1)}.
Primitive read_point_primitive(const Json& value, const std::string& path) {
  reject_unknown_keys(value, path, {"type", "center", "kernel", "weight"}, " for a point");
  const Vec3 center = read_point(require_field(value, path, "center"), path + ".center");
  const KernelSpec kernel = read_kernel(require_field(value, path, "kernel"), path + ".kernel");
  double weight = 1.0;
  if (const auto found = value.find("weight"); found != value.end()) {
    if (found->is_array()) {
      throw InputError("must be a number (a point's weight is a scalar factor), got " + describe(*found),
                       path + ".weight");
    }
    weight = read_number(*found, path + ".weight");
  }
  return construct_located(path, [&] { return PointPrimitive(center, kernel, weight); });
}

// ---------------------------------------------------------------------------

Primitive read_primitive(const Json& value, const std::string& path) {
  const std::string type = read_string(require_field(value, path, "type"), path + ".type");
  if (type == "segment") return read_segment(value, path);
  if (type == "polygon") return read_polygon(value, path);
  if (type == "scalis_segment") return read_scalis_segment(value, path);
  if (type == "scalis_triangle") return read_scalis_triangle(value, path);
  if (type == "point") return read_point_primitive(value, path);
  throw InputError(fmt::format("unknown primitive type \"{}\" (supported: {})", shown_name(type),
                               quoted_list({"segment", "polygon", "scalis_segment", "scalis_triangle", "point"})),
                   path + ".type");
}

// --- Blend nodes (skelconv/skeleton/blend.hpp) ------------------------------

void read_element(const Json& value, const std::string& path, Skeleton& skeleton, Skeleton::NodeId parent);

/// The JSON "blend" name.
BlendKind read_blend_kind(const Json& value, const std::string& path) {
  const std::string name = read_string(value, path);
  const std::optional<BlendKind> kind = blend_from_name(name);
  if (!kind) {
    throw InputError(fmt::format("unknown blend \"{}\" (supported: {})", shown_name(name),
                                 quoted_list({"sum", "union", "super_elliptic"})),
                     path);
  }
  return *kind;
}

/// "r": one number for every child, or an array with one per child.
std::vector<double> read_band_widths(const Json& node, const std::string& path) {
  const Json& r = require_field(node, path, "r");
  if (r.is_array()) return read_numbers(r, path + ".r");
  return {read_number(r, path + ".r")};
}

/// The parameters of the blend node at `path` (checked against its
/// `child_count` children, so that a bad parameter is reported before the
/// children are read). Nodes inherit the file's iso.
Blend read_blend_parameters(const Json& node, const std::string& path, std::size_t child_count, double file_iso) {
  Blend blend;
  blend.kind = read_blend_kind(node["blend"], path + ".blend");
  const std::string context = fmt::format(" for a {} blend", blend_name(blend.kind));
  switch (blend.kind) {
    case BlendKind::sum:
      reject_unknown_keys(node, path, {"blend", "children", "weights"}, context);
      if (const auto found = node.find("weights"); found != node.end()) {
        blend.weights = read_numbers(*found, path + ".weights");
      }
      break;
    case BlendKind::union_max:
      reject_unknown_keys(node, path, {"blend", "children"}, context);
      break;
    case BlendKind::super_elliptic: {
      reject_unknown_keys(node, path, {"blend", "children", "t", "r", "iso", "angle_weighted"}, context);
      blend.t = read_number(require_field(node, path, "t"), path + ".t");
      blend.r = read_band_widths(node, path);
      blend.iso = file_iso;
      if (const auto found = node.find("iso"); found != node.end()) blend.iso = read_number(*found, path + ".iso");
      if (const auto found = node.find("angle_weighted"); found != node.end()) {
        if (!found->is_boolean()) {
          throw InputError("must be true or false, got " + describe(*found), path + ".angle_weighted");
        }
        blend.angle_weighted = found->get<bool>();
      }
      break;
    }
  }
  try {
    validate_blend(blend, child_count);
  } catch (const InputError& error) {
    throw error.inside(path);
  }
  return blend;
}

/// {"blend": NAME, "children": [...], parameters}: a node and, depth-first,
/// its children.
void read_blend_node(const Json& value, const std::string& path, Skeleton& skeleton, Skeleton::NodeId parent) {
  const Json& children = require_field(value, path, "children");
  if (!children.is_array()) {
    throw InputError("must be an array of primitives and blend nodes, got " + describe(children), path + ".children");
  }
  const Skeleton::NodeId node =
      skeleton.add_blend(read_blend_parameters(value, path, children.size(), skeleton.iso()), parent);
  for (std::size_t k = 0; k < children.size(); ++k) {
    read_element(children[k], fmt::format("{}.children[{}]", path, k), skeleton, node);
  }
}

/// A primitive or a blend node, added under `parent`.
void read_element(const Json& value, const std::string& path, Skeleton& skeleton, Skeleton::NodeId parent) {
  require_object(value, path);
  if (value.contains("blend")) return read_blend_node(value, path, skeleton, parent);
  if (!value.contains("type") && value.contains("children")) {
    throw InputError("missing field \"blend\" (a node with \"children\" is a blend node)", path);
  }
  skeleton.add(read_primitive(value, path), parent);
}

/// The optional top-level "iso" (default 1): the level of the surface
/// (checked by Skeleton::set_iso).
double read_file_iso(const Json& document) {
  const auto found = document.find("iso");
  return found == document.end() ? 1.0 : read_number(*found, "iso");
}

Skeleton read_skeleton(const Json& document) {
  if (!document.is_object()) {
    throw InputError("the document must be an object {\"primitives\": [...]}, got " + describe(document));
  }
  reject_unknown_keys(document, "", {"primitives", "iso"});
  Skeleton skeleton;
  skeleton.set_iso(read_file_iso(document));
  const Json& primitives = require_field(document, "", "primitives");
  if (!primitives.is_array()) throw InputError("must be an array, got " + describe(primitives), "primitives");
  for (std::size_t k = 0; k < primitives.size(); ++k) {
    read_element(primitives[k], fmt::format("primitives[{}]", k), skeleton, Skeleton::root);
  }
  skeleton.validate();
  return skeleton;
}

}  // namespace

Skeleton parse_skeleton_json(std::string_view json_text) { return read_skeleton(parse_json(json_text)); }

Skeleton load_skeleton_file(const std::filesystem::path& path) {
  const std::string contents = read_text_file(path, "skeleton file");
  try {
    return parse_skeleton_json(contents);
  } catch (const InputError& error) {
    // Keep the JSON path inside the message: "skel.json: primitives[2]...".
    throw InputError(error.what(), path.string());
  }
}

}  // namespace skelconv
