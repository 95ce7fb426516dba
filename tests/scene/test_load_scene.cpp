/// @file test_load_scene.cpp
/// Scene files -> SceneConfig: the full example, defaults, and every kind of error with the
/// JSON path it is reported at.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <numbers>

#include "scene/scene_test_support.hpp"
#include "sinew/scene/load_scene.hpp"

namespace sinew::scene {
namespace {

using nlohmann::json;
using testing::data_directory;
using testing::load_error;
using testing::minimal_scene;
using testing::parse_error;
using testing::TempDir;
using ::testing::HasSubstr;
using ::testing::StartsWith;

constexpr double kPi = std::numbers::pi;

TEST(LoadScene, FullExample) {
  const SceneConfig scene = load_scene_file(data_directory() + "/full_example.json");
  EXPECT_EQ(scene.name, "uniaxial-mooney-rivlin");
  EXPECT_EQ(scene.units, "mm, N, MPa, s");
  EXPECT_EQ(scene.base_directory, std::filesystem::absolute(data_directory()).lexically_normal().string());

  ASSERT_EQ(scene.materials.size(), 3u);
  const auto& rubber = std::get<material::MooneyRivlinParams>(scene.materials.at("rubber").base);
  EXPECT_EQ(rubber.C1, 0.5);
  EXPECT_EQ(rubber.C2, 0.1);
  EXPECT_EQ(rubber.a, 2.0);
  EXPECT_FALSE(scene.materials.at("rubber").fiber);
  const auto& tendon = scene.materials.at("tendon");
  EXPECT_EQ(std::get<material::VerondaWestmannParams>(tendon.base).a, 10);
  ASSERT_TRUE(tendon.fiber);
  EXPECT_EQ(tendon.fiber->beta, 2.0);
  EXPECT_EQ(tendon.fiber->direction, Vector3(0, 0, 1));
  EXPECT_EQ(std::get<material::NeoHookeanParams>(scene.materials.at("gel").base).lambda, 10.0);

  ASSERT_EQ(scene.bodies.size(), 2u);
  const BodyConfig& block = scene.bodies[0];
  EXPECT_EQ(block.name, "block");
  EXPECT_EQ(block.mesh.file, (std::filesystem::path(scene.base_directory) / "block.msh").string());
  EXPECT_EQ(block.mesh.rotate_angle, 0);
  ASSERT_EQ(block.regions.size(), 5u);
  EXPECT_EQ(block.regions.at("*").material, "rubber");
  EXPECT_EQ(block.regions.at("*").density, 1e-6);
  EXPECT_TRUE(block.regions.at("bone").rigid);
  EXPECT_EQ(block.regions.at("bone").rigid_kind, fem::RigidBody::Kind::Fixed);
  EXPECT_EQ(block.regions.at("patella").rigid_kind, fem::RigidBody::Kind::Free);
  EXPECT_EQ(block.regions.at("patella").density, 2e-6);
  const RegionConfig& tibia = block.regions.at("tibia");
  EXPECT_EQ(tibia.rigid_kind, fem::RigidBody::Kind::Prescribed);
  EXPECT_EQ(tibia.rigid_motion.axis, Vector3(1, 0, 0));
  EXPECT_DOUBLE_EQ(tibia.rigid_motion.angle, kPi / 2);  // stored in radians
  EXPECT_TRUE(tibia.rigid_motion.amplitude.points.empty());  // the default ramp
  EXPECT_EQ(block.regions.at("muscle").fiber_direction, Vector3(0, 0, 1));

  const BodyConfig& ball = scene.bodies[1];
  EXPECT_TRUE(ball.mesh.file.empty());
  EXPECT_EQ(ball.mesh.generate.element_size, 0.1);
  ASSERT_EQ(ball.mesh.parts.size(), 2u);
  EXPECT_EQ(ball.mesh.parts[0].region, "ball");
  EXPECT_EQ(ball.mesh.parts[0].shape.kind, mesh::Shape::Kind::Sphere);
  EXPECT_EQ(ball.mesh.parts[0].shape.center, Vector3(0, 0, 2));
  EXPECT_EQ(ball.mesh.parts[0].shape.radius, 0.5);
  const mesh::Shape& core = ball.mesh.parts[1].shape;
  EXPECT_EQ(core.kind, mesh::Shape::Kind::Difference);
  ASSERT_EQ(core.children.size(), 2u);
  EXPECT_EQ(core.children[0].kind, mesh::Shape::Kind::Box);
  EXPECT_EQ(core.children[0].max, Vector3(1, 1, 1));
  EXPECT_EQ(core.children[1].kind, mesh::Shape::Kind::Cylinder);
  EXPECT_EQ(core.children[1].center, Vector3(0.5, 0.5, 0));
  EXPECT_EQ(core.children[1].radius, 0.2);
  EXPECT_EQ(ball.regions.at("*").material, "gel");

  ASSERT_EQ(scene.boundary_conditions.size(), 3u);
  const BoundaryConditionConfig& clamp = scene.boundary_conditions[0];
  EXPECT_EQ(clamp.kind, BoundaryConditionConfig::Kind::Fixed);
  EXPECT_EQ(clamp.nodes.kind, NodeSelector::Kind::Plane);
  EXPECT_EQ(clamp.nodes.body, "block");
  EXPECT_EQ(clamp.nodes.normal, Vector3(1, 0, 0));
  EXPECT_EQ(clamp.nodes.tolerance, 1e-6);
  const BoundaryConditionConfig& pull = scene.boundary_conditions[1];
  EXPECT_EQ(pull.kind, BoundaryConditionConfig::Kind::Prescribed);
  EXPECT_EQ(pull.nodes.kind, NodeSelector::Kind::Box);
  EXPECT_EQ(pull.nodes.box_min, Vector3(1, 0, 0));
  EXPECT_EQ(pull.nodes.tolerance, 1e-6);
  EXPECT_EQ(pull.motion.translation, Vector3(0.5, 0, 0));
  EXPECT_EQ(pull.motion.amplitude.points, (std::vector<std::pair<double, double>>{{0, 0}, {1, 1}}));
  const BoundaryConditionConfig& roller = scene.boundary_conditions[2];
  EXPECT_EQ(roller.kind, BoundaryConditionConfig::Kind::Planar);
  EXPECT_EQ(roller.nodes.kind, NodeSelector::Kind::Set);
  EXPECT_EQ(roller.nodes.name, "left");
  EXPECT_EQ(roller.normal, Vector3(1, 0, 0));

  EXPECT_EQ(scene.loads.gravity, Vector3(0, 0, -9.81));
  ASSERT_EQ(scene.loads.forces.size(), 1u);
  EXPECT_EQ(scene.loads.forces[0].nodes.kind, NodeSelector::Kind::Region);
  EXPECT_EQ(scene.loads.forces[0].nodes.body, "ball");
  EXPECT_EQ(scene.loads.forces[0].total_force, Vector3(0, 0, -1));

  EXPECT_EQ(scene.solver.stepping.predictor, solver::LoadSteppingOptions::Predictor::TwoPoint);
  EXPECT_EQ(scene.solver.newton.line_search, solver::NewtonOptions::LineSearchRule::Energy);
  EXPECT_EQ(scene.solver.linear.kind, solver::LinearSolverOptions::Kind::Cholmod);
  EXPECT_TRUE(scene.output.vtu);
}

TEST(LoadScene, OmittedKeysTakeTheStructDefaults) {
  const SceneConfig scene = parse_scene(minimal_scene(), "");
  const solver::StaticSolverOptions defaults;
  EXPECT_EQ(scene.solver.stepping.increments, defaults.stepping.increments);
  EXPECT_EQ(scene.solver.stepping.predictor, defaults.stepping.predictor);
  EXPECT_EQ(scene.solver.stepping.min_step, defaults.stepping.min_step);
  EXPECT_EQ(scene.solver.stepping.growth, defaults.stepping.growth);
  EXPECT_EQ(scene.solver.stepping.easy_iterations, defaults.stepping.easy_iterations);
  EXPECT_EQ(scene.solver.newton.max_iterations, defaults.newton.max_iterations);
  EXPECT_EQ(scene.solver.newton.residual_tolerance, defaults.newton.residual_tolerance);
  EXPECT_EQ(scene.solver.newton.increment_tolerance, defaults.newton.increment_tolerance);
  EXPECT_EQ(scene.solver.newton.line_search, defaults.newton.line_search);
  EXPECT_EQ(scene.solver.newton.max_line_search_steps, defaults.newton.max_line_search_steps);
  EXPECT_EQ(scene.solver.newton.quasi_viscosity, defaults.newton.quasi_viscosity);
  EXPECT_EQ(scene.solver.newton.project_element_hessians, defaults.newton.project_element_hessians);
  EXPECT_EQ(scene.solver.newton.max_step_growth, defaults.newton.max_step_growth);
  EXPECT_EQ(scene.solver.linear.kind, defaults.linear.kind);
  EXPECT_EQ(scene.solver.linear.tolerance, defaults.linear.tolerance);
  EXPECT_EQ(scene.solver.linear.max_iterations, defaults.linear.max_iterations);
  EXPECT_EQ(scene.solver.linear.gmres_restart, defaults.linear.gmres_restart);
  const OutputConfig output;
  EXPECT_EQ(scene.output.vtu, output.vtu);
  EXPECT_EQ(scene.output.every, output.every);

  EXPECT_EQ(scene.name, "");
  EXPECT_TRUE(scene.boundary_conditions.empty());
  EXPECT_TRUE(scene.loads.forces.empty());
  EXPECT_EQ(scene.loads.gravity, Vector3::Zero());
  const BodyConfig& body = scene.bodies.at(0);
  EXPECT_EQ(body.mesh.translate, Vector3::Zero());
  EXPECT_EQ(body.mesh.rotate_axis, Vector3::UnitZ());
  EXPECT_EQ(body.mesh.rotate_angle, 0);
  EXPECT_EQ(body.mesh.generate.optimize_passes, mesh::GenerateOptions{}.optimize_passes);
  EXPECT_EQ(body.regions.at("*").density, 0);
  EXPECT_FALSE(body.regions.at("*").rigid);
}

TEST(LoadScene, OptionalsAndConversions) {
  json scene = minimal_scene();
  scene["bodies"][0]["transform"] = {{"rotate", {{"axis", {1, 0, 0}}, {"angle_deg", 180}}}};
  scene["materials"]["fibrous"] = json::parse(R"({"law": "mooney-rivlin", "C1": 1, "a": 1, "fiber": {"alpha": 0, "beta": 1}})");
  scene["bodies"][0]["regions"]["*"] = {{"material", "fibrous"}, {"fiber_direction", {0, 1, 0}}};
  scene["boundary_conditions"] = json::parse(R"([
    {"name": "slide", "type": "planar", "nodes": {"all": true}, "normal": [0, 0, 2], "displacement": -0.1,
     "amplitude": [[0, 0], [0.5, 1], [1, 1]]},
    {"name": "base", "type": "fixed", "nodes": {"set": "cube.surface"}}])");
  const SceneConfig config = parse_scene(scene, "");
  EXPECT_DOUBLE_EQ(config.bodies[0].mesh.rotate_angle, kPi);
  EXPECT_EQ(config.bodies[0].mesh.rotate_axis, Vector3(1, 0, 0));
  const auto& fibrous = config.materials.at("fibrous");
  EXPECT_EQ(std::get<material::MooneyRivlinParams>(fibrous.base).C2, 0);  // default
  EXPECT_EQ(fibrous.fiber->direction, Vector3::UnitX());                  // default
  EXPECT_EQ(config.bodies[0].regions.at("*").fiber_direction, Vector3(0, 1, 0));
  const BoundaryConditionConfig& slide = config.boundary_conditions[0];
  EXPECT_EQ(slide.nodes.kind, NodeSelector::Kind::All);
  EXPECT_EQ(slide.nodes.body, "cube");  // the only body
  EXPECT_EQ(slide.displacement, -0.1);
  EXPECT_EQ(slide.amplitude.points.size(), 3u);
  EXPECT_EQ(config.boundary_conditions[1].nodes.name, "cube.surface");
}

TEST(LoadScene, TorusIntersectionAndShapeTransforms) {
  json scene = minimal_scene();
  scene["bodies"][0]["mesh"]["generate"]["parts"] = json::parse(R"([
    {"region": "slope", "shape": {"box": {"min": [-2, -1, -0.1], "max": [2, 1, 0.1]},
                                  "transform": {"rotate": {"axis": [0, 1, 0], "angle_deg": 45, "center": [0, 0, 1]},
                                                "translate": [0, 0, 2]}}},
    {"region": "bar", "shape": {"torus": {"center": [1, 2, 3], "axis": [0, 0, 2], "radius": 1, "minor_radius": 0.1,
                                          "angle_deg": 90, "start_direction": [0, 1, 0]}}},
    {"region": "ring", "shape": {"torus": {"center": [0, 0, 0], "axis": [1, 0, 0], "radius": 2, "minor_radius": 0.5}}},
    {"region": "cap", "shape": {"intersection": [{"sphere": {"center": [0, 0, 0], "radius": 1}},
                                                 {"box": {"min": [-1, -1, 0.5], "max": [1, 1, 1]},
                                                  "transform": {"translate": [0, 0, 0.25]}}],
                                "transform": {"rotate": {"axis": [1, 0, 0], "angle_deg": -30}}}}])");
  const SceneConfig config = parse_scene(scene, "");
  const auto& parts = config.bodies[0].mesh.parts;
  ASSERT_EQ(parts.size(), 4u);

