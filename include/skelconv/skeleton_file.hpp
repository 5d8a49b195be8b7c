// skelconv/skeleton_file.hpp — reading a Skeleton from JSON.
//
// Schema (documented for users in docs/cli_skeleton.md and docs/cli_blends.md):
//
//   {"primitives": [
//     {"type": "segment", "a": [0,0,0], "b": [1,0,0], "weight": [1, 0.5],
//      "kernel": {"family": "inverse", "degree": 3}},
//     {"type": "segment", "a": [0,1,0], "b": [1,1,0],
//      "kernel": {"family": "cauchy", "degree": 4, "s": 2.0}},
//     {"type": "segment", "a": [0,2,0], "b": [1,2,1],
//      "kernel": {"family": "compact", "degree": 6, "R": 1.5}},
//     {"type": "polygon", "vertices": [[0,3,0], [1,3,0], [1,4,0], [0,4,0]],
//      "kernel": {"family": "inverse", "degree": 3}},
//     {"type": "scalis_segment", "a": [0,5,0], "b": [2,5,0], "radius": [0.2, 0.6],
//      "kernel": {"family": "cauchy", "degree": 4, "sigma": 1.5}, "iso": 1},
//     {"type": "scalis_triangle", "vertices": [[0,6,0], [2,6,0], [0,7.5,0.3]],
//      "radius": [0.2, 0.5, 0.3], "kernel": {"family": "compact", "degree": 4, "sigma": 2}},
//     {"type": "point", "center": [0,9,0], "kernel": {"family": "compact", "degree": 4, "R": 1}, "weight": 2},
//     {"blend": "union", "children": [
//       {"blend": "super_elliptic", "t": 2, "r": [0.3, 0.4], "iso": 1, "angle_weighted": false,
//        "children": [<primitive or blend node>, ...]},
//       {"blend": "sum", "weights": [1, 0.5], "children": [..., ...]}]}],
//    "iso": 1}
//
// "primitives" holds primitives and blend nodes ({"blend": NAME, "children":
// [...], parameters}: skelconv/skeleton/blend.hpp), to any depth; its
// elements' fields add up. The optional top-level "iso" (default 1, > 0) is
// the level of the surface (Skeleton::iso()) and the default "iso" of
// super_elliptic nodes. Parameters of a blend node are checked (against its
// number of children) before its children are read.
//
// The reader is strict, because a skeleton that silently means something
// else than what was written is worse than an error: unknown fields (a typo
// such as "wieght"), duplicate fields, a kernel parameter of another family
// ("R" on a Cauchy kernel), wrong types and numbers that overflow double are
// all rejected. Every error is an InputError whose where() is the JSON path
// of the culprit, e.g. `primitives[2].kernel.R: must be > 0, got -1`,
// `primitives[3].vertices[2]: must be a point [x, y, z] ...` or, inside a
// blend node, `primitives[1].children[0].kernel.R: ...`.
#pragma once

#include <filesystem>
#include <string_view>

#include "skelconv/skeleton.hpp"

namespace skelconv {

/// Parses the JSON text of a skeleton. Throws InputError.
Skeleton parse_skeleton_json(std::string_view json_text);

/// Reads and parses a skeleton file. Throws InputError whose message starts
/// with the file name: `skel.json: primitives[2].kernel.R: must be > 0, got -1`.
Skeleton load_skeleton_file(const std::filesystem::path& path);

}  // namespace skelconv
