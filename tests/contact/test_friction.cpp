// Friction (src/sinew/contact/friction.hpp): the smoothed Coulomb law, the lagged points of a
// configuration, the potential's gradient and Hessian against finite differences over many
// pairs, zero net force and torque at the lag state, and the refusal of bad coefficients.

#include "sinew/contact/friction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include <Eigen/Eigenvalues>

#include "sinew/contact/contact_report.hpp"
#include "sinew/core/error.hpp"
#include "support/contact_fixtures.hpp"
#include "support/fd_check.hpp"

namespace sinew::contact {
namespace {

namespace st = sinew::testing;

TEST(FrictionLaw, IsContinuouslyDifferentiableAndCoulombBeyondTheThreshold) {
  const double eps = 0.3;
  EXPECT_NEAR(friction_f0(0, eps), eps / 3, 1e-15);
  EXPECT_NEAR(friction_f0(eps, eps), eps, 1e-15);
  EXPECT_NEAR(friction_f0(2 * eps, eps), 2 * eps, 1e-15);
  for (const double s : {1e-4, 0.1, 0.2999, 0.3, 0.3001, 0.7}) {
    const double h = 1e-7;
    const double fd = (friction_f0(s + h, eps) - friction_f0(s - h, eps)) / (2 * h);
    EXPECT_NEAR(friction_f1_over_s(s, eps) * s, fd, 1e-6) << s;
    EXPECT_LE(friction_f1_over_s(s, eps) * s, 1 + 1e-12);  // never more than mu N
  }
  EXPECT_NEAR(friction_f1_over_s(0, eps), 2 / eps, 1e-15);
}

struct FrictionSetup {
  st::TwoBoxes boxes = st::two_boxes(2, Vector3(0.55, 0.3, -0.2), 0.4, 7.0, false);
  std::unique_ptr<ContactEnergy> contact;
  std::unique_ptr<FrictionEnergy> friction;
  explicit FrictionSetup(ContactMethod method, double mu = 0.4, double slip = 0.05) {
    contact = std::make_unique<ContactEnergy>(boxes.geometry, ContactOptions{method, PairHessian::Exact});
    friction = std::make_unique<FrictionEnergy>(*contact, FrictionOptions{MatrixX::Constant(2, 2, mu), slip});
    friction->begin_step(boxes.x);
  }
};

/// x moved by a smooth, non-rigid field of size `size`.
Positions moved(const Positions& x, double size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Positions y = x;
  for (Index a = 0; a < x.rows(); ++a)
    for (int c = 0; c < 3; ++c) y(a, c) += size * u(rng);
  return y;
}

TEST(FrictionEnergy, PointsCarryTheNormalForceOfTheContact) {
  for (const ContactMethod method : {ContactMethod::Area, ContactMethod::Point}) {
    FrictionSetup s(method);
    const auto& points = s.friction->points();
    ASSERT_FALSE(points.empty()) << name_of(method);
    double total = 0;
    for (const FrictionPoint& p : points) {
      EXPECT_NEAR(p.triangle_weights.sum(), 1, 1e-12);
      EXPECT_NEAR(p.tet_weights.sum(), 1, 1e-12);
      EXPECT_GT(p.normal_force, 0);
      EXPECT_NEAR((p.basis.transpose() * p.basis - Eigen::Matrix2d::Identity()).norm(), 0, 1e-12);
      total += p.normal_force;
    }
    // N = w ε g |∇g|: the boxes' depth is the exact distance interpolated linearly on two cells
    // per side, so |∇g| is between about 0.5 and √3 and Σ N near ε ∫ g da (ContactReport's mean
    // penetration times area).
    const ContactReport r = contact_report(*s.contact, s.boxes.x);
    EXPECT_GT(total, 0.5 * 7.0 * r.mean_penetration * r.area) << name_of(method);
    EXPECT_LT(total, std::sqrt(3.0) * 7.0 * r.mean_penetration * r.area) << name_of(method);
  }
}

TEST(FrictionEnergy, GradientAndHessianMatchFiniteDifferencesInBothRegimes) {
  for (const ContactMethod method : {ContactMethod::Area, ContactMethod::Point})
    for (const double size : {0.002, 0.2}) {  // sticking (slip below 0.05) and sliding
      SCOPED_TRACE(std::string(name_of(method)) + (size < 0.01 ? " sticking" : " sliding"));
      FrictionSetup s(method);
      const Positions x = moved(s.boxes.x, size, 17);
      auto value = [&](const Eigen::VectorXd& v) { return s.friction->value(st::unflatten(v)); };
      NodalVectors g = NodalVectors::Zero(x.rows(), 3);
      s.friction->add_gradient(x, g);
      const Eigen::VectorXd x0 = st::flatten(x);
      EXPECT_LT(st::relative_error(st::flatten(g), st::fd_gradient(value, x0, 1e-7)), 1e-6);
      auto gradient = [&](const Eigen::VectorXd& v) {
        NodalVectors gv = NodalVectors::Zero(x.rows(), 3);
        s.friction->add_gradient(st::unflatten(v), gv);
        return Eigen::VectorXd(st::flatten(gv));
      };
      std::vector<std::pair<Index, Index>> pairs;
      s.friction->hessian_pattern(pairs);
      BlockSparseMatrix H;
      H.set_pattern(x.rows(), pairs);
      s.friction->add_hessian(x, H);
      const MatrixX dense = H.to_dense();
      EXPECT_LT(st::relative_error(dense, st::fd_jacobian(gradient, x0, 1e-7)), 1e-5);
      const Eigen::SelfAdjointEigenSolver<MatrixX> eig(0.5 * (dense + dense.transpose()));
      EXPECT_GT(eig.eigenvalues().minCoeff(), -1e-9 * eig.eigenvalues().cwiseAbs().maxCoeff());  // convex
    }
}

TEST(FrictionEnergy, ForcesHaveNoNetForceAndNoNetTorqueAtTheLagState) {
  FrictionSetup s(ContactMethod::Area);
  // Move the second box rigidly: its points slide over the first box's.
  Positions x = s.boxes.x;
  const Index half = x.rows() / 2;
  for (Index a = half; a < x.rows(); ++a) x.row(a) += Eigen::RowVector3d(0.01, -0.02, 0.005);
  NodalVectors g = NodalVectors::Zero(x.rows(), 3);
  s.friction->add_gradient(x, g);
  ASSERT_GT(g.norm(), 0);
  EXPECT_LT(g.colwise().sum().norm(), 1e-12 * g.norm());
  // Torque about the origin at the lag state (where the triangle's and the tet's points coincide).
  Vector3 torque = Vector3::Zero();
  for (Index a = 0; a < g.rows(); ++a) torque += Vector3(s.boxes.x.row(a)).cross(Vector3(g.row(a)));
  EXPECT_LT(torque.norm(), 1e-10 * g.norm());
  // The friction on the moving box opposes its motion.
  const Vector3 on_second = -g.bottomRows(half).colwise().sum().transpose();
  EXPECT_LT(on_second.dot(Vector3(0.01, -0.02, 0.005)), 0);
}

TEST(FrictionEnergy, SlidingForceIsMuTimesTheNormalForce) {
  // Far beyond the threshold every point pulls with μ N along its slip.
  FrictionSetup s(ContactMethod::Area, 0.4, 1e-6);
  Positions x = s.boxes.x;
  const Index half = x.rows() / 2;
  for (Index a = half; a < x.rows(); ++a) x.row(a) += Eigen::RowVector3d(0.01, 0, 0);
  const auto u = s.friction->slips(x);
  double expected = 0, bound = 0;  // points whose slip is below the threshold differ by at most μ N ε_u
  for (std::size_t k = 0; k < u.size(); ++k) {
    expected += 0.4 * s.friction->points()[k].normal_force * u[k].norm();
    bound += 0.4 * s.friction->points()[k].normal_force * 1e-6;
  }
  EXPECT_GT(expected, 1000 * bound);
  EXPECT_NEAR(s.friction->value(x), expected, bound);
}

TEST(FrictionEnergy, RefreshReportsTheChangeOfTheNormalForce) {
  FrictionSetup s(ContactMethod::Area);
  EXPECT_NEAR(s.friction->refresh(s.boxes.x), 0, 1e-14);
  Positions x = s.boxes.x;
  for (Index a = x.rows() / 2; a < x.rows(); ++a) x.row(a) += Eigen::RowVector3d(-0.05, 0, 0);  // deeper
  EXPECT_GT(s.friction->refresh(x), 0.01);
  EXPECT_EQ(s.friction->step_start(), s.boxes.x);  // the step's start is kept
}

TEST(FrictionEnergy, BadCoefficientsAndThresholdsAreRefused) {
  const st::TwoBoxes boxes = st::two_boxes(2, Vector3(0.55, 0.3, -0.2), 0.4, 7.0, false);
  ContactEnergy contact(boxes.geometry, {});
  auto message = [&](const MatrixX& mu, double slip) -> std::string {
    try {
      FrictionEnergy f(contact, {mu, slip});
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message(MatrixX::Constant(3, 3, 0.1), 0.1).find("3x3 coefficient matrix for 2 bodies"), std::string::npos);
  MatrixX mu = MatrixX::Constant(2, 2, 0.1);
  mu(0, 1) = -0.1;
  EXPECT_NE(message(mu, 0.1).find("bodies 0 and 1"), std::string::npos);
  mu(0, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(message(mu, 0.1).find("must be finite"), std::string::npos);
  EXPECT_NE(message(MatrixX::Constant(2, 2, 0.1), 0).find("slip threshold 0"), std::string::npos);
  EXPECT_NE(message(MatrixX::Constant(2, 2, 0.1), std::numeric_limits<double>::infinity()).find("slip threshold"),
            std::string::npos);
}

TEST(FrictionEnergy, ASlipVelocityThresholdSetsTheSlipThresholdOfEveryTimeStep) {
  const st::TwoBoxes boxes = st::two_boxes(2, Vector3(0.55, 0.3, -0.2), 0.4, 7.0, false);
  ContactEnergy contact(boxes.geometry, {});
  FrictionEnergy rate(contact, {MatrixX::Constant(2, 2, 0.3), 0.05, 2.0});
  EXPECT_EQ(rate.options().slip_threshold, 0.05);  // before the first step
  rate.set_time_step(0.01);
  EXPECT_DOUBLE_EQ(rate.options().slip_threshold, 0.02);
  rate.begin_step(boxes.x);
  const Positions slid = moved(boxes.x, 0.004, 3);
  const double at_small_step = rate.value(slid);
  rate.set_time_step(0.001);  // a cut step: ten times smaller threshold, a stiffer stick
  EXPECT_DOUBLE_EQ(rate.options().slip_threshold, 0.002);
  EXPECT_NE(rate.value(slid), at_small_step);
  rate.set_time_step(0);  // ignored (not a step)
  EXPECT_DOUBLE_EQ(rate.options().slip_threshold, 0.002);
  // Without a velocity threshold the length stays.
  FrictionEnergy length(contact, {MatrixX::Constant(2, 2, 0.3), 0.05});
  length.set_time_step(0.01);
  EXPECT_EQ(length.options().slip_threshold, 0.05);
  try {
    FrictionEnergy bad(contact, {MatrixX::Constant(2, 2, 0.3), 0.05, -1.0});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("slip velocity threshold -1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sinew::contact
