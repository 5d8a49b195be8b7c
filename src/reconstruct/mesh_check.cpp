// Implementation of skelconv/reconstruct/mesh_check.hpp: plain edge counting
// (no CGAL) so that the check costs O(n log n) and compiles fast; the
// self-intersection test, the union that repairs it and the hole filling,
// which need CGAL, are in self_intersection.cpp, join_overlaps.cpp and
// close_holes.cpp.
#include "skelconv/reconstruct/mesh_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "skelconv/errors.hpp"
#include "skelconv/primitives/segment.hpp"
#include "close_holes.hpp"
#include "join_overlaps.hpp"
#include "union_find.hpp"

namespace skelconv::reconstruct {
namespace {

using Edge = std::pair<std::int32_t, std::int32_t>;

/// Triangles with three distinct vertex indices.
std::vector<std::array<std::int32_t, 3>> proper_triangles(const TriangleMesh& mesh) {
  std::vector<std::array<std::int32_t, 3>> out;
  for (const auto& t : mesh.triangles)
    if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) out.push_back(t);
  return out;
}

/// The index in `mesh` of a triangle of proper_triangles(mesh), as a user
/// counts in the file (from 0, the degenerate ones included).
std::size_t mesh_index(const TriangleMesh& mesh, const std::array<std::int32_t, 3>& triangle) {
  return std::size_t(std::find(mesh.triangles.begin(), mesh.triangles.end(), triangle) - mesh.triangles.begin());
}

/// " (e.g. between vertices i and j)": one edge of a problem, so that a user
/// can find it in a viewer (indices count from 0 in the file's order).
std::string example_edge(const Edge& e) {
  return fmt::format(" (e.g. between vertices {} and {}, counted from 0)", e.first, e.second);
}

/// The edges of a triangle list by how many triangles use them: an edge of
/// more than two is non-manifold; of one, a boundary (open); of two in the
/// same direction, inconsistently oriented. One example of each.
struct EdgeCounts {
  std::size_t open = 0, non_manifold = 0, inconsistent = 0;
  Edge first_open{}, first_non_manifold{}, first_inconsistent{};
};

EdgeCounts count_edges(const std::vector<std::array<std::int32_t, 3>>& triangles) {
  std::map<Edge, int> directed;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  EdgeCounts c;
  for (const auto& [e, n] : directed) {
    const auto back = directed.find({e.second, e.first});
    const int reverse = back == directed.end() ? 0 : back->second;
    if (n + reverse > 2) {
      // once per edge: both directions are in the map when both are used
      if (reverse > 0 && e.first > e.second) continue;
      if (c.non_manifold++ == 0) c.first_non_manifold = e;
    } else if (n == 2) {
      if (c.inconsistent++ == 0) c.first_inconsistent = e;
    } else if (reverse == 0) {
      if (c.open++ == 0) c.first_open = e;
    }
  }
  return c;
}

std::string inconsistent_problem(const EdgeCounts& c) {
  return fmt::format("the mesh's orientation is inconsistent: {} edges are used twice in the same direction{} (some "
                     "triangles are flipped)",
                     c.inconsistent, example_edge(c.first_inconsistent));
}

/// Throws for open, non-manifold, inconsistent (count_edges).
/// `dropped` (triangles with a repeated vertex, ignored) is named in the
/// "open" message: dropping one can leave its neighbours' edges unmatched.
void check_edges(const std::vector<std::array<std::int32_t, 3>>& triangles, std::size_t dropped) {
  const EdgeCounts c = count_edges(triangles);
  if (c.non_manifold)
    throw InputError(fmt::format("the mesh is not manifold: {} edges are shared by more than two triangles{}",
                                 c.non_manifold, example_edge(c.first_non_manifold)));
  if (c.open)
    throw InputError(fmt::format("the mesh is open: {} boundary edges (holes){}{}; reconstruction needs a closed "
                                 "surface",
                                 c.open, example_edge(c.first_open),
                                 dropped ? fmt::format(", after ignoring {} triangle(s) with a repeated vertex",
                                                       dropped)
                                         : std::string()));
  if (c.inconsistent) throw InputError(inconsistent_problem(c));
}

/// Six times the signed volume enclosed by each connected component
/// (divergence theorem: Σ (a−o)·((b−o)×(c−o)) over the triangles, for any
/// origin o since the component is closed). o is a vertex of the component:
/// with the coordinates' origin instead, a mesh of size 1e-3 at 1e4 from it
/// summed terms of 1e12 to a volume of 1e-9, and came out negative.
std::vector<double> component_volumes(const TriangleMesh& mesh,
                                      const std::vector<std::array<std::int32_t, 3>>& triangles) {
  std::vector<std::int32_t> parent(mesh.vertices.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = std::int32_t(i);
  for (const auto& t : triangles)
    for (int k = 1; k < 3; ++k) parent[std::size_t(detail::find_root(parent, t[k]))] = detail::find_root(parent, t[0]);
  std::map<std::int32_t, std::size_t> index;
  std::vector<double> volume;
  for (const auto& t : triangles) {
    const std::int32_t root = detail::find_root(parent, t[0]);
    const auto [it, added] = index.emplace(root, volume.size());
    if (added) volume.push_back(0.0);
    const Vec3& o = mesh.vertices[std::size_t(root)];
    const Vec3 a = mesh.vertices[std::size_t(t[0])] - o, b = mesh.vertices[std::size_t(t[1])] - o,
               c = mesh.vertices[std::size_t(t[2])] - o;
    volume[it->second] += a.dot(b.cross(c));
  }
  return volume;
}

/// Throws InputError when the mesh is too small for its distance from the
/// origin. A skeleton file refuses a segment shorter than
/// Segment::degenerate_length_ratio times its largest coordinate (below
/// that, its direction is lost to rounding), and a reconstruction's shortest
/// pieces reach 5.5e-5 of the input's diagonal (homer's medial mesh; 1.6e-4
/// on the bunny), so the diagonal must be at least 1e5 × that ratio × the
/// largest coordinate (a margin of 5): a mesh 3.5e-3 across placed 1e4
/// from the origin would otherwise run to the end and write a skeleton that
/// skeleton files refuse.
void check_position(const TriangleMesh& mesh, const std::vector<std::array<std::int32_t, 3>>& triangles) {
  constexpr double shortest_piece = 1e-5;  // of the diagonal
  Vec3 lo = Vec3::Constant(INFINITY), hi = -lo;
  double largest_coordinate = 0.0;
  for (const auto& t : triangles)
    for (std::int32_t i : t) {
      const Vec3& v = mesh.vertices[std::size_t(i)];
      lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
      largest_coordinate = std::max(largest_coordinate, v.cwiseAbs().maxCoeff());
    }
  const double diagonal = (hi - lo).norm();
  const double least = Segment::degenerate_length_ratio / shortest_piece * largest_coordinate;
  if (!(diagonal >= least))
    throw InputError(fmt::format("the mesh is {:.3g} across but lies {:.3g} from the origin: its skeleton could "
                                 "not be written accurately in those coordinates (at that distance a skeleton "
                                 "needs a mesh at least {:.3g} across); move the mesh near the origin",
                                 diagonal, largest_coordinate, least));
}

}  // namespace

std::size_t merge_coincident_vertices(TriangleMesh& mesh) {
  // Exact equality of the coordinates: vertices a rounding apart are
  // distinct points of the input, and merging them would be a guess.
  std::map<std::array<double, 3>, std::int32_t> first;
  std::vector<std::int32_t> new_index(mesh.vertices.size());
  std::vector<Vec3> kept;
  std::vector<Vec3> kept_normals;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& v = mesh.vertices[i];
    const auto [it, added] = first.emplace(std::array<double, 3>{v.x(), v.y(), v.z()}, std::int32_t(kept.size()));
    new_index[i] = it->second;
    if (!added) continue;
    kept.push_back(v);
    if (!mesh.normals.empty()) kept_normals.push_back(mesh.normals[i]);
  }
  const std::size_t merged = mesh.vertices.size() - kept.size();
  if (merged == 0) return 0;
  for (auto& t : mesh.triangles)
    for (std::int32_t& i : t)
      if (i >= 0 && std::size_t(i) < new_index.size()) i = new_index[std::size_t(i)];
  mesh.vertices = std::move(kept);
  mesh.normals = std::move(kept_normals);
  return merged;
}

