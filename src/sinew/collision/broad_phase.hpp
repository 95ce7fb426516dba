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

/// A bounding-volume hierarchy over some of the tets: primitive i of `tree` is tet `tets[i]`.
struct TetSubsetTree {
  std::vector<Index> tets;  ///< global tet indices, in the tree's primitive numbering
  AabbTree tree;            ///< built or refit from subset_boxes(x, tets_array, tets)
};

/// One box per tet of the subset `subset` (global indices into `tets`), in that order.
std::vector<Aabb> subset_boxes(const Positions& x, const Tets& tets, const std::vector<Index>& subset);

/// Candidate pairs as triangle_tet_candidates above, each triangle tested only against some of
/// the trees: triangle f belongs to group triangle_group[f] (#F, 0 .. G-1), and group g is tested
/// against the trees trees[k] for k in trees_of_group[g] (G lists). Pairs that share a node are
/// skipped; the result is sorted (triangle, then tet) and identical for any number of threads, so
/// it is the all-tets candidate list restricted to the trees each group names.
std::vector<std::pair<Index, Index>> triangle_tet_candidates(const Positions& x, const Triangles& triangles,
                                                             const Tets& tets,
                                                             const std::vector<TetSubsetTree>& trees,
                                                             const IndexVector& triangle_group,
                                                             const std::vector<std::vector<int>>& trees_of_group,
                                                             double triangle_inflate = 0.0);

}  // namespace sinew::collision
