// Implementation of skelconv/mesh/mesh_reader.hpp.
#include "skelconv/mesh/mesh_reader.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "skelconv/errors.hpp"
#include "skelconv/skeleton/text_file.hpp"

namespace skelconv {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

/// `word` as a finite number, or InputError at `at` ("… is not a finite number").
double finite_number(const std::string& word, const std::string& at) {
  char* end = nullptr;
  const double value = std::strtod(word.c_str(), &end);
  if (word.empty() || *end != '\0' || !std::isfinite(value))
    throw InputError("\"" + word + "\" is not a finite number", at);
  return value;
}

/// The refusal of a mesh beyond the caller's limit (read_mesh's max_triangles).
InputError too_many_triangles(std::size_t max_triangles, const std::string& where) {
  return InputError(fmt::format("the mesh has more than {} triangles, the limit (--max-triangles): raise "
                                "--max-triangles if the time and memory are there",
                                max_triangles),
                    where);
}

/// The corners of a polygon in its plane: 2-D coordinates in which its
/// outline runs counterclockwise (about Newell's normal, the polygon's
/// vector area, which a non-planar or non-convex polygon also has).
std::vector<std::array<double, 2>> polygon_in_its_plane(const TriangleMesh& mesh, const std::vector<std::int64_t>& face) {
  Vec3 normal = Vec3::Zero();
  for (std::size_t k = 0; k < face.size(); ++k)
    normal += mesh.vertices[std::size_t(face[k])].cross(mesh.vertices[std::size_t(face[(k + 1) % face.size()])]);
  const Vec3 n = normal.norm() > 0 ? Vec3(normal.normalized()) : Vec3::UnitZ();
  const Vec3 u = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
  const Vec3 w = n.cross(u);
  std::vector<std::array<double, 2>> q(face.size());
  for (std::size_t k = 0; k < face.size(); ++k) {
    const Vec3& p = mesh.vertices[std::size_t(face[k])];
    q[k] = {p.dot(u), p.dot(w)};
  }
  return q;
}

/// Twice the signed area of the plane triangle (a, b, c): positive when it
/// turns counterclockwise, 0 when its corners are on a line.
double turn(const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/// The sine of the smallest angle that is told from a straight line: corners
/// on a line in space come out of the projection into the plane a rounding
/// error off it, and a triangle of them would have zero area in the mesh.
constexpr double min_sine = 1e-9;

/// Whether (a, b, c) turns counterclockwise by more than rounding (the sine
/// of its angle at a above min_sine).
bool turns_left(const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c) {
  return turn(a, b, c) > min_sine * std::hypot(b[0] - a[0], b[1] - a[1]) * std::hypot(c[0] - a[0], c[1] - a[1]);
}

/// Whether p lies in the triangle (a, b, c) (counterclockwise) or within
/// rounding of it: a corner on an ear's edge blocks the ear as one inside
/// it does, else cutting the ear would leave the rest folded along that edge.
bool in_or_on(const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c,
              const std::array<double, 2>& p) {
  const auto beside = [](const std::array<double, 2>& u, const std::array<double, 2>& v, const std::array<double, 2>& x) {
    return turn(u, v, x) >= -min_sine * std::hypot(v[0] - u[0], v[1] - u[1]) * std::hypot(x[0] - u[0], x[1] - u[1]);
  };
  return beside(a, b, p) && beside(b, c, p) && beside(c, a, p);
}

/// Adds a triangulation of polygon `face` (0-based indices of mesh's
/// vertices); throws too_many_triangles when the mesh would then hold more
/// than max_triangles.
///
/// The fan from the first corner where it is valid (every convex polygon:
/// the triangles (face[0], face[k], face[k + 1])); otherwise ear clipping
/// in the polygon's plane, which cuts off a corner only where its triangle
/// turns the outline's way with no other corner in it or on it. A fan
/// would fold over a non-convex polygon (a letter's outline) and leave a
/// triangle of zero area where three corners lie on a line, and the input
/// checks would then refuse a mesh the file describes correctly. Where no
/// such corner is left (an outline that crosses itself), the rest is
/// fanned, and the checks say what is wrong with it.
void add_polygon(TriangleMesh& mesh, const std::vector<std::int64_t>& face, std::size_t max_triangles,
                 const std::string& where) {
  if (face.size() >= 3 && face.size() - 2 > max_triangles - std::min(max_triangles, mesh.triangles.size()))
    throw too_many_triangles(max_triangles, where);
  const auto add = [&mesh](std::int64_t a, std::int64_t b, std::int64_t c) {
    mesh.triangles.push_back({std::int32_t(a), std::int32_t(b), std::int32_t(c)});
  };
  const auto fan = [&add](const std::vector<std::int64_t>& corners) {
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) add(corners[0], corners[k], corners[k + 1]);
  };
  // Ear clipping costs a test of every corner per ear; beyond this many
  // corners (no file seen has them) the fan is kept.
  constexpr std::size_t max_clipped_corners = 2000;
  if (face.size() == 3 || face.size() > max_clipped_corners) return fan(face);
  const std::vector<std::array<double, 2>> q = polygon_in_its_plane(mesh, face);
  // Convex and winding once (every corner turns left, the turns adding up
  // to one full turn): the fan is valid.
  bool convex = true;
  double winding = 0.0;
  for (std::size_t k = 0; k < q.size() && convex; ++k) {
    const auto& a = q[(k + q.size() - 1) % q.size()];
    const auto& b = q[k];
    const auto& c = q[(k + 1) % q.size()];
    convex = turns_left(a, b, c);
    winding += std::atan2(turn(a, b, c), (b[0] - a[0]) * (c[0] - b[0]) + (b[1] - a[1]) * (c[1] - b[1]));
  }
  constexpr double winding_tolerance = 1e-6;  // radians: rounding only
  if (convex && std::abs(winding - 2 * M_PI) < winding_tolerance) return fan(face);

  std::vector<std::size_t> left(face.size());  // positions in face of the corners not yet cut off
  for (std::size_t k = 0; k < left.size(); ++k) left[k] = k;
  const auto same_position = [&](std::size_t i, std::size_t j) {
    return mesh.vertices[std::size_t(face[i])] == mesh.vertices[std::size_t(face[j])];
  };
  const auto is_ear = [&](std::size_t at) {
    const std::size_t m = left.size();
    const std::size_t a = left[(at + m - 1) % m], b = left[at], c = left[(at + 1) % m];
    if (!turns_left(q[a], q[b], q[c])) return false;
    for (const std::size_t k : left) {
      if (k == a || k == b || k == c || same_position(k, a) || same_position(k, b) || same_position(k, c)) continue;
      if (in_or_on(q[a], q[b], q[c], q[k])) return false;
    }
    return true;
  };
  while (left.size() > 3) {
    // The corner after the first first, as the fan would cut it.
    std::size_t at = 1;
    while (at <= left.size() && !is_ear(at % left.size())) ++at;
    if (at > left.size()) {
      std::vector<std::int64_t> rest;
      for (const std::size_t k : left) rest.push_back(face[k]);
      return fan(rest);
    }
    at %= left.size();
    add(face[left[(at + left.size() - 1) % left.size()]], face[left[at]], face[left[(at + 1) % left.size()]]);
    left.erase(left.begin() + std::ptrdiff_t(at));
  }
  add(face[left[0]], face[left[1]], face[left[2]]);
}

// ---------------------------------------------------------------- PLY ---

enum class PlyFormat { ascii, little, big };

struct PlyProperty {
  std::string name;
  std::string type;        ///< scalar type, or the item type of a list
  std::string count_type;  ///< empty unless a list
};

struct PlyElement {
  std::string name;
  std::size_t count = 0;
  std::vector<PlyProperty> properties;
};

std::size_t ply_type_size(const std::string& type, const std::string& where) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  throw InputError("unknown PLY property type \"" + type + "\"", where);
}

