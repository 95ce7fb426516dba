/// @file tet_quality.cpp

#include "sinew/mesh/tet_quality.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace sinew::mesh {

TetShape tet_shape(const Positions& x, const Tets& tets, Index t) {
  std::array<Vector3, 4> p;
  for (int k = 0; k < 4; ++k) p[static_cast<std::size_t>(k)] = x.row(tets(t, k)).transpose();
  // Outward (or consistently inward) normal of the face opposite corner k.
  std::array<Vector3, 4> normal;
  double area_sum = 0;
  for (int k = 0; k < 4; ++k) {
    const Vector3& a = p[static_cast<std::size_t>((k + 1) % 4)];
    const Vector3& b = p[static_cast<std::size_t>((k + 2) % 4)];
    const Vector3& c = p[static_cast<std::size_t>((k + 3) % 4)];
    Vector3 n = (b - a).cross(c - a);
    area_sum += 0.5 * n.norm();
    if (n.dot(p[static_cast<std::size_t>(k)] - a) > 0) n = -n;  // away from the opposite corner
    normal[static_cast<std::size_t>(k)] = n.normalized();
  }
  TetShape shape;
  shape.min_dihedral_deg = 180;
  for (int k = 0; k < 4; ++k) {
    for (int l = k + 1; l < 4; ++l) {
      const double cosine = std::clamp(normal[static_cast<std::size_t>(k)].dot(normal[static_cast<std::size_t>(l)]), -1.0, 1.0);
      const double angle = 180.0 - std::acos(cosine) * 180.0 / std::numbers::pi;
      shape.min_dihedral_deg = std::min(shape.min_dihedral_deg, angle);
      shape.max_dihedral_deg = std::max(shape.max_dihedral_deg, angle);
    }
  }
  const Vector3 a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
  const double six_volume = std::abs(a.dot(b.cross(c)));
  if (six_volume == 0 || area_sum == 0) {
    shape.min_dihedral_deg = 0;
    shape.radius_ratio = 0;
    return shape;
  }
  const double inradius = 0.5 * six_volume / area_sum;  // 3V / A
  const double circumradius = (a.squaredNorm() * b.cross(c) + b.squaredNorm() * c.cross(a) + c.squaredNorm() * a.cross(b)).norm() /
                              (2.0 * six_volume);
  shape.radius_ratio = std::clamp(3.0 * inradius / circumradius, 0.0, 1.0);
  return shape;
}

MeshQuality mesh_quality(const Positions& x, const Tets& tets, double sliver_angle_deg) {
  MeshQuality quality;
  double ratio_sum = 0;
  for (Index t = 0; t < tets.rows(); ++t) {
    const TetShape shape = tet_shape(x, tets, t);
    if (shape.min_dihedral_deg < quality.min_dihedral_deg) {
      quality.min_dihedral_deg = shape.min_dihedral_deg;
      quality.worst_tet = t;
    }
    quality.max_dihedral_deg = std::max(quality.max_dihedral_deg, shape.max_dihedral_deg);
    quality.worst_radius_ratio = std::min(quality.worst_radius_ratio, shape.radius_ratio);
    ratio_sum += shape.radius_ratio;
    if (shape.min_dihedral_deg < sliver_angle_deg) ++quality.slivers;
  }
  if (tets.rows() > 0) quality.mean_radius_ratio = ratio_sum / static_cast<double>(tets.rows());
  return quality;
}

}  // namespace sinew::mesh