std::size_t remove_unused_vertices(TriangleMesh& mesh) {
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& t : mesh.triangles)
    for (std::int32_t i : t)
      if (i >= 0 && std::size_t(i) < used.size()) used[std::size_t(i)] = true;
  std::vector<std::int32_t> new_index(mesh.vertices.size(), -1);
  std::vector<Vec3> kept;
  std::vector<Vec3> kept_normals;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (!used[i]) continue;
    new_index[i] = std::int32_t(kept.size());
    kept.push_back(mesh.vertices[i]);
    if (!mesh.normals.empty()) kept_normals.push_back(mesh.normals[i]);
  }
  const std::size_t removed = mesh.vertices.size() - kept.size();
  if (removed == 0) return 0;
  for (auto& t : mesh.triangles)
    for (std::int32_t& i : t) i = new_index[std::size_t(i)];
  mesh.vertices = std::move(kept);
  mesh.normals = std::move(kept_normals);
  return removed;
}

void check_mesh_size(const TriangleMesh& mesh, std::size_t max_triangles) {
  if (mesh.triangles.size() > max_triangles) {
    throw InputError(fmt::format("the mesh has {} triangles, more than the limit {} (--max-triangles): raise "
                                 "--max-triangles if the time and memory are there",
                                 mesh.triangles.size(), max_triangles));
  }
  if (mesh.vertices.size() > max_triangles) {
    throw InputError(fmt::format("the mesh has {} vertices, more than the limit {} (--max-triangles; every "
                                 "vertex is a sample of the medial graph): raise --max-triangles if the time "
                                 "and memory are there",
                                 mesh.vertices.size(), max_triangles));
  }
}