/// The values a PLY integer type holds.
struct IntegerRange {
  std::int64_t lo, hi;
};

/// The range of an integer PLY type, or nothing for float and double.
std::optional<IntegerRange> ply_integer_range(const std::string& type) {
  if (type == "char" || type == "int8") return IntegerRange{INT8_MIN, INT8_MAX};
  if (type == "uchar" || type == "uint8") return IntegerRange{0, UINT8_MAX};
  if (type == "short" || type == "int16") return IntegerRange{INT16_MIN, INT16_MAX};
  if (type == "ushort" || type == "uint16") return IntegerRange{0, UINT16_MAX};
  if (type == "int" || type == "int32") return IntegerRange{INT32_MIN, INT32_MAX};
  if (type == "uint" || type == "uint32") return IntegerRange{0, UINT32_MAX};
  return std::nullopt;
}

/// Reads the PLY scalars of the body, ASCII words or binary values. ASCII
/// errors name the line (counted from the file's first), binary ones the
/// byte offset.
class PlyBody {
 public:
  PlyBody(const std::string& bytes, std::size_t start, int start_line, PlyFormat format, std::string where)
      : bytes_(bytes), position_(start), line_(start_line), format_(format), where_(std::move(where)) {}

  double next(const std::string& type) {
    if (format_ == PlyFormat::ascii) {
      const std::string word = next_word();
      if (word.empty()) throw InputError("the PLY body ends early", where_);
      if (const std::optional<IntegerRange> range = ply_integer_range(type)) return integer(word, type, *range);
      try {
        std::size_t used = 0;
        const double value = std::stod(word, &used);
        if (used == word.size()) return value;
      } catch (const std::exception&) {
      }
      throw InputError("\"" + word + "\" is not a number in the PLY body", at());
    }
    const std::size_t size = ply_type_size(type, where_);
    if (position_ + size > bytes_.size()) throw InputError("the PLY body ends early", where_);
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + position_, size);
    position_ += size;
    const bool swap = (format_ == PlyFormat::big) == (std::endian::native == std::endian::little);
    if (swap) std::reverse(raw, raw + size);
    return decode(raw, type);
  }

  /// Refuses anything after the last element but white space (ASCII): a
  /// body longer than its header declares was cut short by a wrong count,
  /// or holds another mesh, and would be read as part of one silently.
  void expect_end() {
    if (format_ == PlyFormat::ascii) {
      const std::string word = next_word();
      if (!word.empty())
        throw InputError("\"" + word + "\" after the last element the header declares (more data than its counts)",
                         at());
      return;
    }
    if (position_ < bytes_.size())
      throw InputError(fmt::format("{} bytes after the last element the header declares (more data than its counts)",
                                   bytes_.size() - position_),
                       where_);
  }

  /// "FILE: line N", the line of the last word read (ASCII).
  std::string at() const { return fmt::format("{}: line {}", where_, word_line_); }

 private:
  /// The next white-space separated word of an ASCII body, or "" at its end.
  std::string next_word() {
    while (position_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[position_]))) {
      if (bytes_[position_] == '\n') ++line_;
      ++position_;
    }
    const std::size_t start = position_;
    while (position_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[position_]))) ++position_;
    word_line_ = line_;
    return bytes_.substr(start, position_ - start);
  }

  /// An ASCII word of an integer property: whole-number text within the
  /// declared type's range. "2.5" or "1e3" for an int, or 300 for a uchar,
  /// would otherwise be read as a different number than the file's writer
  /// could have stored (a binary file of that header cannot hold it).
  double integer(const std::string& word, const std::string& type, const IntegerRange& range) const {
    std::size_t digits = word[0] == '+' || word[0] == '-' ? 1 : 0;
    const bool whole = digits < word.size() && std::all_of(word.begin() + std::ptrdiff_t(digits), word.end(),
                                                           [](unsigned char c) { return std::isdigit(c) != 0; });
    if (!whole)
      throw InputError(fmt::format("\"{}\" is not a whole number, but the property's type is {}", word, type), at());
    // Past 19 digits strtold still orders the value right against the range.
    const long double value = std::strtold(word.c_str(), nullptr);
    if (value < static_cast<long double>(range.lo) || value > static_cast<long double>(range.hi))
      throw InputError(fmt::format("{} is outside the range of the property's type {} ([{}, {}])", word, type,
                                   range.lo, range.hi),
                       at());
    return static_cast<double>(value);
  }

  static double decode(const unsigned char* raw, const std::string& type) {
    const auto get = [raw](auto value) {
      std::memcpy(&value, raw, sizeof value);
      return double(value);
    };
    if (type == "char" || type == "int8") return get(std::int8_t{});
    if (type == "uchar" || type == "uint8") return get(std::uint8_t{});
    if (type == "short" || type == "int16") return get(std::int16_t{});
    if (type == "ushort" || type == "uint16") return get(std::uint16_t{});
    if (type == "int" || type == "int32") return get(std::int32_t{});
    if (type == "uint" || type == "uint32") return get(std::uint32_t{});
    if (type == "float" || type == "float32") return get(float{});
    return get(double{});
  }

  const std::string& bytes_;
  std::size_t position_;
  int line_;           ///< the line at position_ (ASCII)
  int word_line_ = 0;  ///< the line of the last word read (ASCII)
  PlyFormat format_;
  std::string where_;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::ascii;
  std::vector<PlyElement> elements;
  std::size_t body_start = 0;
  int body_line = 0;  ///< the line the body starts on (ASCII)
};