  const mesh::Shape& slope = parts[0].shape;
  EXPECT_EQ(slope.kind, mesh::Shape::Kind::Box);
  EXPECT_EQ(slope.rotation_axis, Vector3(0, 1, 0));
  EXPECT_EQ(slope.rotation_angle_deg, 45);  // degrees, as in the file
  EXPECT_EQ(slope.rotation_center, Vector3(0, 0, 1));
  EXPECT_EQ(slope.translation, Vector3(0, 0, 2));

  const mesh::Shape& bar = parts[1].shape;
  EXPECT_EQ(bar.kind, mesh::Shape::Kind::Torus);
  EXPECT_EQ(bar.center, Vector3(1, 2, 3));
  EXPECT_EQ(bar.axis, Vector3(0, 0, 2));
  EXPECT_EQ(bar.radius, 1);
  EXPECT_EQ(bar.minor_radius, 0.1);
  EXPECT_EQ(bar.angle_deg, 90);
  EXPECT_EQ(bar.start_direction, Vector3(0, 1, 0));
  EXPECT_EQ(bar.rotation_angle_deg, 0);  // no transform: the identity
  EXPECT_EQ(bar.translation, Vector3::Zero());

  const mesh::Shape& ring = parts[2].shape;
  EXPECT_EQ(ring.angle_deg, 360);                     // the default: a full torus
  EXPECT_EQ(ring.start_direction, Vector3::Zero());  // the default reference

