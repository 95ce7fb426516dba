#pragma once
/// @file broad_phase.hpp
/// Broad phase of the triangle-tetrahedron contact (dissertation section 5.4.5): the boundary
/// triangles of every body are tested against a bounding-volume hierarchy over the tetrahedra of
/// every body (self-contact included). Sees only positions and connectivity.

#include <utility>
#include <vector>

#include "sinew/collision/aabb.hpp"
#include "sinew/collision/aabb_tree.hpp"
#include "sinew/core/types.hpp"

namespace sinew::collision {

/// One box per tet: boxes[t] bounds the 4 nodes of tets.row(t) in x (#V x 3), grown by
/// `inflate` (>= 0, length unit) on every side. Size #T.
std::vector<Aabb> tet_boxes(const Positions& x, const Tets& tets, double inflate = 0.0);

/// One box per triangle: boxes[f] bounds the 3 nodes of triangles.row(f) in x (#V x 3), grown by
/// `inflate` (>= 0, length unit). Size #F.
std::vector<Aabb> triangle_boxes(const Positions& x, const Triangles& triangles, double inflate = 0.0);

/// True when triangle f and tet t have a node in common (such pairs are never in contact).
bool shares_node(const Triangles& triangles, Index f, const Tets& tets, Index t);

/// Candidate (triangle, tet) pairs: every pair whose boxes overlap, the triangle box being that
/// of triangles.row(f) in x grown by `triangle_inflate`, the tet box being the one stored in
/// `tet_tree` (which must have been built or refit from tet_boxes(x, tets, ...)); pairs that share
/// a node are skipped. Sorted lexicographically (triangle, then tet), identical for any number
/// of threads. Runs in parallel over fixed blocks of triangles (TBB); each triangle's tets are
/// sorted, and the blocks concatenated in order. x: #V x 3; triangles: #F x 3; tets: #T x 4
/// (indices into x). Cost O(F log T + k log m), m the most candidates of one triangle.
std::vector<std::pair<Index, Index>> triangle_tet_candidates(const Positions& x, const Triangles& triangles,
                                                             const Tets& tets, const AabbTree& tet_tree,
                                                             double triangle_inflate = 0.0);

}  // namespace sinew::collision