PlyHeader parse_ply_header(const std::string& bytes, const std::string& where) {
  PlyHeader header;
  std::size_t position = 0;
  int line_number = 0;
  bool have_format = false;
  while (true) {
    const std::size_t end = bytes.find('\n', position);
    if (end == std::string::npos) throw InputError("the PLY header has no end_header line", where);
    std::string line = bytes.substr(position, end - position);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    position = end + 1;
    ++line_number;
    const std::string at = fmt::format("{}: line {}", where, line_number);
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (line_number == 1) {
      if (keyword != "ply") throw InputError("not a PLY file (the first line is not \"ply\")", at);
    } else if (keyword == "format") {
      std::string name;
      words >> name;
      if (name == "ascii") header.format = PlyFormat::ascii;
      else if (name == "binary_little_endian") header.format = PlyFormat::little;
      else if (name == "binary_big_endian") header.format = PlyFormat::big;
      else throw InputError("unknown PLY format \"" + name + "\"", at);
      have_format = true;
    } else if (keyword == "element") {
      PlyElement element;
      long long count = -1;
      std::string extra;
      // "element vertex 4e3" would read 4 and leave "e3" unread.
      if (!(words >> element.name >> count) || count < 0 || words >> extra)
        throw InputError("malformed element line (expected \"element NAME COUNT\")", at);
      element.count = std::size_t(count);
      header.elements.push_back(element);
    } else if (keyword == "property") {
      if (header.elements.empty()) throw InputError("property before any element", at);
      PlyProperty property;
      std::string type;
      words >> type;
      if (type == "list") {
        words >> property.count_type >> property.type;
        ply_type_size(property.count_type, at);
      }
      else property.type = type;
      ply_type_size(property.type, at);
      if (!(words >> property.name)) throw InputError("malformed property line", at);
      header.elements.back().properties.push_back(property);
    } else if (keyword == "end_header") {
      if (!have_format) throw InputError("the PLY header has no format line", at);
      header.body_start = position;
      header.body_line = line_number + 1;
      return header;
    } else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty()) {
      throw InputError("unknown PLY header keyword \"" + keyword + "\"", at);
    }
  }
}

