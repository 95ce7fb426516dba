#pragma once
/// @file closed_surface.hpp
/// A closed triangle surface that answers "is this point inside?" and "how far is it?": the
/// boundary of a region to tetrahedralize (docs/surface-input.md, regions).

#include <limits>
#include <memory>
#include <string>

#include "sinew/core/types.hpp"
#include "sinew/surface/surface_mesh.hpp"

namespace sinew::surface {

/// Axis-aligned bounds (length).
struct Bounds {
  Vector3 min = Vector3::Constant(std::numeric_limits<double>::infinity());
  Vector3 max = Vector3::Constant(-std::numeric_limits<double>::infinity());
  bool empty() const { return !(min.array() <= max.array()).all(); }
  void extend(const Vector3& x) { min = min.cwiseMin(x); max = max.cwiseMax(x); }
  void extend(const Bounds& b) { if (!b.empty()) { extend(b.min); extend(b.max); } }
};

/// Inside and distance queries on a closed 2-manifold (CGAL AABB tree). Not thread-safe.
class ClosedSurface {
 public:
  /// Throws InputError naming `what` (e.g. "surface \"femur\" (VH_M_Knee_R.glb, mesh
  /// VH_M_femur_R)") when the surface is empty, has a NaN or infinite vertex, is open (its
  /// boundary edges counted, with the location of one), non-manifold, or encloses no volume. A
  /// surface whose triangles all face inward is turned outward.
  ClosedSurface(const SurfaceMesh& mesh, const std::string& what);
  ~ClosedSurface();
  ClosedSurface(ClosedSurface&&) noexcept;
  ClosedSurface& operator=(ClosedSurface&&) noexcept;
  ClosedSurface(const ClosedSurface&) = delete;
  ClosedSurface& operator=(const ClosedSurface&) = delete;

  /// True strictly inside or on the surface.
  bool contains(const Vector3& point) const;
  /// Distance to the surface (length), >= 0 (no inside test).
  double distance(const Vector3& point) const;
  /// Distance to the surface (length), negative inside.
  double signed_distance(const Vector3& point) const;
  /// Enclosed volume (length^3), > 0.
  double volume() const;
  Bounds bounds() const;
  /// The surface, oriented outward.
  const SurfaceMesh& mesh() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sinew::surface
