// The ContactEnergy constructor rejects bad input with sinew::InputError and a message that says
// what is wrong and where (GUIDE.md section 2: strict validation, messages meant for the user).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "sinew/contact/contact_energy.hpp"
#include "sinew/core/error.hpp"
#include "support/contact_fixtures.hpp"

namespace sinew::contact {
namespace {

namespace st = sinew::testing;
using ::testing::AllOf;
using ::testing::HasSubstr;

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

/// A valid two-body geometry (two overlapping 2 x 2 x 2 boxes).
ContactGeometry valid() { return st::two_boxes(2, Vector3(0.5, 0.2, 0.1), 0.3, 7.0).geometry; }

/// The InputError message of the constructor, or a failure if it does not throw one.
std::string input_error(const ContactGeometry& g, ContactOptions options = {}) {
  try {
    const ContactEnergy energy(g, options);
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw something other than InputError: " << e.what();
    return {};
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

TEST(ContactInput, ValidGeometryIsAccepted) {
  for (const ContactMethod m : {ContactMethod::Area, ContactMethod::Point})
    for (const PairHessian h : {PairHessian::Exact, PairHessian::GaussNewton})
      EXPECT_NO_THROW(ContactEnergy(valid(), {m, h}));
  // Zero penalties and zero depths are legal (contact switched off).
  ContactGeometry g = valid();
  g.penalty.setZero();
  g.depth.setZero();
  EXPECT_NO_THROW(ContactEnergy(g, {}));
  // So is a geometry with nothing in it.
  ContactGeometry empty;
  empty.penalty = MatrixX::Zero(0, 0);
  EXPECT_NO_THROW(ContactEnergy(empty, {}));
  // InputError is a sinew::Error.
  g = valid();
  g.penalty(0, 1) = g.penalty(1, 0) = -1;
  EXPECT_THROW(ContactEnergy(g, {}), Error);
}

TEST(ContactInput, PenaltyScalesOfTheWrongSizeOrNotPositive) {
  ContactGeometry g = valid();
  g.tet_penalty_scale = VectorX::Ones(g.tets.rows() - 1);
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("tet penalty scale"), HasSubstr("entries")));
  g = valid();
  g.surface_penalty_scale = VectorX::Ones(g.surface.rows() + 2);
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("triangle penalty scale"), HasSubstr("entries")));
  g = valid();
  g.surface_penalty_scale = VectorX::Ones(g.surface.rows());
  g.surface_penalty_scale[3] = 0;
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("penalty scale of triangle 3"), HasSubstr("> 0")));
  g = valid();
  g.tet_penalty_scale = VectorX::Ones(g.tets.rows());
  g.tet_penalty_scale[5] = kNaN;
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("penalty scale of tet 5"), HasSubstr("finite")));
}

TEST(ContactInput, NegativePenalty) {
  ContactGeometry g = valid();
  g.penalty(0, 1) = g.penalty(1, 0) = -2.5;
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("penalty"), HasSubstr("bodies 0 and 1"), HasSubstr("-2.5"),
                                    HasSubstr(">= 0")));
  g = valid();
  g.penalty(1, 1) = -1;
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("penalty"), HasSubstr("bodies 1 and 1"), HasSubstr(">= 0")));
}

TEST(ContactInput, NonFinitePenalty) {
  ContactGeometry g = valid();
  g.penalty(0, 1) = g.penalty(1, 0) = kNaN;
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("penalty"), HasSubstr("bodies 0 and 1"), HasSubstr("nan"),
                                    HasSubstr("finite")));
  g = valid();
  g.penalty(0, 0) = kInf;
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("penalty"), HasSubstr("bodies 0 and 0"), HasSubstr("inf"),
                                    HasSubstr("finite")));
}

TEST(ContactInput, NonSymmetricPenalty) {
  ContactGeometry g = valid();
  g.penalty(0, 1) = 3;
  g.penalty(1, 0) = 4;
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("penalty"), HasSubstr("symmetric")));
}

TEST(ContactInput, NonSquarePenalty) {
  ContactGeometry g = valid();
  g.penalty = MatrixX::Constant(2, 3, 1.0);
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("penalty"), HasSubstr("square")));
  g.penalty = MatrixX::Constant(3, 2, 1.0);
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("penalty"), HasSubstr("square")));
}

TEST(ContactInput, PenaltyMatrixTooSmallForTheBodies) {
  // Square and valid, but the bodies reach 1 while the penalty covers only body 0.
  ContactGeometry g = valid();
  g.penalty = MatrixX::Constant(1, 1, 1.0);
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("body 1"), HasSubstr("1 bodies")));
}

