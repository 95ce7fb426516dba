#pragma once
/// @file surface_checks.hpp
/// Topology and volume of a triangle surface: a region's boundary must be closed
/// (docs/surface-input.md).

#include "sinew/core/types.hpp"
#include "sinew/surface/surface_mesh.hpp"

namespace sinew::surface {

/// Edge use counts on the vertex indices (coincident vertices are already joined by read_surface).
struct SurfaceTopology {
  Index boundary_edges = 0;      ///< edges used by exactly one triangle
  Index non_manifold_edges = 0;  ///< edges used by three or more triangles
  /// Every edge is shared by exactly two triangles.
  bool closed() const { return boundary_edges == 0 && non_manifold_edges == 0; }
};

/// Counts the undirected edges of `mesh.triangles` by their number of uses.
SurfaceTopology surface_topology(const SurfaceMesh& mesh);

/// Signed enclosed volume by the divergence theorem, sum over triangles of x0 . (x1 x x2) / 6,
/// in scene units cubed; positive for triangles counter-clockwise seen from outside. Meaningful
/// for a closed surface.
double enclosed_volume(const SurfaceMesh& mesh);

/// Total area of the triangles, in scene units squared.
double surface_area(const SurfaceMesh& mesh);

}  // namespace sinew::surface
