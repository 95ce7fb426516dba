// Tests of the per-pair contact integral (src/sinew/contact/pair_integral.hpp): the value against
// the collision module's polygon quadrature and a brute-force fine sampling of ∫ g² over the
// triangle, the point-collocation value by hand, the exact gradient and Hessians against finite
// differences that recompute the clip at every perturbed configuration, and robustness on
// degenerate and badly scaled pairs in test_pair_integral_degenerate.cpp (docs/theory.md).

#include <gtest/gtest.h>

#include <iostream>

#include "contact/pair_integral_support.hpp"

namespace sinew::contact {
namespace {

using namespace pair_testing;
namespace st = sinew::testing;

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
    if (!combinatorics_stable(pg, area, h)) {
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

}  // namespace
}  // namespace sinew::contact
