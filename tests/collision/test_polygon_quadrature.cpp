#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "sinew/collision/clip_triangle_tet.hpp"
#include "sinew/collision/polygon_quadrature.hpp"
#include "support/tet_geometry.hpp"

using namespace sinew;
using namespace sinew::collision;

namespace {

using sinew::testing::random_tet;
using sinew::testing::reference_barycentric;
using sinew::testing::TetMatrix;

/// Radon's 7-point rule on a triangle (exact up to degree 5): barycentric points and weights.
double radon7(const Vector3& a, const Vector3& b, const Vector3& c,
              const std::function<double(const Vector3&)>& f) {
  const double s15 = std::sqrt(15.0);
  const double a1 = (6 - s15) / 21, b1 = (9 + 2 * s15) / 21, w1 = (155 - s15) / 1200;
  const double a2 = (6 + s15) / 21, b2 = (9 - 2 * s15) / 21, w2 = (155 + s15) / 1200;
  auto at = [&](double l0, double l1, double l2) { return f(l0 * a + l1 * b + l2 * c); };
  const double sum = 9.0 / 40 * at(1.0 / 3, 1.0 / 3, 1.0 / 3) +
                     w1 * (at(a1, a1, b1) + at(a1, b1, a1) + at(b1, a1, a1)) +
                     w2 * (at(a2, a2, b2) + at(a2, b2, a2) + at(b2, a2, a2));
  return 0.5 * (b - a).cross(c - a).norm() * sum;
}

/// Integral over the polygon by a fan from its vertex centroid (a different triangulation)
/// with Radon's rule on each piece, subdivided k x k (every sub-triangle exact as well).
double reference_integral(const std::vector<Vector3>& poly,
                          const std::function<double(const Vector3&)>& f, int k) {
  Vector3 center = Vector3::Zero();
  for (const auto& v : poly) center += v / static_cast<double>(poly.size());
  double total = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vector3 a = center, b = poly[i], c = poly[(i + 1) % poly.size()];
    for (int p = 0; p < k; ++p) {
      for (int q = 0; p + q < k; ++q) {
        auto pt = [&](double u, double v) { return a + u / k * (b - a) + v / k * (c - a); };
        total += radon7(pt(p, q), pt(p + 1, q), pt(p, q + 1), f);
        if (p + q + 1 < k) total += radon7(pt(p + 1, q), pt(p + 1, q + 1), pt(p, q + 1), f);
      }
    }
  }
  return total;
}

/// Random clip polygons with at least `min_vertices` vertices.
std::vector<std::pair<ClipPolygon, TetMatrix>> random_polygons(int count, int min_vertices) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<std::pair<ClipPolygon, TetMatrix>> out;
  while (static_cast<int>(out.size()) < count) {
    const TetMatrix tet = random_tet(rng);
    Matrix3 tri;
    for (int i = 0; i < 3; ++i) tri.row(i) = Eigen::RowVector3d(u(rng), u(rng), u(rng)) * 1.2;
    const ClipPolygon p = clip_triangle_tet(tri, tet);
    if (p.count >= min_vertices) out.emplace_back(p, tet);
  }
  return out;
}

}  // namespace

TEST(PolygonQuadrature, MatchesHighOrderRuleOnClipPolygons) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  int with_many_vertices = 0;
  for (const auto& [p, tet] : random_polygons(60, 3)) {
    const Eigen::Vector4d g_nodes(u(rng), u(rng), u(rng), u(rng));
    const PolygonIntegral exact = polygon_quadratic_integral(p, g_nodes);
    std::vector<Vector3> poly(p.vertices.begin(), p.vertices.begin() + p.count);
    auto g2 = [&](const Vector3& x) {
      const double g = g_nodes.dot(reference_barycentric(x, tet));
      return g * g;
    };
    const double reference = reference_integral(poly, g2, 1);
    const double reference_fine = reference_integral(poly, g2, 20);
    const double area = reference_integral(poly, [](const Vector3&) { return 1.0; }, 1);
    EXPECT_NEAR(exact.integral, reference, 1e-10 * std::max(1.0, std::abs(reference)));
    EXPECT_NEAR(exact.integral, reference_fine, 1e-10 * std::max(1.0, std::abs(reference)));
    EXPECT_NEAR(exact.area, area, 1e-13);
    with_many_vertices += p.count >= 5;
  }
  EXPECT_GT(with_many_vertices, 5);
}

