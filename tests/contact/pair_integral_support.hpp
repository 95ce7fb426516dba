#pragma once
/// @file pair_integral_support.hpp
/// Random and adversarial triangle–tet pairs and the value, gradient and Hessian of one pair by
/// method, shared by the pair-integral test files.

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "sinew/collision/clip_triangle_tet.hpp"
#include "sinew/collision/polygon_quadrature.hpp"
#include "sinew/contact/pair_integral.hpp"
#include "support/fd_check.hpp"
#include "support/tet_geometry.hpp"

namespace sinew::contact::pair_testing {

namespace st = sinew::testing;
using collision::ClipPolygon;
using collision::CollocationPoints;
using st::polygon_area;
using st::random_tet;
using st::reference_barycentric;
using st::triangle_area;
using st::unit_tet;

// ---------------------------------------------------------------------------------------------
// Helpers

/// A random pair whose clip polygon has at least `min_area` area: a triangle of random size
/// near the tet's centroid, random non-negative depths (some exactly zero).
inline PairGeometry random_pair(std::mt19937& rng, double min_area = 1e-3) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), u01(0.0, 1.0);
  for (;;) {
    PairGeometry pg;
    pg.tet = random_tet(rng);
    const double size = 0.3 + 1.2 * u01(rng);
    const Eigen::RowVector3d c = pg.tet.colwise().mean() + 0.3 * Eigen::RowVector3d(u(rng), u(rng), u(rng));
    for (int i = 0; i < 3; ++i) pg.triangle.row(i) = c + size * Eigen::RowVector3d(u(rng), u(rng), u(rng));
    for (int a = 0; a < 4; ++a) pg.depth[a] = u01(rng) < 0.2 ? 0.0 : u01(rng);
    const ClipPolygon p = collision::clip_triangle_tet(pg.triangle, pg.tet);
    if (p.count >= 3 && polygon_area(p) > min_area) return pg;
  }
}

/// A random pair for the point method: `inside` (1..3) triangle vertices at random interior
/// points of the tet, the others outside it; random non-negative depths.
inline PairGeometry random_point_pair(std::mt19937& rng, int inside) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), u01(0.0, 1.0);
  PairGeometry pg;
  pg.tet = random_tet(rng);
  for (int i = 0; i < 3; ++i) {
    if (i < inside) {
      Eigen::Vector4d xi(0.05 + u01(rng), 0.05 + u01(rng), 0.05 + u01(rng), 0.05 + u01(rng));
      xi /= xi.sum();
      pg.triangle.row(i) = (pg.tet.transpose() * xi).transpose();
    } else {
      for (;;) {
        const Eigen::RowVector3d x = pg.tet.colwise().mean() + 1.5 * Eigen::RowVector3d(u(rng), u(rng), u(rng));
        if (reference_barycentric(x.transpose(), pg.tet).minCoeff() < -0.05) {
          pg.triangle.row(i) = x;
          break;
        }
      }
    }
  }
  // Which vertices are inside should not follow the local numbering.
  const int roll = static_cast<int>(u01(rng) * 3) % 3;
  Matrix3 rolled;
  for (int i = 0; i < 3; ++i) rolled.row((i + roll) % 3) = pg.triangle.row(i);
  pg.triangle = rolled;
  for (int a = 0; a < 4; ++a) pg.depth[a] = u01(rng) < 0.2 ? 0.0 : u01(rng);
  return pg;
}

/// For the method under test: a pair with a non-empty polygon (area) or inside vertices (point).
inline PairGeometry random_method_pair(std::mt19937& rng, bool area, int trial) {
  return area ? random_pair(rng) : random_point_pair(rng, 1 + trial % 3);
}

inline PairVector to_vector(const PairGeometry& pg) {
  PairVector v;
  for (int k = 0; k < 3; ++k) v.segment<3>(3 * k) = pg.triangle.row(k).transpose();
  for (int k = 0; k < 4; ++k) v.segment<3>(9 + 3 * k) = pg.tet.row(k).transpose();
  return v;
}

inline PairGeometry from_vector(const Eigen::VectorXd& v, const Eigen::Vector4d& depth,
                                const Vector3& multiplier = Vector3::Zero()) {
  PairGeometry pg;
  pg.multiplier = multiplier;
  for (int k = 0; k < 3; ++k) pg.triangle.row(k) = v.segment<3>(3 * k).transpose();
  for (int k = 0; k < 4; ++k) pg.tet.row(k) = v.segment<3>(9 + 3 * k).transpose();
  pg.depth = depth;
  return pg;
}

