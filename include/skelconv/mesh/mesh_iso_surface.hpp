// skelconv/mesh/mesh_iso_surface.hpp — a closed triangle mesh of the surface
// f = iso of an implicit field (the library side of `skelconv mesh`).
//
// Steps (docs/mesh.md explains each and why):
//   1. reject iso ≤ the far-field value (the surface would be unbounded);
//   2. find a box containing the surface (bounding_region.hpp);
//   3. seed every component from the skeleton points (surface_seeds.hpp);
//   4. Delaunay-refine the surface with CGAL Mesh_3 from those seeds, manifold
//      criteria, fixed random seed (src/mesh/cgal_surface_mesher.hpp); or,
//      with MeshMethod::grid, sample the field on a uniform grid and
//      extract the zero set with OpenVDB (src/mesh/grid_surface_mesher.hpp);
//   5. project every vertex onto f = iso by Newton steps and set the exact
//      normals (surface_projection.hpp).
// Same field and options → same mesh, bit for bit.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "skelconv/mesh/bounding_region.hpp"
#include "skelconv/mesh/implicit_field.hpp"
#include "skelconv/mesh/triangle_mesh.hpp"

namespace skelconv {

/// Reported about once per `MeshOptions::progress_interval` seconds during
/// refinement.
struct MeshProgress {
  std::size_t field_evaluations = 0;
  double seconds = 0.0;
};

/// How step 4 makes the triangles.
enum class MeshMethod {
  /// CGAL Mesh_3 Delaunay refinement: closed 2-manifold, adaptive, slow.
  cgal,
  /// OpenVDB volumeToMesh on a uniform grid of spacing `size`: fast, no
  /// topological guarantee below the grid spacing (docs/mesh.md).
  grid,
};

struct MeshOptions {
  double iso = 1.0;
  MeshMethod method = MeshMethod::cgal;
  /// Facet size h (CGAL facet_size: largest facet circumradius; the grid
  /// method's grid spacing); default the bounding box diagonal / 50.
  std::optional<double> size;
  /// Facet distance d (CGAL facet_distance); default h / 10.
  std::optional<double> distance;
  /// Smallest facet angle in degrees; CGAL guarantees termination up to 30.
  double facet_angle = 30.0;
  /// The grid method samples only the cells the surface crosses, found by
  /// continuation from the seeds (docs/mesh.md): a component of the surface
  /// that no seed reaches is then left out, as with CGAL. false: the whole
  /// grid, skipping only what the supports and enclosures prove empty.
  bool grid_from_seeds = true;
  /// Every vertex ends with |f − iso| / |∇f| ≤ projection_tolerance × the
  /// mesh's bounding-box diagonal.
  double projection_tolerance = 1e-9;
  /// false: the vertices stay where the mesher put them (within about a
  /// facet of the surface, without normals) and are not projected. The
  /// projection moves vertices and never changes a triangle, so the
  /// topology (mesh_topology) is the projected mesh's, for less work (the
  /// projection is about a sixth of the grid method's at 480 SCALIS
  /// primitives, the seeds' rays most of the rest); project_iso_surface
  /// finishes such a mesh into the projected one.
  bool project = true;
  unsigned random_seed = 0;
  /// Threads for the seeds' rays, the grid's continuation and the
  /// projection (0: every core, std::thread::hardware_concurrency). The
  /// mesh is the same bytes for any count.
  unsigned threads = 0;
  /// The run is refused before any refinement when it would make more
  /// triangles than this (estimate_triangles below): a facet size far too
  /// small for the box would otherwise run for hours and exhaust memory.
  std::size_t max_triangles = 4'000'000;
  std::function<void(const MeshProgress&)> progress;
  double progress_interval = 1.0;
};

/// A part of the surface the grid method lost: its seeds (surface points
/// found from the skeleton) have no mesh vertex near them, because no grid
/// node lies inside it (find_missed_parts in mesh_iso_surface.cpp).
struct MissedPart {
  Vec3 centre;          ///< the mean of its seeds, inside the part
  /// The smallest side of its seeds' bounding box that is not 0 (the seeds
  /// lie around the skeleton point they were shot from): about its
  /// thickness; 0 when it has one seed.
  double thickness = 0.0;
  std::size_t seeds = 0;
};

/// What the run did and where the time went.
struct MeshReport {
  Box3 box;                  ///< the box the surface was found in
  double size = 0.0;         ///< facet size used
  double distance = 0.0;     ///< facet distance used
  std::size_t seeds = 0;     ///< surface points inserted before refinement
  std::size_t field_evaluations = 0;
  double field_seconds = 0.0;   ///< inside the field (all steps)
  double total_seconds = 0.0;
  double refine_seconds = 0.0;  ///< step 4, field time included
  /// MeshMethod::grid only: the parts of the surface the grid missed (every
  /// one thinner than the spacing), thickest first. Empty with cgal, which
  /// starts from every seed.
  std::vector<MissedPart> missed_parts;
};

/// About how many triangles a mesh of facet size h makes of a surface inside
/// `box`: the box's surface area over h². An order of magnitude, used only
/// to refuse absurd sizes before the work starts. It leans high for the
/// usual shapes: a ball fills its box with π/6 ≈ 0.52 of the box's area,
/// and an equilateral triangle of circumradius h covers 3√3/4 h² ≈ 1.3 h².
double estimate_triangles(const Box3& box, double size);

/// Meshes f = options.iso. Throws InputError (located at "--iso", "--size",
/// "--distance") for an unbounded or absent surface or bad options (a --size
/// whose estimated triangle count exceeds options.max_triangles among them), and
/// EvaluationError if the field cannot be evaluated or a vertex not projected.
TriangleMesh mesh_iso_surface(const ImplicitField& field, const MeshOptions& options, MeshReport* report = nullptr);

/// The projection mesh_iso_surface ends with, on a mesh it made with
/// MeshOptions::project false from the same field and options (`size`: the
/// MeshReport::size of that run, i.e. options.size when given): the result
/// is the mesh project = true makes, to the bit. Throws EvaluationError as
/// mesh_iso_surface does when a vertex cannot be projected.
void project_iso_surface(TriangleMesh& mesh, const ImplicitField& field, const MeshOptions& options, double size);

}  // namespace skelconv
