// skelconv/canal/canal_mesh.hpp — a triangle mesh of a canal surface, swept
// by its characteristic circles (docs/canal.md §4).
//
// The samples (increasing t) each give a ring of `ring_points` vertices on
// their characteristic circle; consecutive rings are joined by two triangles
// per quad. The ring frames (e1, e2 = n × e1 around the circle normal n) are
// carried from ring to ring by projecting e1 on the next circle's plane, so
// the quads do not twist. Where the family ends on a sphere (both ends), a
// cap closes the tube: the part of the end sphere beyond the end circle (on
// the −n side at t = 0, the +n side at the last sample), in rings of about
// the same angular step as around the circles, down to one apex vertex. The
// capped mesh is watertight and has the topology of a sphere: every edge is
// shared by two triangles in opposite directions, V − E + F = 2.
//
// Vertex normals are exact: the envelope touches each sphere along its
// circle, so the normal at p is (p − c)/|r|, pointing away from the axis;
// triangles are counter-clockwise seen from that side.
#pragma once

#include <vector>

#include "skelconv/canal/canal_family.hpp"
#include "skelconv/mesh/triangle_mesh.hpp"

namespace skelconv::canal {

struct CanalMeshOptions {
  /// Vertices around each circle: 64 keeps the chordal area error of a ring
  /// at 1 − sin(2π/64)·64/(2π) = 0.16%.
  int ring_points = 64;
  /// Close both ends with spherical caps (off: an open tube, V − E + F = 0).
  bool caps = true;
  /// A ring frame is refused when the circle normal turns so fast between
  /// two samples that the previous e1 has less than this length once
  /// projected on the next plane (about 87°): use more samples.
  double min_projected_frame = 0.05;
};

/// Meshes the canal surface of `samples` (at least 2, increasing t). Throws
/// EvaluationError, naming the sample's t, when a sample has no
/// characteristic circle, when the radius changes sign between two samples
/// (the family passes through a point or a plane: the surface pinches),
/// or when the frame cannot be carried (see min_projected_frame); throws
/// InputError for fewer than 2 samples or ring_points < 3.
TriangleMesh mesh_canal_surface(const std::vector<FamilySample<double>>& samples, const CanalMeshOptions& options = {});

}  // namespace skelconv::canal