/// Index of the property named one of `names` in `element`, or -1.
int find_property(const PlyElement& element, std::initializer_list<const char*> names) {
  for (std::size_t k = 0; k < element.properties.size(); ++k) {
    for (const char* name : names) {
      if (element.properties[k].name == name) return int(k);
    }
  }
  return -1;
}

void read_ply_element(const PlyElement& element, PlyBody& body, TriangleMesh& mesh, std::size_t max_triangles,
                      const std::string& where) {
  const bool is_vertex = element.name == "vertex";
  const bool is_face = element.name == "face";
  const int x = find_property(element, {"x"}), y = find_property(element, {"y"}), z = find_property(element, {"z"});
  const int indices = find_property(element, {"vertex_indices", "vertex_index"});
  if (is_vertex && (x < 0 || y < 0 || z < 0)) throw InputError("the vertex element lacks x, y or z", where);
  // An element without properties holds no bytes, whatever its count: there
  // is nothing to read (looping over a count of 10^14 would never end).
  if (element.properties.empty()) return;
  std::vector<double> values;  // one list property's entries
  std::vector<std::int64_t> face;
  for (std::size_t item = 0; item < element.count; ++item) {
    Vec3 point = Vec3::Zero();
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const PlyProperty& property = element.properties[p];
      if (property.count_type.empty()) {
        const double value = body.next(property.type);
        if (is_vertex && (int(p) == x || int(p) == y || int(p) == z)) point[int(p) == x ? 0 : int(p) == y ? 1 : 2] = value;
        continue;
      }
      const double count = body.next(property.count_type);
      if (!(count >= 0 && count < 1e6)) throw InputError(fmt::format("{} {}: bad list length", element.name, item), where);
      values.resize(std::size_t(count));
      for (double& value : values) value = body.next(property.type);
      if (!(is_face && int(p) == indices)) continue;
      // Checked as doubles, before the conversion: a float property can hold
      // 1e58 or NaN, whose conversion to an integer is undefined.
      face.clear();
      for (const double value : values) {
        if (!(value >= 0 && value < double(mesh.vertices.size())))
          throw InputError(fmt::format("face {} has vertex index {} outside [0, {})", item, value, mesh.vertices.size()),
                           where);
        // A float list can hold 2.5: no vertex of its own, not to be
        // truncated into vertex 2.
        if (value != std::floor(value))
          throw InputError(fmt::format("face {} has vertex index {}, not a whole number", item, value), where);
        face.push_back(std::int64_t(value));
      }
      // As the OBJ and OFF readers: a face of 1 or 2 corners is no
      // triangle, and dropping it silently could hide a hole.
      if (face.size() < 3)
        throw InputError(fmt::format("face {} has {} corners, a face needs at least 3", item, face.size()), where);
      add_polygon(mesh, face, max_triangles, where);
    }
    if (is_vertex) {
      if (!point.allFinite()) throw InputError(fmt::format("vertex {} is not finite", item), where);
      mesh.vertices.push_back(point);
    }
  }
}