namespace {

/// The closed parts of a mesh whose triangles are all proper (triangles
/// joined by edges, not vertices: parts that touch at a vertex only are
/// distinct parts, and may nest), and the winding number of each.
class ClosedParts {
 public:
  ClosedParts(const TriangleMesh& mesh, const std::vector<std::array<std::int32_t, 3>>& triangles)
      : mesh_(mesh), triangles_(triangles) {
    std::vector<std::int32_t> parent(triangles.size());
    for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = std::int32_t(i);
    std::map<Edge, std::int32_t> first_at;
    for (std::size_t t = 0; t < triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const auto [it, added] = first_at.emplace(
            std::minmax(triangles[t][std::size_t(k)], triangles[t][std::size_t((k + 1) % 3)]), std::int32_t(t));
        if (!added)
          parent[std::size_t(detail::find_root(parent, std::int32_t(t)))] = detail::find_root(parent, it->second);
      }
    std::map<std::int32_t, std::size_t> index;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      const auto [it, added] = index.emplace(detail::find_root(parent, std::int32_t(t)), parts_.size());
      if (added) parts_.emplace_back();
      Part& part = parts_[it->second];
      part.triangles.push_back(t);
      for (int k = 0; k < 3; ++k) part.lo = part.lo.cwiseMin(corner(t, k)), part.hi = part.hi.cwiseMax(corner(t, k));
    }
  }

  std::size_t size() const { return parts_.size(); }
  /// Indices into the triangles the parts were made of.
  const std::vector<std::size_t>& triangles(std::size_t part) const { return parts_[part].triangles; }

  /// Six times the volume the part encloses, negative when it faces inwards
  /// (the origin at one of its corners, as in component_volumes).
  double six_volume(std::size_t part) const {
    const Vec3& o = corner(parts_[part].triangles.front(), 0);
    double sum = 0.0;
    for (std::size_t t : parts_[part].triangles)
      sum += (corner(t, 0) - o).dot((corner(t, 1) - o).cross(corner(t, 2) - o));
    return sum;
  }

  /// The part's winding number at p: its triangles' solid angles (Van
  /// Oosterom and Strackee) over 4π; 1 inside an outward part, −1 inside an
  /// inward one, 0 outside, 1/2 on a face.
  double winding(std::size_t part, const Vec3& p) const {
    const Part& q = parts_[part];
    if ((p.array() < q.lo.array()).any() || (p.array() > q.hi.array()).any()) return 0.0;
    double sum = 0.0;
    for (std::size_t t : q.triangles) {
      const Vec3 a = corner(t, 0) - p, b = corner(t, 1) - p, c = corner(t, 2) - p;
      const double la = a.norm(), lb = b.norm(), lc = c.norm();
      sum += 2.0 * std::atan2(a.dot(b.cross(c)), la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la);
    }
    return sum / (4.0 * std::numbers::pi);
  }