  const mesh::Shape& cap = parts[3].shape;
  EXPECT_EQ(cap.kind, mesh::Shape::Kind::Intersection);
  ASSERT_EQ(cap.children.size(), 2u);
  EXPECT_EQ(cap.children[1].translation, Vector3(0, 0, 0.25));
  EXPECT_EQ(cap.children[1].rotation_angle_deg, 0);
  EXPECT_EQ(cap.rotation_angle_deg, -30);
  EXPECT_EQ(cap.rotation_center, Vector3::Zero());  // the default centre
  EXPECT_EQ(cap.translation, Vector3::Zero());      // the default translation
}

TEST(LoadScene, RelativeMeshPathsResolveAgainstTheBaseDirectory) {
  json scene = minimal_scene();
  scene["bodies"][0]["mesh"] = {{"file", "block.msh"}};
  EXPECT_EQ(parse_scene(scene, data_directory()).bodies[0].mesh.file, data_directory() + "/block.msh");
  scene["bodies"][0]["mesh"] = {{"file", "../data/./block.msh"}};
  EXPECT_EQ(parse_scene(scene, data_directory()).bodies[0].mesh.file, data_directory() + "/block.msh");
  scene["bodies"][0]["mesh"] = {{"file", data_directory() + "/block.msh"}};
  EXPECT_EQ(parse_scene(scene, "/nonexistent").bodies[0].mesh.file, data_directory() + "/block.msh");
}

