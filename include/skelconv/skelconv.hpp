// skelconv/skelconv.hpp — the public C++ API in one header (docs/api.md).
//
//     #include <skelconv/skelconv.hpp>   // link skelconv::skelconv
//
// What it declares, all in namespace skelconv:
//   - errors:          InputError (bad input, with where()), EvaluationError
//   - kernels:         KernelSpec, KernelFamily (kernel_spec.hpp)
//   - primitives:      Segment, Polygon, ScalisSegment, ScalisTriangle,
//                      PointPrimitive, and Primitive (any of them)
//   - skeletons:       Skeleton (a tree of blend nodes: Blend), read from JSON
//                      by parse_skeleton_json / load_skeleton_file
//   - fields:          Skeleton::value / gradient / value_and_gradient at a
//                      point, evaluate_batch for many points (all cores)
//   - bounds:          interval::enclose, interval::classify_octree (sound
//                      enclosures of f over boxes)
//   - meshing:         mesh_iso_surface, skeleton_field, write_mesh, TriangleMesh
//
// Everything here evaluates in double. It includes none of the generated
// kernels (tens of thousands of lines): those are compiled once inside the
// library. The generated kernels themselves, templates on the scalar type
// (float, double, long double, Boost.Multiprecision), are opt-in:
// <skelconv/primitives/generic.hpp> (docs/api.md, "Other scalar types").
//
// The other headers under skelconv/ are the pieces this one gathers, or
// internals of the generated code (stable_recurrence.hpp, gauss_moments.hpp,
// clip.hpp, polygon_field.hpp, *_input.hpp); names in a `detail` namespace
// are not part of the API.
#pragma once

#include "skelconv/errors.hpp"
#include "skelconv/geometry.hpp"
#include "skelconv/kernels/kernel_spec.hpp"

#include "skelconv/primitives/polygon.hpp"
#include "skelconv/primitives/point.hpp"
#include "skelconv/primitives/primitive.hpp"
#include "skelconv/primitives/scalis_segment.hpp"
#include "skelconv/primitives/scalis_triangle.hpp"
#include "skelconv/primitives/segment.hpp"

#include "skelconv/skeleton/skeleton.hpp"
#include "skelconv/skeleton/blend.hpp"
#include "skelconv/skeleton/skeleton_file.hpp"

#include "skelconv/field/batch.hpp"

#include "skelconv/interval/enclosure.hpp"
#include "skelconv/interval/octree.hpp"

#include "skelconv/mesh/implicit_field.hpp"
#include "skelconv/mesh/mesh_iso_surface.hpp"
#include "skelconv/mesh/triangle_mesh.hpp"
