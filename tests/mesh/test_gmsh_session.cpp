#include "sinew/mesh/gmsh_session.hpp"

#include <gmock/gmock.h>
#include <gmsh.h>
#include <gtest/gtest.h>

#include <stdexcept>

#include "sinew/core/error.hpp"
#include "sinew/mesh/generate.hpp"

namespace sinew::mesh {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::StartsWith;

TEST(GmshSession, GmshErrorsBecomeInputErrorsWithGmshsMessage) {
  GmshSession session;
  try {
    session.run("setting an option", [] { gmsh::option::setNumber("Mesh.NoSuchOption", 1); });
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(),
                AllOf(StartsWith("setting an option: "), HasSubstr("Mesh.NoSuchOption")));
  }
  // The session stays usable after a failed step.
  EXPECT_EQ(session.run("adding a box", [] { return gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1); }),
            1);
}

TEST(GmshSession, SinewErrorsPassThroughUnchanged) {
  GmshSession session;
  try {
    session.run("a step", [] { throw SolveError("not a Gmsh problem"); });
    FAIL() << "expected SolveError";
  } catch (const SolveError& error) {
    EXPECT_STREQ(error.what(), "not a Gmsh problem");
  }
}

TEST(GmshSession, SessionsDoNotNest) {
  GmshSession session;
  EXPECT_THROW(GmshSession{}, std::logic_error);
}

TEST(GmshSession, MeshingFailureIsSilentAndReportsGmshsMessage) {
  // A sphere far thinner than the element size: Gmsh's meshing fails inside its OpenMP loop,
  // where a thrown exception would abort the process; it must come back as an InputError.
  Shape speck;
  speck.kind = Shape::Kind::Sphere;
  speck.radius = 1e-6;
  GenerateOptions options;
  options.element_size = 0.1;
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  std::string message;
  try {
    generate_mesh({Part{"speck", speck}}, options);
  } catch (const InputError& error) {
    message = error.what();
  }
  const std::string out = ::testing::internal::GetCapturedStdout();
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_THAT(message, AllOf(HasSubstr("meshing part speck"), HasSubstr("No elements in volume")));
  EXPECT_EQ(out, "");
  EXPECT_EQ(err, "");
}

TEST(GmshSession, EmptyOpenCascadeMessageSaysWhatIsWrong) {
  // A box thinner than OpenCASCADE's tolerance: OpenCASCADE throws an exception without a
  // message, which Gmsh logs as a bare "OpenCASCADE exception ".
  Shape sheet;
  sheet.kind = Shape::Kind::Box;
  sheet.min = Vector3::Zero();
  sheet.max = Vector3(1, 1, 1e-11);
  GenerateOptions options;
  options.element_size = 0.5;
  std::string message;
  try {
    generate_mesh({Part{"sheet", sheet}}, options);
  } catch (const InputError& error) {
    message = error.what();
  }
  EXPECT_THAT(message, AllOf(HasSubstr("part \"sheet\", box"), HasSubstr("degenerate"),
                             HasSubstr("1e-7")));
  EXPECT_THAT(message, ::testing::Not(::testing::EndsWith("exception ")));
}

}  // namespace
}  // namespace sinew::mesh