// ---------------------------------------------------------------- errors

TEST(LoadSceneErrors, MissingSceneFile) {
  EXPECT_EQ(load_error("/nonexistent/scene.json"), "scene file not found: /nonexistent/scene.json");
}

TEST(LoadSceneErrors, MalformedJsonNamesFileLineAndColumn) {
  const TempDir directory;
  const std::string path = directory.write("scene.json", "{\n  \"units\": \"m\",\n  \"bodies\": [1, 2,, 3]\n}\n");
  const std::string message = load_error(path);
  EXPECT_THAT(message, StartsWith(path + ":3:19: malformed JSON: "));
  EXPECT_THAT(message, HasSubstr("parse error at line 3, column 19"));  // nlohmann agrees
}

TEST(LoadSceneErrors, MalformedJsonPositionAgreesWithTheParser) {
  for (const std::string text : {"", "{", "{\"units\": ", "{\n\n  \"a\": tru\n}", "{\"a\": 1}\n  x", "[1, 2]\n\n  }"}) {
    const TempDir directory;
    const std::string path = directory.write("scene.json", text);
    const std::string message = load_error(path);
    const std::size_t at = message.find("parse error at line ");
    ASSERT_NE(at, std::string::npos) << message;
    int line = 0, column = 0;
    ASSERT_EQ(std::sscanf(message.c_str() + at, "parse error at line %d, column %d", &line, &column), 2) << message;
    EXPECT_THAT(message, StartsWith(path + ":" + std::to_string(line) + ":" + std::to_string(column) + ": "))
        << "for " << text;
  }
}

TEST(LoadSceneErrors, DuplicateKeyInFile) {
  const TempDir directory;
  const std::string path = directory.write("scene.json", R"({"units": "m", "solver": {"increments": 2, "increments": 3}, "bodies": []})");
  EXPECT_EQ(load_error(path), "solver.increments: duplicate key\n(in scene file " + path + ")");
}

TEST(LoadSceneErrors, FileErrorsEndWithTheFileName) {
  json scene = minimal_scene();
  scene["solver"] = {{"increments", 0}};
  const TempDir directory;
  const std::string path = directory.write("scene.json", scene.dump(2));
  EXPECT_EQ(load_error(path), "solver.increments: must be >= 1, got 0\n(in scene file " + path + ")");
}

TEST(LoadSceneErrors, UnknownKeyWithSuggestion) {
  json scene = minimal_scene();
  scene["bodies"][0]["regions"]["*"]["densty"] = 1;
  EXPECT_EQ(parse_error(scene), "bodies[0].regions[\"*\"].densty: unknown key; did you mean \"density\"?");
  scene = minimal_scene();
  scene["solver"] = {{"newton", {{"max_iteration", 3}}}};
  EXPECT_EQ(parse_error(scene), "solver.newton.max_iteration: unknown key; did you mean \"max_iterations\"?");
}

TEST(LoadSceneErrors, WrongType) {
  json scene = minimal_scene();
  scene["solver"] = {{"increments", "ten"}};
  EXPECT_EQ(parse_error(scene), "solver.increments: must be an integer, got \"ten\"");
  scene = minimal_scene();
  scene["loads"] = {{"gravity", {0, -9.81}}};
  EXPECT_EQ(parse_error(scene), "loads.gravity: must be an array of 3 numbers [x, y, z], got [0,-9.81]");
  scene = minimal_scene();
  scene["bodies"] = json::object();
  EXPECT_EQ(parse_error(scene), "bodies: must be an array, got {}");
}

TEST(LoadSceneErrors, OutOfRange) {
  json scene = minimal_scene();
  scene["bodies"][0]["regions"] = {{"muscle", {{"material", "gel"}, {"density", -1}}}};
  EXPECT_EQ(parse_error(scene), "bodies[0].regions.muscle.density: must be >= 0, got -1");
  scene = minimal_scene();
  scene["solver"] = {{"linear", {{"tolerance", 1}}}};
  EXPECT_EQ(parse_error(scene), "solver.linear.tolerance: must be < 1, got 1");
}

TEST(LoadSceneErrors, NegativeStiffness) {
  json scene = minimal_scene();
  scene["materials"]["rubber"] = {{"law", "mooney-rivlin"}, {"C1", -1}, {"a", 1}};
  scene["materials"]["gel"]["mu"] = 0;
  EXPECT_EQ(parse_error(scene), "materials.gel.mu: must be > 0, got 0\nmaterials.rubber.C1: must be > 0, got -1");
}

TEST(LoadSceneErrors, NanLikeStringIsAWrongType) {
  json scene = minimal_scene();
  scene["materials"]["gel"]["mu"] = "nan";
  scene["materials"]["gel"]["lambda"] = "Infinity";
  EXPECT_EQ(parse_error(scene),
            "materials.gel.mu: must be a number, got \"nan\"\nmaterials.gel.lambda: must be a number, got \"Infinity\"");
}

TEST(LoadSceneErrors, NonFiniteNumberInProgrammaticJson) {
  json scene = minimal_scene();
  scene["loads"] = {{"gravity", {0, 0, std::numeric_limits<double>::infinity()}}};
  EXPECT_EQ(parse_error(scene), "loads.gravity: must hold finite numbers, got [0,0,null]");
}

