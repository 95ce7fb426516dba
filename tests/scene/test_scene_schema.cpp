/// @file test_scene_schema.cpp
/// The scene schema as the single source of truth: its defaults equal the C++ structs', every
/// key is documented, docs/scene-reference.md is up to date, the JSON Schema export is sound.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "scene/scene_test_support.hpp"
#include "sinew/scene/scene_schema.hpp"

namespace sinew::scene {
namespace {

using nlohmann::json;

const SchemaNode& node_at(const std::string& path) { return testing::schema_node_at(path); }

json default_at(const std::string& path) {
  const SchemaNode& node = node_at(path);
  if (!node.default_value) throw std::runtime_error("no default at " + path);
  return *node.default_value;
}

json vec(const Vector3& v) { return json::array({v.x(), v.y(), v.z()}); }

TEST(SceneSchema, DocumentedDefaultsEqualTheStructDefaults) {
  const solver::StaticSolverOptions solver;
  EXPECT_EQ(default_at("solver.increments"), solver.stepping.increments);
  EXPECT_EQ(default_at("solver.predictor"), name_of(solver.stepping.predictor));
  EXPECT_EQ(default_at("solver.predictor"), "tangent");
  EXPECT_EQ(default_at("solver.min_step"), solver.stepping.min_step);
  EXPECT_EQ(default_at("solver.growth"), solver.stepping.growth);
  EXPECT_EQ(default_at("solver.easy_iterations"), solver.stepping.easy_iterations);
  EXPECT_EQ(default_at("solver.newton.max_iterations"), solver.newton.max_iterations);
  EXPECT_EQ(default_at("solver.newton.residual_tolerance"), solver.newton.residual_tolerance);
  EXPECT_EQ(default_at("solver.newton.increment_tolerance"), solver.newton.increment_tolerance);
  EXPECT_EQ(default_at("solver.newton.line_search"), name_of(solver.newton.line_search));
  EXPECT_EQ(default_at("solver.newton.max_line_search_steps"), solver.newton.max_line_search_steps);
  EXPECT_EQ(default_at("solver.newton.quasi_viscosity"), solver.newton.quasi_viscosity);
  EXPECT_EQ(default_at("solver.newton.project_hessians"), solver.newton.project_element_hessians);
  EXPECT_EQ(default_at("solver.newton.max_step_growth"), solver.newton.max_step_growth);
  EXPECT_EQ(default_at("solver.linear.solver"), name_of(solver.linear.kind));
  EXPECT_EQ(default_at("solver.linear.tolerance"), solver.linear.tolerance);
  EXPECT_EQ(default_at("solver.linear.max_iterations"), solver.linear.max_iterations);
  EXPECT_EQ(default_at("solver.linear.gmres_restart"), solver.linear.gmres_restart);

  const OutputConfig output;
  EXPECT_EQ(default_at("output.vtu"), output.vtu);
  EXPECT_EQ(default_at("output.every"), output.every);

  const MeshSourceConfig mesh_source;
  EXPECT_EQ(default_at("bodies.[].transform.translate"), vec(mesh_source.translate));
  EXPECT_EQ(default_at("bodies.[].transform.rotate.axis"), vec(mesh_source.rotate_axis));
  EXPECT_EQ(default_at("bodies.[].transform.rotate.angle_deg"), mesh_source.rotate_angle);
  EXPECT_EQ(default_at("bodies.[].mesh.generate.optimize_passes"), mesh::GenerateOptions{}.optimize_passes);
  EXPECT_EQ(default_at("bodies.[].regions.[].density"), RegionConfig{}.density);
  const mesh::Shape shape;
  EXPECT_EQ(default_at("bodies.[].mesh.generate.parts.[].shape.torus.angle_deg"), shape.angle_deg);
  EXPECT_EQ(default_at("bodies.[].mesh.generate.parts.[].shape.transform.translate"), vec(shape.translation));
  EXPECT_EQ(default_at("bodies.[].mesh.generate.parts.[].shape.transform.rotate.center"), vec(shape.rotation_center));
  EXPECT_EQ(default_at("materials.[].C2"), material::MooneyRivlinParams{}.C2);
  EXPECT_EQ(default_at("materials.[].fiber.direction"), vec(material::FiberParams{}.direction));

  const NodeSelector selector;
  EXPECT_EQ(default_at("boundary_conditions.[].nodes.box.padding"), selector.tolerance);
  EXPECT_EQ(default_at("boundary_conditions.[].nodes.plane.tolerance"), selector.tolerance);
  EXPECT_EQ(default_at("boundary_conditions.[].displacement"), BoundaryConditionConfig{}.displacement);
  const fem::RigidMotion motion;
  EXPECT_EQ(default_at("boundary_conditions.[].motion.translation"), vec(motion.translation));
  EXPECT_EQ(default_at("boundary_conditions.[].motion.rotation.point"), vec(motion.axis_point));
  EXPECT_EQ(default_at("loads.gravity"), vec(LoadsConfig{}.gravity));
}

/// Every key has a one-line description and a required key has no default.
void expect_documented(const SchemaNode& node, const std::string& path) {
  if (!node.key.empty()) {
    EXPECT_FALSE(node.doc.empty()) << path << " has no description";
    EXPECT_EQ(node.doc.find('\n'), std::string::npos) << path;
    EXPECT_FALSE(node.required && node.default_value) << path << " is required and has a default";
  }
  for (const SchemaNode& property : node.properties) expect_documented(property, path + "." + property.key);
  for (const SchemaVariant& variant : node.variants) {
    EXPECT_FALSE(variant.doc.empty()) << path << " variant " << variant.tag;
    for (const SchemaNode& property : variant.properties) expect_documented(property, path + "." + property.key);
  }
  for (const SchemaNode& item : node.items) expect_documented(item, path + "[]");
  if (node.type == SchemaType::Ref) {
    EXPECT_TRUE(scene_schema().definitions.count(node.ref)) << path;
  }
}

TEST(SceneSchema, EveryKeyIsDocumented) {
  expect_documented(scene_schema().root, "");
  for (const auto& [name, definition] : scene_schema().definitions) {
    EXPECT_FALSE(definition.doc.empty()) << name;
    expect_documented(definition, name);
  }
}

TEST(SceneSchema, DefaultsPassTheirOwnSchema) {
  // A scene of only required keys validates, and completion fills every default in.
  const SceneConfig config = parse_scene(testing::minimal_scene(), "");
  EXPECT_EQ(config.solver.stepping.increments, solver::LoadSteppingOptions{}.increments);
}

TEST(SceneSchema, ExampleOfTheReferenceParses) {
  const SceneConfig scene = parse_scene(json::parse(scene_example_json()), testing::data_directory());
  EXPECT_EQ(scene.bodies.size(), 2u);
  EXPECT_EQ(scene.boundary_conditions.size(), 3u);
}

TEST(SceneSchema, ReferenceDocumentIsUpToDate) {
  const std::string path = std::string(SINEW_SOURCE_DIR) + "/docs/scene-reference.md";
  std::ifstream in(path, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  EXPECT_TRUE(content.str() == scene_reference_markdown())
      << path << " is out of date with the scene schema (src/sinew/scene/scene_schema.cpp). Regenerate it from "
      << "sinew::scene::scene_reference_markdown(): `sinew schema --markdown > docs/scene-reference.md`.";
}

TEST(SceneSchema, ReferenceHasATablePerObject) {
  const std::string markdown = scene_reference_markdown();
  for (const char* heading : {"### Top level", "### `materials.<name>`", "### `materials.<name>.fiber`",
                              "### `bodies[]`", "### `bodies[].mesh`", "### `bodies[].mesh.generate`",
                              "### `bodies[].regions.<name>`", "### `boundary_conditions[]`", "### `loads`",
                              "### `solver`", "### `solver.newton`", "### `solver.linear`", "### `output`",
                              "### node_selector", "### motion", "### shape", "### amplitude", "## Example"}) {
    EXPECT_NE(markdown.find(heading), std::string::npos) << heading;
  }
  EXPECT_THAT(markdown, ::testing::HasSubstr(
                            "| `increments` | integer | `10` | >= 1; <= 1e+06 | load increments (an output after each) |"));
  EXPECT_THAT(markdown, ::testing::HasSubstr("With `law` = `\"mooney-rivlin\"`"));
}

TEST(SceneSchema, JsonSchemaExport) {
  const json schema = scene_json_schema();
  EXPECT_EQ(schema.at("$schema"), "http://json-schema.org/draft-07/schema#");
  EXPECT_EQ(schema.at("type"), "object");
  EXPECT_EQ(schema.at("required"), json::array({"units", "bodies"}));
  EXPECT_EQ(schema.at("additionalProperties"), false);
  for (const char* name : {"node_selector", "motion", "amplitude", "shape"}) {
    EXPECT_TRUE(schema.at("definitions").contains(name)) << name;
  }
  const json& solver = schema.at("properties").at("solver");
  EXPECT_EQ(solver.at("properties").at("increments").at("default"), 10);
  EXPECT_EQ(solver.at("properties").at("predictor").at("enum"), json::array({"none", "two-point", "tangent"}));
  const json& material = schema.at("properties").at("materials").at("additionalProperties");
  ASSERT_EQ(material.at("oneOf").size(), 3u);  // one closed alternative per law
  EXPECT_EQ(material.at("oneOf")[0].at("properties").at("law").at("const"), "mooney-rivlin");
  EXPECT_EQ(material.at("oneOf")[0].at("required"), json::array({"law", "C1", "a"}));
  const json& selector = schema.at("definitions").at("node_selector");
  EXPECT_EQ(selector.at("oneOf").size(), 5u);
  const json& shape = schema.at("definitions").at("shape");
  EXPECT_EQ(shape.at("properties").at("union").at("items").at("$ref"), "#/definitions/shape");
  EXPECT_EQ(shape.at("properties").at("intersection").at("items").at("$ref"), "#/definitions/shape");
  EXPECT_EQ(shape.at("oneOf").size(), 7u);  // "transform" is not an alternative
  EXPECT_TRUE(shape.at("properties").contains("transform"));
}

}  // namespace
}  // namespace sinew::scene
