// Implementation of skelconv/canal/canal_file.hpp.
//
// Parsing follows src/skeleton/skeleton_file.cpp: nlohmann's parser with a
// callback that knows the JSON path of the value being parsed (to locate a
// duplicate key or a number overflowing double), then a walk over the
// document that checks presence, types and allowed keys with each value's
// path.
#include "skelconv/canal/canal_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <type_traits>
#include <variant>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "skelconv/errors.hpp"
#include "skelconv/skeleton/text_file.hpp"
#include "../detail/input_checks.hpp"

namespace skelconv::canal {
namespace {

using Json = nlohmann::json;

// --- Parsing, with the path of the current value ------------------------------

/// One open object or array of the parser: its keys so far, or its index.
struct OpenValue {
  bool is_object = false;
  std::string key;
  std::size_t index = 0;
  std::set<std::string> keys;
};

std::string path_of(const std::vector<OpenValue>& open, std::size_t depth) {
  std::string path;
  for (std::size_t k = 0; k < depth; ++k) {
    path = open[k].is_object ? join_location(path, open[k].key) : fmt::format("{}[{}]", path, open[k].index);
  }
  return path;
}

/// nlohmann's message without its "[json.exception.parse_error.101] " tag.
std::string untagged(const char* what) {
  std::string_view text(what);
  if (const std::size_t end = text.find("] "); text.starts_with("[json.exception.") && end != text.npos) {
    text.remove_prefix(end + 2);
  }
  return std::string(text);
}

Json parse_document(std::string_view text) {
  detail::require_no_nul_byte(text);
  std::vector<OpenValue> open;
  auto next_element = [&open] {
    if (!open.empty() && !open.back().is_object) ++open.back().index;
  };
  const Json::parser_callback_t callback = [&](int, Json::parse_event_t event, Json& parsed) {
    using Event = Json::parse_event_t;
    if (event == Event::object_start || event == Event::array_start) {
      detail::require_json_nesting(open.size(), path_of(open, open.size()));
      open.emplace_back();
      open.back().is_object = event == Event::object_start;
    }
    if (event == Event::object_end || event == Event::array_end) open.pop_back();
    if (event == Event::object_end || event == Event::array_end || event == Event::value) next_element();
    if (event == Event::key) {
      open.back().key = parsed.get<std::string>();
      if (!open.back().keys.insert(open.back().key).second) {
        throw InputError(fmt::format("duplicate field \"{}\"", open.back().key), path_of(open, open.size() - 1));
      }
    }
    return true;
  };
  try {
    return Json::parse(text.begin(), text.end(), callback);
  } catch (const Json::parse_error& error) {
    throw InputError("malformed JSON: " + untagged(error.what()));
  } catch (const Json::out_of_range& error) {
    throw InputError(untagged(error.what()) + " (too large for double precision)", path_of(open, open.size()));
  }
}

// --- Reading the document ------------------------------------------------------

std::string shown(const Json& value) {
  if (value.is_object()) return "an object";
  std::string text = value.dump();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return text;
}

void allow_only(const Json& object, const std::string& path, std::initializer_list<std::string_view> allowed) {
  for (const auto& item : object.items()) {
    if (std::find(allowed.begin(), allowed.end(), item.key()) == allowed.end()) {
      std::string names;
      for (std::string_view name : allowed) names += fmt::format("{}\"{}\"", names.empty() ? "" : ", ", name);
      throw InputError(fmt::format("unknown field \"{}\" (allowed: {})", item.key(), names), path);
    }
  }
}

const Json& field(const Json& object, const std::string& path, const char* key) {
  if (!object.is_object()) throw InputError("must be an object, got " + shown(object), path);
  const auto found = object.find(key);
  if (found == object.end()) throw InputError(fmt::format("missing field \"{}\"", key), path);
  return *found;
}

double number(const Json& value, const std::string& path) {
  if (!value.is_number()) throw InputError("must be a number, got " + shown(value), path);
  return value.get<double>();
}

Vector3<double> point(const Json& value, const std::string& path) {
  if (!value.is_array() || value.size() != 3) {
    throw InputError("must be a point [x, y, z] (an array of 3 numbers), got " + shown(value), path);
  }
  return {number(value[0], path + "[0]"), number(value[1], path + "[1]"), number(value[2], path + "[2]")};
}

/// {"center": [x, y, z], "radius": r}, r ≠ 0.
Sphere<double> sphere(const Json& value, const std::string& path) {
  if (!value.is_object()) throw InputError("must be a sphere {\"center\": [x, y, z], \"radius\": r}, got " + shown(value), path);
  allow_only(value, path, {"center", "radius"});
  const Sphere<double> result{point(field(value, path, "center"), path + ".center"),
                              number(field(value, path, "radius"), path + ".radius")};
  try {
    sphere_vector(result);
  } catch (const InputError& error) {
    throw error.inside(path);
  }
  return result;
}

/// A sphere, or {"normal": [nx, ny, nz], "offset": d} with n ≠ 0.
Pole pole(const Json& value, const std::string& path) {
  if (value.is_object() && value.contains("normal")) {
    allow_only(value, path, {"normal", "offset"});
    const Plane<double> plane{point(field(value, path, "normal"), path + ".normal"),
                              number(field(value, path, "offset"), path + ".offset")};
    try {
      plane_vector(plane);  // validates the normal
    } catch (const InputError& error) {
      throw error.inside(path);
    }
    return plane;
  }
  if (value.is_object() && !value.contains("center")) {
    throw InputError("must be a sphere {\"center\", \"radius\"} or a plane {\"normal\", \"offset\"}", path);
  }
  return sphere(value, path);
}

Interpolation interpolation(const Json& value, const std::string& path) {
  if (value == "lorentz") return Interpolation::lorentz;
  if (value == "linear") return Interpolation::linear;
  throw InputError(fmt::format("unknown interpolation {} (supported: \"lorentz\", \"linear\")", shown(value)), path);
}

int sample_count(const Json& value, const std::string& path) {
  const double count = number(value, path);
  if (count != std::floor(count) || count < 2 || count > max_canal_samples) {
    throw InputError(fmt::format("must be an integer from 2 to {}, got {}", max_canal_samples, shown(value)), path);
  }
  return int(count);
}

CanalInput read_input(const Json& document) {
  if (!document.is_object()) throw InputError("the document must be an object {\"spheres\": [...], ...}, got " + shown(document));
  allow_only(document, "", {"spheres", "interpolation", "pole", "samples"});
  CanalInput input;
  const Json& spheres = field(document, "", "spheres");
  if (!spheres.is_array()) throw InputError("must be an array of spheres, got " + shown(spheres), "spheres");
  for (std::size_t k = 0; k < spheres.size(); ++k) input.spheres.push_back(sphere(spheres[k], fmt::format("spheres[{}]", k)));
  if (input.spheres.size() < 2) {
    throw InputError(fmt::format("at least 2 spheres are needed, got {}", input.spheres.size()), "spheres");
  }
  input.interpolation = interpolation(field(document, "", "interpolation"), "interpolation");
  const auto pole_value = document.find("pole");
  if (input.interpolation == Interpolation::lorentz) {
    if (pole_value == document.end()) throw InputError("missing field \"pole\" (the lorentz interpolation needs a pole)");
    input.pole = pole(*pole_value, "pole");
  } else if (pole_value != document.end()) {
    throw InputError("unknown field \"pole\" for the linear interpolation (it has no pole)");
  }
  input.samples = sample_count(field(document, "", "samples"), "samples");
  return input;
}

/// The frame the family is computed in: x_local = (x − origin) / scale, the
/// origin the centre of the spheres' bounding box, the scale a power of two
/// near their size (centres' spread and radii), so scaling is exact. The
/// Lorentz tolerances (sphere_interpolation.hpp, characteristic_circle.hpp)
/// are relative to the Euclidean norm of the ℝ⁵ vectors, about |c|²/|r|: in
/// world coordinates, spheres of radius 0.3 at 1e4 from the origin made a
/// pole 7 away pass for tangent. Translations and homotheties are Möbius
/// maps, linear on ℝ⁵ and preserving L, so the family and its circles are
/// the same in either frame but for rounding.
struct LocalFrame {
  Vector3<double> origin;
  double scale;

