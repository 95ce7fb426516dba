// contact_report (src/sinew/contact/contact_report.hpp): the force between two bodies is the sum
// of the nodal contact forces on one of them, self-contact is reported as a magnitude per body,
// and reporting at another configuration leaves the energy the solver uses as it was.

#include "sinew/contact/contact_report.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "support/contact_fixtures.hpp"
#include "support/fd_check.hpp"

namespace sinew::contact {
namespace {

namespace st = sinew::testing;
using st::gradient_at;

class ContactReportMethods : public ::testing::TestWithParam<ContactMethod> {};

TEST_P(ContactReportMethods, BodyPairForceIsTheSumOfTheNodalForcesOnOneBody) {
  const auto boxes = st::two_boxes(2, Vector3(0.55, 0.3, -0.2), 0.4, 7.0, false);
  const Positions& x = boxes.x;
  ContactEnergy energy(boxes.geometry, {GetParam(), PairHessian::GaussNewton});
  const NodalVectors gradient = gradient_at(energy, x);
  const ContactReport r = contact_report(energy, x);
  ASSERT_GT(r.pairs, 0);
  EXPECT_EQ(r.num_bodies, 2);
  EXPECT_EQ(r.energy, energy.value(x));
  const Index na = x.rows() / 2;
  const Vector3 on_body0 = -gradient.topRows(na).colwise().sum().transpose();
  const Vector3 on_body1 = -gradient.bottomRows(na).colwise().sum().transpose();
  const Vector3& f = r.force_between(0, 1);
  EXPECT_GT(f.norm(), 0);
  EXPECT_LT((f - on_body0).norm(), 1e-12 * f.norm());
  EXPECT_LT((f + on_body1).norm(), 1e-12 * f.norm());  // action and reaction
  EXPECT_EQ(r.body_pair_force[1 * 2 + 0].norm(), 0.0);   // only i < j is filled
  EXPECT_EQ(r.self_contact_force_magnitude.size(), 2);
  EXPECT_EQ(r.self_contact_force_magnitude.norm(), 0.0);
  EXPECT_LT(st::relative_error(r.nodal_force, -gradient), 1e-14);
}

// Both boxes as one body: every pair is self-contact; the body's figure is half the sum of the
// magnitudes of its nodal forces, and no body pair force is reported.
TEST_P(ContactReportMethods, SelfContactIsHalfTheSumOfTheNodalForceMagnitudes) {
  auto boxes = st::two_boxes(2, Vector3(0.55, 0.3, -0.2), 0.4, 7.0, false);
  ContactGeometry& g = boxes.geometry;
  g.surface_body.setZero();
  g.tet_body.setZero();
  g.penalty = MatrixX::Constant(1, 1, 7.0);
  ContactEnergy energy(g, {GetParam(), PairHessian::GaussNewton});
  const NodalVectors gradient = gradient_at(energy, boxes.x);
  const ContactReport r = contact_report(energy, boxes.x);
  ASSERT_GT(r.pairs, 0);
  ASSERT_EQ(r.self_contact_force_magnitude.size(), 1);
  double half_sum = 0;
  for (Index a = 0; a < gradient.rows(); ++a) half_sum += 0.5 * gradient.row(a).norm();
  EXPECT_GT(half_sum, 0);
  EXPECT_NEAR(r.self_contact_force_magnitude[0], half_sum, 1e-12 * half_sum);
  ASSERT_EQ(r.body_pair_force.size(), 1u);
  EXPECT_EQ(r.body_pair_force[0].norm(), 0.0);
}

// Three bodies (the second box split into bodies 1 and 2 by halves of its triangles and tets):
// only entries i < j are filled, and the forces on body 0 from bodies 1 and 2 add up to the
// contact force on body 0's nodes (body 0 has no self-contact at rest).
TEST_P(ContactReportMethods, EachForceGoesToItsOwnBodyPair) {
  auto boxes = st::two_boxes(2, Vector3(0.55, 0.3, -0.2), 0.4, 7.0, true);
  ContactGeometry& g = boxes.geometry;
  g.surface_body.tail(g.surface.rows() / 4).setConstant(2);
  g.tet_body.tail(g.tets.rows() / 4).setConstant(2);
  g.penalty = MatrixX::Constant(3, 3, 7.0);
  ContactEnergy energy(g, {GetParam(), PairHessian::GaussNewton});
  const NodalVectors gradient = gradient_at(energy, boxes.x);
  const ContactReport r = contact_report(energy, boxes.x);
  ASSERT_EQ(r.body_pair_force.size(), 9u);
  ASSERT_EQ(r.self_contact_force_magnitude.size(), 3);
  EXPECT_EQ(r.self_contact_force_magnitude[0], 0.0);
  EXPECT_TRUE(r.self_contact_force_magnitude.allFinite());
  EXPECT_GE(r.self_contact_force_magnitude.minCoeff(), 0.0);
  const Index na = boxes.x.rows() / 2;
  const Vector3 on_body0 = -gradient.topRows(na).colwise().sum().transpose();
  const Vector3 sum = r.force_between(0, 1) + r.force_between(0, 2);
  EXPECT_GT(r.force_between(0, 1).norm(), 0);
  EXPECT_GT(r.force_between(0, 2).norm(), 0);
  EXPECT_LT((sum - on_body0).norm(), 1e-12 * on_body0.norm());
  for (Index i = 0; i < 3; ++i)
    for (Index j = 0; j <= i; ++j) EXPECT_EQ(r.body_pair_force[static_cast<std::size_t>(i * 3 + j)].norm(), 0.0);
}

// The largest penetration per body pair: the three-body split above, with each pair's figure
// positive where that pair touches, none larger than the overall largest, and the overall
// largest being one of them; entries i > j stay zero.
TEST_P(ContactReportMethods, MaxPenetrationPerBodyPair) {
  auto boxes = st::two_boxes(2, Vector3(0.55, 0.3, -0.2), 0.4, 7.0, true);
  ContactGeometry& g = boxes.geometry;
  g.surface_body.tail(g.surface.rows() / 4).setConstant(2);
  g.tet_body.tail(g.tets.rows() / 4).setConstant(2);
  g.penalty = MatrixX::Constant(3, 3, 7.0);
  ContactEnergy energy(g, {GetParam(), PairHessian::GaussNewton});
  const ContactReport r = contact_report(energy, boxes.x);
  ASSERT_EQ(r.body_pair_max_penetration.size(), 9u);
  ASSERT_GT(r.max_penetration, 0);
  EXPECT_GT(r.max_penetration_between(0, 1), 0);
  EXPECT_GT(r.max_penetration_between(0, 2), 0);
  double largest = 0;
  for (Index i = 0; i < 3; ++i)
    for (Index j = 0; j < 3; ++j) {
      const double d = r.body_pair_max_penetration[static_cast<std::size_t>(i * 3 + j)];
      EXPECT_GE(d, 0);
      EXPECT_LE(d, r.max_penetration);
      if (i > j) {
        EXPECT_EQ(d, 0.0);
      }
      largest = std::max(largest, d);
    }
  EXPECT_EQ(largest, r.max_penetration);
}

// Reporting at a configuration other than the energy's keeps the energy at its own: the same
// pairs, revision and value, and the report equals that of an energy updated to the other.
TEST_P(ContactReportMethods, ReportingElsewhereDoesNotChangeTheEnergy) {
  const auto here = st::two_boxes(2, Vector3(0.5, 0.2, 0.1), 0.3, 7.0);
  const auto there = st::two_boxes(2, Vector3(0.7, 0.1, 0.05), 0.3, 7.0);
  ContactEnergy energy(here.geometry, {GetParam(), PairHessian::GaussNewton});
  energy.begin_step(here.x);
  const auto pairs = energy.active_pairs();
  const auto revision = energy.pattern_revision();
  const double value = energy.value(here.x);

  const ContactReport elsewhere = contact_report(energy, there.x);
  EXPECT_TRUE(energy.collisions().is_current(here.x));
  EXPECT_EQ(energy.active_pairs(), pairs);
  EXPECT_EQ(energy.pattern_revision(), revision);
  EXPECT_EQ(energy.value(here.x), value);

  ContactEnergy moved(there.geometry, {GetParam(), PairHessian::GaussNewton});
  moved.update(there.x);
  const ContactReport expected = contact_report(moved, there.x);
  EXPECT_EQ(elsewhere.pairs, expected.pairs);
  EXPECT_EQ(elsewhere.energy, expected.energy);
  EXPECT_EQ(elsewhere.energy, moved.value(there.x));
  EXPECT_EQ(elsewhere.area, expected.area);
  EXPECT_EQ(elsewhere.nodal_force, expected.nodal_force);
  EXPECT_NE(elsewhere.energy, value);
}

TEST_P(ContactReportMethods, AnOverflowedConfigurationHasInfiniteEnergyAndNoPairs) {
  const auto boxes = st::two_boxes(2, Vector3(0.62, 0.31, 0.17), 0.3, 7.0);
  ContactOptions tight{GetParam(), PairHessian::Exact};
  tight.candidate_cap = 1;
  ContactEnergy energy(boxes.geometry, tight);
  energy.update(boxes.x);
  const ContactReport r = contact_report(energy, boxes.x);
  EXPECT_EQ(r.pairs, 0);
  EXPECT_EQ(r.energy, std::numeric_limits<double>::infinity());
  EXPECT_EQ(r.nodal_force.norm(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Methods, ContactReportMethods, ::testing::Values(ContactMethod::Area, ContactMethod::Point),
                         [](const auto& info) { return info.param == ContactMethod::Area ? "Area" : "Point"; });

}  // namespace
}  // namespace sinew::contact
