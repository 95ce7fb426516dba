// Tests of the augmented Lagrangian term of the pair integral (pair_integral.hpp): with
// multipliers q at the triangle's vertices the integral is ∫ (g² + 2 q g) da, q linear over the
// triangle. Its value against the polygon moments, its exact gradient and Hessian against finite
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
    const PairVector g = pair_gradient(pg, area);
    auto f = [&](const Eigen::VectorXd& v) { return pair_value(from_vector(v, pg.depth, pg.multiplier), area); };
    const Eigen::VectorXd fd = st::fd_gradient(f, to_vector(pg), 1e-6);
    EXPECT_LT(st::relative_error(g, fd), 1e-6) << method_name(area) << " trial " << trial;
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
    const Derivatives d = pair_hessian(pg, area, PairHessian::Exact);
    EXPECT_LT(st::relative_error(d.gradient, pair_gradient(pg, area)), 1e-14);
    auto grad = [&](const Eigen::VectorXd& v) {
      return Eigen::VectorXd(pair_gradient(from_vector(v, pg.depth, pg.multiplier), area));
    };
    EXPECT_LT(st::relative_error(d.hessian, st::fd_jacobian(grad, x0, h)), 1e-5) << method_name(area) << " trial " << trial;
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

INSTANTIATE_TEST_SUITE_P(Methods, MultiplierTerm, ::testing::Values(true, false),
                         [](const auto& info) { return info.param ? "Area" : "Point"; });

}  // namespace
}  // namespace sinew::contact