/// The pair integral with the clip (or the inside test) recomputed for this configuration.
inline double pair_value(const PairGeometry& pg, bool area) {
  if (area) return area_integral(pg, collision::clip_triangle_tet(pg.triangle, pg.tet));
  return point_integral(pg, collision::triangle_vertices_in_tet(pg.triangle, pg.tet));
}

inline PairVector pair_gradient(const PairGeometry& pg, bool area) {
  PairVector g;
  if (area)
    area_integral_gradient(pg, collision::clip_triangle_tet(pg.triangle, pg.tet), g);
  else
    point_integral_gradient(pg, collision::triangle_vertices_in_tet(pg.triangle, pg.tet), g);
  return g;
}

struct Derivatives {
  double value = 0;
  PairVector gradient;
  PairMatrix hessian;
};

inline Derivatives pair_hessian(const PairGeometry& pg, bool area, PairHessian kind) {
  Derivatives d;
  if (area)
    d.value = area_integral_hessian(pg, collision::clip_triangle_tet(pg.triangle, pg.tet), kind, d.gradient,
                                    d.hessian);
  else
    d.value = point_integral_hessian(pg, collision::triangle_vertices_in_tet(pg.triangle, pg.tet), kind,
                                     d.gradient, d.hessian);
  return d;
}

/// Brute force ∫_{t ∩ e} g² da: the centroids of the n² sub-triangles of a uniform subdivision of
/// the triangle, kept when inside the tet (tet_barycentric >= 0), g = depth . xi, weight A / n².
inline double sampled_integral(const PairGeometry& pg, int n) {
  const Vector3 q0 = pg.triangle.row(0), q1 = pg.triangle.row(1), q2 = pg.triangle.row(2);
  double sum = 0;
  auto add = [&](double u, double v) {
    const Vector3 x = q0 + u * (q1 - q0) + v * (q2 - q0);
    const Eigen::Vector4d xi = collision::tet_barycentric(x, pg.tet);
    if ((xi.array() >= 0.0).all()) {
      const double g = pg.depth.dot(xi);
      sum += g * g;
    }
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j) {
      add((i + 1.0 / 3) / n, (j + 1.0 / 3) / n);
      if (i + j + 1 < n) add((i + 2.0 / 3) / n, (j + 2.0 / 3) / n);
    }
  return triangle_area(pg.triangle) * sum / (static_cast<double>(n) * n);
}

/// Smallest |xi_f| of any triangle vertex: how close the point method is to a switch.
inline double min_abs_barycentric(const PairGeometry& pg) {
  double m = 1e300;
  for (int i = 0; i < 3; ++i)
    m = std::min(m, reference_barycentric(pg.triangle.row(i).transpose(), pg.tet).cwiseAbs().minCoeff());
  return m;
}

inline bool same_combinatorics(const ClipPolygon& a, const ClipPolygon& b) {
  if (a.count != b.count) return false;
  for (int k = 0; k < a.count; ++k)
    if (!(a.provenance[static_cast<std::size_t>(k)] == b.provenance[static_cast<std::size_t>(k)])) return false;
  return true;
}

inline bool same_points(const CollocationPoints& a, const CollocationPoints& b) {
  if (a.count != b.count) return false;
  for (int k = 0; k < a.count; ++k)
    if (a.vertex[static_cast<std::size_t>(k)] != b.vertex[static_cast<std::size_t>(k)]) return false;
  return true;
}

/// True when every configuration within ±h of pg in one of the 21 variables has the same clip
/// polygon combinatorics (area method, non-empty) or the same inside vertices (point method):
/// there the integral is smooth and its Hessian can be compared with differences.
inline bool combinatorics_stable(const PairGeometry& pg, bool area, double h) {
  const PairVector x0 = to_vector(pg);
  const ClipPolygon p0 = collision::clip_triangle_tet(pg.triangle, pg.tet);
  const CollocationPoints c0 = collision::triangle_vertices_in_tet(pg.triangle, pg.tet);
  bool stable = area ? p0.count >= 3 : c0.count > 0;
  for (int i = 0; i < kPairVariables && stable; ++i)
    for (const double s : {-h, h}) {
      PairVector x = x0;
      x[i] += s;
      const PairGeometry q = from_vector(x, pg.depth);
      stable = stable && (area ? same_combinatorics(p0, collision::clip_triangle_tet(q.triangle, q.tet))
                               : same_points(c0, collision::triangle_vertices_in_tet(q.triangle, q.tet)));
    }
  return stable;
}

inline const char* method_name(bool area) { return area ? "area" : "point"; }


}  // namespace sinew::contact::pair_testing