TEST(LoadSceneErrors, MissingRequiredKey) {
  json scene = minimal_scene();
  scene.erase("units");
  scene["bodies"][0].erase("regions");
  EXPECT_THAT(parse_error(scene), StartsWith("units: missing required key ("));
  EXPECT_THAT(parse_error(scene), HasSubstr("\nbodies[0].regions: missing required key ("));
}

TEST(LoadSceneErrors, AllErrorsAreListedOnePerLine) {
  json scene = minimal_scene();
  scene["solver"] = {{"increments", 0}, {"growth", "fast"}};
  scene["output"] = {{"evry", 2}};
  scene["bodies"][0]["regions"]["*"]["density"] = -1;
  EXPECT_EQ(parse_error(scene),
            "bodies[0].regions[\"*\"].density: must be >= 0, got -1\n"
            "solver.increments: must be >= 1, got 0\n"
            "solver.growth: must be a number, got \"fast\"\n"
            "output.evry: unknown key; did you mean \"every\"?");
}

TEST(LoadSceneErrors, UnknownMaterialLawAndKeysOfAnotherLaw) {
  json scene = minimal_scene();
  scene["materials"]["gel"]["law"] = "neo-hooke";
  EXPECT_EQ(parse_error(scene),
            "materials.gel.law: must be one of \"mooney-rivlin\", \"veronda-westmann\", \"neo-hookean\", got "
            "\"neo-hooke\"; did you mean \"neo-hookean\"?");
  scene = minimal_scene();
  scene["materials"]["gel"]["C1"] = 1;
  EXPECT_EQ(parse_error(scene),
            "materials.gel.C1: unknown key for law \"neo-hookean\"; allowed keys: \"law\", \"fiber\", \"mu\", \"lambda\"");
}

TEST(LoadSceneErrors, UnknownMaterial) {
  json scene = minimal_scene();
  scene["bodies"][0]["regions"]["*"]["material"] = "gle";
  EXPECT_EQ(parse_error(scene), "bodies[0].regions[\"*\"].material: unknown material \"gle\"; did you mean \"gel\"?");
  scene["bodies"][0]["regions"]["*"]["material"] = "steel";
  EXPECT_EQ(parse_error(scene), "bodies[0].regions[\"*\"].material: unknown material \"steel\"; materials: \"gel\"");
}

TEST(LoadSceneErrors, RegionMustBeRigidOrHaveAMaterial) {
  json scene = minimal_scene();
  scene["bodies"][0]["regions"]["*"] = {{"density", 1}};
  EXPECT_EQ(parse_error(scene), "bodies[0].regions[\"*\"]: needs \"material\" (deformable) or \"rigid\"");
  scene["bodies"][0]["regions"]["*"] = {{"material", "gel"}, {"rigid", "fixed"}};
  EXPECT_EQ(parse_error(scene),
            "bodies[0].regions[\"*\"]: has both \"material\" and \"rigid\"; a region is either deformable or rigid");
  scene["bodies"][0]["regions"]["*"] = {{"rigid", "moving"}};
  EXPECT_EQ(parse_error(scene), "bodies[0].regions[\"*\"].rigid: must be one of \"fixed\", \"free\", got \"moving\"");
  scene["bodies"][0]["regions"]["*"] = {{"rigid", 3}};
  EXPECT_EQ(parse_error(scene), "bodies[0].regions[\"*\"].rigid: must be a string or an object, got 3");
  scene["bodies"][0]["regions"]["*"] = {{"rigid", {{"prescribed", {{"translaton", {1, 0, 0}}}}}}};
  EXPECT_EQ(parse_error(scene),
            "bodies[0].regions[\"*\"].rigid.prescribed.translaton: unknown key; did you mean \"translation\"?");
  scene["bodies"][0]["regions"]["*"] = {{"material", "gel"}, {"fiber_direction", {1, 0, 0}}};
  EXPECT_EQ(parse_error(scene), "bodies[0].regions[\"*\"].fiber_direction: material \"gel\" has no \"fiber\" to orient");
}

TEST(LoadSceneErrors, DuplicateBody) {
  json scene = minimal_scene();
  scene["bodies"].push_back(scene["bodies"][0]);
  EXPECT_EQ(parse_error(scene), "bodies[1].name: duplicate body name \"cube\"");
}

TEST(LoadSceneErrors, SelectorBodies) {
  json scene = minimal_scene();
  scene["bodies"].push_back(scene["bodies"][0]);
  scene["bodies"][1]["name"] = "other";
  scene["boundary_conditions"] = json::parse(R"([{"name": "a", "type": "fixed", "nodes": {"all": true}},
                                                 {"name": "b", "type": "fixed", "nodes": {"body": "cub", "all": true}}])");
  EXPECT_EQ(parse_error(scene),
            "boundary_conditions[0].nodes.body: required when the scene has more than one body (bodies: \"cube\", "
            "\"other\")\n"
            "boundary_conditions[1].nodes.body: unknown body \"cub\"; did you mean \"cube\"?");
}