TriangleMesh read_ply(const std::string& bytes, std::size_t max_triangles, const std::string& where) {
  const PlyHeader header = parse_ply_header(bytes, where);
  // Every face of at least three corners makes at least one triangle: a
  // header declaring more faces than the limit is refused before its body.
  for (const PlyElement& element : header.elements) {
    if (element.name == "face" && element.count > max_triangles) {
      throw InputError(fmt::format("the PLY header declares {} faces, more than the limit of {} triangles "
                                   "(--max-triangles): raise --max-triangles if the time and memory are there",
                                   element.count, max_triangles),
                       where);
    }
  }
  PlyBody body(bytes, header.body_start, header.body_line, header.format, where);
  TriangleMesh mesh;
  bool vertices_read = false;
  for (const PlyElement& element : header.elements) {
    if (element.name == "face" && !vertices_read)
      throw InputError("the face element comes before the vertex element", where);
    read_ply_element(element, body, mesh, max_triangles, where);
    vertices_read = vertices_read || element.name == "vertex";
  }
  body.expect_end();
  return mesh;
}

// ---------------------------------------------------------------- OBJ ---

/// One OBJ face corner "i", "i/t", "i//n" or "i/t/n" → 0-based vertex index.
std::int64_t obj_index(const std::string& corner, std::size_t vertex_count, const std::string& at) {
  const std::string head = corner.substr(0, corner.find('/'));
  long long index = 0;
  std::size_t used = 0;
  try {
    index = std::stoll(head, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != head.size()) throw InputError("bad face corner \"" + corner + "\"", at);
  const long long resolved = index < 0 ? (long long)vertex_count + index : index - 1;
  if (index == 0 || resolved < 0 || resolved >= (long long)vertex_count)
    throw InputError(fmt::format("face index {} outside [1, {}]", index, vertex_count), at);
  return resolved;
}

/// OBJ statements that say nothing about the surface's shape: normals,
/// texture and parameter-space vertices, grouping, smoothing, materials and
/// display attributes. Their lines are skipped.
bool obj_ignored_statement(const std::string& keyword) {
  static constexpr const char* ignored[] = {"vn",     "vt",       "vp",       "g",          "o",          "s",
                                            "mg",     "usemtl",   "mtllib",   "usemap",     "maplib",     "lod",
                                            "bevel",  "c_interp", "d_interp", "shadow_obj", "trace_obj", "ctech",
                                            "stech"};
  return std::find(std::begin(ignored), std::end(ignored), keyword) != std::end(ignored);
}

/// OBJ statements of geometry other than polygonal faces: points, lines and
/// free-form curves and surfaces. Skipping them would drop part of what the
/// file describes without a word, so they are refused.
bool obj_unsupported_geometry(const std::string& keyword) {
  static constexpr const char* geometry[] = {"p",    "l",   "cstype", "deg",  "bmat", "step", "curv", "curv2",
                                             "surf", "parm", "trim",  "hole", "scrv", "sp",   "end",  "con"};
  return std::find(std::begin(geometry), std::end(geometry), keyword) != std::end(geometry);
}

/// OBJ: "v x y z" (then optionally w, or an r g b colour, as some exporters
/// write) and "f i j k ..." lines, `#` comments (also at the end of a line),
/// the statements of obj_ignored_statement skipped. Anything else is refused
/// at its line: a binary file renamed .obj, a typo ("vv"), or geometry this
/// reader does not take would otherwise be read as a smaller mesh silently.
TriangleMesh read_obj(const std::string& text, std::size_t max_triangles, const std::string& where) {
  TriangleMesh mesh;
  std::istringstream lines(text);
  std::string line;
  std::vector<std::int64_t> face;
  for (int line_number = 1; std::getline(lines, line); ++line_number) {
    const std::string at = fmt::format("{}: line {}", where, line_number);
    std::istringstream words(line.substr(0, line.find('#')));
    std::string keyword;
    words >> keyword;
    if (keyword == "v") {
      Vec3 point;
      std::string word[3];
      if (!(words >> word[0] >> word[1] >> word[2])) throw InputError("a vertex needs x y z", at);
      for (int k = 0; k < 3; ++k) point[k] = finite_number(word[k], at);
      int extra = 0;
      for (std::string rest; words >> rest; ++extra) finite_number(rest, at);
      if (extra != 0 && extra != 1 && extra != 3 && extra != 4)
        throw InputError(fmt::format("a vertex has {} numbers: expected x y z, optionally followed by w or by a "
                                     "colour r g b",
                                     3 + extra),
                         at);
      mesh.vertices.push_back(point);
    } else if (keyword == "f") {
      face.clear();
      for (std::string corner; words >> corner;) face.push_back(obj_index(corner, mesh.vertices.size(), at));
      if (face.size() < 3) throw InputError("a face needs at least 3 corners", at);
      add_polygon(mesh, face, max_triangles, at);
    } else if (obj_unsupported_geometry(keyword)) {
      throw InputError("\"" + keyword + "\" (point, line or free-form geometry) is not supported: the mesh must be "
                       "made of polygonal faces (\"f\")",
                       at);
    } else if (!keyword.empty() && !obj_ignored_statement(keyword)) {
      throw InputError(fmt::format("unknown OBJ statement \"{}\" (expected v, f, a comment, or one of vn, vt, "
                                   "vp, g, o, s, usemtl, mtllib)",
                                   keyword.size() > 40 ? keyword.substr(0, 40) + "..." : keyword),
                       at);
    }
  }
  return mesh;
}


// ---------------------------------------------------------------- OFF ---

/// The next number of an OFF file, skipping `#` comments to the end of a
/// line; `what` names it in the message when it is missing or malformed.
class OffWords {
 public:
  OffWords(const std::string& text, std::string where) : where_(std::move(where)) {
    std::istringstream lines(text);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
      std::istringstream words(line.substr(0, line.find('#')));
      for (std::string word; words >> word;) words_.push_back({word, number});
    }
  }
  bool done() const { return next_ >= words_.size(); }
  std::string word(const std::string& what) {
    if (done()) throw InputError("the file ends before " + what, where_);
    return words_[next_++].text;
  }
  double number(const std::string& what) {
    const std::string text = word(what);
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (*end != '\0' || !std::isfinite(value))
      throw InputError("\"" + text + "\" is not a finite number (" + what + ")", at());
    return value;
  }
  std::int64_t count(const std::string& what) {
    const double value = number(what);
    if (!(value >= 0.0 && value < 1e9 && value == std::floor(value)))
      throw InputError(fmt::format("{} must be a whole number ≥ 0, got {}", what, value), at());
    return static_cast<std::int64_t>(value);
  }
  std::string at() const { return fmt::format("{}: line {}", where_, words_[next_ - 1].line); }
  std::size_t words_left() const { return words_.size() - next_; }
  /// Skips the rest of the line of the last word read (a colour).
  void skip_rest_of_line() {
    while (!done() && words_[next_].line == words_[next_ - 1].line) ++next_;
  }

 private:
  struct Word {
    std::string text;
    int line;
  };
  std::vector<Word> words_;
  std::size_t next_ = 0;
  std::string where_;
};

