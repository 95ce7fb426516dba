#pragma once
/// @file closed_fixtures.hpp
/// Closed triangle surfaces made in memory for the closed-surface, solid, repair and mesher
/// tests: an axis-aligned box, a subdivided icosahedron (a sphere), two surfaces merged into one.

#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "sinew/surface/surface_mesh.hpp"

namespace sinew::testing {

/// The box [lo, hi]: 8 vertices, 12 triangles, counter-clockwise seen from outside.
inline surface::SurfaceMesh box_surface(const Vector3& lo = Vector3::Zero(), const Vector3& hi = Vector3::Ones()) {
  surface::SurfaceMesh mesh;
  mesh.name = "box";
  mesh.vertices.resize(8, 3);
  for (Index v = 0; v < 8; ++v) {
    const int i = (v == 1 || v == 2 || v == 5 || v == 6) ? 1 : 0;  // the corners of unit_cube()
    const int j = (v == 2 || v == 3 || v == 6 || v == 7) ? 1 : 0;
    const int k = v >= 4 ? 1 : 0;
    mesh.vertices.row(v) << (i ? hi.x() : lo.x()), (j ? hi.y() : lo.y()), (k ? hi.z() : lo.z());
  }
  mesh.triangles.resize(12, 3);
  mesh.triangles << 0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,  //
      3, 7, 6, 3, 6, 2, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5;
  return mesh;
}

/// A sphere of `radius` about `center`: the icosahedron with every triangle split into four
/// `subdivisions` times, vertices pushed onto the sphere (20 * 4^s triangles, outward). Inscribed:
/// its vertices lie on the sphere and its volume is a little below (4/3) pi r^3.
inline surface::SurfaceMesh icosphere(double radius, int subdivisions = 3, const Vector3& center = Vector3::Zero()) {
  const double p = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vector3> vertices{{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
                                {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
  for (Vector3& v : vertices) v.normalize();
  std::vector<std::array<Index, 3>> triangles{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                              {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                              {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                              {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<Index, Index>, Index> midpoint;
    const auto middle = [&](Index a, Index b) {
      const auto key = std::minmax(a, b);
      const auto [it, added] = midpoint.try_emplace({key.first, key.second}, static_cast<Index>(vertices.size()));
      if (added) vertices.push_back((vertices[static_cast<std::size_t>(a)] + vertices[static_cast<std::size_t>(b)]).normalized());
      return it->second;
    };
    std::vector<std::array<Index, 3>> finer;
    for (const auto& [a, b, c] : triangles) {
      const Index ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
      finer.insert(finer.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    triangles = std::move(finer);
  }
  surface::SurfaceMesh mesh;
  mesh.name = "sphere";
  mesh.vertices.resize(static_cast<Index>(vertices.size()), 3);
  for (std::size_t v = 0; v < vertices.size(); ++v) mesh.vertices.row(static_cast<Index>(v)) = (center + radius * vertices[v]).transpose();
  mesh.triangles.resize(static_cast<Index>(triangles.size()), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) mesh.triangles(static_cast<Index>(t), k) = triangles[t][static_cast<std::size_t>(k)];
  }
  return mesh;
}

/// Both surfaces as one SurfaceMesh (b's vertices after a's; no vertex joined).
inline surface::SurfaceMesh merged(const surface::SurfaceMesh& a, const surface::SurfaceMesh& b) {
  surface::SurfaceMesh mesh;
  mesh.name = a.name + "+" + b.name;
  mesh.vertices.resize(a.vertices.rows() + b.vertices.rows(), 3);
  mesh.vertices << a.vertices, b.vertices;
  mesh.triangles.resize(a.triangles.rows() + b.triangles.rows(), 3);
  mesh.triangles << a.triangles, (b.triangles.array() + static_cast<Index>(a.vertices.rows())).matrix();
  return mesh;
}

/// `mesh` with triangle `t` removed.
inline surface::SurfaceMesh without_triangle(const surface::SurfaceMesh& mesh, Index t) {
  surface::SurfaceMesh result = mesh;
  result.triangles.resize(mesh.triangles.rows() - 1, 3);
  result.triangles << mesh.triangles.topRows(t), mesh.triangles.bottomRows(mesh.triangles.rows() - t - 1);
  return result;
}

}  // namespace sinew::testing
