#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sinew/collision/point_triangle_distance.hpp"

namespace sinew::collision {
namespace {

/// Minimum distance to a dense barycentric sampling of the triangle (n subdivisions per edge).
double sampled_distance(const Vector3& p, const Vector3& a, const Vector3& b, const Vector3& c, int n) {
  double best = 1e300;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double u = double(i) / n, v = double(j) / n;
      best = std::min(best, (p - ((1 - u - v) * a + u * b + v * c)).norm());
    }
  return best;
}

void expect_valid(const PointTriangleResult& r, const Vector3& p, const Vector3& a, const Vector3& b,
                  const Vector3& c) {
  EXPECT_GE(r.barycentric.minCoeff(), 0.0);
  EXPECT_NEAR(r.barycentric.sum(), 1.0, 1e-12);
  const Vector3 q = r.barycentric[0] * a + r.barycentric[1] * b + r.barycentric[2] * c;
  EXPECT_LE((q - r.closest).norm(), 1e-12 * (1 + q.norm()));
  EXPECT_NEAR(r.squared_distance, (p - r.closest).squaredNorm(), 1e-12);
}

TEST(PointTriangleDistance, MatchesDenseSamplingAtRandom) {
  std::mt19937 rng(11);
  std::normal_distribution<double> g(0.0, 1.0);
  const int n = 300;
  for (int trial = 0; trial < 150; ++trial) {
    const Vector3 a(g(rng), g(rng), g(rng)), b(g(rng), g(rng), g(rng)), c(g(rng), g(rng), g(rng));
    const Vector3 p = Vector3(g(rng), g(rng), g(rng)) * 1.5;
    const PointTriangleResult r = closest_point_on_triangle(p, a, b, c);
    expect_valid(r, p, a, b, c);
    const double exact = std::sqrt(r.squared_distance);
    const double sampled = sampled_distance(p, a, b, c, n);
    const double h = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()}) / n;
    EXPECT_LE(exact, sampled + 1e-12);  // the exact minimum is never above a sample
    EXPECT_LE(sampled - exact, h);      // and the sampling comes within its spacing
  }
}

TEST(PointTriangleDistance, EveryVoronoiRegion) {
  const Vector3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  struct Case {
    Vector3 p;
    TriangleRegion region;
    Vector3 closest;
  };
  const Case cases[] = {
      {{-1, -1, 2}, TriangleRegion::VertexA, a},
      {{2, -0.5, -1}, TriangleRegion::VertexB, b},
      {{-0.5, 3, 0.5}, TriangleRegion::VertexC, c},
      {{0.5, -1, 1}, TriangleRegion::EdgeAB, {0.5, 0, 0}},
      {{1, 1, -2}, TriangleRegion::EdgeBC, {0.5, 0.5, 0}},
      {{-1, 0.25, 0}, TriangleRegion::EdgeCA, {0, 0.25, 0}},
      {{0.25, 0.25, 3}, TriangleRegion::Face, {0.25, 0.25, 0}},
  };
  for (const Case& cs : cases) {
    const PointTriangleResult r = closest_point_on_triangle(cs.p, a, b, c);
    EXPECT_EQ(r.region, cs.region) << cs.p.transpose();
    EXPECT_LE((r.closest - cs.closest).norm(), 1e-15) << cs.p.transpose();
    EXPECT_NEAR(r.squared_distance, (cs.p - cs.closest).squaredNorm(), 1e-14);
    expect_valid(r, cs.p, a, b, c);
  }
}

TEST(PointTriangleDistance, PointsOnTheTriangleHaveZeroDistanceVerticesExactly) {
  std::mt19937 rng(5);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const Vector3 a(g(rng), g(rng), g(rng)), b(g(rng), g(rng), g(rng)), c(g(rng), g(rng), g(rng));
    EXPECT_EQ(closest_point_on_triangle(a, a, b, c).squared_distance, 0.0);
    EXPECT_EQ(closest_point_on_triangle(b, a, b, c).squared_distance, 0.0);
    EXPECT_EQ(closest_point_on_triangle(c, a, b, c).squared_distance, 0.0);
    const Vector3 inside = 0.2 * a + 0.3 * b + 0.5 * c;
    const PointTriangleResult r = closest_point_on_triangle(inside, a, b, c);
    EXPECT_LT(r.squared_distance, 1e-24);
    EXPECT_NEAR(r.barycentric[0], 0.2, 1e-9);
    EXPECT_NEAR(r.barycentric[2], 0.5, 1e-9);
  }
}

TEST(PointTriangleDistance, DegenerateTriangles) {
  std::mt19937 rng(9);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const Vector3 a(g(rng), g(rng), g(rng)), b(g(rng), g(rng), g(rng));
    const Vector3 p = Vector3(g(rng), g(rng), g(rng));
    // Collinear (c between a and b, and c beyond b), two coincident vertices, all coincident.
    const Vector3 cs[] = {0.3 * a + 0.7 * b, -0.5 * a + 1.5 * b, a, b};
    for (const Vector3& c : cs) {
      const PointTriangleResult r = closest_point_on_triangle(p, a, b, c);
      ASSERT_TRUE(std::isfinite(r.squared_distance));
      expect_valid(r, p, a, b, c);
      const double sampled = sampled_distance(p, a, b, c, 400);
      const double h = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()}) / 400;
      EXPECT_LE(std::sqrt(r.squared_distance), sampled + 1e-12);
      EXPECT_LE(sampled - std::sqrt(r.squared_distance), h + 1e-12);
    }
    const PointTriangleResult r = closest_point_on_triangle(p, a, a, a);
    EXPECT_EQ(r.closest, a);
    EXPECT_EQ(r.region, TriangleRegion::VertexA);
    EXPECT_DOUBLE_EQ(r.squared_distance, (p - a).squaredNorm());
  }
}

}  // namespace
}  // namespace sinew::collision