/// Whether `keyword` is Geomview's OFF keyword for 3-D vertices: "OFF"
/// after any of the prefixes "ST" (texture coordinates), "C" (a colour) and
/// "N" (a normal) that say what follows x y z on a vertex's line (NOFF is
/// what CGAL and MeshLab write with normals). "4" and "n" (4-D and n-D
/// vertices) are not 3-D surfaces.
bool is_off_keyword(std::string_view keyword) {
  if (!keyword.ends_with("OFF")) return false;
  keyword.remove_suffix(3);
  if (keyword.starts_with("ST")) keyword.remove_prefix(2);
  if (keyword.starts_with("C")) keyword.remove_prefix(1);
  if (keyword.starts_with("N")) keyword.remove_prefix(1);
  return keyword.empty();
}

/// OFF (Geomview): "OFF" (or "COFF", "NOFF", "STCNOFF"...), then the
/// vertex, face and edge counts, one vertex "x y z" per line, one face "n
/// i0 … i(n−1)" (0-based) per line; what follows on a vertex's or a face's
/// line (a normal, a colour, texture coordinates) is ignored.
TriangleMesh read_off(const std::string& text, std::size_t max_triangles, const std::string& where) {
  OffWords words(text, where);
  std::string keyword = words.word("the OFF keyword");
  if (!is_off_keyword(keyword))
    throw InputError("an OFF file starts with \"OFF\" (or \"COFF\", \"NOFF\", \"STOFF\": 3-D vertices), got \"" +
                         keyword + "\"",
                     words.at());
  const std::int64_t vertex_count = words.count("the vertex count");
  const std::int64_t face_count = words.count("the face count");
  words.count("the edge count");
  if (static_cast<double>(face_count) > static_cast<double>(max_triangles)) throw too_many_triangles(max_triangles, words.at());
  TriangleMesh mesh;
  // Room for the vertices the file can hold (three words each), not for
  // what a header claims: a count of 10^8 over a short body is refused at
  // its end, after reading what is there, not after reserving gigabytes.
  mesh.vertices.reserve(std::min(static_cast<std::size_t>(vertex_count), words.words_left() / 3));
  for (std::int64_t v = 0; v < vertex_count; ++v) {
    const std::string what = fmt::format("vertex {}", v);
    Vec3 point;
    for (int k = 0; k < 3; ++k) point[k] = words.number(what);
    words.skip_rest_of_line();
    mesh.vertices.push_back(point);
  }
  std::vector<std::int64_t> face;
  for (std::int64_t f = 0; f < face_count; ++f) {
    const std::string what = fmt::format("face {}", f);
    const std::int64_t corners = words.count(what + "'s corner count");
    if (corners < 3) throw InputError(what + " needs at least 3 corners", words.at());
    face.clear();
    for (std::int64_t k = 0; k < corners; ++k) {
      const std::int64_t index = words.count(what + "'s corner");
      if (index >= vertex_count)
        throw InputError(fmt::format("{} has vertex index {} outside [0, {})", what, index, vertex_count), words.at());
      face.push_back(index);
    }
    add_polygon(mesh, face, max_triangles, words.at());
    words.skip_rest_of_line();
  }
  // More than the counts declare: a wrong count, whose rest would be
  // ignored silently (as a PLY body's, read_ply).
  if (!words.done())
    throw InputError(fmt::format("\"{}\" after the last face the header declares (more data than its counts)",
                                 words.word("")),
                     words.at());
  return mesh;
}


