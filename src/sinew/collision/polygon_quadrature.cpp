#include "sinew/collision/polygon_quadrature.hpp"

#include <array>
#include <algorithm>
#include <cassert>

namespace sinew::collision {

PolygonIntegral polygon_quadratic_integral(std::span<const Vector3> vertices,
                                           std::span<const double> values) {
  assert(vertices.size() == values.size());
  PolygonIntegral result;
  const std::size_t n = std::min(vertices.size(), values.size());
  if (n < 3) return result;
  const Vector3& xa = vertices[0];
  const double ga = values[0];
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const double area = 0.5 * (vertices[k] - xa).cross(vertices[k + 1] - xa).norm();
    const double gb = values[k], gc = values[k + 1];
    result.area += area;
    result.integral += area / 6.0 * (ga * ga + gb * gb + gc * gc + ga * gb + gb * gc + gc * ga);
  }
  return result;
}

PolygonIntegral polygon_quadratic_integral(const ClipPolygon& polygon,
                                           const Eigen::Vector4d& nodal_values) {
  std::array<double, kMaxClipVertices> g{};
  const auto n = static_cast<std::size_t>(polygon.count);
  for (std::size_t k = 0; k < n; ++k) g[k] = nodal_values.dot(polygon.barycentric[k]);
  return polygon_quadratic_integral(std::span<const Vector3>(polygon.vertices.data(), n),
                                    std::span<const double>(g.data(), n));
}

}  // namespace sinew::collision
