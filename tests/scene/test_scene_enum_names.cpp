/// @file test_scene_enum_names.cpp
/// The names of every enumeration a scene names, written once in its name table: they round-trip,
/// the schema allows exactly them, and the reader rejects any other name with a message that
/// names the key path, the bad value and the allowed values.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scene/scene_test_support.hpp"
#include "sinew/contact/contact_energy.hpp"
#include "sinew/core/enum_names.hpp"
#include "sinew/fem/constraints_config.hpp"
#include "sinew/fem/mass_matrix.hpp"
#include "sinew/material/law.hpp"
#include "sinew/material/material_spec.hpp"
#include "sinew/mesh/generate.hpp"
#include "sinew/scene/scene_config.hpp"
#include "sinew/scene/scene_schema.hpp"
#include "sinew/solver/solver_config.hpp"

namespace sinew::scene {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;
using testing::schema_node_at;

template <NamedEnum E>
void expect_round_trip() {
  std::vector<std::string> seen;
  for (const auto& [value, name] : enum_names(E{})) {
    EXPECT_FALSE(name.empty());
    EXPECT_EQ(name_of(value), name);
    EXPECT_EQ(parse_name<E>(name), value) << name;
    for (const std::string& other : seen) EXPECT_NE(other, name) << "a name twice";
    seen.emplace_back(name);
  }
  EXPECT_FALSE(parse_name<E>("no-such-name").has_value());
}

TEST(SceneEnumNames, EveryTableRoundTrips) {
  expect_round_trip<contact::ContactMethod>();
  expect_round_trip<contact::PairHessian>();
  expect_round_trip<solver::LinearSolverOptions::Kind>();
  expect_round_trip<solver::NewtonOptions::LineSearchRule>();
  expect_round_trip<solver::LoadSteppingOptions::Predictor>();
  expect_round_trip<solver::DynamicOptions::Integrator>();
  expect_round_trip<fem::MassKind>();
  expect_round_trip<fem::RigidBody::Kind>();
  expect_round_trip<material::Law>();
  expect_round_trip<mesh::Shape::Kind>();
  expect_round_trip<NodeSelector::Kind>();
  expect_round_trip<BoundaryConditionConfig::Kind>();
}

TEST(SceneEnumNames, TablesCoverEveryValue) {
  // Each table lists every enumerator once: the last enumerator's underlying value + 1 entries.
  EXPECT_EQ(contact::kContactMethodNames.size(), 2u);
  EXPECT_EQ(contact::kPairHessianNames.size(), 3u);
  EXPECT_EQ(solver::kLinearSolverNames.size(), 5u);
  EXPECT_EQ(solver::kLineSearchNames.size(), 2u);
  EXPECT_EQ(solver::kPredictorNames.size(), 3u);
  EXPECT_EQ(solver::kIntegratorNames.size(), 3u);
  EXPECT_EQ(fem::kMassKindNames.size(), 2u);
  EXPECT_EQ(fem::kRigidKindNames.size(), 3u);
  EXPECT_EQ(material::kLawNames.size(), 3u);
  EXPECT_EQ(mesh::kShapeKindNames.size(), 7u);
  EXPECT_EQ(kNodeSelectorKindNames.size(), 5u);
  EXPECT_EQ(kBoundaryConditionKindNames.size(), 3u);
}

TEST(SceneEnumNames, LawOfFollowsTheVariantOrder) {
  EXPECT_EQ(material::law_of(material::MooneyRivlinParams{}), material::Law::MooneyRivlin);
  EXPECT_EQ(material::law_of(material::VerondaWestmannParams{}), material::Law::VerondaWestmann);
  EXPECT_EQ(material::law_of(material::NeoHookeanParams{}), material::Law::NeoHookean);
}

template <NamedEnum E>
std::vector<json> table_as_json() {
  std::vector<json> names;
  for (const std::string& name : names_of<E>()) names.emplace_back(name);
  return names;
}

TEST(SceneEnumNames, SchemaEnumListsEqualTheTables) {
  EXPECT_EQ(schema_node_at("contact.method").allowed, table_as_json<contact::ContactMethod>());
  EXPECT_EQ(schema_node_at("contact.hessian").allowed, table_as_json<contact::PairHessian>());
  EXPECT_EQ(schema_node_at("solver.linear.solver").allowed, table_as_json<solver::LinearSolverOptions::Kind>());
  EXPECT_EQ(schema_node_at("solver.newton.line_search").allowed,
            table_as_json<solver::NewtonOptions::LineSearchRule>());
  EXPECT_EQ(schema_node_at("solver.predictor").allowed, table_as_json<solver::LoadSteppingOptions::Predictor>());
  EXPECT_EQ(schema_node_at("dynamics.integrator").allowed, table_as_json<solver::DynamicOptions::Integrator>());
  EXPECT_EQ(schema_node_at("dynamics.mass").allowed, table_as_json<fem::MassKind>());
  EXPECT_EQ(schema_node_at("materials.[].law").allowed, table_as_json<material::Law>());
  EXPECT_EQ(schema_node_at("boundary_conditions.[].type").allowed, table_as_json<BoundaryConditionConfig::Kind>());
  // The kinds written as keys: the one_of alternatives.
  EXPECT_EQ(scene_schema().definitions.at("shape").one_of, names_of<mesh::Shape::Kind>());
  EXPECT_EQ(scene_schema().definitions.at("node_selector").one_of, names_of<NodeSelector::Kind>());
  // The JSON Schema export carries the same lists.
  const json exported = scene_json_schema();
  EXPECT_EQ(exported["properties"]["contact"]["properties"]["method"]["enum"],
            json(table_as_json<contact::ContactMethod>()));
}

/// A scene that uses every enumeration: contact, dynamics, a boundary condition, a rigid region.
json scene_with_every_name() {
  json scene = testing::minimal_scene();
  scene["contact"] = json::object();
  scene["dynamics"] = {{"end_time", 1.0}, {"output_interval", 0.1}};
  scene["boundary_conditions"] = json::parse(R"([{"name": "clamp", "type": "fixed", "nodes": {"all": true}}])");
  scene["bodies"][0]["regions"]["bone"] = {{"rigid", "fixed"}};
  return scene;
}

/// The scene after the schema (every default filled in), as read_scene expects it.
json completed(const json& scene) {
  const SchemaValidation validation = validate_and_complete(scene_schema(), scene);
  EXPECT_TRUE(validation.errors.empty()) << validation.errors.front();
  return validation.completed;
}

/// The InputError message of read_scene, "" (and a failure) when it accepts the scene.
std::string read_error(const json& scene) {
  try {
    read_scene(scene, testing::data_directory());
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "read_scene accepted " << scene.dump();
  return "";
}

struct BadName {
  json::json_pointer pointer;  ///< where the name is in the scene
  std::string path;            ///< the JSON path the message names
  std::string allowed;         ///< names_list of the enum
};

std::vector<BadName> bad_names() {
  return {
      {json::json_pointer("/contact/method"), "contact.method", names_list<contact::ContactMethod>()},
      {json::json_pointer("/contact/hessian"), "contact.hessian", names_list<contact::PairHessian>()},
      {json::json_pointer("/dynamics/integrator"), "dynamics.integrator", names_list<solver::DynamicOptions::Integrator>()},
      {json::json_pointer("/dynamics/mass"), "dynamics.mass", names_list<fem::MassKind>()},
      {json::json_pointer("/solver/linear/solver"), "solver.linear.solver",
       names_list<solver::LinearSolverOptions::Kind>()},
      {json::json_pointer("/solver/newton/line_search"), "solver.newton.line_search",
       names_list<solver::NewtonOptions::LineSearchRule>()},
      {json::json_pointer("/solver/predictor"), "solver.predictor", names_list<solver::LoadSteppingOptions::Predictor>()},
      {json::json_pointer("/materials/gel/law"), "materials.gel.law", names_list<material::Law>()},
      {json::json_pointer("/boundary_conditions/0/type"), "boundary_conditions[0].type",
       names_list<BoundaryConditionConfig::Kind>()},
      {json::json_pointer("/bodies/0/regions/bone/rigid"), "bodies[0].regions.bone.rigid",
       "\"fixed\", \"free\" or {\"prescribed\": motion}"},
  };
}

TEST(SceneEnumNames, TheSceneReadsWithEveryName) {
  EXPECT_NO_THROW(read_scene(completed(scene_with_every_name()), testing::data_directory()));
}

TEST(SceneEnumNames, ReaderRejectsUnknownNamesNamingPathValueAndAllowedNames) {
  const json good = completed(scene_with_every_name());
  for (const BadName& bad : bad_names()) {
    SCOPED_TRACE(bad.path);
    json scene = good;
    scene[bad.pointer] = "no-such-name";
    const std::string message = read_error(scene);
    EXPECT_THAT(message, HasSubstr(bad.path + ": unknown value \"no-such-name\"; allowed: " + bad.allowed));
  }
}

TEST(SceneEnumNames, ReaderRejectsTheLastNameOfAnotherTable) {
  // The old reader took any name it did not know for the last value; a name of another
  // enumeration is as unknown as any other.
  json scene = completed(scene_with_every_name());
  scene["contact"]["method"] = "gauss-newton";
  scene["dynamics"]["mass"] = "explicit";
  scene["bodies"][0]["regions"]["bone"]["rigid"] = "prescribed";  // needs its motion: {"prescribed": ...}
  const std::string message = read_error(scene);
  EXPECT_THAT(message, HasSubstr("contact.method: unknown value \"gauss-newton\""));
  EXPECT_THAT(message, HasSubstr("dynamics.mass: unknown value \"explicit\""));
  EXPECT_THAT(message, HasSubstr("bodies[0].regions.bone.rigid: unknown value \"prescribed\""));
}

TEST(SceneEnumNames, ParseSceneRejectsUnknownNamesNamingPathAndAllowedNames) {
  for (const BadName& bad : bad_names()) {
    SCOPED_TRACE(bad.path);
    if (bad.path == "bodies[0].regions.bone.rigid") continue;  // "fixed"/"free" or {"prescribed": ...}
    json scene = scene_with_every_name();
    scene[bad.pointer] = "no-such-name";
    const std::string message = testing::parse_error(scene);
    EXPECT_THAT(message, HasSubstr(bad.path + ": "));
    EXPECT_THAT(message, HasSubstr("\"no-such-name\""));
    EXPECT_THAT(message, HasSubstr(bad.allowed));
  }
}

}  // namespace
}  // namespace sinew::scene