TEST(LoadSceneErrors, SelectorWithTwoKindsOrNone) {
  json scene = minimal_scene();
  scene["boundary_conditions"] = json::parse(R"([{"name": "a", "type": "fixed", "nodes": {"set": "x", "box": {"min": [0,0,0], "max": [1,1,1]}}},
                                                 {"name": "b", "type": "fixed", "nodes": {"body": "cube"}},
                                                 {"name": "c", "type": "fixed", "nodes": {"all": false}}])");
  EXPECT_EQ(parse_error(scene),
            "boundary_conditions[0].nodes: must hold exactly one of \"set\", \"region\", \"box\", \"plane\", \"all\"; "
            "found \"set\", \"box\"\n"
            "boundary_conditions[1].nodes: must hold exactly one of \"set\", \"region\", \"box\", \"plane\", \"all\"; "
            "found none\n"
            "boundary_conditions[2].nodes.all: must be true, got false");
}

TEST(LoadSceneErrors, BoundaryConditionKeysDependOnTheType) {
  json scene = minimal_scene();
  scene["boundary_conditions"] = json::parse(R"([{"name": "a", "type": "fixed", "nodes": {"all": true}, "normal": [1, 0, 0]},
                                                 {"name": "b", "type": "prescribed", "nodes": {"all": true}},
                                                 {"name": "a", "type": "planar", "nodes": {"all": true}, "normal": [0, 0, 0]}])");
  EXPECT_EQ(parse_error(scene),
            "boundary_conditions[0].normal: unknown key for type \"fixed\"; allowed keys: \"name\", \"type\", \"nodes\"\n"
            "boundary_conditions[1].motion: missing required key (the prescribed motion)\n"
            "boundary_conditions[2].normal: must not be the zero vector");
  scene["boundary_conditions"][0].erase("normal");
  scene["boundary_conditions"][1]["motion"] = json::object();
  scene["boundary_conditions"][2]["normal"] = {0, 0, 1};
  EXPECT_EQ(parse_error(scene), "boundary_conditions[2].name: duplicate boundary condition name \"a\"");
}

TEST(LoadSceneErrors, AmplitudeNotIncreasing) {
  json scene = minimal_scene();
  scene["boundary_conditions"] = json::parse(R"([{"name": "pull", "type": "prescribed", "nodes": {"all": true},
     "motion": {"translation": [1, 0, 0], "amplitude": [[0, 0], [0.5, 1], [0.5, 2], [0.25, 0]]}}])");
  EXPECT_EQ(parse_error(scene),
            "boundary_conditions[0].motion.amplitude[2][0]: lambda must be strictly increasing, got 0.5 after 0.5\n"
            "boundary_conditions[0].motion.amplitude[3][0]: lambda must be strictly increasing, got 0.25 after 0.5");
  scene["boundary_conditions"][0]["motion"]["amplitude"] = json::parse("[[0, 0, 1]]");
  EXPECT_EQ(parse_error(scene), "boundary_conditions[0].motion.amplitude[0]: must hold exactly 2 elements, got 3");
}

TEST(LoadSceneErrors, MissingMeshFile) {
  json scene = minimal_scene();
  scene["bodies"][0]["mesh"] = {{"file", "missing.msh"}};
  EXPECT_EQ(parse_error(scene, "/nonexistent/dir"),
            "bodies[0].mesh.file: mesh file not found: /nonexistent/dir/missing.msh");
}

TEST(LoadSceneErrors, MeshNeedsExactlyOneSource) {
  json scene = minimal_scene();
  scene["bodies"][0]["mesh"]["file"] = "block.msh";
  EXPECT_EQ(parse_error(scene), "bodies[0].mesh: must hold exactly one of \"file\", \"generate\", \"surfaces\"; found \"file\", \"generate\"");
}

TEST(LoadSceneErrors, ShapesAreCheckedRecursively) {
  json scene = minimal_scene();
  scene["bodies"][0]["mesh"]["generate"]["parts"] = json::parse(R"([
    {"region": "a", "shape": {"union": [{"box": {"min": [0, 0, 0], "max": [1, 0, 1]}},
                                        {"difference": [{"sphere": {"center": [0, 0, 0], "radius": -1}}]}]}},
    {"region": "a", "shape": {"cylinder": {"base": [0, 0, 0], "axis": [0, 0, 1], "radius": 1}}}])");
  EXPECT_EQ(parse_error(scene),
            "bodies[0].mesh.generate.parts[0].shape.union[1].difference: must hold at least 2 elements, got 1\n"
            "bodies[0].mesh.generate.parts[0].shape.union[1].difference[0].sphere.radius: must be > 0, got -1");
  scene["bodies"][0]["mesh"]["generate"]["parts"][0]["shape"]["union"][1] = {
      {"sphere", {{"center", {0, 0, 0}}, {"radius", 1}}}};
  EXPECT_EQ(parse_error(scene),
            "bodies[0].mesh.generate.parts[0].shape.union[0].box: max must exceed min in every component\n"
            "bodies[0].mesh.generate.parts[1].region: duplicate part region \"a\"");
}

