/// @file surface_checks.cpp

#include "sinew/surface/surface_checks.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace sinew::surface {

SurfaceTopology surface_topology(const SurfaceMesh& mesh) {
  std::vector<std::uint64_t> edges;
  edges.reserve(static_cast<std::size_t>(mesh.triangles.rows()) * 3);
  for (Index t = 0; t < mesh.triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const auto a = static_cast<std::uint32_t>(mesh.triangles(t, k));
      const auto b = static_cast<std::uint32_t>(mesh.triangles(t, (k + 1) % 3));
      edges.push_back((std::uint64_t{std::min(a, b)} << 32) | std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  SurfaceTopology topology;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1) ++topology.boundary_edges;
    if (j - i > 2) ++topology.non_manifold_edges;
    i = j;
  }
  return topology;
}

namespace {

/// The corners of triangle `t`, in its winding order.
std::array<Vector3, 3> corners(const SurfaceMesh& mesh, Index t) {
  return {mesh.vertices.row(mesh.triangles(t, 0)).transpose(), mesh.vertices.row(mesh.triangles(t, 1)).transpose(),
          mesh.vertices.row(mesh.triangles(t, 2)).transpose()};
}

}  // namespace

double enclosed_volume(const SurfaceMesh& mesh) {
  double six_volume = 0;
  for (Index t = 0; t < mesh.triangles.rows(); ++t) {
    const auto [a, b, c] = corners(mesh, t);
    six_volume += a.dot(b.cross(c));
  }
  return six_volume / 6;
}

double surface_area(const SurfaceMesh& mesh) {
  double twice_area = 0;
  for (Index t = 0; t < mesh.triangles.rows(); ++t) {
    const auto [a, b, c] = corners(mesh, t);
    twice_area += (b - a).cross(c - a).norm();
  }
  return twice_area / 2;
}

}  // namespace sinew::surface