  /// The part's largest triangle: its centroid is a point of the part away
  /// from its edges and corners, where another part may touch it.
  std::size_t largest_triangle(std::size_t part) const {
    std::size_t largest = parts_[part].triangles.front();
    double largest_area = -1.0;
    for (std::size_t t : parts_[part].triangles)
      if (const double area = (corner(t, 1) - corner(t, 0)).cross(corner(t, 2) - corner(t, 0)).norm();
          area > largest_area)
        largest = t, largest_area = area;
    return largest;
  }

  /// Whether the part lies inside another part, outward or inward (its
  /// winding number's magnitude, at the largest triangle's centroid, over
  /// 3/4: halfway between 1 inside and 1/2 on a face, so that a part
  /// touching another is not inside it). Meaningful for parts that do not
  /// cross: a part overlapping another has points inside it.
  bool inside_another(std::size_t part, bool outward_only) const {
    const std::size_t t = largest_triangle(part);
    const Vec3 p = (corner(t, 0) + corner(t, 1) + corner(t, 2)) / 3.0;
    for (std::size_t other = 0; other < parts_.size(); ++other)
      if (other != part)
        if (const double w = winding(other, p); outward_only ? w > 0.75 : std::abs(w) > 0.75) return true;
    return false;
  }

 private:
  struct Part {
    std::vector<std::size_t> triangles;
    Vec3 lo = Vec3::Constant(INFINITY), hi = -Vec3::Constant(INFINITY);
  };
  const Vec3& corner(std::size_t t, int k) const {
    return mesh_.vertices[std::size_t(triangles_[t][std::size_t(k)])];
  }
  const TriangleMesh& mesh_;
  const std::vector<std::array<std::int32_t, 3>>& triangles_;
  std::vector<Part> parts_;
};

/// The parts of a closed, consistently oriented mesh that face inwards
/// (a negative volume) though no other part encloses them: such a part is
/// no cavity (a void lies inside the solid), but a surface wound the other
/// way round, e.g. one patch of a CAD export or the whole of an inside-out
/// one.
std::vector<std::size_t> inward_parts_inside_no_other(const ClosedParts& parts) {
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < parts.size(); ++k)
    if (parts.six_volume(k) < 0.0 && !parts.inside_another(k, false)) out.push_back(k);
  return out;
}

}  // namespace

void check_no_nested_parts(const TriangleMesh& mesh) {
  const auto triangles = proper_triangles(mesh);
  const ClosedParts parts(mesh, triangles);
  if (parts.size() < 2) return;
  std::size_t nested = 0, example = 0;
  for (std::size_t k = 0; k < parts.size(); ++k)
    if (parts.inside_another(k, true) && nested++ == 0) example = parts.largest_triangle(k);
  if (nested)
    throw InputError(fmt::format("the mesh has {} closed part(s) inside another part (e.g. the part of triangle {}, "
                                 "counted from 0), crossing nothing: such a part encloses the inside of the solid "
                                 "twice; remove it",
                                 nested, mesh_index(mesh, triangles[example])));
}

void check_closed_mesh(const TriangleMesh& mesh, bool test_crossings) {
  const auto triangles = proper_triangles(mesh);
  if (triangles.empty())
    throw InputError(mesh.vertices.empty()
                         ? std::string("the mesh is empty: it has no triangle")
                         : fmt::format("the mesh is empty: it has no triangle, only {} vertices (a point cloud?); "
                                       "skeletonize needs a closed surface: mesh the points first",
                                       mesh.vertices.size()));
  check_edges(triangles, mesh.triangles.size() - triangles.size());
  for (const auto& t : triangles)
    for (std::int32_t i : t)
      if (i < 0 || std::size_t(i) >= mesh.vertices.size())
        throw InputError(fmt::format("a triangle refers to vertex {}, but the mesh has {}", i, mesh.vertices.size()));
  const std::vector<double> volumes = component_volumes(mesh, triangles);
  double total = 0.0;
  for (double v : volumes) total += v;
  const auto inside_out = [] {
    return InputError("the mesh is inside out: its triangles face inwards (enclosed volume is negative); flip them");
  };
  const auto negative = std::count_if(volumes.begin(), volumes.end(), [](double v) { return v < 0.0; });
  if (!(total > 0.0) && (negative == 0 || std::size_t(negative) == volumes.size())) throw inside_out();
  if (negative) {
    const ClosedParts parts(mesh, triangles);
    if (const auto wound = inward_parts_inside_no_other(parts); !wound.empty())
      throw InputError(fmt::format("the mesh has {} inward-facing part(s) that lie inside no other part (e.g. the "
                                   "part of triangle {}, counted from 0): their triangles are wound the other way "
                                   "round; flip them",
                                   wound.size(), mesh_index(mesh, triangles[parts.triangles(wound.front()).front()])));
    if (!(total > 0.0)) throw inside_out();
    std::size_t inward = 0;
    for (std::size_t k = 0; k < parts.size(); ++k) inward += parts.six_volume(k) < 0.0;
    throw InputError(fmt::format("the mesh has {} inward-facing part(s) inside other parts, i.e. cavities inside "
                                 "the solid; cavities are not supported",
                                 inward));
  }
  check_position(mesh, triangles);
  if (test_crossings) check_no_self_intersection(mesh), check_no_nested_parts(mesh);
}

