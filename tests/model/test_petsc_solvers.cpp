/// @file test_petsc_solvers.cpp
/// A contact scene (a soft box pressed onto a rigid plate, on planar rollers) solved with
/// each of PETSc's solvers reaches the state CHOLMOD reaches: the scene's `linear` section
/// chooses the solver and nothing else changes.

#include <gtest/gtest.h>

#include "sinew/model/solve_model.hpp"
#include "sinew/scene/load_scene.hpp"
#include "support/contact_scenes.hpp"

namespace sinew::model {
namespace {

using nlohmann::json;

solver::StepperResult solve_with(const std::string& linear_solver) {
  json scene = sinew::testing::pressed_box_on_plate_scene();
  scene["solver"]["increments"] = 2;
  scene["solver"]["linear"] = {{"solver", linear_solver}, {"tolerance", 1e-10}, {"max_iterations", 500}};
  Model model = build_model(scene::parse_scene(scene, ""));
  return solve_model(model);
}

TEST(PetscSolvers, MumpsAndGamgReachTheStateCholmodReaches) {
  const solver::StepperResult cholmod = solve_with("cholmod");
  ASSERT_TRUE(cholmod.success) << cholmod.message;
  const double size = (cholmod.last_state.x.colwise().maxCoeff() - cholmod.last_state.x.colwise().minCoeff()).norm();
  for (const char* kind : {"petsc-mumps", "petsc-gamg"}) {
    const solver::StepperResult petsc = solve_with(kind);
    ASSERT_TRUE(petsc.success) << kind << ": " << petsc.message;
    EXPECT_LT((petsc.last_state.x - cholmod.last_state.x).cwiseAbs().maxCoeff(), 1e-8 * size) << kind;
    EXPECT_EQ(petsc.newton_iterations, cholmod.newton_iterations) << kind;
    if (std::string(kind) == "petsc-gamg") {
      EXPECT_GT(petsc.linear.linear_iterations, 0) << "CG iterations are counted";
    }
  }
}

}  // namespace
}  // namespace sinew::model
