// Tests of the per-pair contact integral (src/sinew/contact/pair_integral.hpp): the value against
// the collision module's polygon quadrature and a brute-force fine sampling of ∫ g² over the
// triangle, the point-collocation value by hand, the exact gradient and Hessians against finite
// differences that recompute the clip at every perturbed configuration, and robustness on
// degenerate and badly scaled pairs (GUIDE.md sections 1 and 3).

#include "sinew/contact/pair_integral.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "sinew/collision/clip_triangle_tet.hpp"
#include "sinew/collision/polygon_quadrature.hpp"
#include "support/fd_check.hpp"
#include "support/tet_geometry.hpp"

namespace sinew::contact {
namespace {

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
PairGeometry random_pair(std::mt19937& rng, double min_area = 1e-3) {
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
PairGeometry random_point_pair(std::mt19937& rng, int inside) {
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
PairGeometry random_method_pair(std::mt19937& rng, bool area, int trial) {
  return area ? random_pair(rng) : random_point_pair(rng, 1 + trial % 3);
}

PairVector to_vector(const PairGeometry& pg) {
  PairVector v;
  for (int k = 0; k < 3; ++k) v.segment<3>(3 * k) = pg.triangle.row(k).transpose();
  for (int k = 0; k < 4; ++k) v.segment<3>(9 + 3 * k) = pg.tet.row(k).transpose();
  return v;
}

PairGeometry from_vector(const Eigen::VectorXd& v, const Eigen::Vector4d& depth) {
  PairGeometry pg;
  for (int k = 0; k < 3; ++k) pg.triangle.row(k) = v.segment<3>(3 * k).transpose();
  for (int k = 0; k < 4; ++k) pg.tet.row(k) = v.segment<3>(9 + 3 * k).transpose();
  pg.depth = depth;
  return pg;
}

/// The pair integral with the clip (or the inside test) recomputed for this configuration.
double pair_value(const PairGeometry& pg, bool area) {
  if (area) return area_integral(pg, collision::clip_triangle_tet(pg.triangle, pg.tet));
  return point_integral(pg, collision::triangle_vertices_in_tet(pg.triangle, pg.tet));
}

PairVector pair_gradient(const PairGeometry& pg, bool area) {
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

Derivatives pair_hessian(const PairGeometry& pg, bool area, PairHessian kind) {
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
double sampled_integral(const PairGeometry& pg, int n) {
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
double min_abs_barycentric(const PairGeometry& pg) {
  double m = 1e300;
  for (int i = 0; i < 3; ++i)
    m = std::min(m, reference_barycentric(pg.triangle.row(i).transpose(), pg.tet).cwiseAbs().minCoeff());
  return m;
}

bool same_combinatorics(const ClipPolygon& a, const ClipPolygon& b) {
  if (a.count != b.count) return false;
  for (int k = 0; k < a.count; ++k)
    if (!(a.provenance[static_cast<std::size_t>(k)] == b.provenance[static_cast<std::size_t>(k)])) return false;
  return true;
}

bool same_points(const CollocationPoints& a, const CollocationPoints& b) {
  if (a.count != b.count) return false;
  for (int k = 0; k < a.count; ++k)
    if (a.vertex[static_cast<std::size_t>(k)] != b.vertex[static_cast<std::size_t>(k)]) return false;
  return true;
}

const char* method_name(bool area) { return area ? "area" : "point"; }

// ---------------------------------------------------------------------------------------------
// Values

TEST(PairIntegral, AreaIntegralEqualsThePolygonQuadratureOfTheCollisionModule) {
  std::mt19937 rng(101);
  int many_vertices = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const PairGeometry pg = random_pair(rng);
    const ClipPolygon p = collision::clip_triangle_tet(pg.triangle, pg.tet);
    const double I = area_integral(pg, p);
    const collision::PolygonIntegral ref = collision::polygon_quadratic_integral(p, pg.depth);
    EXPECT_NEAR(I, ref.integral, 1e-12 * std::max(1.0, ref.integral)) << "trial " << trial;
    // The derivative entry points return the same value.
    PairVector g;
    PairMatrix H;
    EXPECT_NEAR(area_integral_gradient(pg, p, g), I, 1e-14 * std::max(1.0, I));
    EXPECT_NEAR(area_integral_hessian(pg, p, PairHessian::Exact, g, H), I, 1e-14 * std::max(1.0, I));
    EXPECT_NEAR(area_integral_hessian(pg, p, PairHessian::GaussNewton, g, H), I, 1e-14 * std::max(1.0, I));
    // Moments: the same area as the collision module; ∫ g da and max g by the fan rule.
    const PolygonMoments m = area_moments(pg, p);
    EXPECT_NEAR(m.area, ref.area, 1e-13);
    double max_g = 0;
    for (int k = 0; k < p.count; ++k)
      max_g = std::max(max_g, pg.depth.dot(p.barycentric[static_cast<std::size_t>(k)]));
    EXPECT_NEAR(m.max_depth, max_g, 1e-13);
    EXPECT_LE(m.depth_integral, m.area * m.max_depth * (1 + 1e-12) + 1e-15);
    EXPECT_GE(m.depth_integral, 0.0);
    many_vertices += p.count >= 5;
  }
  EXPECT_GT(many_vertices, 10);
}

TEST(PairIntegral, AreaIntegralMatchesFineSamplingAndTheErrorShrinksWithTheGrid) {
  // Brute force over the whole triangle (the sampler knows nothing of the clip polygon); the
  // error comes from the cells cut by the polygon's boundary, O(1/n).
  std::mt19937 rng(202);
  const std::array<int, 4> grid{50, 100, 200, 400};
  std::array<double, 4> total_error{};
  double total_exact = 0;
  const int pairs = 8;
  for (int trial = 0; trial < pairs; ++trial) {
    const PairGeometry pg = random_pair(rng, 0.05);
    const double exact = area_integral(pg, collision::clip_triangle_tet(pg.triangle, pg.tet));
    total_exact += exact;
    const double scale = triangle_area(pg.triangle) * pg.depth.maxCoeff() * pg.depth.maxCoeff();
    for (std::size_t k = 0; k < grid.size(); ++k) {
      const double error = std::abs(sampled_integral(pg, grid[k]) - exact);
      total_error[k] += error;
      // One row of cells along a boundary of length O(triangle size) with g² <= max depth².
      EXPECT_LT(error, 3.0 * scale / grid[k]) << "trial " << trial << " n " << grid[k];
    }
  }
  std::cout << "[pair integral] sum of |exact - sampled| over " << pairs << " pairs (sum exact " << total_exact
            << "):";
  for (std::size_t k = 0; k < grid.size(); ++k) std::cout << " n=" << grid[k] << ": " << total_error[k];
  std::cout << "\n";
  EXPECT_LT(total_error[3], 1e-3 * total_exact);
  for (std::size_t k = 0; k + 1 < grid.size(); ++k)
    EXPECT_LT(total_error[k + 1], 0.75 * total_error[k]) << "n " << grid[k] << " -> " << grid[k + 1];
  EXPECT_LT(total_error[3], 0.25 * total_error[0]);
}

TEST(PairIntegral, PointIntegralIsTheHandComputedVertexSum) {
  std::mt19937 rng(303);
  int with_points[4] = {0, 0, 0, 0};
  for (int trial = 0; trial < 400; ++trial) {
    const PairGeometry pg = trial % 2 ? random_pair(rng) : random_point_pair(rng, 1 + (trial / 2) % 3);
    if (min_abs_barycentric(pg) < 1e-9) continue;  // the inside test would be a coin toss
    const CollocationPoints pts = collision::triangle_vertices_in_tet(pg.triangle, pg.tet);
    double expected = 0, area = 0, depth_integral = 0, max_depth = 0;
    int inside = 0;
    const double A = triangle_area(pg.triangle);
    for (int v = 0; v < 3; ++v) {
      const Eigen::Vector4d xi = reference_barycentric(pg.triangle.row(v).transpose(), pg.tet);
      if ((xi.array() < 0.0).any()) continue;
      const double g = pg.depth.dot(xi);
      expected += A / 3 * g * g;
      area += A / 3;
      depth_integral += A / 3 * g;
      max_depth = std::max(max_depth, g);
      ++inside;
    }
    ++with_points[inside];
    ASSERT_EQ(pts.count, inside) << "trial " << trial;
    EXPECT_NEAR(point_integral(pg, pts), expected, 1e-13 * std::max(1.0, expected)) << "trial " << trial;
    PairVector g;
    PairMatrix H;
    EXPECT_NEAR(point_integral_gradient(pg, pts, g), expected, 1e-13 * std::max(1.0, expected));
    EXPECT_NEAR(point_integral_hessian(pg, pts, PairHessian::Exact, g, H), expected, 1e-13 * std::max(1.0, expected));
    EXPECT_NEAR(point_integral_hessian(pg, pts, PairHessian::GaussNewton, g, H), expected,
                1e-13 * std::max(1.0, expected));
    const PolygonMoments m = point_moments(pg, pts);
    EXPECT_NEAR(m.area, area, 1e-13);
    EXPECT_NEAR(m.depth_integral, depth_integral, 1e-13);
    EXPECT_NEAR(m.max_depth, max_depth, 1e-13);
  }
  // Every case occurs: no vertex, one, two, all three inside.
  for (int k = 0; k < 4; ++k) EXPECT_GT(with_points[k], 10) << k << " vertices inside";
}

TEST(PairIntegral, EmptyPolygonAndNoPointsGiveZeroEverything) {
  PairGeometry pg;
  pg.tet << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  pg.triangle << 5, 5, 5, 6, 5, 5, 5, 6, 5;
  pg.depth << 1, 2, 3, 4;
  const ClipPolygon p = collision::clip_triangle_tet(pg.triangle, pg.tet);
  const CollocationPoints pts = collision::triangle_vertices_in_tet(pg.triangle, pg.tet);
  ASSERT_EQ(p.count, 0);
  ASSERT_EQ(pts.count, 0);
  for (const PairHessian kind : {PairHessian::Exact, PairHessian::GaussNewton}) {
    PairVector g = PairVector::Constant(7.0);
    PairMatrix H = PairMatrix::Constant(7.0);
    EXPECT_EQ(area_integral_hessian(pg, p, kind, g, H), 0.0);
    EXPECT_EQ(g.norm(), 0.0);
    EXPECT_EQ(H.norm(), 0.0);
    g.setConstant(7.0);
    H.setConstant(7.0);
    EXPECT_EQ(point_integral_hessian(pg, pts, kind, g, H), 0.0);
    EXPECT_EQ(g.norm(), 0.0);
    EXPECT_EQ(H.norm(), 0.0);
  }
  PairVector g = PairVector::Constant(7.0);
  EXPECT_EQ(area_integral_gradient(pg, p, g), 0.0);
  EXPECT_EQ(g.norm(), 0.0);
  g.setConstant(7.0);
  EXPECT_EQ(point_integral_gradient(pg, pts, g), 0.0);
  EXPECT_EQ(g.norm(), 0.0);
  EXPECT_EQ(area_moments(pg, p).area, 0.0);
  EXPECT_EQ(point_moments(pg, pts).area, 0.0);
}

TEST(PairIntegral, ConstantDepthGivesDepthSquaredTimesArea) {
  std::mt19937 rng(404);
  for (int trial = 0; trial < 50; ++trial) {
    PairGeometry pg = random_pair(rng);
    pg.depth.setConstant(0.7);
    const ClipPolygon p = collision::clip_triangle_tet(pg.triangle, pg.tet);
    EXPECT_NEAR(area_integral(pg, p), 0.49 * polygon_area(p), 1e-14);
  }
}

// ---------------------------------------------------------------------------------------------
// Derivatives

class PairDerivatives : public ::testing::TestWithParam<bool> {};  // true: area, false: point

TEST_P(PairDerivatives, GradientMatchesFiniteDifferencesWithTheClipRecomputed) {
  const bool area = GetParam();
  std::mt19937 rng(area ? 505 : 506);
  int tested = 0;
  double worst = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const PairGeometry pg = random_method_pair(rng, area, trial);
    // The point method is discontinuous where a vertex crosses a face: stay away from that.
    if (!area && min_abs_barycentric(pg) < 1e-4) continue;
    const double I = pair_value(pg, area);
    if (I <= 1e-8) continue;
    const PairVector g = pair_gradient(pg, area);
    auto f = [&](const Eigen::VectorXd& v) { return pair_value(from_vector(v, pg.depth), area); };
    const Eigen::VectorXd fd = st::fd_gradient(f, to_vector(pg), 1e-6);
    const double err = st::relative_error(g, fd);
    worst = std::max(worst, err);
    EXPECT_LT(err, 1e-6) << method_name(area) << " trial " << trial << "\nanalytic " << g.transpose() << "\nfd       "
                         << fd.transpose();
    ++tested;
  }
  std::cout << "[pair integral] " << method_name(area) << ": " << tested
            << " pairs, worst relative gradient error " << worst << "\n";
  EXPECT_GT(tested, 100);
}

TEST(PairIntegral, AreaGradientIsContinuousAcrossCombinatorialChanges) {
  // Configurations exactly at a switch of the polygon's combinatorics: a triangle vertex on a
  // tet face plane, a tet vertex on the triangle's plane. The central differences straddle the
  // switch; the area integral is C1 there, so they still match the gradient.
  std::mt19937 rng(555);
  std::uniform_real_distribution<double> u(-1.0, 1.0), u01(0.0, 1.0);
  int tested = 0;
  double worst = 0, worst6 = 0;
  for (int trial = 0; trial < 120; ++trial) {
    PairGeometry pg;
    pg.tet = random_tet(rng);
    for (int a = 0; a < 4; ++a) pg.depth[a] = u01(rng);
    if (trial % 2 == 0) {
      // Triangle vertex 0 on face (trial / 2) % 4 of the tet, inside the face.
      Eigen::Vector4d xi(0.1 + u01(rng), 0.1 + u01(rng), 0.1 + u01(rng), 0.1 + u01(rng));
      xi[(trial / 2) % 4] = 0;
      xi /= xi.sum();
      pg.triangle.row(0) = (pg.tet.transpose() * xi).transpose();
      const Eigen::RowVector3d c = pg.tet.colwise().mean();
      for (int i = 1; i < 3; ++i) pg.triangle.row(i) = c + 0.8 * Eigen::RowVector3d(u(rng), u(rng), u(rng));
    } else {
      // Tet vertex (trial / 2) % 4 inside the triangle, in its plane.
      const Eigen::RowVector3d q = pg.tet.row((trial / 2) % 4);
      const Eigen::RowVector3d d1(u(rng), u(rng), u(rng)), d2(u(rng), u(rng), u(rng));
      pg.triangle.row(0) = q - 0.6 * d1 - 0.6 * d2;
      pg.triangle.row(1) = q + 1.2 * d1 - 0.6 * d2;
      pg.triangle.row(2) = q - 0.6 * d1 + 1.2 * d2;
    }
    const double I = pair_value(pg, true);
    if (I < 1e-6) continue;
    const PairVector g = pair_gradient(pg, true);
    auto f = [&](const Eigen::VectorXd& v) { return pair_value(from_vector(v, pg.depth), true); };
    // The Hessian jumps at the switch, so the central difference is off by O(h): the error must
    // shrink in proportion to h (a jump of the gradient itself would not).
    const double err6 = st::relative_error(g, st::fd_gradient(f, to_vector(pg), 1e-6));
    const double err8 = st::relative_error(g, st::fd_gradient(f, to_vector(pg), 1e-8));
    worst6 = std::max(worst6, err6);
    worst = std::max(worst, err8);
    EXPECT_LT(err6, 1e-3) << "trial " << trial;
    EXPECT_LT(err8, 1e-5) << "trial " << trial;
    ++tested;
  }
  std::cout << "[pair integral] area at combinatorial switches: " << tested
            << " pairs, worst relative gradient error " << worst6 << " (h = 1e-6), " << worst << " (h = 1e-8)\n";
  EXPECT_GT(tested, 60);
}

TEST_P(PairDerivatives, GradientIsTranslationAndRotationInvariant) {
  // Σ over the 7 nodes of the gradient is 0 (translation) and so is Σ x × gradient (rotation).
  const bool area = GetParam();
  std::mt19937 rng(area ? 515 : 516);
  for (int trial = 0; trial < 100; ++trial) {
    const PairGeometry pg = random_method_pair(rng, area, trial);
    const PairVector g = pair_gradient(pg, area);
    const PairVector x = to_vector(pg);
    Vector3 net = Vector3::Zero(), torque = Vector3::Zero();
    for (int k = 0; k < 7; ++k) {
      net += g.segment<3>(3 * k);
      torque += Vector3(x.segment<3>(3 * k)).cross(Vector3(g.segment<3>(3 * k)));
    }
    const double scale = g.norm() + 1e-300;
    EXPECT_LT(net.norm(), 1e-12 * scale) << method_name(area) << " trial " << trial;
    EXPECT_LT(torque.norm(), 1e-12 * scale) << method_name(area) << " trial " << trial;
  }
}

TEST_P(PairDerivatives, ExactHessianMatchesDifferencesOfTheGradientWhereTheCombinatoricsIsStable) {
  const bool area = GetParam();
  std::mt19937 rng(area ? 607 : 608);
  const double h = 1e-6;
  int tested = 0, skipped = 0;
  double worst = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const PairGeometry pg = random_method_pair(rng, area, trial);
    const PairVector x0 = to_vector(pg);
    // Same polygon combinatorics (or the same inside vertices) at every perturbed configuration.
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
    if (!stable) {
      ++skipped;
      continue;
    }
    const Derivatives d = pair_hessian(pg, area, PairHessian::Exact);
    EXPECT_LT(st::relative_error(d.gradient, pair_gradient(pg, area)), 1e-14);
    EXPECT_LT(st::relative_error(d.hessian, d.hessian.transpose()), 1e-12) << "trial " << trial;
    auto grad = [&](const Eigen::VectorXd& v) {
      return Eigen::VectorXd(pair_gradient(from_vector(v, pg.depth), area));
    };
    const Eigen::MatrixXd fd = st::fd_jacobian(grad, x0, h);
    const double err = st::relative_error(d.hessian, fd);
    worst = std::max(worst, err);
    EXPECT_LT(err, 1e-5) << method_name(area) << " trial " << trial;
    ++tested;
  }
  std::cout << "[pair integral] " << method_name(area) << ": exact Hessian checked on " << tested << " pairs ("
            << skipped << " skipped, combinatorics changes within h), worst relative error " << worst << "\n";
  EXPECT_GT(tested, 100);
}

TEST_P(PairDerivatives, GaussNewtonHessianIsSymmetricPositiveSemiDefinite) {
  const bool area = GetParam();
  std::mt19937 rng(area ? 709 : 710);
  int nonzero = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const PairGeometry pg = random_method_pair(rng, area, trial);
    const Derivatives d = pair_hessian(pg, area, PairHessian::GaussNewton);
    // The gradient it returns is still the exact one.
    EXPECT_LT(st::relative_error(d.gradient, pair_gradient(pg, area)), 1e-14);
    EXPECT_LT(st::relative_error(d.hessian, d.hessian.transpose(), 1e-300), 1e-14);
    const Eigen::SelfAdjointEigenSolver<PairMatrix> eig(d.hessian);
    const double top = eig.eigenvalues().cwiseAbs().maxCoeff();
    EXPECT_GE(eig.eigenvalues().minCoeff(), -1e-12 * top) << method_name(area) << " trial " << trial;
    nonzero += top > 0;
  }
  EXPECT_GT(nonzero, 50);
}

TEST_P(PairDerivatives, ProjectedHessianIsTheNearestPositiveSemiDefiniteMatrixToTheExactOne) {
  const bool area = GetParam();
  std::mt19937 rng(area ? 811 : 812);
  int indefinite = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const PairGeometry pg = random_method_pair(rng, area, trial);
    const Derivatives exact = pair_hessian(pg, area, PairHessian::Exact);
    const Derivatives projected = pair_hessian(pg, area, PairHessian::Projected);
    EXPECT_LT(st::relative_error(projected.gradient, exact.gradient, 1e-300), 1e-14);
    const Eigen::SelfAdjointEigenSolver<PairMatrix> e(exact.hessian), p(projected.hessian);
    const double top = e.eigenvalues().cwiseAbs().maxCoeff() + 1e-300;
    EXPECT_GE(p.eigenvalues().minCoeff(), -1e-12 * top) << method_name(area) << " trial " << trial;
    // Frobenius distance to the exact Hessian = norm of its negative eigenvalues.
    const double negative = e.eigenvalues().cwiseMin(0.0).norm();
    EXPECT_NEAR((projected.hessian - exact.hessian).norm(), negative, 1e-10 * top) << "trial " << trial;
    indefinite += negative > 1e-9 * top;
  }
  std::cout << "[pair integral] " << method_name(area) << ": " << indefinite << " of 150 exact pair Hessians indefinite\n";
  EXPECT_GT(indefinite, 0);
}

INSTANTIATE_TEST_SUITE_P(Methods, PairDerivatives, ::testing::Values(true, false),
                         [](const auto& info) { return info.param ? "Area" : "Point"; });

// ---------------------------------------------------------------------------------------------
// Degenerate and adversarial pairs

struct Case {
  std::string name;
  Matrix3 triangle;
  TetVertices tet;
};

std::vector<Case> adversarial_cases() {
  std::vector<Case> cases;
  auto add = [&](const std::string& name, std::initializer_list<double> v) {
    Matrix3 m;
    auto it = v.begin();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m(i, j) = *it++;
    cases.push_back({name, m, unit_tet()});
  };
  const double e = 1e-12;
  add("coplanar with face z=0, equal to it", {0, 0, 0, 1, 0, 0, 0, 1, 0});
  add("coplanar with face z=0, larger", {-1, -1, 0, 3, -1, 0, -1, 3, 0});
  add("coplanar with face z=0, partly", {0.2, 0.2, 0, 2, 0.2, 0, 0.2, 2, 0});
  add("coplanar with the slanted face", {1, 0, 0, 0, 1, 0, 0, 0, 1});
  add("coplanar with the slanted face, larger", {2, -0.5, -0.5, -0.5, 2, -0.5, -0.5, -0.5, 2});
  add("edge through a tet vertex", {-1, 0, 1, 1, 0, 1, 0.1, 0.5, 0.2});
  add("edge through a tet vertex, other side", {-0.5, 0.5, 0.5, 0.5, -0.5, 1.5, 0.3, 0.3, 0.1});
  add("vertex on a tet vertex", {0, 0, 1, 0.3, 0.3, 0.3, -0.2, 0.5, 0.3});
  add("vertex on a tet edge", {0.5, 0, 0, 0.2, 0.3, 0.4, 0.1, 0.1, 0.6});
  add("vertex on a tet face", {0.2, 0.2, 0, 0.2, 0.2, 0.5, 0.5, 0.2, 0.3});
  add("tet vertex on the triangle, touching", {-1, -1, 1, 2, -1, 1, -1, 2, 1});
  add("tet vertex inside the triangle, tilted", {-1, -1, 2.5, 2, -1, -3.5, -1, 2, 4});
  add("triangle plane contains a tet edge", {-1, -1, -1, 3, 0.5, 0.5, -1, 2, 2});
  add("edge along a tet edge", {0, 0, 0, 1, 0, 0, 0.3, -0.5, 0.5});
  add("edge along a tet edge, in a face", {0, 0, 0, 1, 0, 0, 0.3, 0.0, 0.5});
  add("edge longer than a tet edge", {-1, 0, 0, 2, 0, 0, 0.3, 0.3, 0.3});
  add("through three tet vertices", {1, 0, 0, 0, 1, 0, 0, 0, 1});
  add("through two tet vertices", {1, 0, 0, 0, 0, 1, 0.2, 0.6, 0.2});
  add("plane at 1e-12 to face z=0, inside", {-1, -1, e, 3, -1, 2 * e, -1, 3, 3 * e});
  add("plane at 1e-12 to face z=0, crossing", {-1, -1, -e, 3, -1, e, -1, 3, 2 * e});
  add("plane at 1e-12 to face z=0, just outside", {-1, -1, -e, 3, -1, -2 * e, -1, 3, -3 * e});
  add("edge at 1e-12 to tet edge 0-1", {-1, -e, 0, 2, 2 * e, 0, 0.3, 0.3, 0.3});
  add("edge at 1e-12 to tet edge 0-1, in face", {-1, -e, 0, 2, 2 * e, 0, 0.3, 0.3, 0.0});
  add("edge at 1e-12 to tet edge 0-1, out of face", {-1, -e, 0, 2, 2 * e, 0, 0.3, -0.5, 0.5});
  add("edge at 1e-12 to the slanted face", {-0.2, 0.6, 0.6 + e, 1.2, -0.4, 0.2, 0.2, 0.2, 0.2});
  add("tiny triangle at a tet vertex", {0, 0, 1, e, 0, 1, 0, e, 1});
  add("tiny triangle inside", {0.2, 0.2, 0.2, 0.2 + e, 0.2, 0.2, 0.2, 0.2 + e, 0.2});
  add("touching along an edge only", {0, 0, 0, 1, 0, 0, 0.5, -1, -0.5});
  // A nearly flat tet (sliver) against an ordinary triangle.
  Case sliver{"sliver tet", Matrix3(), unit_tet()};
  sliver.triangle << -1, -1, 1e-7, 3, -1, 1e-7, -1, 3, 1e-7;
  sliver.tet.row(3) << 0.3, 0.3, 2e-7;
  cases.push_back(sliver);
  return cases;
}

Matrix3 moved(const Matrix3& m, const Matrix3& r, const Vector3& shift, double scale) {
  Matrix3 out;
  for (int i = 0; i < 3; ++i) out.row(i) = (scale * (r * m.row(i).transpose() + shift)).transpose();
  return out;
}

TetVertices moved(const TetVertices& m, const Matrix3& r, const Vector3& shift, double scale) {
  TetVertices out;
  for (int i = 0; i < 4; ++i) out.row(i) = (scale * (r * m.row(i).transpose() + shift)).transpose();
  return out;
}

/// Value, gradient and both Hessians of both methods are finite, the value is >= 0, and the area
/// value agrees with the collision module's quadrature of the same polygon.
void expect_finite_everything(const PairGeometry& pg, const std::string& where) {
  const ClipPolygon p = collision::clip_triangle_tet(pg.triangle, pg.tet);
  const CollocationPoints pts = collision::triangle_vertices_in_tet(pg.triangle, pg.tet);
  const double L = std::max(pg.triangle.cwiseAbs().maxCoeff(), pg.tet.cwiseAbs().maxCoeff());
  for (const bool area : {true, false}) {
    const double I = area ? area_integral(pg, p) : point_integral(pg, pts);
    EXPECT_TRUE(std::isfinite(I)) << where << " " << method_name(area);
    EXPECT_GE(I, 0.0) << where << " " << method_name(area);
    PairVector g;
    if (area)
      area_integral_gradient(pg, p, g);
    else
      point_integral_gradient(pg, pts, g);
    EXPECT_TRUE(g.allFinite()) << where << " " << method_name(area) << " gradient " << g.transpose();
    for (const PairHessian kind : {PairHessian::Exact, PairHessian::GaussNewton}) {
      PairVector gh;
      PairMatrix H;
      const double Ih = area ? area_integral_hessian(pg, p, kind, gh, H) : point_integral_hessian(pg, pts, kind, gh, H);
      const char* kname = kind == PairHessian::Exact ? "exact" : "Gauss-Newton";
      EXPECT_TRUE(std::isfinite(Ih)) << where << " " << method_name(area) << " " << kname;
      EXPECT_TRUE(gh.allFinite()) << where << " " << method_name(area) << " " << kname;
      EXPECT_TRUE(H.allFinite()) << where << " " << method_name(area) << " " << kname;
    }
  }
  if (p.count >= 3) {
    const double ref = collision::polygon_quadratic_integral(p, pg.depth).integral;
    const double dmax = pg.depth.maxCoeff();
    EXPECT_NEAR(area_integral(pg, p), ref, 1e-9 * (L * L * dmax * dmax) + 1e-12 * ref) << where;
  }
}

TEST(PairIntegralDegenerate, AdversarialPairsGiveFiniteNonNegativeValuesAndDerivatives) {
  std::mt19937 rng(811);
  std::uniform_real_distribution<double> u(-1, 1);
  int nonempty = 0;
  for (const Case& c : adversarial_cases()) {
    for (const double scale : {1.0, 1e-9, 1e6}) {
      for (const bool zero_depth : {false, true}) {
        PairGeometry pg;
        pg.depth = zero_depth ? Eigen::Vector4d(Eigen::Vector4d::Zero())
                              : Eigen::Vector4d(Eigen::Vector4d(0.1, 0.4, 0.7, 1.0) * scale);
        // As given (exact zeros), then after random rigid motions (round-off instead of zeros).
        pg.triangle = scale * c.triangle;
        pg.tet = scale * c.tet;
        const std::string where = c.name + " scale " + std::to_string(scale) + (zero_depth ? " zero depth" : "");
        expect_finite_everything(pg, where);
        if (zero_depth) {
          EXPECT_EQ(area_integral(pg, collision::clip_triangle_tet(pg.triangle, pg.tet)), 0.0) << where;
          EXPECT_EQ(point_integral(pg, collision::triangle_vertices_in_tet(pg.triangle, pg.tet)), 0.0) << where;
        }
        nonempty += collision::clip_triangle_tet(pg.triangle, pg.tet).count >= 3;
        for (int r = 0; r < 4; ++r) {
          const Matrix3 rot = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
          const Vector3 shift(u(rng), u(rng), u(rng));
          PairGeometry q = pg;
          q.triangle = moved(c.triangle, rot, shift, scale);
          q.tet = moved(c.tet, rot, shift, scale);
          expect_finite_everything(q, where + " moved " + std::to_string(r));
        }
        // Reversed triangle orientation and permuted tet vertices.
        PairGeometry f = pg;
        f.triangle.row(1).swap(f.triangle.row(2));
        f.tet.row(0).swap(f.tet.row(3));
        std::swap(f.depth[0], f.depth[3]);
        expect_finite_everything(f, where + " flipped");
        if (::testing::Test::HasFailure()) return;
      }
    }
  }
  EXPECT_GT(nonempty, 30);
}

TEST(PairIntegralDegenerate, RandomTrianglesWithVerticesOnTetFeatures) {
  // Triangle vertices at tet vertices, on tet edges and faces, or outside; optional rigid motion
  // and scaling to 1e-9 or 1e6.
  std::mt19937 rng(912);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::uniform_int_distribution<int> pick(0, 5);
  const std::array<double, 3> scales{1.0, 1e-9, 1e6};
  for (int trial = 0; trial < 600; ++trial) {
    const TetVertices tet = random_tet(rng);
    Matrix3 tri;
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector4d xi(u(rng), u(rng), u(rng), u(rng));
      const int zeros = pick(rng);
      for (int z = 0; z < std::min(zeros, 3); ++z) xi[(i + z + trial) % 4] = 0.0;
      if (zeros >= 4) xi[(i + trial) % 4] = -0.5 * u(rng);
      xi /= xi.sum();
      tri.row(i) = (tet.transpose() * xi).transpose();
    }
    const double scale = scales[static_cast<std::size_t>(trial % 3)];
    const Matrix3 rot =
        trial % 2 ? Matrix3(Eigen::Quaterniond::UnitRandom().toRotationMatrix()) : Matrix3(Matrix3::Identity());
    const Vector3 shift = trial % 2 ? Vector3(u(rng), u(rng), u(rng)) : Vector3::Zero();
    PairGeometry pg;
    pg.triangle = moved(tri, rot, shift, scale);
    pg.tet = moved(tet, rot, shift, scale);
    pg.depth = scale * Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng));
    if (trial % 5 == 0) pg.depth.setZero();
    expect_finite_everything(pg, "trial " + std::to_string(trial));
    if (::testing::Test::HasFailure()) {
      ADD_FAILURE() << "trial " << trial << "\n" << pg.triangle << "\n" << pg.tet;
      return;
    }
  }
}

