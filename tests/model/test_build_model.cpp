/// @file test_build_model.cpp
/// model::build_model: the terms a scene gets, the dynamics part, the checks validate shares
/// with run, and set_contact changing the contact without re-meshing.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene_test_support.hpp"
#include "support/contact_scenes.hpp"
#include "sinew/core/error.hpp"
#include "sinew/mesh/tet_mesh.hpp"
#include "sinew/model/solve_model.hpp"
#include "sinew/scene/load_scene.hpp"

namespace sinew::model {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

/// A soft box [0,1]^2 x [0,0.5] (density 1) resting on a rigid plate, under gravity.
json contact_scene() {
  json scene = sinew::testing::box_on_plate_scene();
  scene["bodies"][0]["regions"]["gel"]["density"] = 1.0;
  scene["loads"] = {{"gravity", {0, 0, -0.5}}};
  return scene;
}

Model build(const json& scene) { return build_model(scene::parse_scene(scene, "")); }

std::string build_error(const json& scene) {
  try {
    build(scene);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(BuildModel, AStaticContactSceneGetsElasticExternalAndContactTermsAndItsScales) {
  const Model model = build(contact_scene());
  ASSERT_TRUE(model.problem && model.dofs && model.elastic && model.external && model.objective);
  ASSERT_TRUE(model.contact);
  ASSERT_TRUE(model.contact_setup);
  EXPECT_FALSE(model.is_dynamic());
  EXPECT_EQ(model.contact_body_names(), (std::vector<std::string>{"box", "plate"}));
  // The reference force: the stiffest initial modulus (the bulk modulus lambda + 2 mu / 3) times
  // the squared bounding-box diagonal.
  const Vector3 extent(3, 3, 1.5);
  EXPECT_NEAR(model.scales.characteristic_length, extent.norm(), 1e-12);
  EXPECT_NEAR(model.scales.reference_force, (10.0 + 2.0 / 3.0) * extent.squaredNorm(), 1e-9);
  EXPECT_EQ(model.scales.node_viscosity.size(), 0);
}

TEST(BuildModel, QuasiViscosityGivesEveryNodeADampingProportionalToItsElementSize) {
  json scene = contact_scene();
  scene["solver"]["newton"]["quasi_viscosity"] = 2.0;
  const Model model = build(scene);
  ASSERT_EQ(model.scales.node_viscosity.size(), model.problem->mesh.num_nodes());
  EXPECT_GT(model.scales.node_viscosity.minCoeff(), 0.0);
}

// solver.stabilization: D_a = eta mu_min (rest volume around a)^(1/3) on the nodes with unknowns,
// 0 on the fixed plate's (their motion is given and must not count as dissipation); none at 0.
TEST(BuildModel, TheStabilizationDampsOnlyNodesWithUnknowns) {
  json scene = contact_scene();
  scene["solver"]["stabilization"] = 0.01;
  const Model model = build(scene);
  ASSERT_TRUE(model.stabilization);
  const BlockSparseMatrix& D = model.stabilization->matrix();
  const auto& mesh = model.problem->mesh;
  VectorX volume = VectorX::Zero(mesh.num_nodes());
  for (Index t = 0; t < mesh.num_tets(); ++t)
    for (int i = 0; i < 4; ++i) volume[mesh.tets(t, i)] += std::abs(mesh::signed_volume(mesh.rest, mesh.tets, t));
  double shear = 1e300;
  for (const auto& law : model.problem->region_material)
    if (law) shear = std::min(shear, law->initial_shear_modulus());
  int damped = 0, given = 0;
  for (Index a = 0; a < mesh.num_nodes(); ++a) {
    const Matrix3& block = D.values()[static_cast<std::size_t>(D.find(a, a))];
    if (model.dofs->num_node_dofs(a) == 0) {
      EXPECT_EQ(block.norm(), 0.0) << "node " << a;
      ++given;
    } else {
      EXPECT_NEAR((block - 0.01 * shear * std::cbrt(volume[a]) * Matrix3::Identity()).norm(), 0.0, 1e-12) << "node " << a;
      ++damped;
    }
  }
  EXPECT_GT(damped, 0);
  EXPECT_GT(given, 0);

  scene["solver"]["stabilization"] = 0.0;
  EXPECT_FALSE(build(scene).stabilization);
}

TEST(BuildModel, SetContactChangesMethodAndPenaltyWithoutRemeshingOrANewDepth) {
  Model model = build(contact_scene());
  const fem::Problem* problem = model.problem.get();
  const VectorX depth = model.contact->geometry().depth;
  const MatrixX scene_penalty = model.contact->geometry().penalty;

  set_contact(model, {.method = contact::ContactMethod::Point, .penalty = 7.0});
  EXPECT_EQ(model.problem.get(), problem) << "no new mesh";
  ASSERT_TRUE(model.contact);
  EXPECT_EQ(model.contact->options().method, contact::ContactMethod::Point);
  EXPECT_EQ(model.contact->geometry().depth, depth);
  const MatrixX& penalty = model.contact->geometry().penalty;
  for (Index a = 0; a < penalty.rows(); ++a)
    for (Index b = 0; b < penalty.cols(); ++b) EXPECT_EQ(penalty(a, b), scene_penalty(a, b) > 0 ? 7.0 : 0.0);

  // Penalty 0 removes the contact term: the objective is elastic + external alone.
  set_contact(model, {.penalty = 0});
  EXPECT_FALSE(model.contact);
  fem::State state = model.dofs->initial_state(0.0);
  const fem::BodyRange& box = model.problem->bodies.at(0);
  state.x.col(2).segment(box.first_node, box.num_nodes).array() -= 0.01;  // the box sinks into the plate
  model.objective->set_load_parameter(1.0);
  model.external->set_load_parameter(1.0);
  EXPECT_DOUBLE_EQ(model.objective->value(state), model.elastic->value(state.x) + model.external->value(state.x));

  set_contact(model, {.method = contact::ContactMethod::Area, .penalty = 7.0});
  ASSERT_TRUE(model.contact);
  model.objective->begin_step(state);
  EXPECT_GT(model.objective->value(state), model.elastic->value(state.x) + model.external->value(state.x));
}

TEST(BuildModel, SetContactRefusesBadPenaltiesWithTheScenesBound) {
  Model model = build(contact_scene());
  EXPECT_THROW(set_contact(model, {.penalty = -1}), InputError);
  EXPECT_THROW(set_contact(model, {.penalty = std::nan("")}), InputError);
  try {
    set_contact(model, {.penalty = 1e12});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("times the automatic penalty"));
  }
  json plain = contact_scene();
  plain.erase("contact");
  Model without = build(plain);
  EXPECT_FALSE(without.contact);
  EXPECT_THROW(set_contact(without, {.penalty = 1}), InputError);
}

TEST(BuildModel, DynamicsGetsMassInertiaAndRayleighViscosity) {
  json scene = contact_scene();
  scene["dynamics"] = {{"integrator", "implicit-euler"}, {"end_time", 0.1}, {"output_interval", 0.05},
                       {"mass_damping", 0.5}};
  const Model model = build(scene);
  ASSERT_TRUE(model.is_dynamic());
  EXPECT_TRUE(model.dynamics->mass);
  EXPECT_TRUE(model.dynamics->inertia);
  EXPECT_TRUE(model.dynamics->viscosity);

  scene["dynamics"]["integrator"] = "quasistatic";
  scene["dynamics"].erase("mass_damping");
  const Model quasistatic = build(scene);
  EXPECT_FALSE(quasistatic.dynamics->inertia);
  EXPECT_FALSE(quasistatic.dynamics->viscosity);

  scene["dynamics"]["integrator"] = "explicit";
  const Model explicit_model = build(scene);
  EXPECT_GT(explicit_model.dynamics->elastic_critical_time_step, 0.0);
  EXPECT_GT(explicit_model.dynamics->contact_critical_time_step, 0.0);
  EXPECT_EQ(explicit_model.dynamics->critical_time_step,
            std::min(explicit_model.dynamics->elastic_critical_time_step,
                     explicit_model.dynamics->contact_critical_time_step));
}

// What `sinew validate` and `sinew run` both build: an explicit run with a free massless
// rigid body is refused here, before anything runs.
TEST(BuildModel, AnExplicitRunWithAFreeMasslessPartIsAnInputError) {
  json scene = contact_scene();
  scene["bodies"][1]["regions"]["plate"] = {{"rigid", "free"}, {"density", 0}};
  scene["dynamics"] = {{"integrator", "explicit"}, {"end_time", 0.01}, {"output_interval", 0.01}};
  EXPECT_THAT(build_error(scene), HasSubstr("density"));
  scene["dynamics"]["integrator"] = "implicit-euler";  // implicit: the potential may hold it
  EXPECT_EQ(build_error(scene), "no error");
}

TEST(SolveModel, AStaticModelIsPressedOntoThePlate) {
  // The box's top is pushed down by 0.02 on rollers (x = 0 and y = 0 faces held in their
  // planes): contact holds the bottom up, so the box is compressed.
  json scene = sinew::testing::pressed_box_on_plate_scene();
  scene["solver"]["increments"] = 2;
  Model model = build(scene);
  const solver::StepperResult result = solve_model(model);
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_EQ(result.segments_completed, 2);
  EXPECT_EQ(result.last_state.lambda, 1.0);
  EXPECT_EQ(result.t, 1.0);
  const fem::BodyRange& box = model.problem->bodies.at(0);
  const VectorX z = result.last_state.x.col(2).segment(box.first_node, box.num_nodes);
  EXPECT_NEAR(z.maxCoeff(), 0.48, 1e-9);
  EXPECT_LT(z.minCoeff(), 0.0) << "the penalty lets the bottom sink a little";
  EXPECT_GT(z.minCoeff(), -0.01) << "but not far";
}

}  // namespace
}  // namespace sinew::model
