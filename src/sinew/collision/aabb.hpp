#pragma once
/// @file aabb.hpp
/// Axis-aligned bounding boxes (Eigen::AlignedBox3d) and the few helpers the broad phase and
/// the bounding-volume hierarchy need. Coordinates are in the scene's length unit.

#include <Eigen/Geometry>
#include <vector>

#include "sinew/core/types.hpp"

namespace sinew::collision {

/// An axis-aligned box [min, max] in 3D (length unit of the positions it bounds). A
/// default-constructed Aabb is empty (min = +inf, max = -inf) and grows with extend().
using Aabb = Eigen::AlignedBox3d;

/// True when the closed boxes a and b share at least one point (touching counts). An empty
/// box overlaps nothing. O(1), no allocation.
inline bool overlaps(const Aabb& a, const Aabb& b) {
  return (a.min().array() <= b.max().array()).all() && (b.min().array() <= a.max().array()).all();
}

/// The box grown by `margin` (>= 0, length unit) on every side.
inline Aabb inflated(const Aabb& box, double margin) {
  return Aabb(box.min().array() - margin, box.max().array() + margin);
}

/// Squared distance (length unit squared) from point p to the closed box; 0 inside.
inline double squared_distance(const Aabb& box, const Vector3& p) {
  const Vector3 below = (box.min() - p).cwiseMax(0.0);
  const Vector3 above = (p - box.max()).cwiseMax(0.0);
  return below.squaredNorm() + above.squaredNorm();
}

/// Box of the nodes `indices` (any Eigen row/vector of Index, e.g. tets.row(t)) of x (#V x 3),
/// grown by `margin` (>= 0, length unit) on every side.
template <class IndexRow>
Aabb box_of(const Positions& x, const IndexRow& indices, double margin) {
  Aabb box;
  for (int k = 0; k < indices.size(); ++k) box.extend(x.row(indices(k)).transpose());
  return inflated(box, margin);
}

}  // namespace sinew::collision
