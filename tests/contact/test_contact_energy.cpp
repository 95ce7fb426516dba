#include "sinew/contact/contact_energy.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "sinew/core/error.hpp"

#include "support/contact_fixtures.hpp"
#include "support/fd_check.hpp"

namespace sinew::contact {
namespace {

namespace st = sinew::testing;

struct Evaluated {
  double value;
  NodalVectors gradient;
  MatrixX hessian;
};

Evaluated evaluate(ContactEnergy& energy, const Positions& x) {
  energy.update(x);
  Evaluated e;
  e.value = energy.value(x);
  e.gradient = NodalVectors::Zero(x.rows(), 3);
  energy.add_gradient(x, e.gradient);
  std::vector<std::pair<Index, Index>> pairs;
  energy.hessian_pattern(pairs);
  BlockSparseMatrix H;
  H.set_pattern(static_cast<Index>(x.rows()), pairs);
  energy.add_hessian(x, H);
  e.hessian = H.to_dense();
  return e;
}

class ContactEnergyMethods : public ::testing::TestWithParam<ContactMethod> {};

TEST_P(ContactEnergyMethods, GradientIsTheExactGradientOfTheTotalEnergy) {
  const auto boxes = st::two_boxes(2, Vector3(0.62, 0.31, 0.17), 0.3, 7.0);
  ContactEnergy energy(boxes.geometry, {GetParam(), PairHessian::Exact});
  const Evaluated e = evaluate(energy, boxes.x);
  ASSERT_GT(energy.active_pairs().size(), 20u);
  ASSERT_GT(e.value, 0);
  auto f = [&](const Eigen::VectorXd& v) {
    const Positions x = st::unflatten(v);
    energy.update(x);
    return energy.value(x);
  };
  const Eigen::VectorXd fd = st::fd_gradient(f, st::flatten(boxes.x), 1e-7);
  EXPECT_LT(st::relative_error(st::flatten(e.gradient), fd), 1e-6);
}

TEST_P(ContactEnergyMethods, ExactHessianMatchesDifferencesOfTheGradient) {
  const auto boxes = st::two_boxes(2, Vector3(0.58, 0.27, 0.21), 0.25, 3.0);
  ContactEnergy energy(boxes.geometry, {GetParam(), PairHessian::Exact});
  const Evaluated e = evaluate(energy, boxes.x);
  auto grad = [&](const Eigen::VectorXd& v) {
    const Positions x = st::unflatten(v);
    energy.update(x);
    NodalVectors g = NodalVectors::Zero(x.rows(), 3);
    energy.add_gradient(x, g);
    return Eigen::VectorXd(st::flatten(g));
  };
  const Eigen::MatrixXd fd = st::fd_jacobian(grad, st::flatten(boxes.x), 1e-7);
  EXPECT_LT(st::relative_error(e.hessian, fd), 1e-5);
  EXPECT_LT(st::relative_error(e.hessian, e.hessian.transpose()), 1e-12);
}

TEST_P(ContactEnergyMethods, SharesOfThePairsSumToTheWholeEnergy) {
  // What the ranks of a run on several processes evaluate (docs/mpi.md): each the pairs whose tet
  // it owns; their values, gradients and Hessians add up to the whole term's.
  const auto boxes = st::two_boxes(2, Vector3(0.6, 0.3, 0.2), 0.3, 5.0);
  ContactEnergy whole(boxes.geometry, {GetParam(), PairHessian::Exact});
  const Evaluated all = evaluate(whole, boxes.x);
  ASSERT_GT(whole.active_pairs().size(), 20u);
  const auto num_tets = static_cast<std::size_t>(boxes.geometry.tets.rows());
  for (int parts : {2, 3, 7}) {
    std::vector<int> owner(num_tets);
    for (std::size_t t = 0; t < num_tets; ++t) owner[t] = static_cast<int>((t * 7 / 3) % static_cast<std::size_t>(parts));
    Evaluated sum{0, NodalVectors::Zero(boxes.x.rows(), 3), MatrixX::Zero(all.hessian.rows(), all.hessian.cols())};
    for (int part = 0; part < parts; ++part) {
      ContactEnergy share(boxes.geometry, {GetParam(), PairHessian::Exact});
      share.set_share(owner, part);
      const Evaluated e = evaluate(share, boxes.x);
      EXPECT_LT(e.value, all.value) << "part " << part << " of " << parts << " holds every pair";
      sum.value += e.value;
      sum.gradient += e.gradient;
      sum.hessian += e.hessian;
    }
    EXPECT_NEAR(sum.value, all.value, 1e-12 * all.value) << parts << " parts";
    EXPECT_LT((sum.gradient - all.gradient).norm(), 1e-12 * all.gradient.norm()) << parts << " parts";
    EXPECT_LT((sum.hessian - all.hessian).norm(), 1e-12 * all.hessian.norm()) << parts << " parts";
  }
  ContactEnergy share(boxes.geometry, {GetParam(), PairHessian::Exact});
  EXPECT_THAT([&] { share.set_share(std::vector<int>(num_tets + 1, 0), 0); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("tet owners for")));
}

TEST_P(ContactEnergyMethods, GaussNewtonHessianIsPositiveSemiDefinite) {
  const auto boxes = st::two_boxes(2, Vector3(0.58, 0.27, 0.21), 0.25, 3.0);
  ContactEnergy energy(boxes.geometry, {GetParam(), PairHessian::GaussNewton});
  const Evaluated e = evaluate(energy, boxes.x);
  const Eigen::SelfAdjointEigenSolver<MatrixX> eig(e.hessian);
  EXPECT_GT(eig.eigenvalues().maxCoeff(), 0);
  EXPECT_GT(eig.eigenvalues().minCoeff(), -1e-12 * eig.eigenvalues().maxCoeff());
}

TEST_P(ContactEnergyMethods, ForcesSumToZeroAndCarryNoTorque) {
  for (const double angle : {0.0, 0.4, 1.1}) {
    const auto boxes = st::two_boxes(3, Vector3(0.5, 0.45, -0.3), angle, 11.0);
    ContactEnergy energy(boxes.geometry, {GetParam(), PairHessian::GaussNewton});
    const Evaluated e = evaluate(energy, boxes.x);
    ASSERT_GT(e.value, 0);
    const Vector3 net = e.gradient.colwise().sum().transpose();
    Vector3 torque = Vector3::Zero();
    for (Index a = 0; a < boxes.x.rows(); ++a)
      torque += Vector3(boxes.x.row(a)).cross(Vector3(e.gradient.row(a)));
    const double scale = e.gradient.rowwise().norm().sum();
    EXPECT_LT(net.norm(), 1e-12 * scale) << "angle " << angle;
    EXPECT_LT(torque.norm(), 1e-12 * scale) << "angle " << angle;
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, ContactEnergyMethods, ::testing::Values(ContactMethod::Area, ContactMethod::Point),
                         [](const auto& info) { return info.param == ContactMethod::Area ? "Area" : "Point"; });

// A configuration whose broad phase finds more candidates than the cap (a wild Newton trial
// state) is invalid: value +inf, no pairs built, and a gradient request says why. Below the
// cap the same configuration is valid and has pairs.
TEST(ContactEnergyCap, TooManyCandidatesMakeTheStateInvalidWithoutBuildingPairs) {
  const auto boxes = st::two_boxes(2, Vector3(0.62, 0.31, 0.17), 0.3, 7.0);
  ContactEnergy roomy(boxes.geometry, {ContactMethod::Area, PairHessian::Exact});
  roomy.update(boxes.x);
  ASSERT_TRUE(roomy.is_valid(boxes.x));
  const Index candidates = roomy.last_update_times().candidates;
  ASSERT_GT(candidates, 20);
  ASSERT_GT(roomy.active_pairs().size(), 0u);

  ContactOptions tight{ContactMethod::Area, PairHessian::Exact};
  tight.candidate_cap = static_cast<std::size_t>(candidates) - 1;
  ContactEnergy capped(boxes.geometry, tight);
  capped.update(boxes.x);
  EXPECT_FALSE(capped.is_valid(boxes.x));
  EXPECT_EQ(capped.value(boxes.x), std::numeric_limits<double>::infinity());
  EXPECT_TRUE(capped.active_pairs().empty());
  NodalVectors g = NodalVectors::Zero(boxes.x.rows(), 3);
  try {
    capped.add_gradient(boxes.x, g);
    ADD_FAILURE() << "a gradient at an overflowed configuration was computed";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("candidate pairs at this configuration (more than the cap)"),
              std::string::npos)
        << e.what();
  }
}

// Per-triangle and per-tet penalty factors: a pair uses the body pair's penalty times the smaller
// factor. Scaling every factor by s scales the energy by s; scaling only one side's tets leaves
// the pairs whose triangles keep factor 1 unchanged.
TEST(ContactEnergyPenaltyScale, APairUsesTheSmallerFactor) {
  const auto boxes = st::two_boxes(2, Vector3(0.62, 0.31, 0.17), 0.3, 7.0, /*self_contact=*/false);
  ContactEnergy plain(boxes.geometry, {});
  plain.update(boxes.x);
  const double e0 = plain.value(boxes.x);
  ASSERT_GT(e0, 0);

  ContactGeometry all = boxes.geometry;
  all.surface_penalty_scale = VectorX::Constant(all.surface.rows(), 3.0);
  all.tet_penalty_scale = VectorX::Constant(all.tets.rows(), 3.0);
  ContactEnergy tripled(all, {});
  tripled.update(boxes.x);
  EXPECT_NEAR(tripled.value(boxes.x), 3 * e0, 1e-12 * e0);

  ContactGeometry one_side = boxes.geometry;  // stiff tets, triangles at 1: min is 1
  one_side.tet_penalty_scale = VectorX::Constant(one_side.tets.rows(), 10.0);
  ContactEnergy unchanged(one_side, {});
  unchanged.update(boxes.x);
  EXPECT_NEAR(unchanged.value(boxes.x), e0, 1e-12 * e0);
  for (Index f = 0; f < one_side.surface.rows(); f += 7)
    for (Index t = 0; t < one_side.tets.rows(); t += 5)
      EXPECT_EQ(unchanged.pair_penalty(f, t), plain.pair_penalty(f, t));

  // Body 0's triangles and tets stiff, body 1's soft: each pair takes the soft factor.
  ContactGeometry mixed = boxes.geometry;
  mixed.surface_penalty_scale = VectorX::Ones(mixed.surface.rows());
  mixed.tet_penalty_scale = VectorX::Ones(mixed.tets.rows());
  for (Index f = 0; f < mixed.surface.rows(); ++f)
    if (mixed.surface_body[f] == 0) mixed.surface_penalty_scale[f] = 4;
  for (Index t = 0; t < mixed.tets.rows(); ++t)
    mixed.tet_penalty_scale[t] = mixed.tet_body[t] == 0 ? 4 : 0.5;
  ContactEnergy energy(mixed, {});
  for (Index f = 0; f < mixed.surface.rows(); f += 3)
    for (Index t = 0; t < mixed.tets.rows(); t += 4) {
      const double base = mixed.penalty(mixed.surface_body[f], mixed.tet_body[t]);
      EXPECT_EQ(energy.pair_penalty(f, t),
                base * std::min(mixed.surface_penalty_scale[f], mixed.tet_penalty_scale[t]));
    }
}

}  // namespace
}  // namespace sinew::contact
