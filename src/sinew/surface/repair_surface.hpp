#pragma once
/// @file repair_surface.hpp
/// Repair of a scanned triangle surface before it bounds a region (docs/surface-input.md,
/// preparation): degenerate and duplicate triangles dropped, holes filled, the triangles remeshed
/// to a target edge length, self-intersections found.

#include <string>
#include <vector>

#include "sinew/core/types.hpp"
#include "sinew/surface/surface_mesh.hpp"

namespace sinew::surface {

struct RepairOptions {
  bool drop_degenerate = true;   ///< drop triangles of (near) zero area
  bool drop_duplicates = true;   ///< drop triangles with the same three vertices as an earlier one
  bool fill_holes = true;        ///< close every hole (boundary loop) with a refined patch
  /// > 0: after the holes are filled, the triangles are remeshed isotropically (CGAL's
  /// isotropic_remeshing: splits, collapses, flips and tangential smoothing) toward this edge
  /// length (length); 0 keeps the triangles as they are.
  double remesh_edge_length = 0;
};

/// Two triangles of one surface that cross each other, and a point where they do.
struct SelfIntersection {
  Index triangle_a = 0, triangle_b = 0;  ///< 0-based indices among the surface's manifold triangles
  Vector3 location = Vector3::Zero();     ///< a point of both: the mean of the corners of their intersection (length)
};

/// What repair_surface changed.
struct RepairReport {
  Index degenerate_dropped = 0;   ///< triangles of zero area (or repeated vertices)
  Index duplicates_dropped = 0;   ///< triangles repeating another's vertices
  Index holes_filled = 0;         ///< boundary loops closed
  Index triangles_added = 0;      ///< by hole filling
  Index non_manifold_dropped = 0; ///< triangles that would make an edge shared by more than two
  Index triangles_remeshed = 0;   ///< triangles after remeshing (0: not remeshed)
  bool closed_before_remesh = false;  ///< the surface was closed when remeshing started
  double volume_before_remesh = 0;    ///< enclosed volumes before and after remeshing (length^3; see
  double volume_after_remesh = 0;     ///< enclosed_volume), meaningful when it was closed
};

/// Returns the repaired copy of `surface`. Never throws for a bad surface; the caller checks
/// the result (ClosedSurface does). `report` (optional) says what changed.
SurfaceMesh repair_surface(const SurfaceMesh& surface, const RepairOptions& options, RepairReport* report = nullptr);

/// Pairs of triangles that intersect other than at a shared vertex or edge, at most `limit`
/// of them (0 = all).
std::vector<SelfIntersection> find_self_intersections(const SurfaceMesh& surface, std::size_t limit = 10);

}  // namespace sinew::surface