  explicit LocalFrame(const std::vector<Sphere<double>>& spheres) {
    Vector3<double> low = spheres.front().center, high = low;
    double size = 0.0;
    for (const Sphere<double>& s : spheres) {
      low = low.cwiseMin(s.center);
      high = high.cwiseMax(s.center);
      size = std::max(size, std::abs(s.radius));
    }
    origin = 0.5 * (low + high);
    size = std::max(size, 0.5 * (high - low).maxCoeff());
    scale = std::exp2(std::round(std::log2(size)));  // size > 0: every radius is non-zero
  }

  Sphere<double> to_local(const Sphere<double>& s) const { return {(s.center - origin) / scale, s.radius / scale}; }
  /// n·x = d becomes n·x_local = (d − n·origin) / scale.
  Plane<double> to_local(const Plane<double>& p) const {
    return {p.normal, (p.offset - p.normal.dot(origin)) / scale};
  }
  Vector3<double> to_world(const Vector3<double>& p) const { return origin + scale * p; }
  FamilySample<double> to_world(FamilySample<double> sample) const {
    sample.sphere = {to_world(sample.sphere.center), scale * sample.sphere.radius};
    if (sample.circle) {
      sample.circle->center = to_world(sample.circle->center);
      sample.circle->radius *= scale;
    }
    return sample;
  }
};

void append_point(std::string& text, const Vector3<double>& p) {
  fmt::format_to(std::back_inserter(text), "[{:.17g}, {:.17g}, {:.17g}]", p.x(), p.y(), p.z());
}

}  // namespace

CanalInput parse_canal_json(std::string_view json_text) { return read_input(parse_document(json_text)); }

CanalInput load_canal_file(const std::filesystem::path& path) {
  const std::string contents = read_text_file(path, "canal file");
  try {
    return parse_canal_json(contents);
  } catch (const InputError& error) {
    throw InputError(error.what(), path.string());
  }
}

std::vector<FamilySample<double>> sample_canal(const CanalInput& input) {
  const auto t_of = [&input](int j) { return double(j) / double(input.samples - 1); };
  if (input.spheres.empty()) throw InputError("at least 2 spheres are needed, got 0", "spheres");
  const LocalFrame frame(input.spheres);
  std::vector<Sphere<double>> local;
  for (const Sphere<double>& sphere : input.spheres) local.push_back(frame.to_local(sphere));
  std::vector<FamilySample<double>> samples;
  if (input.interpolation == Interpolation::linear) {
    const LinearSphereFamily<double> family(local);
    for (int j = 0; j < input.samples; ++j) samples.push_back(frame.to_world(family.sample(t_of(j))));
    return samples;
  }
  std::vector<Vector5<double>> spheres;
  for (const Sphere<double>& sphere : local) spheres.push_back(sphere_vector(sphere));
  const Vector5<double> pole =
      std::visit([&frame](const auto& p) {
        if constexpr (std::is_same_v<std::decay_t<decltype(p)>, Plane<double>>) return plane_vector(frame.to_local(p));
        else return sphere_vector(frame.to_local(p));
      }, *input.pole);
  const SphereInterpolation<double> family(spheres, pole);
  const long long pieces = (long long)input.spheres.size() - 1, steps = input.samples - 1;
  for (int j = 0; j < input.samples; ++j) {
    samples.push_back(frame.to_world(sample_family(family, t_of(j))));
    // At a knot, the input sphere itself (its round trip through ℝ⁵ would
    // change the last digits of the centre and radius).
    if (j * pieces % steps == 0) samples.back().sphere = input.spheres[std::size_t(j * pieces / steps)];
  }
  return samples;
}

std::string canal_samples_json(const std::vector<FamilySample<double>>& samples) {
  std::string text = "{\"samples\": [\n";
  for (std::size_t j = 0; j < samples.size(); ++j) {
    const FamilySample<double>& sample = samples[j];
    fmt::format_to(std::back_inserter(text), "  {{\"t\": {:.17g}, \"sphere\": {{\"center\": ", sample.t);
    append_point(text, sample.sphere.center);
    fmt::format_to(std::back_inserter(text), ", \"radius\": {:.17g}}}, \"circle\": ", sample.sphere.radius);
    if (sample.circle) {
      text += "{\"center\": ";
      append_point(text, sample.circle->center);
      fmt::format_to(std::back_inserter(text), ", \"radius\": {:.17g}, \"normal\": ", sample.circle->radius);
      append_point(text, sample.circle->normal);
      text += "}";
    } else {
      text += "null";
    }
    text += j + 1 < samples.size() ? "},\n" : "}\n";
  }
  return text + "]}\n";
}

}  // namespace skelconv::canal
