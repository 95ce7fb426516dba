#pragma once
/// @file point_triangle_distance.hpp
/// Exact distance from a point to a closed triangle in 3D, with the closest point, its
/// barycentric coordinates and the Voronoi region (vertex, edge or face) it lies in. Robust for
/// degenerate triangles (collinear or coincident vertices): the closest point is then searched on
/// the three edges, each of which may itself have zero length. Heap-free.

#include "sinew/core/types.hpp"

namespace sinew::collision {

/// Voronoi region of the triangle (a, b, c) containing the closest point.
enum class TriangleRegion { VertexA, VertexB, VertexC, EdgeAB, EdgeBC, EdgeCA, Face };

/// Result of closest_point_on_triangle().
struct PointTriangleResult {
  double squared_distance = 0.0;  ///< |p - closest|^2, length unit squared
  Vector3 closest = Vector3::Zero();  ///< closest point of the triangle, length unit
  /// Barycentric coordinates (of a, b, c) of `closest`: all >= 0, sum 1; closest = Σ λ_i v_i.
  Vector3 barycentric = Vector3::Zero();
  TriangleRegion region = TriangleRegion::Face;
};

/// Closest point to p on the closed triangle (a, b, c) (all length unit). Exact up to rounding:
/// Voronoi-region classification (Ericson, Real-Time Collision Detection 5.1.5) for a
/// non-degenerate triangle; for a degenerate one (|(b-a)x(c-a)|^2 <= 1e-24 * max edge^4) the
/// nearest of the three edge segments. A point that coincides with a vertex gets that vertex
/// exactly (distance exactly 0).
PointTriangleResult closest_point_on_triangle(const Vector3& p, const Vector3& a, const Vector3& b, const Vector3& c);

/// Squared distance (length unit squared) from p to the closed triangle (a, b, c).
inline double point_triangle_squared_distance(const Vector3& p, const Vector3& a, const Vector3& b,
                                              const Vector3& c) {
  return closest_point_on_triangle(p, a, b, c).squared_distance;
}

/// Closest point to p on the closed segment [a, b] (length unit); t in [0, 1] is returned with
/// closest = (1 - t) a + t b. A zero-length segment gives t = 0.
Vector3 closest_point_on_segment(const Vector3& p, const Vector3& a, const Vector3& b, double& t);

}  // namespace sinew::collision