TEST(PolygonQuadrature, MatchesFineMidpointSampling) {
  // Independent of any quadrature rule: centroids of 200 x 200 sub-triangles per fan triangle.
  // The midpoint rule's O(h²) error bounds the tolerance.
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (const auto& [p, tet] : random_polygons(5, 4)) {
    const Eigen::Vector4d g_nodes(u(rng), u(rng), u(rng), u(rng));
    const PolygonIntegral exact = polygon_quadratic_integral(p, g_nodes);
    const int n = 200;
    double sampled = 0;
    for (int k = 1; k + 1 < p.count; ++k) {
      const Vector3 a = p.vertices[0], b = p.vertices[k], c = p.vertices[k + 1];
      const double cell = 0.5 * (b - a).cross(c - a).norm() / (n * n);
      auto add = [&](double s, double t) {
        const Vector3 x = a + s / n * (b - a) + t / n * (c - a);
        const double g = g_nodes.dot(reference_barycentric(x, tet));
        sampled += cell * g * g;
      };
      for (int i = 0; i < n; ++i) {
        for (int j = 0; i + j < n; ++j) {
          add(i + 1.0 / 3, j + 1.0 / 3);
          if (i + j + 1 < n) add(i + 2.0 / 3, j + 2.0 / 3);
        }
      }
    }
    EXPECT_NEAR(exact.integral, sampled, 1e-4 * std::max(1.0, std::abs(exact.integral)));
  }
}

TEST(PolygonQuadrature, InvariantToTheFanStartingVertex) {
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (const auto& [p, tet] : random_polygons(30, 4)) {
    const Eigen::Vector4d g_nodes(u(rng), u(rng), u(rng), u(rng));
    const PolygonIntegral base = polygon_quadratic_integral(p, g_nodes);
    for (int shift = 1; shift < p.count; ++shift) {
      ClipPolygon rotated = p;
      for (int k = 0; k < p.count; ++k) {
        const auto from = static_cast<std::size_t>((k + shift) % p.count);
        rotated.vertices[static_cast<std::size_t>(k)] = p.vertices[from];
        rotated.barycentric[static_cast<std::size_t>(k)] = p.barycentric[from];
      }
      const PolygonIntegral r = polygon_quadratic_integral(rotated, g_nodes);
      EXPECT_NEAR(r.integral, base.integral, 1e-13 * std::max(1.0, base.integral));
      EXPECT_NEAR(r.area, base.area, 1e-14);
    }
  }
}

TEST(PolygonQuadrature, ConstantFieldGivesValueSquaredTimesArea) {
  for (const auto& [p, tet] : random_polygons(20, 3)) {
    const PolygonIntegral r = polygon_quadratic_integral(p, Eigen::Vector4d::Constant(1.7));
    EXPECT_NEAR(r.integral, 1.7 * 1.7 * r.area, 1e-13);
    // Area by the vector-area (shoelace) formula.
    Vector3 vector_area = Vector3::Zero();
    for (int k = 0; k < p.count; ++k) {
      vector_area += 0.5 * p.vertices[k].cross(p.vertices[(k + 1) % p.count]);
    }
    EXPECT_NEAR(r.area, vector_area.norm(), 1e-13);
  }
}

TEST(PolygonQuadrature, ClosedFormOnAUnitSquareAndHexagon) {
  const std::vector<Vector3> square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  std::vector<double> g;
  for (const auto& v : square) g.push_back(1 + 2 * v.x() - v.y());
  // (1 + 2x - y)² = 1 + 4x² + y² + 4x - 2y - 4xy; integrals: 1 + 4/3 + 1/3 + 2 - 1 - 1 = 8/3.
  const PolygonIntegral r = polygon_quadratic_integral(square, g);
  EXPECT_NEAR(r.integral, 8.0 / 3.0, 1e-15);
  EXPECT_NEAR(r.area, 1.0, 1e-15);

  // Regular hexagon of circumradius 1 in a tilted plane, g = distance along its x axis:
  // ∫ x² da = (5 sqrt(3) / 16) R⁴.
  const Vector3 e1 = Vector3(1, 1, 0).normalized(), e2 = Vector3(-1, 1, 2).normalized();
  std::vector<Vector3> hex;
  std::vector<double> gx;
  for (int k = 0; k < 6; ++k) {
    const double a = k * M_PI / 3;
    hex.push_back(Vector3(0.3, -0.2, 1.0) + std::cos(a) * e1 + std::sin(a) * e2);
    gx.push_back(std::cos(a));
  }
  const PolygonIntegral h = polygon_quadratic_integral(hex, gx);
  EXPECT_NEAR(h.integral, 5.0 * std::sqrt(3.0) / 16.0, 1e-14);
  EXPECT_NEAR(h.area, 3.0 * std::sqrt(3.0) / 2.0, 1e-14);
}

TEST(PolygonQuadrature, FewerThanThreeVerticesIsZero) {
  const std::vector<Vector3> two{{0, 0, 0}, {1, 0, 0}};
  const std::vector<double> g{1, 2};
  const PolygonIntegral r = polygon_quadratic_integral(two, g);
  EXPECT_EQ(r.integral, 0.0);
  EXPECT_EQ(r.area, 0.0);
  EXPECT_EQ(polygon_quadratic_integral(ClipPolygon{}, Eigen::Vector4d::Ones()).area, 0.0);
}
