/// @file test_build_contact.cpp
/// The scene's "contact" section and per-body depth options -> contact::ContactGeometry:
/// depths from chosen surfaces, a file or a node field of the mesh file, penalties (automatic, global, per pair), and the
/// errors a user gets for a bad set-up.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/scene_test_support.hpp"
#include "support/contact_scenes.hpp"
#include "sinew/core/error.hpp"
#include "sinew/scene/build_contact.hpp"
#include "sinew/scene/build_problem.hpp"
#include "sinew/scene/load_scene.hpp"
#include "support/box_mesh.hpp"

namespace sinew::scene {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

/// A soft box [0,1]^2 x [0,0.5] and a rigid plate below it.
json contact_scene() { return sinew::testing::box_on_plate_scene(); }

ContactSetup contact_setup(const json& scene_json) {
  const SceneConfig scene = parse_scene(scene_json, "");
  const fem::Problem problem = build_problem(scene);
  return build_contact(scene, problem);
}

std::string build_contact_error(const json& scene_json) {
  try {
    contact_setup(scene_json);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(BuildContact, DepthIsTheRestDistanceToTheBoundaryAndPenaltyFollowsStiffnessAndSize) {
  const ContactSetup setup = contact_setup(contact_scene());
  const auto& g = setup.geometry;
  ASSERT_EQ(setup.body_names, (std::vector<std::string>{"box", "plate"}));
  const SceneConfig scene = parse_scene(contact_scene(), "");
  const fem::Problem problem = build_problem(scene);
  const auto& box = problem.bodies[0];
  for (Index v = box.first_node; v < box.first_node + box.num_nodes; ++v) {
    const Vector3 X = problem.mesh.rest.row(v);
    const double exact = std::min({X.x(), 1 - X.x(), X.y(), 1 - X.y(), X.z(), 0.5 - X.z()});
    EXPECT_NEAR(g.depth[v], exact, 1e-12) << "node " << v;
  }
  // E = mu (3 lambda + 2 mu) / (lambda + mu) = 32/11; the plate is rigid, so the box's E counts.
  const double E = 32.0 / 11.0;
  EXPECT_NEAR(setup.body_young_modulus[0], E, 1e-12);
  EXPECT_TRUE(std::isinf(setup.body_young_modulus[1]));
  const double h = std::min(setup.body_edge_length[0], setup.body_edge_length[1]);
  EXPECT_NEAR(g.penalty(0, 1), 10 * E / h, 1e-12 * g.penalty(0, 1));
  EXPECT_EQ(g.penalty(0, 1), g.penalty(1, 0));
  EXPECT_GT(g.penalty(0, 0), 0);   // self-contact of the soft box
  EXPECT_EQ(g.penalty(1, 1), 0.0); // a rigid body cannot penetrate itself
}

TEST(BuildContact, PairsOverrideTheGlobalPenaltyAndCanSwitchContactOff) {
  json scene = contact_scene();
  scene["contact"] = json::parse(R"({"penalty": 7, "self_contact": false,
      "pairs": [{"bodies": ["plate", "box"], "penalty": 3}]})");
  ContactSetup setup = contact_setup(scene);
  EXPECT_EQ(setup.geometry.penalty(0, 1), 3.0);
  EXPECT_EQ(setup.geometry.penalty(0, 0), 0.0);
  scene["contact"] = json::parse(R"({"pairs": [{"bodies": ["box", "plate"], "enabled": false}]})");
  setup = contact_setup(scene);
  EXPECT_EQ(setup.geometry.penalty(0, 1), 0.0);
}

// A penalty 1e15 ran the Hertz ball past 300 s in tiny steps: penalties far above the automatic
// one are refused with the ratio, the automatic value and what to do.
TEST(BuildContact, APenaltyFarAboveTheAutomaticOneIsRefused) {
  json scene = contact_scene();
  const ContactSetup automatic = contact_setup(scene);
  const double allowed = automatic.geometry.penalty(0, 1) * kMaxPenaltyOverAutomatic;
  scene["contact"] = {{"penalty", 0.5 * allowed}};
  EXPECT_EQ(build_contact_error(scene), "no error");
  scene["contact"] = {{"penalty", 2 * allowed}};
  const std::string error = build_contact_error(scene);
  EXPECT_NE(error.find("the penalty between \"box\" and \"plate\""), std::string::npos) << error;
  EXPECT_NE(error.find("times the automatic penalty 10 E / h"), std::string::npos) << error;
  EXPECT_NE(error.find("lower it"), std::string::npos) << error;
  // A region scale counts: the pair's penalty times the largest contact_penalty_scale.
  scene["contact"] = {{"penalty", 0.5 * allowed}};
  scene["bodies"][0]["regions"]["gel"]["contact_penalty_scale"] = 4;
  EXPECT_NE(build_contact_error(scene).find("with contact_penalty_scale 4"), std::string::npos);
}

TEST(BuildContact, RegionPenaltyScalesReachTheirTetsAndSurfaceTriangles) {
  // Without a scale anywhere the arrays stay empty (every factor 1).
  const ContactSetup plain = contact_setup(contact_scene());
  EXPECT_EQ(plain.geometry.tet_penalty_scale.size(), 0);
  EXPECT_EQ(plain.geometry.surface_penalty_scale.size(), 0);

  json scene = contact_scene();
  scene["bodies"][1]["regions"]["plate"]["contact_penalty_scale"] = 8.0;
  const SceneConfig config = parse_scene(scene, "");
  const fem::Problem problem = build_problem(config);
  const ContactSetup setup = build_contact(config, problem);
  const auto& g = setup.geometry;
  ASSERT_EQ(g.tet_penalty_scale.size(), g.tets.rows());
  ASSERT_EQ(g.surface_penalty_scale.size(), g.surface.rows());
  for (Index t = 0; t < g.tets.rows(); ++t)
    EXPECT_EQ(g.tet_penalty_scale[t], g.tet_body[t] == 1 ? 8.0 : 1.0) << "tet " << t;
  for (Index f = 0; f < g.surface.rows(); ++f)
    EXPECT_EQ(g.surface_penalty_scale[f], g.surface_body[f] == 1 ? 8.0 : 1.0) << "triangle " << f;

  // The "*" entry's factor covers the regions without an entry of their own.
  json starred = contact_scene();
  starred["bodies"][0]["regions"] = json::parse(R"({"*": {"material": "gel", "contact_penalty_scale": 3.0}})");
  const ContactSetup star = contact_setup(starred);
  ASSERT_EQ(star.geometry.tet_penalty_scale.size(), star.geometry.tets.rows());
  for (Index t = 0; t < star.geometry.tets.rows(); ++t)
    EXPECT_EQ(star.geometry.tet_penalty_scale[t], star.geometry.tet_body[t] == 0 ? 3.0 : 1.0) << "tet " << t;

  scene["bodies"][1]["regions"]["plate"]["contact_penalty_scale"] = 0.0;
  try {
    parse_scene(scene, "");
    ADD_FAILURE() << "a zero penalty scale was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("contact_penalty_scale"));
  }
}

TEST(BuildContact, DepthFromChosenFacesOnly) {
  json scene = contact_scene();
  scene["bodies"][0]["contact"] =
      json::parse(R"({"depth_nodes": [{"plane": {"point": [0, 0, 0], "normal": [0, 0, 1], "tolerance": 1e-9}}]})");
  const ContactSetup setup = contact_setup(scene);
  const SceneConfig config = parse_scene(scene, "");
  const fem::Problem problem = build_problem(config);
  const auto& box = problem.bodies[0];
  for (Index v = box.first_node; v < box.first_node + box.num_nodes; ++v)
    EXPECT_NEAR(setup.geometry.depth[v], problem.mesh.rest(v, 2), 1e-12) << "node " << v;
}

TEST(BuildContact, ExcludedFacesAreNeitherContactSurfaceNorZeroDepthSurface) {
  // The box's top z = 0.5 as a cut face: its triangles leave the contact surface, and depth is
  // measured from the other five sides (at the top, the distance to the sides and the bottom).
  json scene = contact_scene();
  scene["bodies"][0]["contact"] =
      json::parse(R"({"exclude_faces": [{"plane": {"point": [0, 0, 0.5], "normal": [0, 0, 1], "tolerance": 1e-9}}]})");
  const ContactSetup setup = contact_setup(scene);
  const ContactSetup full = contact_setup(contact_scene());
  const SceneConfig config = parse_scene(scene, "");
  const fem::Problem problem = build_problem(config);
  const auto& box = problem.bodies[0];
  const auto& g = setup.geometry;
  Index box_triangles = 0, full_box_triangles = 0, top_triangles = 0;
  for (Index f = 0; f < full.geometry.surface.rows(); ++f) {
    if (full.geometry.surface_body[f] != 0) continue;
    ++full_box_triangles;
    bool top = true;
    for (int k = 0; k < 3; ++k) top = top && std::abs(problem.mesh.rest(full.geometry.surface(f, k), 2) - 0.5) < 1e-12;
    if (top) ++top_triangles;
  }
  for (Index f = 0; f < g.surface.rows(); ++f) {
    if (g.surface_body[f] != 0) continue;
    ++box_triangles;
    bool top = true;
    for (int k = 0; k < 3; ++k) top = top && std::abs(problem.mesh.rest(g.surface(f, k), 2) - 0.5) < 1e-12;
    EXPECT_FALSE(top) << "triangle " << f << " lies on the excluded face";
  }
  EXPECT_GT(top_triangles, 0);
  EXPECT_EQ(box_triangles, full_box_triangles - top_triangles);
  for (Index v = box.first_node; v < box.first_node + box.num_nodes; ++v) {
    const Vector3 X = problem.mesh.rest.row(v);
    const double exact = std::min({X.x(), 1 - X.x(), X.y(), 1 - X.y(), X.z()});
    EXPECT_NEAR(g.depth[v], exact, 1e-12) << "node " << v;
  }
  // The tets are all still there (they can be penetrated).
  EXPECT_EQ(g.tets.rows(), full.geometry.tets.rows());
  // Excluding every face is an error with its path.
  scene["bodies"][0]["contact"] = json::parse(R"({"exclude_faces": [{"all": true}]})");
  EXPECT_THAT(build_contact_error(scene), HasSubstr("bodies[0].contact.exclude_faces: excludes every boundary face"));
}

TEST(BuildContact, APlaneExcludesTheFacesInItNotTheSideWallsNearIt) {
  // A cut plane's tolerance must cover the mesher's round-off on the cap, and is often far
  // larger (the VH knee's: a tenth of the element size). The box's sides then have faces whose
  // three nodes are all within it near the top; they meet the cut but are not the cut, and
  // must stay contact and zero-depth surface (else depth > 0 on them, and a surface sliding
  // along the side wall into the band meets a kink in the energy: docs/contact.md, "Cut faces").
  json tight = contact_scene(), loose = contact_scene();
  tight["bodies"][0]["contact"] =
      json::parse(R"({"exclude_faces": [{"plane": {"point": [0, 0, 0.5], "normal": [0, 0, 1], "tolerance": 1e-9}}]})");
  loose["bodies"][0]["contact"] =
      json::parse(R"({"exclude_faces": [{"plane": {"point": [0, 0, 0.5], "normal": [0, 0, 1], "tolerance": 0.3}}]})");
  const fem::Problem problem = build_problem(parse_scene(loose, ""));
  const ContactSetup full = contact_setup(contact_scene());
  Index side_faces_in_band = 0;
  for (Index f = 0; f < full.geometry.surface.rows(); ++f) {
    if (full.geometry.surface_body[f] != 0) continue;
    bool in_band = true, on_top = true;
    for (int k = 0; k < 3; ++k) {
      const double z = problem.mesh.rest(full.geometry.surface(f, k), 2);
      in_band = in_band && z >= 0.2;
      on_top = on_top && std::abs(z - 0.5) < 1e-12;
    }
    if (in_band && !on_top) ++side_faces_in_band;
  }
  ASSERT_GT(side_faces_in_band, 0) << "the band must hold side-wall faces for this test to mean anything";
  const ContactSetup a = contact_setup(tight), b = contact_setup(loose);
  EXPECT_EQ(a.geometry.surface, b.geometry.surface);
  EXPECT_EQ(a.geometry.depth, b.geometry.depth);
}

TEST(BuildContact, DepthFromAFile) {
  json scene = contact_scene();
  const SceneConfig config = parse_scene(scene, "");
  const fem::Problem problem = build_problem(config);
  const Index nodes = problem.bodies[0].num_nodes;
  const testing::TempDir directory("sinew-depth-file");
  const auto path = directory / "depth.txt";
  {
    std::ofstream out(path);
    out << "# depth per node\n";
    for (Index v = 0; v < nodes; ++v) out << 0.5 * v << (v % 7 == 6 ? "\n" : " ");
  }
  scene["bodies"][0]["contact"] = {{"depth_file", path.string()}};
  const ContactSetup setup = contact_setup(scene);
  for (Index v = 0; v < nodes; ++v) EXPECT_EQ(setup.geometry.depth[problem.bodies[0].first_node + v], 0.5 * v);
  {
    std::ofstream out(path);
    out << "1 2 -3\n";
  }
  const std::string message = build_contact_error(scene);
  EXPECT_THAT(message, HasSubstr("bodies[0].contact.depth_file"));
  EXPECT_THAT(message, HasSubstr("line 1: depth -3 must be finite and >= 0"));
  {
    std::ofstream out(path);
    out << "1 2 3\n";
  }
  EXPECT_THAT(build_contact_error(scene), HasSubstr("has 3 depths, the body's mesh has " + std::to_string(nodes)));
  {
    std::ofstream out(path);
    out << "1 nan\n";
  }
  EXPECT_THAT(build_contact_error(scene), HasSubstr("must be finite"));
}

/// A Gmsh 2.2 ASCII file of the box [0,1]^2 x [0,0.5] (structured, 18 nodes), node tags
/// 1000 - 7v so that the reader renumbers the nodes in reverse, with $NodeData blocks:
/// "depth" = z, "temperature" = x - 1 (negative at x < 1), "nan_depth" = z but NaN at
/// (1, 1, 0.5), "partial" = z without a value at (0, 0, 0).
void write_box_with_fields(const std::string& path) {
  const mesh::TetMesh box = sinew::testing::box_mesh(2, 2, 1, 0.5);
  const auto tag = [](Index v) { return 1000 - 7 * v; };
  std::ofstream out(path);
  out.precision(17);
  out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << box.num_nodes() << "\n";
  for (Index v = 0; v < box.num_nodes(); ++v)
    out << tag(v) << " " << box.rest(v, 0) << " " << box.rest(v, 1) << " " << box.rest(v, 2) << "\n";
  out << "$EndNodes\n$Elements\n" << box.num_tets() << "\n";
  for (Index t = 0; t < box.num_tets(); ++t) {
    out << t + 1 << " 4 2 0 1";
    for (int k = 0; k < 4; ++k) out << " " << tag(box.tets(t, k));
    out << "\n";
  }
  out << "$EndElements\n";
  const auto field = [&](const std::string& name, const auto& value) {
    std::ostringstream rows;
    rows.precision(17);
    Index count = 0;
    for (Index v = 0; v < box.num_nodes(); ++v) {
      const std::string text = value(Vector3(box.rest.row(v).transpose()));
      if (text.empty()) continue;
      rows << tag(v) << " " << text << "\n";
      ++count;
    }
    out << "$NodeData\n1\n\"" << name << "\"\n1\n0\n3\n0\n1\n" << count << "\n" << rows.str() << "$EndNodeData\n";
  };
  const auto number = [](double x) {
    std::ostringstream text;
    text.precision(17);
    text << x;
    return text.str();
  };
  field("depth", [&](const Vector3& X) { return number(X.z()); });
  field("temperature", [&](const Vector3& X) { return number(X.x() - 1); });
  field("nan_depth", [&](const Vector3& X) { return X == Vector3(1, 1, 0.5) ? std::string("nan") : number(X.z()); });
  field("partial", [&](const Vector3& X) { return X.isZero() ? std::string() : number(X.z()); });
}

/// contact_scene() with the box read from `msh_path`, as the second body, lifted by 0.25.
json file_box_scene(const std::string& msh_path, const std::string& depth_field) {
  json scene = contact_scene();
  json box = scene["bodies"][0];
  box["mesh"] = {{"file", msh_path}};
  box["transform"] = {{"translate", {0, 0, 0.25}}};
  box["regions"] = {{"*", {{"material", "gel"}}}};
  box["contact"] = {{"depth_field", depth_field}};
  scene["bodies"] = json::array({scene["bodies"][1], box});
  return scene;
}

TEST(BuildContact, DepthFromANodeFieldOfTheMeshFile) {
  const testing::TempDir directory("sinew-depth-field");
  const std::string path = directory.file("box.msh");
  write_box_with_fields(path);
  const json scene = file_box_scene(path, "depth");
  const SceneConfig config = parse_scene(scene, "");
  const fem::Problem problem = build_problem(config);
  const ContactSetup setup = build_contact(config, problem);
  const auto& box = problem.bodies[1];
  ASSERT_EQ(box.num_nodes, 18);
  for (Index v = box.first_node; v < box.first_node + box.num_nodes; ++v)
    EXPECT_NEAR(setup.geometry.depth[v], problem.mesh.rest(v, 2) - 0.25, 1e-15) << "node " << v;
  // The plate keeps its distance to its own boundary; the box's fields do not reach it.
  const auto& plate = problem.bodies[0];
  EXPECT_EQ(setup.geometry.depth.segment(plate.first_node, plate.num_nodes).minCoeff(), 0.0);
  ASSERT_EQ(problem.mesh.node_fields.count("box/depth"), 1u);
  EXPECT_TRUE(problem.mesh.node_fields.at("box/depth").segment(plate.first_node, plate.num_nodes).array().isNaN().all());
}

TEST(BuildContact, DepthFieldErrorsNameThePathAndTheField) {
  const testing::TempDir directory("sinew-depth-field");
  const std::string path = directory.file("box.msh");
  write_box_with_fields(path);
  EXPECT_THAT(build_contact_error(file_box_scene(path, "dpeth")),
              HasSubstr("bodies[1].contact.depth_field: the mesh file has no node field \"dpeth\" (fields: depth, "
                        "nan_depth, temperature, partial (unusable: no value at 1 of the mesh's 18 nodes"));
  EXPECT_THAT(build_contact_error(file_box_scene(path, "partial")),
              HasSubstr("bodies[1].contact.depth_field: the mesh file's node field \"partial\" cannot be used: no "
                        "value at 1 of the mesh's 18 nodes, e.g. node 17 (Gmsh node tag 1000) at (0, 0, 0)"));
  EXPECT_THAT(build_contact_error(file_box_scene(path, "nan_depth")),
              HasSubstr("bodies[1].contact.depth_field: node field \"nan_depth\" has value nan at node 0 (rest "
                        "position (1, 1, 0.75)); depths must be finite and >= 0"));
  const std::string negative = build_contact_error(file_box_scene(path, "temperature"));
  EXPECT_THAT(negative, HasSubstr("bodies[1].contact.depth_field: node field \"temperature\" has value -"));
  EXPECT_THAT(negative, HasSubstr(", and 11 more nodes with a negative or non-finite value; depths must be finite and >= 0"));

  // Checked at load: a generated mesh has no fields; one depth source only.
  json scene = contact_scene();
  scene["bodies"][0]["contact"] = {{"depth_field", "depth"}};
  EXPECT_THAT(testing::parse_error(scene, ""),
              HasSubstr("bodies[0].contact.depth_field: needs a mesh file (\"mesh\": {\"file\": ...})"));
  scene = file_box_scene(path, "depth");
  scene["bodies"][1]["contact"]["depth_region"] = "default";
  EXPECT_THAT(testing::parse_error(scene, ""), HasSubstr("bodies[1].contact: give at most one of"));
}

TEST(BuildContact, BadSetUpsAreReportedWithTheirPath) {
  json scene = contact_scene();
  scene["bodies"][0]["contact"] = {{"depth_face_set", "nope"}};
  EXPECT_THAT(build_contact_error(scene),
              HasSubstr("bodies[0].contact.depth_face_set: body \"box\" has no face set \"nope\" (it has: gel.surface)"));
  scene["bodies"][0]["contact"] = {{"depth_region", "bone"}};
  EXPECT_THAT(build_contact_error(scene), HasSubstr("bodies[0].contact.depth_region: body \"box\" has no region \"bone\""));
  // Two rigid bodies have no automatic penalty.
  scene = contact_scene();
  scene["bodies"][0]["regions"]["gel"] = {{"rigid", "fixed"}};
  scene["contact"] = json::parse(R"({"pairs": [{"bodies": ["box", "plate"]}]})");
  EXPECT_THAT(build_contact_error(scene), HasSubstr("contact.pairs[0]: bodies \"box\" and \"plate\" are both rigid"));
}

TEST(BuildContact, SceneErrorsNameTheEntry) {
  json scene = contact_scene();
  scene["contact"] = json::parse(R"({"method": "points", "penalty": -1})");
  const std::string schema_errors = testing::parse_error(scene, "");
  EXPECT_THAT(schema_errors, HasSubstr("contact.method: must be one of \"area\", \"point\""));
  EXPECT_THAT(schema_errors, HasSubstr("contact.penalty: must be > 0"));
  scene["contact"] = json::parse(R"({
      "pairs": [{"bodies": ["box", "plates"]}, {"bodies": ["box", "plate"], "enabled": false, "penalty": 2}]})");
  const std::string message = testing::parse_error(scene, "");
  EXPECT_THAT(message, HasSubstr("contact.pairs[0].bodies[1]: unknown body \"plates\""));
  EXPECT_THAT(message, HasSubstr("did you mean"));
  EXPECT_THAT(message, HasSubstr("a disabled pair has no penalty"));
  scene = contact_scene();
  scene["bodies"][0]["contact"] = {{"depth_file", "missing.txt"}, {"depth_region", "gel"}};
  const std::string both = testing::parse_error(scene, "/nonexistent");
  EXPECT_THAT(both, HasSubstr("give at most one of"));
}

}  // namespace
}  // namespace sinew::scene

