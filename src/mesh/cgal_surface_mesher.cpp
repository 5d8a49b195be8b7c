// Implementation of cgal_surface_mesher.hpp (CGAL Mesh_3, CGAL 5.5 API).
#include "cgal_surface_mesher.hpp"

#include <CGAL/assertions_behaviour.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/facets_in_complex_3_to_triangle_mesh.h>
#include <CGAL/refine_mesh_3.h>

namespace skelconv::detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Domain = CGAL::Labeled_mesh_domain_3<Kernel>;
using Triangulation = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using Complex = CGAL::Mesh_complex_3_in_triangulation_3<Triangulation>;
using Criteria = CGAL::Mesh_criteria_3<Triangulation>;
namespace params = CGAL::parameters;

Point to_point(const Vec3& p) { return Point(p.x(), p.y(), p.z()); }

/// Inserts the seeds as surface vertices (dimension 2, the surface patch
/// between subdomain 0 outside and 1 inside), as CGAL's own initialisation
/// does (Mesh_3/initialize_triangulation_from_labeled_image.h).
void insert_seeds(Complex& complex, const Domain& domain, const std::vector<Vec3>& seeds) {
  Triangulation& triangulation = complex.triangulation();
  const auto weighted = triangulation.geom_traits().construct_weighted_point_3_object();
  // Labels: the implicit wrapper gives 1 where level < 0 and 0 elsewhere;
  // the patch between them is the pair (0, 1).
  const Domain::Index index = domain.index_from_surface_patch_index(Domain::Surface_patch_index(0, 1));
  for (const Vec3& seed : seeds) {
    const auto vertex = triangulation.insert(weighted(to_point(seed)));
    if (vertex == Triangulation::Vertex_handle()) continue;  // hidden (cannot happen with zero weights)
    complex.set_dimension(vertex, 2);
    complex.set_index(vertex, index);
  }
}

TriangleMesh to_triangle_mesh(const CGAL::Surface_mesh<Point>& surface) {
  TriangleMesh mesh;
  mesh.vertices.reserve(surface.number_of_vertices());
  for (auto v : surface.vertices()) {
    const Point& p = surface.point(v);
    mesh.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  mesh.triangles.reserve(surface.number_of_faces());
  for (auto f : surface.faces()) {
    std::array<std::int32_t, 3> triangle{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(surface.halfedge(f), surface)) triangle[k++] = std::int32_t(v.idx());
    mesh.triangles.push_back(triangle);
  }
  return mesh;
}

void ignore_warning(const char*, const char*, const char*, int, const char*) {}

/// While alive, CGAL warnings are not printed. The one refine_mesh_3 can
/// give (Mesher_3.h, unconditional: "The mesh refinement process can't
/// start", when no facet of the seeds' triangulation meets the surface) is
/// eight lines on stderr, where every message of the command is one line;
/// the refinement then returns no facets, which the caller reports itself.
class WarningsSilenced {
 public:
  WarningsSilenced() : previous_(CGAL::set_warning_handler(ignore_warning)) {}
  ~WarningsSilenced() { CGAL::set_warning_handler(previous_); }
  WarningsSilenced(const WarningsSilenced&) = delete;
  WarningsSilenced& operator=(const WarningsSilenced&) = delete;

 private:
  CGAL::Failure_function previous_;
};

}  // namespace

TriangleMesh cgal_surface_mesh(const CgalSurfaceRequest& request) {
  // Mesh_3 draws far points from CGAL's default generator (seeded from the
  // clock) and initial points from the domain's: fix both.
  CGAL::get_default_random() = CGAL::Random(request.random_seed);
  CGAL::Random domain_random(request.random_seed);

  const auto level = [&request](const Point& p) { return request.level(Vec3(p.x(), p.y(), p.z())); };
  const Kernel::Iso_cuboid_3 box(to_point(request.box.lo), to_point(request.box.hi));
  const Domain domain = Domain::create_implicit_mesh_domain(
      level, box, params::relative_error_bound = request.relative_error_bound, params::p_rng = &domain_random);
  const Criteria criteria(params::facet_angle = request.facet_angle, params::facet_size = request.facet_size,
                          params::facet_distance = request.facet_distance);

  Complex complex;
  insert_seeds(complex, domain, request.seeds);
  {
    const WarningsSilenced silenced;
    CGAL::refine_mesh_3(complex, domain, criteria, params::no_perturb(), params::no_exude(), params::manifold());
  }

  if (complex.number_of_facets_in_complex() == 0) return {};
  CGAL::Surface_mesh<Point> surface;
  CGAL::facets_in_complex_3_to_triangle_mesh(complex, surface);
  return to_triangle_mesh(surface);
}

}  // namespace skelconv::detail
