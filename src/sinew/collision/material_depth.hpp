#pragma once
/// @file material_depth.hpp
/// Material depth (docs/theory.md, dissertation section 5.4.1): for a node of a body, the
/// distance in the rest configuration from the node to that body's contact surface (0 on the
/// surface). Exact point-triangle distances; the default search goes through a bounding-volume
/// hierarchy over the surface triangles, the exhaustive search of the seed is kept as the
/// reference. Call once per body with that body's surface and nodes.

#include <vector>

#include "sinew/core/types.hpp"

namespace sinew::collision {

/// Material depth of the given nodes. rest: #V x 3 rest positions (length unit); surface: #F x 3
/// triangles (indices into rest), the zero-depth surface of the body; nodes: the node indices to
/// evaluate. Returns a vector of nodes.size() depths (length unit), depth[i] for nodes[i]:
/// the exact distance from rest.row(nodes[i]) to the nearest triangle of `surface`, exactly 0
/// for a node that is a vertex of `surface`. Uses an AabbTree over the triangle boxes and a
/// branch-and-bound nearest search: O(F log F + N log F) typically. Runs in parallel over nodes.
/// Throws InputError when `surface` is empty and `nodes` is not, or an index is out of range.
VectorX material_depth(const Positions& rest, const Triangles& surface, const std::vector<Index>& nodes);

/// Same result by the seed's exhaustive search (every node against every triangle), O(N F).
/// The test oracle for material_depth().
VectorX material_depth_exhaustive(const Positions& rest, const Triangles& surface, const std::vector<Index>& nodes);

}  // namespace sinew::collision
