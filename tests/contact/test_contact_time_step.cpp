/// @file test_contact_time_step.cpp
/// The explicit integrator's contact bound: ω_a² = 2 ε A_a / m_a at the stiffest surface node.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sinew/contact/contact_time_step.hpp"
#include "support/contact_fixtures.hpp"

namespace sinew::contact {
namespace {

TEST(ContactTimeStep, StiffestNodeIsTheOneWithTheLargestAreaPerMassAndFixedNodesAreSkipped) {
  const auto boxes = sinew::testing::two_boxes(2, Vector3(0, 0, 0.9), 0.0, 1000.0);
  const Index n = boxes.x.rows();
  VectorX mass = VectorX::Constant(n, 0.5);
  // One light surface node: it is the critical one, with ω² = 2 ε A / m by hand.
  const Index light = boxes.geometry.surface(0, 0);
  mass[light] = 1e-3;
  double area = 0;
  for (Index f = 0; f < boxes.geometry.surface.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (boxes.geometry.surface(f, k) == light) {
        const Vector3 a = boxes.x.row(boxes.geometry.surface(f, 0)), b = boxes.x.row(boxes.geometry.surface(f, 1)),
                      c = boxes.x.row(boxes.geometry.surface(f, 2));
        area += 0.5 * (b - a).cross(c - a).norm() / 3;
      }
  const ContactTimeStep step = contact_critical_time_step(boxes.geometry, boxes.x, mass);
  EXPECT_EQ(step.critical_node, light);
  EXPECT_NEAR(step.omega_max, std::sqrt(2 * 1000.0 * area / 1e-3), 1e-9 * step.omega_max);
  EXPECT_NEAR(step.dt, 2 / step.omega_max, 1e-15);
  // The same node held fixed (mass 0) is skipped; no movable node at all: no bound.
  mass[light] = 0;
  EXPECT_NE(contact_critical_time_step(boxes.geometry, boxes.x, mass).critical_node, light);
  EXPECT_EQ(contact_critical_time_step(boxes.geometry, boxes.x, VectorX::Zero(n)).dt,
            std::numeric_limits<double>::infinity());
  EXPECT_THROW(contact_critical_time_step(boxes.geometry, boxes.x, VectorX::Zero(n + 1)), std::invalid_argument);
}

}  // namespace
}  // namespace sinew::contact
