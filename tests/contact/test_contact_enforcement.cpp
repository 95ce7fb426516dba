// Penetration control (src/sinew/contact/contact_enforcement.hpp): the Uzawa update of the nodal
// contact pressures, the adaptive penalty growth, the energy with pressures (value, gradient and
// Hessian against finite differences over a multi-pair configuration), and the refusal of bad
// penalties and pressures.

#include "sinew/contact/contact_enforcement.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sinew/core/error.hpp"
#include "support/contact_fixtures.hpp"
#include "support/fd_check.hpp"

namespace sinew::contact {
namespace {

namespace st = sinew::testing;

st::TwoBoxes overlapping_boxes() { return st::two_boxes(2, Vector3(0.55, 0.3, -0.2), 0.4, 7.0, false); }

TEST(ContactEnforcement, FirstUpdateIsThePenaltyTimesTheDeepestPenetrationOnEachNodesTriangles) {
  // From zero pressures, p_i = ε max g over the supports of the pairs of node i's triangles.
  const auto boxes = overlapping_boxes();
  ContactEnergy energy(boxes.geometry, {ContactMethod::Area, PairHessian::Exact});
  energy.update(boxes.x);
  const ContactReport r = contact_report(energy, boxes.x);
  ASSERT_GT(r.pairs, 0);
  const VectorX p = updated_contact_pressure(energy.collisions());
  ASSERT_EQ(p.size(), boxes.x.rows());
  VectorX expected = VectorX::Zero(boxes.x.rows());
  const CollisionSet& set = energy.collisions();
  for (const ActivePair& pair : set.pairs()) {
    const PolygonMoments m = set.integrator().moments(set.pair_geometry_at(boxes.x, pair), pair.support);
    if (!(m.area > 0)) continue;
    for (int k = 0; k < 3; ++k) {
      double& e = expected[boxes.geometry.surface(pair.triangle, k)];
      e = std::max(e, 7.0 * m.max_depth);
    }
  }
  EXPECT_LT((p - expected).cwiseAbs().maxCoeff(), 1e-14 * expected.maxCoeff());
  EXPECT_GT(p.maxCoeff(), 0.0);
  EXPECT_NEAR(p.maxCoeff(), 7.0 * r.max_penetration, 1e-12 * p.maxCoeff());
  // Nodes on no penetrating triangle keep zero pressure.
  std::vector<char> in_contact(static_cast<std::size_t>(boxes.x.rows()), 0);
  for (const ActivePair& pair : energy.collisions().pairs())
    for (int k = 0; k < 3; ++k) in_contact[static_cast<std::size_t>(boxes.geometry.surface(pair.triangle, k))] = 1;
  for (Index i = 0; i < p.size(); ++i)
    if (!in_contact[static_cast<std::size_t>(i)]) {
      EXPECT_EQ(p[i], 0.0) << "node " << i;
    }
  // A second update adds the same increment (the configuration did not change).
  energy.set_pressure(p);
  const VectorX p2 = updated_contact_pressure(energy.collisions());
  EXPECT_LT((p2 - 2 * p).norm(), 1e-12 * p.norm());
}

TEST(ContactEnforcement, PressureAddsIntegralOfPressureTimesDepthToTheEnergy) {
  // A constant pressure c on every node: Ec(p) - Ec(0) = c ∫ g da over all pairs.
  const auto boxes = overlapping_boxes();
  ContactEnergy energy(boxes.geometry, {ContactMethod::Area, PairHessian::Exact});
  energy.update(boxes.x);
  const double plain = energy.value(boxes.x);
  const ContactReport r = contact_report(energy, boxes.x);
  energy.set_pressure(VectorX::Constant(boxes.x.rows(), 0.8));
  EXPECT_NEAR(energy.value(boxes.x) - plain, 0.8 * r.mean_penetration * r.area, 1e-12 * plain);
}

TEST(ContactEnforcement, EnergyWithPressuresHasExactGradientAndHessianOverManyPairs) {
  for (const ContactMethod method : {ContactMethod::Area, ContactMethod::Point}) {
    const auto boxes = overlapping_boxes();
    ContactEnergy energy(boxes.geometry, {method, PairHessian::Exact});
    energy.update(boxes.x);
    VectorX p = updated_contact_pressure(energy.collisions());
    for (Index i = 0; i < p.size(); ++i) p[i] *= 1.0 + 0.3 * std::sin(static_cast<double>(i));  // not uniform
    energy.set_pressure(p);
    // The onset ramp at half the deepest penetration: pieces of the support on both sides of it.
    energy.set_pressure_onset(0.5 * contact_report(energy, boxes.x).max_penetration);
    auto value = [&](const Eigen::VectorXd& v) {
      const Positions x = st::unflatten(v);
      energy.update(x);
      return energy.value(x);
    };
    const Eigen::VectorXd x0 = st::flatten(boxes.x);
    const Eigen::VectorXd fd = st::fd_gradient(value, x0, 1e-7);
    const NodalVectors g = st::gradient_at(energy, boxes.x);
    EXPECT_LT(st::relative_error(st::flatten(g), fd), 1e-5) << name_of(method);
    // Zero net force and torque: the pressure term is invariant under rigid motions too.
    EXPECT_LT(g.colwise().sum().norm(), 1e-10 * g.norm()) << name_of(method);
    Vector3 torque = Vector3::Zero();
    for (Index a = 0; a < g.rows(); ++a) torque += Vector3(boxes.x.row(a)).cross(Vector3(g.row(a)));
    EXPECT_LT(torque.norm(), 1e-9 * g.norm()) << name_of(method);
    if (method == ContactMethod::Area) {
      auto gradient = [&](const Eigen::VectorXd& v) { return Eigen::VectorXd(st::flatten(st::gradient_at(energy, st::unflatten(v)))); };
      const MatrixX H = st::hessian_at(energy, boxes.x);
      EXPECT_LT(st::relative_error(H, st::fd_jacobian(gradient, x0, 1e-7)), 1e-4);
    }
  }
}

TEST(ContactEnforcement, GrownPenaltyScalesOnlyThePairsAboveTheTolerance) {
  ContactReport r;
  r.num_bodies = 3;
  r.body_pair_max_penetration.assign(9, 0.0);
  r.body_pair_max_penetration[0 * 3 + 1] = 0.05;  // 5x the tolerance
  r.body_pair_max_penetration[1 * 3 + 1] = 0.5;   // 50x: capped
  r.body_pair_max_penetration[0 * 3 + 2] = 0.005; // below
  MatrixX penalty = MatrixX::Constant(3, 3, 2.0);
  penalty(2, 2) = 0;
  const MatrixX grown = grown_penalty(penalty, r, 0.01, 10);
  EXPECT_DOUBLE_EQ(grown(0, 1), 2.0 * 2 * 5);
  EXPECT_DOUBLE_EQ(grown(1, 0), grown(0, 1));
  EXPECT_DOUBLE_EQ(grown(1, 1), 20.0);
  EXPECT_DOUBLE_EQ(grown(0, 2), 2.0);
  EXPECT_DOUBLE_EQ(grown(0, 0), 2.0);
  EXPECT_DOUBLE_EQ(grown(2, 2), 0.0);
}

TEST(ContactEnforcement, SetPenaltyChangesTheEnergyInProportionAndKeepsThePairs) {
  const auto boxes = overlapping_boxes();
  ContactEnergy energy(boxes.geometry, {ContactMethod::Area, PairHessian::Exact});
  energy.update(boxes.x);
  const double before = energy.value(boxes.x);
  const auto pairs = energy.active_pairs();
  MatrixX penalty = boxes.geometry.penalty;
  penalty(0, 1) = penalty(1, 0) = 21.0;
  energy.set_penalty(penalty);
  EXPECT_NEAR(energy.value(boxes.x), 3 * before, 1e-12 * before);
  EXPECT_EQ(energy.active_pairs(), pairs);
  EXPECT_EQ(energy.geometry().penalty(0, 1), 21.0);
}

TEST(ContactEnforcement, BadPenaltiesAndPressuresAreRefusedAndChangeNothing) {
  const auto boxes = overlapping_boxes();
  ContactEnergy energy(boxes.geometry, {ContactMethod::Area, PairHessian::Exact});
  energy.update(boxes.x);
  const double before = energy.value(boxes.x);
  auto expect_refused = [&](auto&& change, const std::string& needle) {
    try {
      change();
      ADD_FAILURE() << "accepted: " << needle;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
    EXPECT_EQ(energy.value(boxes.x), before);
  };
  MatrixX p = boxes.geometry.penalty;
  expect_refused([&] { energy.set_penalty(MatrixX::Constant(3, 3, 1.0)); }, "3x3 matrix for 2 bodies");
  p(0, 1) = p(1, 0) = std::numeric_limits<double>::quiet_NaN();
  expect_refused([&] { energy.set_penalty(p); }, "bodies 0 and 1");
  p = boxes.geometry.penalty;
  p(0, 0) = 5;  // self-contact was off
  expect_refused([&] { energy.set_penalty(p); }, "only change between positive values");
  p = boxes.geometry.penalty;
  p(0, 1) = 3;  // not symmetric
  expect_refused([&] { energy.set_penalty(p); }, "symmetric");
  expect_refused([&] { energy.set_pressure(VectorX::Zero(3)); }, "3 values for");
  VectorX bad = VectorX::Zero(boxes.x.rows());
  bad[4] = -1;
  expect_refused([&] { energy.set_pressure(bad); }, "node 4");
  bad[4] = std::numeric_limits<double>::infinity();
  expect_refused([&] { energy.set_pressure(bad); }, "node 4");
  expect_refused([&] { energy.set_pressure_onset(-1e-3); }, "pressure onset: -0.001");
  expect_refused([&] { energy.set_pressure_onset(std::numeric_limits<double>::quiet_NaN()); }, "pressure onset: nan");
}

TEST(ContactEnforcement, MeanSurfaceEdgeOfAUnitCubeMesh) {
  const auto boxes = overlapping_boxes();
  const double h = mean_surface_edge(boxes.geometry, boxes.x);
  // n = 2 cells per side of a unit cube: edges of 0.5 and face diagonals of 0.5 sqrt(2).
  EXPECT_GT(h, 0.5);
  EXPECT_LT(h, 0.5 * std::sqrt(2.0));
  ContactGeometry empty = boxes.geometry;
  empty.surface.resize(0, 3);
  EXPECT_EQ(mean_surface_edge(empty, boxes.x), 0.0);
}

}  // namespace
}  // namespace sinew::contact