namespace {

/// A triangle by its corners' coordinates, starting at the least corner
/// (the orientation kept): the same key in a mesh and in its repair, whose
/// vertices are renumbered.
using TriangleKey = std::array<double, 9>;

TriangleKey triangle_key(const TriangleMesh& mesh, const std::array<std::int32_t, 3>& t) {
  std::array<std::array<double, 3>, 3> c;
  for (int k = 0; k < 3; ++k) {
    const Vec3& v = mesh.vertices[std::size_t(t[std::size_t(k)])];
    c[std::size_t(k)] = {v.x(), v.y(), v.z()};
  }
  const std::size_t least = std::size_t(std::min_element(c.begin(), c.end()) - c.begin());
  TriangleKey key;
  for (std::size_t k = 0; k < 3; ++k)
    for (std::size_t i = 0; i < 3; ++i) key[3 * k + i] = c[(least + k) % 3][i];
  return key;
}

/// Why `joined`, the union of `input`'s parts, is not a valid input, or
/// empty. It must pass every check, crossings included, and keep the
/// input's bounding box: an extreme point of a union is a vertex of one of
/// its parts, so only the rounding of new vertices may move it.
std::string union_failure(const TriangleMesh& input, TriangleMesh& joined) {
  // The cut splits the vertices where closed parts touch at one point, and
  // may round two new vertices to one position: joined again, as on input.
  merge_coincident_vertices(joined);
  try {
    check_closed_mesh(joined, false);
  } catch (const InputError& e) {
    // The fact, not its advice to the user ("; flip them"): the union is
    // ours, not the user's mesh.
    return e.problem().substr(0, e.problem().find("; "));
  }
  // Rounding new vertices to double can make triangles cross again.
  if (const SelfIntersections left = find_self_intersections(joined); !left.none())
    return left.degenerate ? fmt::format("{} triangle(s) of zero area made", left.degenerate)
                           : fmt::format("{} crossing pair(s) left", left.pairs);
  const auto box = [](const TriangleMesh& m) {
    Vec3 lo = Vec3::Constant(INFINITY), hi = -lo;
    for (const auto& t : proper_triangles(m))
      for (std::int32_t i : t) lo = lo.cwiseMin(m.vertices[std::size_t(i)]), hi = hi.cwiseMax(m.vertices[std::size_t(i)]);
    return std::pair{lo, hi};
  };
  constexpr double box_tolerance = 1e-9;  // of the diagonal: rounding only
  const auto [lo, hi] = box(input);
  const auto [new_lo, new_hi] = box(joined);
  const double moved = std::max((new_lo - lo).cwiseAbs().maxCoeff(), (new_hi - hi).cwiseAbs().maxCoeff());
  if (!(moved <= box_tolerance * (hi - lo).norm()))
    return fmt::format("its bounding box moved by {:.3g} of the diagonal", moved / (hi - lo).norm());
  return {};
}

}  // namespace