namespace sinew::scene {
namespace {

// contact.enforcement (contact_enforcement.hpp): what is read, and every inconsistent choice
// refused with its path.
TEST(ContactEnforcementScene, ReadsTheMethodAndTheTolerances) {
  nlohmann::json scene = testing::minimal_scene();
  scene["contact"] = nlohmann::json::parse(
      R"({"enforcement": {"method": "augmented-lagrangian", "penetration_tolerance": 0.01, "max_updates": 7}})");
  SceneConfig config = parse_scene(scene, "");
  EXPECT_EQ(config.contact.enforcement.method, contact::ContactEnforcement::AugmentedLagrangian);
  EXPECT_EQ(config.contact.enforcement.penetration_tolerance, 0.01);
  EXPECT_EQ(config.contact.enforcement.max_updates, 7);
  EXPECT_FALSE(config.contact.relative_penetration_tolerance);
  scene["contact"] = nlohmann::json::parse(
      R"({"enforcement": {"method": "adaptive-penalty", "relative_tolerance": 0.002, "max_growth": 4}})");
  config = parse_scene(scene, "");
  EXPECT_EQ(config.contact.enforcement.method, contact::ContactEnforcement::AdaptivePenalty);
  EXPECT_EQ(config.contact.relative_penetration_tolerance.value_or(0), 0.002);
  EXPECT_EQ(config.contact.enforcement.max_growth, 4);
  scene["contact"] = nlohmann::json::object();
  config = parse_scene(scene, "");
  EXPECT_EQ(config.contact.enforcement.method, contact::ContactEnforcement::Penalty);
  EXPECT_EQ(config.contact.friction.coefficient, 0.0);
  scene["contact"] = nlohmann::json::parse(
      R"({"friction": {"coefficient": 0.3, "slip_threshold": 0.01, "max_updates": 2},
          "pairs": [{"bodies": ["cube", "cube"], "friction": 0.5}]})");
  config = parse_scene(scene, "");
  EXPECT_EQ(config.contact.friction.coefficient, 0.3);
  EXPECT_EQ(config.contact.friction.slip_threshold.value_or(0), 0.01);
  EXPECT_EQ(config.contact.friction.max_updates, 2);
  ASSERT_EQ(config.contact.pairs.size(), 1u);
  EXPECT_EQ(config.contact.pairs[0].friction.value_or(0), 0.5);
}

TEST(ContactEnforcementScene, InconsistentChoicesAreRefusedWithTheirPath) {
  using ::testing::HasSubstr;
  nlohmann::json scene = testing::minimal_scene();
  scene["contact"] = nlohmann::json::parse(R"({"enforcement": {"method": "augmented-lagrangian"}})");
  EXPECT_THAT(testing::parse_error(scene, ""),
              HasSubstr("contact.enforcement: \"augmented-lagrangian\" needs a tolerance: penetration_tolerance"));
  scene["contact"] = nlohmann::json::parse(
      R"({"enforcement": {"method": "adaptive-penalty", "penetration_tolerance": 0.1, "relative_tolerance": 0.1}})");
  EXPECT_THAT(testing::parse_error(scene, ""),
              HasSubstr("contact.enforcement.relative_tolerance: give penetration_tolerance or relative_tolerance, not both"));
  scene["contact"] = nlohmann::json::parse(R"({"enforcement": {"method": "lagrange", "penetration_tolerance": 0.1}})");
  EXPECT_THAT(testing::parse_error(scene, ""), HasSubstr("contact.enforcement.method"));
  scene["contact"] = nlohmann::json::parse(R"({"enforcement": {"penetration_tolerance": -1}})");
  EXPECT_THAT(testing::parse_error(scene, ""), HasSubstr("contact.enforcement.penetration_tolerance"));
  scene["contact"] = nlohmann::json::parse(
      R"({"enforcement": {"method": "augmented-lagrangian", "penetration_tolerance": 0.1, "max_updates": 0}})");
  EXPECT_THAT(testing::parse_error(scene, ""), HasSubstr("contact.enforcement.max_updates"));
  scene["contact"] = nlohmann::json::parse(
      R"({"enforcement": {"method": "adaptive-penalty", "penetration_tolerance": 0.1, "max_growth": 1}})");
  EXPECT_THAT(testing::parse_error(scene, ""), HasSubstr("contact.enforcement.max_growth"));
  scene["contact"] = nlohmann::json::parse(R"({"friction": {"coefficient": 0.3}})");
  scene["dynamics"] = nlohmann::json::parse(R"({"integrator": "explicit", "end_time": 1, "output_interval": 0.5})");
  EXPECT_THAT(testing::parse_error(scene, ""), HasSubstr("contact.friction: friction needs an implicit solve"));
  scene["contact"] = nlohmann::json::parse(R"({"friction": {"coefficient": -0.3, "slip_threshold": 0}})");
  const std::string bad_friction = testing::parse_error(scene, "");
  EXPECT_THAT(bad_friction, HasSubstr("contact.friction.coefficient"));
  EXPECT_THAT(bad_friction, HasSubstr("contact.friction.slip_threshold"));
  scene.erase("dynamics");
  scene["contact"] = nlohmann::json::parse(
      R"({"pairs": [{"bodies": ["cube", "cube"], "enabled": false, "friction": 0.2}]})");
  EXPECT_THAT(testing::parse_error(scene, ""),
              HasSubstr("contact.pairs[0].friction: a disabled pair has no friction"));
  scene["contact"] = nlohmann::json::parse(
      R"({"enforcement": {"method": "augmented-lagrangian", "penetration_tolerance": 0.1}})");
  scene["dynamics"] = nlohmann::json::parse(R"({"integrator": "explicit", "end_time": 1, "output_interval": 0.5})");
  EXPECT_THAT(testing::parse_error(scene, ""),
              HasSubstr("contact.enforcement.method: explicit integration keeps the penalty it started with"));
}

TEST(FrictionScene, ASlipVelocityThresholdIsForDynamicsAndExcludesASlipLength) {
  using ::testing::HasSubstr;
  nlohmann::json scene = testing::minimal_scene();
  scene["contact"] = nlohmann::json::parse(R"({"friction": {"coefficient": 0.3, "slip_velocity_threshold": 0.5}})");
  EXPECT_THAT(testing::parse_error(scene, ""),
              HasSubstr("contact.friction.slip_velocity_threshold: a slip velocity needs time steps"));
  scene["dynamics"] = nlohmann::json::parse(R"({"integrator": "implicit-euler", "end_time": 1, "output_interval": 0.5})");
  const SceneConfig config = parse_scene(scene, "");
  EXPECT_EQ(config.contact.friction.slip_velocity_threshold.value_or(0), 0.5);
  EXPECT_FALSE(config.contact.friction.slip_threshold.has_value());
  scene["contact"]["friction"]["slip_threshold"] = 0.01;
  EXPECT_THAT(testing::parse_error(scene, ""),
              HasSubstr("give either slip_threshold (length) or slip_velocity_threshold (length / time), not both"));
  scene["contact"]["friction"].erase("slip_threshold");
  scene["contact"]["friction"]["slip_velocity_threshold"] = -2;
  EXPECT_THAT(testing::parse_error(scene, ""), HasSubstr("contact.friction.slip_velocity_threshold"));
}

}  // namespace
}  // namespace sinew::scene