// Regression: a zero-area triangle (collinear or coincident vertices) whose clip has count >= 3
// used to give a NaN area integral (0.5 / |n| = inf times a zero fan area) and NaN gradients for
// both methods (d|n| = n / |n| at n = 0), so a collapsed surface triangle inside another body
// made ContactEnergy::value NaN. It contributes nothing: value 0, finite derivatives.
TEST(PairIntegralDegenerate, ZeroAreaTriangleGivesFiniteValues) {
  PairGeometry pg;
  pg.tet = unit_tet();
  pg.depth << 0.1, 0.4, 0.7, 1.0;
  std::vector<Matrix3> triangles(3);
  triangles[0] << 0.1, 0.1, 0.1, 0.2, 0.2, 0.2, 0.3, 0.3, 0.3;   // collinear, inside
  triangles[1] << -1, 0.2, 0.2, 2, 0.2, 0.2, 0.5, 0.2, 0.2;      // collinear, crossing
  triangles[2] << 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.3, 0.2, 0.1;   // two coincident vertices
  for (const Matrix3& t : triangles) {
    pg.triangle = t;
    const ClipPolygon p = collision::clip_triangle_tet(pg.triangle, pg.tet);
    const CollocationPoints c = collision::triangle_vertices_in_tet(pg.triangle, pg.tet);
    PairVector g;
    PairMatrix H;
    EXPECT_EQ(area_integral(pg, p), 0.0);
    area_integral_gradient(pg, p, g);
    EXPECT_TRUE(g.allFinite());
    area_integral_hessian(pg, p, PairHessian::Exact, g, H);
    EXPECT_TRUE(H.allFinite());
    EXPECT_EQ(point_integral(pg, c), 0.0);
    point_integral_gradient(pg, c, g);
    EXPECT_TRUE(g.allFinite());
    point_integral_hessian(pg, c, PairHessian::Exact, g, H);
    EXPECT_TRUE(H.allFinite());
  }
}