OverlapRepair check_closed_mesh_joining_overlaps(TriangleMesh& mesh) {
  check_closed_mesh(mesh, false);
  const SelfIntersections found = find_self_intersections(mesh);
  // CGAL's autorefinement does not handle a triangle of zero area where it
  // meets others: it threw "Non-handled triple intersection of input
  // triangles" on one lying on another part's face.
  if (found.degenerate > 0)
    throw InputError(fmt::format("{}, and the boolean union of --repair cannot cut through such triangles; remove "
                                 "them (collapse their shortest edge) first",
                                 degenerate_triangle_problem(found)));
  if (found.pairs == 0) {
    check_no_nested_parts(mesh);
    return {};
  }
  detail::JoinedMesh joined = detail::join_overlapping_parts(mesh);
  if (joined.refused)
    throw InputError(fmt::format("the mesh intersects itself ({} crossing pair(s), e.g. triangles {} and {}) through "
                                 "a vertex where parts touch: {}; the boolean union of --repair cannot cut through "
                                 "such a vertex; separate the parts there in a modeller first",
                                 found.pairs, found.first, found.second, joined.failure));
  if (joined.mesh) joined.failure = union_failure(mesh, *joined.mesh);
  if (!joined.failure.empty())
    throw InputError(fmt::format("the mesh intersects itself ({} crossing pair(s), e.g. triangles {} and {}) and the "
                                 "union of its overlapping parts is not a valid mesh: {}; join them by a boolean "
                                 "union in a modeller first",
                                 found.pairs, found.first, found.second, joined.failure));
  std::map<TriangleKey, std::size_t> before;
  std::size_t proper = 0;
  for (const auto& t : proper_triangles(mesh)) ++before[triangle_key(mesh, t)], ++proper;
  std::size_t kept = 0;
  for (const auto& t : joined.mesh->triangles) {
    const auto it = before.find(triangle_key(*joined.mesh, t));
    if (it != before.end() && it->second > 0) --it->second, ++kept;
  }
  OverlapRepair repair;
  repair.crossing_pairs = found.pairs;
  repair.triangles_removed = proper - kept;
  repair.triangles_added = joined.mesh->triangles.size() - kept;
  repair.cavities_filled = joined.cavities_filled;
  mesh = std::move(*joined.mesh);
  // The winding number removes a part nested whole in another with the
  // rest of the inside: kept as a guard on the union's own output.
  check_no_nested_parts(mesh);
  return repair;
}

bool has_holes_or_non_manifold_edges(const TriangleMesh& mesh) {
  const EdgeCounts c = count_edges(proper_triangles(mesh));
  return (c.open > 0 || c.non_manifold > 0) && c.inconsistent == 0;
}

namespace {

/// Turns round the triangles of `mesh` that disagree with their
/// neighbours: across every edge of two triangles one must run a → b and
/// the other b → a. Each connected part keeps the orientation of its first
/// triangle in the file's order (which side is out is decided after, by
/// the enclosed volume: flip_inward_parts). Returns how many triangles it
/// turned; throws InputError for a part that no orientation makes
/// consistent (a Möbius band). Edges of more than two triangles are
/// ignored: the caller orients only meshes without them.
std::size_t orient_consistently(TriangleMesh& mesh) {
  std::vector<std::size_t> in_mesh;  // the proper triangles' indices in the mesh
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (const auto& c = mesh.triangles[t]; c[0] != c[1] && c[1] != c[2] && c[2] != c[0]) in_mesh.push_back(t);
  // Per edge (lower vertex first), its triangles and whether each runs
  // from the lower vertex to the higher.
  std::map<Edge, std::vector<std::pair<std::size_t, bool>>> at_edge;
  for (std::size_t t = 0; t < in_mesh.size(); ++t) {
    const auto& c = mesh.triangles[in_mesh[t]];
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = c[std::size_t(k)], b = c[std::size_t((k + 1) % 3)];
      at_edge[std::minmax(a, b)].emplace_back(t, a < b);
    }
  }
  std::vector<std::vector<std::pair<std::size_t, bool>>> neighbours(in_mesh.size());  // (u, same direction)
  for (const auto& [edge, uses] : at_edge)
    if (uses.size() == 2) {
      const bool same = uses[0].second == uses[1].second;
      neighbours[uses[0].first].emplace_back(uses[1].first, same);
      neighbours[uses[1].first].emplace_back(uses[0].first, same);
    }
  // Breadth first from each part's first triangle: a neighbour that runs
  // the shared edge the same way is flipped relative to its finder.
  constexpr std::uint8_t unseen = 2;
  std::vector<std::uint8_t> flip(in_mesh.size(), unseen);
  std::vector<std::size_t> queue;
  for (std::size_t seed = 0; seed < in_mesh.size(); ++seed) {
    if (flip[seed] != unseen) continue;
    flip[seed] = 0;
    queue.assign(1, seed);
    for (std::size_t next = 0; next < queue.size(); ++next) {
      const std::size_t t = queue[next];
      for (const auto& [u, same] : neighbours[t]) {
        const std::uint8_t wanted = flip[t] ^ std::uint8_t(same);
        if (flip[u] == unseen) {
          flip[u] = wanted;
          queue.push_back(u);
        } else if (flip[u] != wanted) {
          throw InputError(fmt::format("the mesh is not orientable: the part of triangle {} (counted from 0) has no "
                                       "consistent orientation (a Möbius band); it bounds no solid",
                                       in_mesh[seed]));
        }
      }
    }
  }
  std::size_t turned = 0;
  for (std::size_t t = 0; t < in_mesh.size(); ++t)
    if (flip[t] == 1) std::swap(mesh.triangles[in_mesh[t]][1], mesh.triangles[in_mesh[t]][2]), ++turned;
  return turned;
}

