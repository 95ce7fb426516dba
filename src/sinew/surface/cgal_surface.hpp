#pragma once
/// @file cgal_surface.hpp
/// Conversions between sinew's SurfaceMesh and CGAL's Surface_mesh (private to the surface module;
/// only its .cpp files include CGAL).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "sinew/surface/surface_mesh.hpp"

namespace sinew::surface::cgal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

inline Point to_point(const Vector3& x) { return {x.x(), x.y(), x.z()}; }
inline Vector3 to_vector(const Point& p) { return {p.x(), p.y(), p.z()}; }

/// SurfaceMesh -> Surface_mesh: every vertex, then the triangles that CGAL accepts as a
/// manifold face (a triangle that would make an edge non-manifold is counted in `rejected`).
Mesh to_cgal(const SurfaceMesh& surface, Index* rejected = nullptr);

/// Surface_mesh -> SurfaceMesh (garbage collected first), keeping `name`.
SurfaceMesh from_cgal(const Mesh& mesh, const std::string& name);

}  // namespace sinew::surface::cgal