// ---------------------------------------------------------------- STL ---

/// Adds one STL facet's three corners as new vertices (STL stores no shared
/// vertices: the consumer merges coincident ones where it needs a closed
/// surface, as reconstruct::merge_coincident_vertices does).
void add_stl_facet(TriangleMesh& mesh, const std::array<Vec3, 3>& corners, std::size_t max_triangles,
                   const std::string& where) {
  if (mesh.triangles.size() >= max_triangles) throw too_many_triangles(max_triangles, where);
  const auto first = std::int32_t(mesh.vertices.size());
  for (const Vec3& corner : corners) {
    if (!corner.allFinite()) throw InputError("a vertex is not finite", where);
    mesh.vertices.push_back(corner);
  }
  mesh.triangles.push_back({first, first + 1, first + 2});
}

/// Binary STL: an 80-byte header, a little-endian uint32 facet count, then
/// 50 bytes a facet (normal, three corners: twelve float32; two attribute
/// bytes). Chosen when the file's size is exactly 84 + 50 × count: ASCII
/// files start with "solid", but so do many binary headers.
bool is_binary_stl(const std::string& bytes) {
  if (bytes.size() < 84) return false;
  std::uint32_t count = 0;
  for (int k = 3; k >= 0; --k) count = count << 8 | std::uint8_t(bytes[80 + std::size_t(k)]);
  return bytes.size() == 84 + 50 * std::uint64_t(count);
}

/// Whether `bytes` holds a NUL byte, which no text file has and a binary
/// STL all but always does (each facet ends in two attribute bytes, zero
/// unless an exporter stores colours there, and a coordinate or normal
/// component 0 is four). Used only to name the problem of an STL file of
/// neither form: a binary one cut short or padded would otherwise be read
/// as ASCII text and fail at its first word.
bool looks_binary(const std::string& bytes) { return bytes.find('\0') != std::string::npos; }

/// The message for a file that looks binary but whose size is not the
/// 84 + 50 × count that its facet count gives.
InputError binary_stl_size_error(const std::string& bytes, const std::string& where) {
  std::uint32_t count = 0;
  for (int k = 3; k >= 0; --k) count = count << 8 | std::uint8_t(bytes[80 + std::size_t(k)]);
  return InputError(fmt::format("a binary STL file whose size does not match its facet count: bytes 80 to 83 say "
                                "{} facets, 84 + 50 × {} = {} bytes, but the file has {} bytes (cut short, or "
                                "bytes after the last facet)",
                                count, count, 84 + 50 * std::uint64_t(count), bytes.size()),
                    where);
}