/// Turns round the parts of a closed, consistently oriented `mesh` that
/// face inwards though no other part encloses them
/// (inward_parts_inside_no_other: every part of an inside-out export, or
/// one patch wound the other way), and says how many triangles and parts it
/// flipped; nothing for any other mesh. An inward part inside another may be
/// a cavity, which check_closed_mesh names.
std::pair<std::size_t, std::size_t> flip_inward_parts(TriangleMesh& mesh) {
  const auto triangles = proper_triangles(mesh);
  const EdgeCounts edges = count_edges(triangles);
  if (triangles.empty() || edges.open || edges.non_manifold || edges.inconsistent) return {0, 0};
  const std::vector<double> volumes = component_volumes(mesh, triangles);
  if (std::none_of(volumes.begin(), volumes.end(), [](double v) { return v < 0.0; })) return {0, 0};
  const ClosedParts parts(mesh, triangles);
  const auto wound = inward_parts_inside_no_other(parts);
  // The proper triangles' indices in the mesh, in order.
  std::vector<std::size_t> in_mesh;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (const auto& c = mesh.triangles[t]; c[0] != c[1] && c[1] != c[2] && c[2] != c[0]) in_mesh.push_back(t);
  std::size_t flipped = 0;
  for (std::size_t k : wound)
    for (std::size_t t : parts.triangles(k)) {
      auto& c = mesh.triangles[in_mesh[t]];
      std::swap(c[1], c[2]);
      ++flipped;
    }
  return {flipped, wound.size()};
}

}  // namespace

void check_closed_mesh_offering_repair(const TriangleMesh& mesh, std::string_view repair_option) {
  const auto offer = [repair_option](const InputError& error, std::string_view repair_does) {
    return InputError(
        fmt::format("{} (or pass {} to let skeletonize {})", error.problem(), repair_option, repair_does));
  };
  try {
    check_closed_mesh(mesh, false);
  } catch (const InputError& error) {
    if (const EdgeCounts c = count_edges(proper_triangles(mesh)); c.inconsistent && !c.non_manifold) {
      TriangleMesh oriented = mesh;
      orient_consistently(oriented);  // throws for a Möbius band
      throw offer(error, "orient its triangles consistently");
    }
    if (has_holes_or_non_manifold_edges(mesh)) throw offer(error, "split non-manifold edges and fill holes");
    TriangleMesh flipped = mesh;
    if (const std::size_t n = flip_inward_parts(flipped).first; n > 0)
      throw offer(error, n == proper_triangles(mesh).size() ? "turn it round" : "turn those parts round");
    throw;
  }
  try {
    check_no_self_intersection(mesh);
  } catch (const InputError& error) {
    // The repair joins crossing parts; it refuses zero-area triangles too.
    if (find_self_intersections(mesh).degenerate > 0) throw;
    throw offer(error, "join them");
  }
  check_no_nested_parts(mesh);
}