TEST(LoadSceneErrors, TorusIntersectionAndTransformInputs) {
  json scene = minimal_scene();
  scene["bodies"][0]["mesh"]["generate"]["parts"] = json::parse(R"([
    {"region": "a", "shape": {"torus": {"center": [0, 0, 0], "axis": [0, 0, 0], "radius": 1, "minor_radius": 0,
                                        "angle_deg": 400}}},
    {"region": "b", "shape": {"intersection": [{"box": {"min": [0, 0, 0], "max": [1, 1, 1]}}]}},
    {"region": "c", "shape": {"box": {"min": [0, 0, 0], "max": [1, 1, 1]},
                              "transform": {"rotate": {"axis": [0, 0, 0], "angle_deg": 10, "centre": [0, 0, 0]},
                                            "translate": [0, 0]}}},
    {"region": "d", "shape": {"box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "transform": {"rotate": {"axis": [1, 0, 0]}}}},
    {"region": "e", "shape": {"transform": {"translate": [0, 0, 1]}}},
    {"region": "f", "shape": {"torus": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": 1, "minor_radius": 0.5,
                                        "angle_deg": 0, "start_direction": [0, 0, 0]}}}])");
  EXPECT_EQ(parse_error(scene),
            "bodies[0].mesh.generate.parts[0].shape.torus.axis: must not be the zero vector\n"
            "bodies[0].mesh.generate.parts[0].shape.torus.minor_radius: must be > 0, got 0\n"
            "bodies[0].mesh.generate.parts[0].shape.torus.angle_deg: must be <= 360, got 400\n"
            "bodies[0].mesh.generate.parts[1].shape.intersection: must hold at least 2 elements, got 1\n"
            "bodies[0].mesh.generate.parts[2].shape.transform.rotate.centre: unknown key; did you mean \"center\"?\n"
            "bodies[0].mesh.generate.parts[2].shape.transform.rotate.axis: must not be the zero vector\n"
            "bodies[0].mesh.generate.parts[2].shape.transform.translate: must be an array of 3 numbers [x, y, z], got [0,0]\n"
            "bodies[0].mesh.generate.parts[3].shape.transform.rotate.angle_deg: missing required key (angle (degrees, "
            "right-hand rule))\n"
            "bodies[0].mesh.generate.parts[4].shape: must hold exactly one of \"box\", \"sphere\", \"cylinder\", "
            "\"torus\", \"union\", \"difference\", \"intersection\"; found none\n"
            "bodies[0].mesh.generate.parts[5].shape.torus.angle_deg: must be > 0, got 0\n"
            "bodies[0].mesh.generate.parts[5].shape.torus.start_direction: must not be the zero vector");

  // What the schema cannot see: the radii compared, the start direction along the axis.
  scene["bodies"][0]["mesh"]["generate"]["parts"] = json::parse(R"([
    {"region": "a", "shape": {"box": {"min": [0, 0, 0], "max": [1, 1, 1]}}},
    {"region": "b", "shape": {"torus": {"center": [0, 0, 0], "axis": [0, 0, 1], "radius": 1, "minor_radius": 1.5,
                                        "start_direction": [0, 0, -3]}}}])");
  EXPECT_EQ(parse_error(scene),
            "bodies[0].mesh.generate.parts[1].shape.torus.minor_radius: must be < radius (1), got 1.5\n"
            "bodies[0].mesh.generate.parts[1].shape.torus.start_direction: must not be parallel to axis");
}

TEST(LoadSceneErrors, EnumSuggestion) {
  json scene = minimal_scene();
  scene["solver"] = {{"predictor", "two_point"}, {"linear", {{"solver", "CG"}}}};
  EXPECT_EQ(parse_error(scene),
            "solver.predictor: must be one of \"none\", \"two-point\", \"tangent\", got \"two_point\"; did you mean "
            "\"two-point\"?\n"
            "solver.linear.solver: must be one of \"cholmod\", \"gmres\", \"cg\", \"petsc-gamg\", \"petsc-mumps\", got "
            "\"CG\"; did you mean \"cg\"?");
}

TEST(LoadSceneErrors, BodyNamesCannotHoldASlash) {
  json scene = minimal_scene();
  scene["bodies"][0]["name"] = "a/b";
  EXPECT_EQ(parse_error(scene), "bodies[0].name: must not contain '/' (it separates body and region names)");
  scene["bodies"][0]["name"] = "";
  EXPECT_EQ(parse_error(scene), "bodies[0].name: must not be empty");
}

}  // namespace
}  // namespace sinew::scene

namespace sinew::scene {
namespace {

TEST(LoadSceneDynamics, SectionIsReadWithDefaultsAndBadValuesNameTheirPath) {
  json scene = minimal_scene();
  scene["dynamics"] = {{"integrator", "explicit"}, {"end_time", 2.0}, {"output_interval", 0.5}, {"mass_damping", 3.0}};
  const SceneConfig config = parse_scene(scene, "");
  EXPECT_TRUE(config.dynamics.enabled);
  EXPECT_EQ(config.dynamics.options.integrator, solver::DynamicOptions::Integrator::Explicit);
  EXPECT_EQ(config.dynamics.options.end_time, 2.0);
  EXPECT_EQ(config.dynamics.options.output_interval, 0.5);
  EXPECT_EQ(config.dynamics.options.time_step, 0.0);  // default: output_interval / 10
  EXPECT_EQ(config.dynamics.mass, fem::MassKind::Lumped);
  EXPECT_EQ(config.dynamics.mass_damping, 3.0);
  EXPECT_EQ(config.dynamics.stiffness_damping, 0.0);
  EXPECT_FALSE(parse_scene(minimal_scene(), "").dynamics.enabled);

  scene["dynamics"]["end_time"] = -1.0;
  EXPECT_EQ(parse_error(scene), "dynamics.end_time: must be > 0, got -1");
  scene["dynamics"]["end_time"] = 1.0;
  scene["dynamics"]["mass_damping"] = -2.0;
  EXPECT_EQ(parse_error(scene), "dynamics.mass_damping: must be >= 0, got -2");
  scene["dynamics"].erase("mass_damping");
  scene["dynamics"]["integrator"] = "newmark";
  EXPECT_THAT(parse_error(scene), HasSubstr("dynamics.integrator"));
  scene["dynamics"]["integrator"] = "implicit-euler";
  scene["dynamics"].erase("output_interval");
  EXPECT_THAT(parse_error(scene), HasSubstr("dynamics.output_interval"));
}

TEST(LoadScene, KeyframesKeyedByLambdaOrByTimeBecomeLoadParameters) {
  json scene = minimal_scene();
  scene["boundary_conditions"] = json::parse(R"([{"name": "move", "type": "prescribed", "nodes": {"all": true},
     "motion": {"pivot": [1, 2, 3], "keyframes": [
       {"lambda": 0},
       {"lambda": 0.5, "translation": [1, 0, 0], "rotation": {"axis": [0, 0, 2], "angle_deg": 90}},
       {"lambda": 1, "translation": [2, 0, 0]}]}}])");
  SceneConfig config = parse_scene(scene, "");
  const fem::RigidMotion& motion = config.boundary_conditions.at(0).motion;
  ASSERT_EQ(motion.keyframes.size(), 3u);
  EXPECT_EQ(motion.keyframes[1].lambda, 0.5);
  EXPECT_EQ(motion.pivot, Vector3(1, 2, 3));
  EXPECT_NEAR(Eigen::AngleAxisd(motion.keyframes[1].rotation).angle(), M_PI / 2, 1e-15);
  EXPECT_EQ(motion.keyframes[2].translation, Vector3(2, 0, 0));

