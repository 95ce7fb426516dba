// Tests of the augmented Lagrangian term of the pair integral (pair_integral.hpp): with
// multipliers q at the triangle's vertices the integral is ∫ (g² + 2 q r(g)) da, q linear over the
// triangle, r(g) = g without an onset ramp and the C¹ ramp of width δ with one. Its value against the polygon moments, its exact gradient and Hessian against finite
// differences that recompute the clip, and the per-vertex moments the multiplier update uses.

#include <gtest/gtest.h>

#include "contact/pair_integral_support.hpp"

namespace sinew::contact {
namespace {

using namespace pair_testing;
namespace st = sinew::testing;

PolygonMoments moments(const PairGeometry& pg, bool area) {
  if (area) return area_moments(pg, collision::clip_triangle_tet(pg.triangle, pg.tet));
  return point_moments(pg, collision::triangle_vertices_in_tet(pg.triangle, pg.tet));
}

Vector3 random_multiplier(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 2.0);
  return {u(rng), u(rng), u(rng)};
}

/// The pair `pg` (its depths, multipliers and onset) with the 21 coordinates v.
PairGeometry at(const Eigen::VectorXd& v, const PairGeometry& pg) {
  PairGeometry q = from_vector(v, pg.depth, pg.multiplier);
  q.multiplier_onset = pg.multiplier_onset;
  return q;
}

class MultiplierTerm : public ::testing::TestWithParam<bool> {};  // true: area, false: point

TEST_P(MultiplierTerm, VertexMomentsSumToTheAreaAndTheDepthIntegral) {
  const bool area = GetParam();
  std::mt19937 rng(area ? 811 : 812);
  for (int trial = 0; trial < 100; ++trial) {
    const PairGeometry pg = random_method_pair(rng, area, trial);
    const PolygonMoments m = moments(pg, area);
    EXPECT_NEAR(m.vertex_area.sum(), m.area, 1e-12 * (1 + m.area)) << "trial " << trial;
    EXPECT_NEAR(m.vertex_depth_integral.sum(), m.depth_integral, 1e-12 * (1 + m.depth_integral)) << "trial " << trial;
    EXPECT_GE(m.vertex_area.minCoeff(), -1e-12);
  }
}

TEST_P(MultiplierTerm, MultiplierAtOneVertexAddsTwiceThatVertexDepthMoment) {
  // I(q = c e_k) - I(0) = 2 c ∫ N_k g da: the term is linear in q and weighted by the shape function.
  const bool area = GetParam();
  std::mt19937 rng(area ? 821 : 822);
  int tested = 0;
  for (int trial = 0; trial < 100; ++trial) {
    PairGeometry pg = random_method_pair(rng, area, trial);
    const double plain = pair_value(pg, area);
    const PolygonMoments m = moments(pg, area);
    for (int k = 0; k < 3; ++k) {
      pg.multiplier = Vector3::Zero();
      pg.multiplier[k] = 0.37;
      EXPECT_NEAR(pair_value(pg, area) - plain, 2 * 0.37 * m.vertex_depth_integral[k], 1e-12 * (1 + plain))
          << "trial " << trial << " vertex " << k;
    }
    pg.multiplier.setConstant(0.5);  // a constant q: 2 q ∫ g
    EXPECT_NEAR(pair_value(pg, area) - plain, 2 * 0.5 * m.depth_integral, 1e-12 * (1 + plain));
    ++tested;
  }
  EXPECT_EQ(tested, 100);
}

TEST_P(MultiplierTerm, GradientMatchesFiniteDifferences) {
  const bool area = GetParam();
  std::mt19937 rng(area ? 831 : 832);
  int tested = 0;
  for (int trial = 0; trial < 150; ++trial) {
    PairGeometry pg = random_method_pair(rng, area, trial);
    if (!area && min_abs_barycentric(pg) < 1e-4) continue;  // the point method jumps there
    pg.multiplier = random_multiplier(rng);
    if (pair_value(pg, area) <= 1e-8) continue;
    // Without the onset ramp, and with it at half the deepest point (the fan is split).
    for (const double onset : {0.0, 0.5 * moments(pg, area).max_depth}) {
      pg.multiplier_onset = onset;
      const PairVector g = pair_gradient(pg, area);
      auto f = [&](const Eigen::VectorXd& v) { return pair_value(at(v, pg), area); };
      const Eigen::VectorXd fd = st::fd_gradient(f, to_vector(pg), 1e-6);
      EXPECT_LT(st::relative_error(g, fd), 1e-6) << method_name(area) << " trial " << trial << " onset " << onset;
    }
    ++tested;
  }
  EXPECT_GT(tested, 80);
}

TEST_P(MultiplierTerm, ExactHessianMatchesDifferencesOfTheGradient) {
  const bool area = GetParam();
  std::mt19937 rng(area ? 841 : 842);
  const double h = 1e-6;
  int tested = 0;
  for (int trial = 0; trial < 120; ++trial) {
    PairGeometry pg = random_method_pair(rng, area, trial);
    pg.multiplier = random_multiplier(rng);
    const PairVector x0 = to_vector(pg);
    if (!combinatorics_stable(pg, area, h)) continue;
    for (const double onset : {0.0, 0.5 * moments(pg, area).max_depth}) {
      pg.multiplier_onset = onset;
      const Derivatives d = pair_hessian(pg, area, PairHessian::Exact);
      EXPECT_LT(st::relative_error(d.gradient, pair_gradient(pg, area)), 1e-14);
      auto grad = [&](const Eigen::VectorXd& v) { return Eigen::VectorXd(pair_gradient(at(v, pg), area)); };
      EXPECT_LT(st::relative_error(d.hessian, st::fd_jacobian(grad, x0, h)), 1e-5)
          << method_name(area) << " trial " << trial << " onset " << onset;
    }
    ++tested;
  }
  EXPECT_GT(tested, 60);
}

TEST_P(MultiplierTerm, GaussNewtonKeepsTheExactGradient) {
  const bool area = GetParam();
  std::mt19937 rng(area ? 851 : 852);
  for (int trial = 0; trial < 50; ++trial) {
    PairGeometry pg = random_method_pair(rng, area, trial);
    pg.multiplier = random_multiplier(rng);
    const Derivatives d = pair_hessian(pg, area, PairHessian::GaussNewton);
    EXPECT_LT(st::relative_error(d.gradient, pair_gradient(pg, area)), 1e-12) << "trial " << trial;
    EXPECT_NEAR(d.value, pair_value(pg, area), 1e-12 * (1 + std::abs(d.value)));
  }
}

/// The pair with multipliers and the onset δ at half its deepest point, so that the support
/// has points on both sides of g = δ (the split of the fan triangles is exercised).
PairGeometry with_onset_inside(PairGeometry pg, std::mt19937& rng, bool area) {
  pg.multiplier = random_multiplier(rng);
  pg.multiplier_onset = 0.5 * moments(pg, area).max_depth;
  return pg;
}

TEST_P(MultiplierTerm, OnsetRampLiesBetweenTheLinearTermAndItsShiftByHalfTheOnset) {
  // g - δ/2 <= r(g) <= g and the integrand has 2 q r(g), so I0 - δ ∫ q <= Iδ <= I0 for q >= 0,
  // with ∫ q = Σ q_k ∫ N_k.
  const bool area = GetParam();
  std::mt19937 rng(area ? 861 : 862);
  int strict = 0;
  for (int trial = 0; trial < 100; ++trial) {
    PairGeometry pg = with_onset_inside(random_method_pair(rng, area, trial), rng, area);
    const double ramped = pair_value(pg, area);
    const double delta = pg.multiplier_onset;
    pg.multiplier_onset = 0;
    const double linear = pair_value(pg, area);
    const double integral_q = pg.multiplier.dot(moments(pg, area).vertex_area);
    const double tol = 1e-12 * (1 + std::abs(linear));
    EXPECT_LE(ramped, linear + tol) << method_name(area) << " trial " << trial;
    EXPECT_GE(ramped, linear - delta * integral_q - tol) << method_name(area) << " trial " << trial;
    if (ramped < linear - 1e-9 * (1 + linear)) ++strict;
  }
  EXPECT_GT(strict, 50);  // the ramp does change the value
}

TEST_P(MultiplierTerm, OnsetDeeperThanThePenetrationMakesTheTermQuadratic) {
  // Every g < δ: 2 q r(g) = q g² / δ, so with a constant q, Iδ = (1 + q/δ) ∫ g².
  const bool area = GetParam();
  std::mt19937 rng(area ? 871 : 872);
  for (int trial = 0; trial < 100; ++trial) {
    PairGeometry pg = random_method_pair(rng, area, trial);
    const double plain = pair_value(pg, area);
    const double delta = 1.5 * moments(pg, area).max_depth + 1e-3;
    pg.multiplier.setConstant(0.4);
    pg.multiplier_onset = delta;
    EXPECT_NEAR(pair_value(pg, area), (1 + 0.4 / delta) * plain, 1e-11 * (1 + plain)) << method_name(area) << " trial " << trial;
  }
}

TEST(MultiplierOnset, ThePointsForceGrowsContinuouslyFromTheSurface) {
  // One collocation point at depth g: dI/dg = 2 g + 2 q r'(g) is 2 q at g = 0 without the ramp
  // (the jump that stalled Newton where a pressed point reaches the surface) and 0 with it.
  std::mt19937 rng(901);
  PairGeometry pg = random_method_pair(rng, /*area=*/false, 0);
  pg.multiplier.setConstant(0.3);
  const auto slope_at_surface = [&](double onset) {
    pg.multiplier_onset = onset;
    const collision::CollocationPoints points = collision::triangle_vertices_in_tet(pg.triangle, pg.tet);
    // Scale the depths so the value at the first point is tiny: the slope in the depth scale s at
    // s -> 0 is the slope of the integrand at g = 0.
    const Eigen::Vector4d depth = pg.depth;
    const auto value = [&](double s) {
      PairGeometry q = pg;
      q.depth = s * depth;
      return point_integral(q, points);
    };
    const double s = 1e-7;
    return (value(2 * s) - value(s)) / s;
  };
  EXPECT_GT(slope_at_surface(0.0), 1e-3);
  EXPECT_LT(std::abs(slope_at_surface(0.05)), 1e-5);
}

INSTANTIATE_TEST_SUITE_P(Methods, MultiplierTerm, ::testing::Values(true, false),
                         [](const auto& info) { return info.param ? "Area" : "Point"; });

}  // namespace
}  // namespace sinew::contact