InputRepair check_closed_mesh_repairing(TriangleMesh& mesh, double max_hole_area) {
  InputRepair repair;
  auto triangles = proper_triangles(mesh);
  EdgeCounts edges = count_edges(triangles);
  // Triangles flipped against their neighbours (a shuffled export): each
  // part is oriented from its first triangle, and the parts then facing
  // inwards are turned round below. At an edge of more than two triangles
  // which ones are neighbours is not known.
  if (edges.inconsistent && !edges.non_manifold) {
    repair.surface.triangles_reoriented = orient_consistently(mesh);
    triangles = proper_triangles(mesh);
    edges = count_edges(triangles);
  }
  if (edges.open > 0 || edges.non_manifold > 0) {
    // A flipped triangle's edges would be split like non-manifold ones and
    // the holes left filled: the orientation is the user's to fix there.
    if (edges.inconsistent)
      throw InputError(inconsistent_problem(edges) +
                       " (--repair orients triangles only where no edge has more than two)");
    for (const auto& t : triangles)
      for (std::int32_t i : t)
        if (i < 0 || std::size_t(i) >= mesh.vertices.size())
          throw InputError(fmt::format("a triangle refers to vertex {}, but the mesh has {}", i, mesh.vertices.size()));
    detail::ClosedMesh closed = detail::close_holes(mesh);
    if (!closed.mesh)
      throw InputError(fmt::format("the mesh is {} and could not be closed: {}; close it in a modeller first",
                                   edges.non_manifold ? "not manifold" : "open", closed.failure));
    SurfaceRepair& s = repair.surface;
    s.non_manifold_edges = edges.non_manifold;
    s.isolated_vertices_removed = closed.isolated_vertices_removed;
    s.holes_filled = closed.holes.size();
    double patches = 0.0;
    const detail::FilledHole* largest = nullptr;
    for (const detail::FilledHole& h : closed.holes) {
      s.boundary_edges += h.edges;
      s.holes_not_faired += !h.faired;
      s.triangles_added += h.triangles;
      s.vertices_added += h.vertices;
      patches += h.patch_area;
      if (!largest || h.patch_area > largest->patch_area) largest = &h;
    }
    // The closed surface's area: the input's triangles and the patches.
    double area = patches;
    for (const auto& t : triangles) {
      const Vec3& a = mesh.vertices[std::size_t(t[0])];
      area += 0.5 * (mesh.vertices[std::size_t(t[1])] - a).cross(mesh.vertices[std::size_t(t[2])] - a).norm();
    }
    if (largest) {
      s.largest_hole_area = largest->patch_area / area;
      // A hole of exactly the limit (two of an octahedron's eight faces
      // missing: 1/4) is filled, whatever the rounding of the two areas.
      constexpr double rounding_margin = 1e-9;
      if (!(s.largest_hole_area <= max_hole_area * (1 + rounding_margin))) {
        Vec3 lo = Vec3::Constant(INFINITY), hi = -lo;
        for (const Vec3& v : closed.mesh->vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
        throw InputError(fmt::format(
            "the mesh is open and one of its {} hole(s) is too large to fill: {} boundary edges, {:.3g} times the "
            "diagonal long, whose patch would be {:.1f}% of the closed surface's area (--repair fills up to "
            "{:.3g}%: a larger opening is a shape left open, not a missing piece); close it in a modeller first",
            closed.holes.size(), largest->edges, largest->length / (hi - lo).norm(), 100.0 * s.largest_hole_area,
            100.0 * max_hole_area));
      }
    }
    s.vertices_split = closed.vertices_split;
    mesh = std::move(*closed.mesh);
    // CGAL's union crashed (a segmentation fault in its corefinement, on
    // CGAL's diplodocus) on a surface with distinct vertices at one
    // position: where the split sheets also cross, the mesh is refused.
    if (s.vertices_split > 0)
      if (const SelfIntersections found = find_self_intersections(mesh); found.pairs > 0)
        throw InputError(fmt::format(
            "the mesh is not manifold: {} edges are shared by more than two triangles{}; split along them ({} "
            "vertices copied), its sheets cross each other ({} crossing pair(s), e.g. triangles {} and {} of the "
            "split mesh), and the boolean union of --repair cannot join sheets that meet at split vertices; "
            "separate them in a modeller first",
            edges.non_manifold, example_edge(edges.first_non_manifold), s.vertices_split, found.pairs, found.first,
            found.second));
  }
  std::tie(repair.surface.triangles_flipped, repair.surface.parts_flipped) = flip_inward_parts(mesh);
  repair.overlaps = check_closed_mesh_joining_overlaps(mesh);
  return repair;
}

}  // namespace skelconv::reconstruct