  scene["dynamics"] = {{"end_time", 2.0}, {"output_interval", 0.5}};
  scene["boundary_conditions"][0]["motion"]["keyframes"] = json::parse(R"([{"time": 0}, {"time": 0.5, "translation": [1, 0, 0]}, {"time": 2}])");
  config = parse_scene(scene, "");
  ASSERT_EQ(config.boundary_conditions.at(0).motion.keyframes.size(), 3u);
  EXPECT_EQ(config.boundary_conditions.at(0).motion.keyframes[1].lambda, 0.25);
}

TEST(LoadSceneErrors, EveryBadKeyframeIsNamedByItsPath) {
  json scene = minimal_scene();
  scene["boundary_conditions"] = json::parse(R"([{"name": "move", "type": "prescribed", "nodes": {"all": true},
     "motion": {"translation": [1, 0, 0], "keyframes": [
       {"lambda": 0},
       {"lambda": 0.5, "time": 0.5},
       {},
       {"time": 1},
       {"lambda": 0.5},
       {"lambda": 0.25}]}}])");
  EXPECT_EQ(parse_error(scene),
            "boundary_conditions[0].motion.keyframes: keyframes replace \"translation\", \"rotation\" and "
            "\"amplitude\": give either the keyframes or those\n"
            "boundary_conditions[0].motion.keyframes[1]: give the keyframe's place as exactly one of \"lambda\" (load "
            "parameter) or \"time\"\n"
            "boundary_conditions[0].motion.keyframes[2]: give the keyframe's place as exactly one of \"lambda\" (load "
            "parameter) or \"time\"\n"
            "boundary_conditions[0].motion.keyframes[3]: keyframes of one motion are keyed all by \"lambda\" or all by "
            "\"time\", not both\n"
            "boundary_conditions[0].motion.keyframes[5].lambda: keyframes must be strictly increasing, got 0.25 after 0.5");
  scene["boundary_conditions"][0]["motion"] = json::parse(R"({"keyframes": [{"time": 0}, {"time": 1}]})");
  EXPECT_EQ(parse_error(scene),
            "boundary_conditions[0].motion.keyframes[0].time: a keyframe keyed by time needs a dynamic analysis (a "
            "\"dynamics\" section); a static one is keyed by \"lambda\"\n"
            "boundary_conditions[0].motion.keyframes[1].time: a keyframe keyed by time needs a dynamic analysis (a "
            "\"dynamics\" section); a static one is keyed by \"lambda\"");
  scene["boundary_conditions"][0]["motion"] =
      json::parse(R"({"keyframes": [{"lambda": 0, "rotation": {"axis": [0, 0, 0], "angle_deg": 10}}]})");
  EXPECT_EQ(parse_error(scene), "boundary_conditions[0].motion.keyframes[0].rotation.axis: must not be the zero vector");
  scene["boundary_conditions"][0]["motion"] = json::parse(R"({"keyframes": [{"lambda": 0, "translation": [1e300, 0, 0]}]})");
  EXPECT_THAT(parse_error(scene), ::testing::HasSubstr("boundary_conditions[0].motion.keyframes[0].translation[0]"));
  scene["boundary_conditions"][0]["motion"] = json::parse(R"({"keyframes": []})");
  EXPECT_THAT(parse_error(scene), ::testing::HasSubstr("boundary_conditions[0].motion.keyframes"));
}

TEST(LoadSceneErrors, StepGrowthBelowOneIsRefused) {
  json scene = minimal_scene();
  scene["solver"] = {{"newton", {{"max_step_growth", 0.5}}}};
  EXPECT_EQ(parse_error(scene), "solver.newton.max_step_growth: must be >= 1, got 0.5");
  scene["solver"] = {{"newton", {{"max_step_growth", 1}}}};
  EXPECT_EQ(parse_scene(scene, data_directory()).solver.newton.max_step_growth, 1.0);
}

}  // namespace
}  // namespace sinew::scene
