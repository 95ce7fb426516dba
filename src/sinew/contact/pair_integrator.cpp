#include "sinew/contact/pair_integrator.hpp"

#include <algorithm>
#include <cmath>

namespace sinew::contact {

bool tet_crosses_triangle_plane(const PairGeometry& pg) {
  const Vector3 a = pg.triangle.row(0);
  const Vector3 normal = (Vector3(pg.triangle.row(1)) - a).cross(Vector3(pg.triangle.row(2)) - a);
  const double length = normal.norm();
  if (!(length > 0)) return true;  // degenerate triangle: let the clip and the integral decide
  double scale = 0;
  for (int k = 1; k < 4; ++k) scale = std::max(scale, (pg.tet.row(k) - pg.tet.row(0)).cwiseAbs().maxCoeff());
  const double tolerance = 1e-12 * scale;
  int below = 0, above = 0, on = 0;
  for (int k = 0; k < 4; ++k) {
    const double d = normal.dot(Vector3(pg.tet.row(k)) - a) / length;
    if (d > tolerance)
      ++above;
    else if (d < -tolerance)
      ++below;
    else
      ++on;
  }
  if (above > 0 && below > 0) return true;
  return on >= 3;
}

bool tet_within_triangle_edges(const PairGeometry& pg) {
  const Vector3 q[3] = {pg.triangle.row(0), pg.triangle.row(1), pg.triangle.row(2)};
  const Vector3 normal = (q[1] - q[0]).cross(q[2] - q[0]);
  if (!(normal.squaredNorm() > 0)) return true;  // degenerate triangle: let the clip decide
  const double scale = std::max(pg.triangle.cwiseAbs().maxCoeff(), pg.tet.cwiseAbs().maxCoeff());
  for (int i = 0; i < 3; ++i) {
    const Vector3& a = q[i];
    const Vector3& b = q[(i + 1) % 3];
    // In the triangle's plane, perpendicular to edge ab, pointing to the opposite vertex.
    const Vector3 inward = normal.cross(b - a);
    const double margin = 1e-9 * inward.norm() * scale;
    bool beyond = true;
    for (int k = 0; k < 4 && beyond; ++k) beyond = inward.dot(Vector3(pg.tet.row(k)) - a) < -margin;
    if (beyond) return false;
  }
  return true;
}

namespace {

// Most candidates of the broad phase are neighbours that merely touch the triangle's plane from
// one side, or lie beside the triangle; the plane and edge tests reject them before clipping.
const PairIntegrator kAreaIntegrator{
    ContactMethod::Area,
    [](const PairGeometry& pg, PairSupport& s) {
      if (!tet_crosses_triangle_plane(pg) || !tet_within_triangle_edges(pg)) return false;
      s.polygon = collision::clip_triangle_tet(pg.triangle, pg.tet);
      return s.polygon.count >= 3;
    },
    [](const PairGeometry& pg, const PairSupport& s) { return area_integral(pg, s.polygon); },
    [](const PairGeometry& pg, const PairSupport& s, PairVector& gradient) {
      return area_integral_gradient(pg, s.polygon, gradient);
    },
    [](const PairGeometry& pg, const PairSupport& s, PairHessian kind, PairUnknowns unknowns, PairVector& gradient,
       PairMatrix& hessian) { return area_integral_hessian(pg, s.polygon, kind, gradient, hessian, unknowns); },
    [](const PairGeometry& pg, const PairSupport& s) { return area_moments(pg, s.polygon); },
};

const PairIntegrator kPointIntegrator{
    ContactMethod::Point,
    [](const PairGeometry& pg, PairSupport& s) {
      s.points = collision::triangle_vertices_in_tet(pg.triangle, pg.tet);
      return s.points.count > 0;
    },
    [](const PairGeometry& pg, const PairSupport& s) { return point_integral(pg, s.points); },
    [](const PairGeometry& pg, const PairSupport& s, PairVector& gradient) {
      return point_integral_gradient(pg, s.points, gradient);
    },
    [](const PairGeometry& pg, const PairSupport& s, PairHessian kind, PairUnknowns unknowns, PairVector& gradient,
       PairMatrix& hessian) { return point_integral_hessian(pg, s.points, kind, gradient, hessian, unknowns); },
    [](const PairGeometry& pg, const PairSupport& s) { return point_moments(pg, s.points); },
};

}  // namespace

const PairIntegrator& pair_integrator(ContactMethod method) {
  return method == ContactMethod::Area ? kAreaIntegrator : kPointIntegrator;
}

}  // namespace sinew::contact
