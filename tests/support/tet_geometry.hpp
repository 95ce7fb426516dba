#pragma once
/// @file tet_geometry.hpp
/// Reference geometry of one triangle and one tet for the clipping, quadrature and pair-integral
/// tests, computed independently of the library: barycentric coordinates by a 4x4 solve, random
/// well-shaped tets, the unit tet, triangle and clip-polygon areas.

#include <cmath>
#include <cstddef>
#include <random>

#include <Eigen/Core>
#include <Eigen/LU>

#include "sinew/collision/clip_triangle_tet.hpp"

namespace sinew::testing {

/// The four vertices of a tet, one per row (the layout of contact::TetVertices).
using TetMatrix = Eigen::Matrix<double, 4, 3>;

/// Barycentric coordinates of `x` in `tet` by a 4x4 solve (independent of the library's
/// per-face formula).
inline Eigen::Vector4d reference_barycentric(const Vector3& x, const TetMatrix& tet) {
  Eigen::Matrix4d m;
  m.topRows<3>() = tet.transpose();
  m.row(3).setOnes();
  Eigen::Vector4d rhs;
  rhs << x, 1.0;
  return m.fullPivLu().solve(rhs);
}

/// The tet (0,0,0), (1,0,0), (0,1,0), (0,0,1).
inline TetMatrix unit_tet() {
  TetMatrix t;
  t << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  return t;
}

/// A well-shaped random tet in [-1, 1]^3 (|det| of the edge matrix > 0.2).
inline TetMatrix random_tet(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (;;) {
    TetMatrix t;
    for (int i = 0; i < 4; ++i) t.row(i) = Eigen::RowVector3d(u(rng), u(rng), u(rng));
    Matrix3 d;
    for (int i = 0; i < 3; ++i) d.row(i) = t.row(i + 1) - t.row(0);
    if (std::abs(d.determinant()) > 0.2) return t;
  }
}

/// Area of the triangle whose vertices are the rows of `t`.
inline double triangle_area(const Matrix3& t) {
  return 0.5 * (t.row(1) - t.row(0)).cross(t.row(2) - t.row(0)).norm();
}

/// Area of a (convex) clip polygon, by a fan from its first vertex.
inline double polygon_area(const collision::ClipPolygon& p) {
  double area = 0;
  for (int k = 1; k + 1 < p.count; ++k) {
    area += 0.5 * (p.vertices[static_cast<std::size_t>(k)] - p.vertices[0])
                      .cross(p.vertices[static_cast<std::size_t>(k + 1)] - p.vertices[0])
                      .norm();
  }
  return area;
}

}  // namespace sinew::testing
