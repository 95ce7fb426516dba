/// @file surface_checks.cpp

#include "sinew/surface/surface_checks.hpp"

#include <algorithm>
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

double enclosed_volume(const SurfaceMesh& mesh) {
  double six_volume = 0;
  for (Index t = 0; t < mesh.triangles.rows(); ++t) {
    const Vector3 a = mesh.vertices.row(mesh.triangles(t, 0)).transpose();
    const Vector3 b = mesh.vertices.row(mesh.triangles(t, 1)).transpose();
    const Vector3 c = mesh.vertices.row(mesh.triangles(t, 2)).transpose();
    six_volume += a.dot(b.cross(c));
  }
  return six_volume / 6;
}

}  // namespace sinew::surface