float little_endian_float(const char* p) {
  std::uint32_t bits = 0;
  for (int k = 3; k >= 0; --k) bits = bits << 8 | std::uint8_t(p[k]);
  return std::bit_cast<float>(bits);
}

TriangleMesh read_binary_stl(const std::string& bytes, std::size_t max_triangles, const std::string& where) {
  const std::size_t count = (bytes.size() - 84) / 50;
  if (count > max_triangles) throw too_many_triangles(max_triangles, where);
  TriangleMesh mesh;
  mesh.vertices.reserve(3 * count);
  mesh.triangles.reserve(count);
  for (std::size_t f = 0; f < count; ++f) {
    const char* facet = bytes.data() + 84 + 50 * f + 12;  // past the normal
    std::array<Vec3, 3> corners;
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) corners[std::size_t(c)][k] = little_endian_float(facet + 12 * c + 4 * k);
    add_stl_facet(mesh, corners, max_triangles, fmt::format("{}: facet {}", where, f));
  }
  return mesh;
}

/// ASCII STL: "solid name", then per facet "facet normal nx ny nz", "outer
/// loop", three "vertex x y z", "endloop", "endfacet"; "endsolid". The
/// normals are ignored (the orientation is the corners' order), as are
/// blank lines; anything else is refused at its line.
TriangleMesh read_ascii_stl(const std::string& text, std::size_t max_triangles, const std::string& where) {
  TriangleMesh mesh;
  std::istringstream lines(text);
  std::string line;
  std::array<Vec3, 3> corners;
  int corner = -1;  // -1: outside a loop
  bool solid = false, ended = false;
  for (int line_number = 1; std::getline(lines, line); ++line_number) {
    const std::string at = fmt::format("{}: line {}", where, line_number);
    std::istringstream words(line);
    std::string written;
    if (!(words >> written)) continue;
    // The keywords are lower case in the format, upper case from some
    // exporters ("SOLID", "FACET NORMAL"): either is read.
    const std::string keyword = lower(written);
    if (ended) throw InputError("text after \"endsolid\"", at);
    if (!solid) {
      if (keyword != "solid") throw InputError("an ASCII STL file starts with \"solid\", got \"" + written + "\"", at);
      solid = true;
    } else if (keyword == "facet" || keyword == "endloop") {
      if (keyword == "endloop" && corner != 3) throw InputError("a loop needs exactly 3 vertices", at);
    } else if (keyword == "outer") {
      corner = 0;
    } else if (keyword == "vertex") {
      if (corner < 0 || corner >= 3) throw InputError("a vertex outside an \"outer loop\" of 3", at);
      Vec3& v = corners[std::size_t(corner++)];
      for (int k = 0; k < 3; ++k) {
        std::string number;
        if (!(words >> number)) throw InputError("a vertex needs x, y and z", at);
        v[k] = finite_number(number, at);
      }
    } else if (keyword == "endfacet") {
      if (corner != 3) throw InputError("a facet needs an \"outer loop\" of 3 vertices", at);
      add_stl_facet(mesh, corners, max_triangles, at);
      corner = -1;
    } else if (keyword == "endsolid") {
      if (corner != -1) throw InputError("\"endsolid\" inside a facet", at);
      ended = true;
    } else {
      throw InputError("unknown STL keyword \"" + written + "\"", at);
    }
  }
  if (!solid) throw InputError("the file is empty: an ASCII STL file starts with \"solid\"", where);
  if (!ended) throw InputError("the file ends before \"endsolid\"", where);
  return mesh;
}

}  // namespace

TriangleMesh read_mesh(const std::filesystem::path& path, std::size_t max_triangles) {
  const std::string extension = lower(path.extension().string());
  if (extension != ".ply" && extension != ".obj" && extension != ".off" && extension != ".stl")
    throw InputError("unknown mesh format \"" + path.extension().string() + "\" (use .ply, .obj, .off or .stl)",
                     path.string());
  const std::string bytes = read_text_file(path, "mesh file");
  if (extension == ".stl") {
    if (is_binary_stl(bytes)) return read_binary_stl(bytes, max_triangles, path.string());
    if (bytes.size() >= 84 && looks_binary(bytes)) throw binary_stl_size_error(bytes, path.string());
    return read_ascii_stl(bytes, max_triangles, path.string());
  }
  if (extension == ".ply") return read_ply(bytes, max_triangles, path.string());
  if (extension == ".off") return read_off(bytes, max_triangles, path.string());
  return read_obj(bytes, max_triangles, path.string());
}

}  // namespace skelconv