TEST(ContactInput, NegativeDepth) {
  ContactGeometry g = valid();
  g.depth[5] = -0.25;
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("depth"), HasSubstr("node 5"), HasSubstr("-0.25"), HasSubstr(">= 0")));
}

TEST(ContactInput, NonFiniteDepth) {
  ContactGeometry g = valid();
  g.depth[7] = kNaN;
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("depth"), HasSubstr("node 7"), HasSubstr("nan"), HasSubstr("finite")));
  g = valid();
  g.depth[0] = kInf;
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("depth"), HasSubstr("node 0"), HasSubstr("inf"), HasSubstr("finite")));
}

TEST(ContactInput, SurfaceBodyOutOfRange) {
  ContactGeometry g = valid();
  g.surface_body[3] = 2;
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("surface triangle 3"), HasSubstr("body 2"), HasSubstr("2 bodies")));
  g = valid();
  g.surface_body[0] = -1;
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("surface triangle 0"), HasSubstr("body -1")));
}

TEST(ContactInput, TetBodyOutOfRange) {
  ContactGeometry g = valid();
  g.tet_body[11] = 5;
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("tet 11"), HasSubstr("body 5"), HasSubstr("2 bodies")));
  g = valid();
  g.tet_body[0] = -3;
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("tet 0"), HasSubstr("body -3")));
}

TEST(ContactInput, NodeIndexWithoutADepth) {
  const ContactGeometry base = valid();
  const Index nodes = static_cast<Index>(base.depth.size());
  ContactGeometry g = base;
  g.surface(2, 1) = nodes;  // one past the last node with a depth
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("surface triangle"), HasSubstr("node without a material depth")));
  g = base;
  g.tets(4, 3) = nodes + 10;
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("tet"), HasSubstr("node without a material depth")));
  g = base;
  g.surface(0, 0) = -1;
  EXPECT_THAT(input_error(g), HasSubstr("material depth"));
  g = base;
  g.tets(0, 0) = -1;
  EXPECT_THAT(input_error(g), HasSubstr("material depth"));
  // Equivalently: the depth vector is one node short.
  g = base;
  g.depth.conservativeResize(nodes - 1);
  EXPECT_THAT(input_error(g), HasSubstr("node without a material depth"));
}

TEST(ContactInput, SizeMismatches) {
  ContactGeometry g = valid();
  g.surface_body.conservativeResize(g.surface_body.size() - 1);
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("surface_body"), HasSubstr("one entry per surface triangle")));
  g = valid();
  g.surface_body.conservativeResize(g.surface_body.size() + 1);
  g.surface_body[g.surface_body.size() - 1] = 0;
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("surface_body"), HasSubstr("one entry per surface triangle")));
  g = valid();
  g.tet_body.conservativeResize(g.tet_body.size() - 1);
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("tet_body"), HasSubstr("one entry per tet")));
  g = valid();
  g.tet_body.resize(0);
  EXPECT_THAT(input_error(g), AllOf(HasSubstr("tet_body"), HasSubstr("one entry per tet")));
}

TEST(ContactInput, PositionsOfTheWrongSizeAreRejectedAtUpdate) {
  // Not a constructor check (the constructor never sees x), but the first use must not read out
  // of bounds.
  const auto boxes = st::two_boxes(2, Vector3(0.5, 0.2, 0.1), 0.3, 7.0);
  ContactEnergy energy(boxes.geometry, {});
  const Positions fewer = boxes.x.topRows(boxes.x.rows() - 1);
  EXPECT_THROW(energy.update(fewer), std::invalid_argument);
  Positions more(boxes.x.rows() + 1, 3);
  more.topRows(boxes.x.rows()) = boxes.x;
  more.bottomRows(1).setZero();
  EXPECT_THROW(energy.begin_step(more), std::invalid_argument);
}

// Regression: begin_step(x) used to build the tet boxes from x before update(x) checked its
// number of rows, so an x with fewer rows than nodes was read out of bounds (AddressSanitizer:
// heap-buffer-overflow in collision::tet_boxes).
TEST(ContactInput, BeginStepRejectsPositionsWithTooFewRows) {
  const auto boxes = st::two_boxes(2, Vector3(0.5, 0.2, 0.1), 0.3, 7.0);
  ContactEnergy energy(boxes.geometry, {});
  const Positions fewer = boxes.x.topRows(2);
  EXPECT_THROW(energy.begin_step(fewer), std::invalid_argument);
}

}  // namespace
}  // namespace sinew::contact
