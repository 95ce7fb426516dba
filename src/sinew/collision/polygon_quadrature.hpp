#pragma once
/// @file polygon_quadrature.hpp
/// Exact integral of the square of a linear field over a planar convex polygon (the contact
/// energy integrand g^2 over triangle ∩ tet, docs/theory.md, dissertation eqs. 5.49-5.54):
/// a triangle fan from vertex 0 with the degree-2 exact rule on each fan triangle,
///   ∫_T g² da = A/6 (g_a² + g_b² + g_c² + g_a g_b + g_b g_c + g_c g_a).
/// No heap.

#include <span>

#include "sinew/collision/clip_triangle_tet.hpp"
#include "sinew/core/types.hpp"

namespace sinew::collision {

/// Integral of g² and area of a polygon.
struct PolygonIntegral {
  double integral = 0.0;  ///< ∫ g² da, in (unit of g)² x length²
  double area = 0.0;      ///< polygon area, length²
};

/// `vertices`: the n polygon vertices in order (3D, planar, convex), n = vertices.size();
/// `values`: g at each vertex (same length), g linear on the polygon's plane.
/// n < 3 gives zero. Exact for a linear g up to round-off.
PolygonIntegral polygon_quadratic_integral(std::span<const Vector3> vertices,
                                           std::span<const double> values);

/// The same over a clip polygon, with g = nodal_values . xi (xi the barycentric coordinates
/// of the point in the tet, nodal_values the 4 values of g at the tet's vertices).
PolygonIntegral polygon_quadratic_integral(const ClipPolygon& polygon,
                                           const Eigen::Vector4d& nodal_values);

}  // namespace sinew::collision