TEST(PairIntegralDegenerate, ScaleCovariance) {
  // Lengths and depths scaled by s: I scales by s^4, the gradient by s^3, the Hessian by s^2.
  std::mt19937 rng(1013);
  for (int trial = 0; trial < 30; ++trial) {
    const PairGeometry pg = trial % 2 ? random_pair(rng) : random_point_pair(rng, 1 + (trial / 2) % 3);
    if (min_abs_barycentric(pg) < 1e-6) continue;
    for (const double s : {1e-9, 1e6}) {
      PairGeometry q = pg;
      q.triangle *= s;
      q.tet *= s;
      q.depth *= s;
      for (const bool area : {true, false}) {
        const Derivatives a = pair_hessian(pg, area, PairHessian::Exact);
        const Derivatives b = pair_hessian(q, area, PairHessian::Exact);
        EXPECT_NEAR(b.value / std::pow(s, 4), a.value, 1e-10 * std::max(1e-3, a.value)) << method_name(area);
        EXPECT_LT(st::relative_error(b.gradient / std::pow(s, 3), a.gradient, 1e-3), 1e-10) << method_name(area);
        EXPECT_LT(st::relative_error(b.hessian / (s * s), a.hessian, 1e-3), 1e-9) << method_name(area);
      }
    }
  }
}

}  // namespace
}  // namespace sinew::contact
