#pragma once
/// @file aabb_tree.hpp
/// A bounding-volume hierarchy of axis-aligned boxes (dissertation section 5.4.5): built
/// top-down by splitting each node's primitives along the greatest extent of the node's box at
/// the median of the box centers, stored as a flat array of nodes (no pointers), refit
/// bottom-up with the same topology when the primitives move.
///
/// Costs, for n primitives and leaves of at most `leaf_size` primitives:
/// - build(): O(n log n) time (nth_element per level), O(n) memory; depth <= log2(n) + 2.
/// - memory: about 2n/leaf_size nodes plus a copy of the n primitive boxes in leaf order, so a
///   query tests each primitive's own box, not only its leaf's.
/// - refit(): O(n) time, no allocation (children are stored after their parent, so one
///   reverse sweep over the nodes is a bottom-up traversal).
/// - query(): O(log n + k) for k reported primitives on well-shaped meshes (worst case O(n));
///   no allocation (fixed-size traversal stack).
/// - nearest(): branch and bound, typically O(log n) primitive tests; no allocation.
///
/// Usage in contact: build() at every load or time step, refit() at every Newton iteration.

#include <algorithm>
#include <array>
#include <limits>
#include <utility>
#include <vector>

#include "sinew/collision/aabb.hpp"
#include "sinew/core/types.hpp"

namespace sinew::collision {

class AabbTree {
 public:
  /// One node of the flat array. A leaf holds primitives primitive_order()[first, first + count);
  /// an inner node (count == 0) has its two children at nodes()[first] and nodes()[first + 1].
  struct Node {
    Aabb box;
    Index first = 0;
    Index count = 0;
    bool is_leaf() const { return count > 0; }
  };

  AabbTree() = default;
  /// Builds over `boxes` (one box per primitive, primitive i = boxes[i]); see build().
  explicit AabbTree(const std::vector<Aabb>& boxes, int leaf_size = 4) { build(boxes, leaf_size); }

  /// Rebuilds topology and boxes over `boxes` (one per primitive). leaf_size >= 1 is the
  /// maximum number of primitives per leaf. O(n log n).
  void build(const std::vector<Aabb>& boxes, int leaf_size = 4);

  /// Updates every node's box from new primitive boxes, keeping the topology. `boxes` must
  /// have the same size as at build(). O(n), no allocation. Throws std::invalid_argument on a
  /// size mismatch.
  void refit(const std::vector<Aabb>& boxes);

  /// Calls callback(Index primitive) for every primitive whose box overlaps `box` (closed
  /// boxes, touching counts). Order: depth-first, deterministic. No allocation.
  template <class Callback>
  void query(const Aabb& box, Callback&& callback) const;

  /// Appends to `out` every primitive whose box overlaps `box` (does not clear `out`).
  void query(const Aabb& box, std::vector<Index>& out) const {
    query(box, [&out](Index p) { out.push_back(p); });
  }

  /// Branch-and-bound nearest primitive to point p. `squared_distance(Index primitive)` returns
  /// the squared distance from p to that primitive (length unit squared), which must be >= the
  /// squared distance from p to the primitive's box. Returns {primitive, squared distance},
  /// or {-1, +inf} for an empty tree. On ties the first primitive found wins. No allocation.
  template <class SquaredDistance>
  std::pair<Index, double> nearest(const Vector3& p, SquaredDistance&& squared_distance) const;

  Index num_primitives() const { return static_cast<Index>(order_.size()); }
  bool empty() const { return nodes_.empty(); }
  /// The flat node array; nodes()[0] is the root (whose box bounds everything).
  const std::vector<Node>& nodes() const { return nodes_; }
  /// Primitive indices in leaf order (a permutation of 0 .. n-1).
  const std::vector<Index>& primitive_order() const { return order_; }
  /// Box of primitive i as of the last build() or refit().
  const Aabb& primitive_box(Index i) const { return leaf_boxes_[static_cast<std::size_t>(slot_[static_cast<std::size_t>(i)])]; }
  /// Box of the whole set (empty box for an empty tree).
  Aabb bounds() const { return nodes_.empty() ? Aabb() : nodes_[0].box; }

 private:
  /// Maximum depth of a traversal stack; the median split keeps the depth <= log2(n) + 2.
  static constexpr int kStackSize = 128;
  std::vector<Node> nodes_;
  std::vector<Index> order_;
  std::vector<Aabb> leaf_boxes_;  ///< leaf_boxes_[k] = box of primitive order_[k] (leaf order)
  std::vector<Index> slot_;       ///< inverse of order_: slot_[order_[k]] = k
};

template <class Callback>
void AabbTree::query(const Aabb& box, Callback&& callback) const {
  if (nodes_.empty() || !overlaps(nodes_[0].box, box)) return;
  std::array<Index, kStackSize> stack;
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
    if (node.is_leaf()) {
      for (Index k = node.first; k < node.first + node.count; ++k)
        if (overlaps(leaf_boxes_[static_cast<std::size_t>(k)], box)) callback(order_[static_cast<std::size_t>(k)]);
      continue;
    }
    // Push the right child first so the left subtree is visited first (deterministic order).
    for (Index c = node.first + 1; c >= node.first; --c)
      if (overlaps(nodes_[static_cast<std::size_t>(c)].box, box)) stack[top++] = c;
  }
}

template <class SquaredDistance>
std::pair<Index, double> AabbTree::nearest(const Vector3& p, SquaredDistance&& squared_distance_to) const {
  std::pair<Index, double> best{-1, std::numeric_limits<double>::infinity()};
  if (nodes_.empty()) return best;
  std::array<std::pair<Index, double>, kStackSize> stack;
  int top = 0;
  stack[top++] = {0, squared_distance(nodes_[0].box, p)};
  while (top > 0) {
    const auto [n, bound] = stack[--top];
    if (bound >= best.second) continue;
    const Node& node = nodes_[static_cast<std::size_t>(n)];
    if (node.is_leaf()) {
      for (Index k = node.first; k < node.first + node.count; ++k) {
        if (squared_distance(leaf_boxes_[static_cast<std::size_t>(k)], p) >= best.second) continue;
        const Index prim = order_[static_cast<std::size_t>(k)];
        const double d = squared_distance_to(prim);
        if (d < best.second) best = {prim, d};
      }
      continue;
    }
    const double d0 = squared_distance(nodes_[static_cast<std::size_t>(node.first)].box, p);
    const double d1 = squared_distance(nodes_[static_cast<std::size_t>(node.first + 1)].box, p);
    // Push the farther child first so the nearer one is explored first.
    if (d0 <= d1) {
      if (d1 < best.second) stack[top++] = {node.first + 1, d1};
      if (d0 < best.second) stack[top++] = {node.first, d0};
    } else {
      if (d0 < best.second) stack[top++] = {node.first, d0};
      if (d1 < best.second) stack[top++] = {node.first + 1, d1};
    }
  }
  return best;
}

}  // namespace sinew::collision
