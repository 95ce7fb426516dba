/// @file test_build_problem.cpp
/// SceneConfig -> fem::Problem: concatenated numbering, regions, materials, rigid bodies,
/// selectors against brute force, and the conflicts it must refuse.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <map>
#include <numeric>
#include <numbers>

#include "scene/scene_test_support.hpp"
#include "sinew/scene/build_problem.hpp"
#include "sinew/scene/scene_schema.hpp"

namespace sinew::scene {
namespace {

using nlohmann::json;
using testing::data_directory;
using ::testing::HasSubstr;

/// Two generated bodies: "slab" (soft gel below, fiber-reinforced rubber above, x, y in [0, 1],
/// z in [0, 1]) and "plate" (a rigid box translated to z in [-0.6, -0.1]).
json two_body_scene() {
  return json::parse(R"({
    "units": "m, N, Pa, s",
    "materials": {
      "gel": {"law": "neo-hookean", "mu": 1.0, "lambda": 10.0},
      "tendon": {"law": "mooney-rivlin", "C1": 1, "a": 5, "fiber": {"alpha": 1, "beta": 1, "direction": [1, 0, 0]}}
    },
    "bodies": [
      {"name": "slab",
       "mesh": {"generate": {"element_size": 0.5, "parts": [
         {"region": "soft", "shape": {"box": {"min": [0, 0, 0], "max": [1, 1, 0.5]}}},
         {"region": "fibers", "shape": {"box": {"min": [0, 0, 0.5], "max": [1, 1, 1]}}}]}},
       "regions": {"soft": {"material": "gel", "density": 2},
                   "fibers": {"material": "tendon", "density": 3, "fiber_direction": [0, 1, 0]}}},
      {"name": "plate",
       "mesh": {"generate": {"element_size": 0.5, "parts": [
         {"region": "plate", "shape": {"box": {"min": [0, 0, -0.5], "max": [1, 1, 0]}}}]}},
       "transform": {"translate": [0, 0, -0.1]},
       "regions": {"*": {"rigid": {"prescribed": {"translation": [0, 0, 0.2]}}, "density": 7}}}
    ],
    "boundary_conditions": [
      {"name": "left", "type": "fixed", "nodes": {"body": "slab", "plane": {"point": [0, 0.3, 0.3], "normal": [-2, 0, 0]}}},
      {"name": "right", "type": "prescribed", "nodes": {"body": "slab", "box": {"min": [1, 0, 0], "max": [1, 1, 0.5], "padding": 1e-9}},
       "motion": {"translation": [0.1, 0, 0]}},
      {"name": "roll", "type": "planar", "nodes": {"body": "slab", "set": "soft.surface"}, "normal": [0, 0, 1]}
    ],
    "loads": {"gravity": [0, 0, -9.81],
              "forces": [{"name": "lift", "nodes": {"body": "plate", "all": true}, "total_force": [0, 0, 1]},
                         {"name": "top", "nodes": {"body": "slab", "region": "fibers"}, "total_force": [0, 1, 0]}]}
  })");
}

fem::Problem build(const json& scene) { return build_problem(parse_scene(scene, data_directory())); }

std::string build_error(const json& scene) {
  const SceneConfig config = parse_scene(scene, data_directory());
  try {
    build_problem(config);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "build_problem accepted " << scene.dump();
  return "";
}

Index region_index(const fem::Problem& problem, const std::string& name) {
  const auto& names = problem.mesh.region_names;
  const auto it = std::find(names.begin(), names.end(), name);
  EXPECT_NE(it, names.end()) << name;
  return static_cast<Index>(it - names.begin());
}

std::vector<Index> brute_force(const fem::Problem& problem, const fem::BodyRange& body,
                               const std::function<bool(const Vector3&)>& inside) {
  std::vector<Index> nodes;
  for (Index v = body.first_node; v < body.first_node + body.num_nodes; ++v) {
    if (inside(problem.mesh.rest.row(v).transpose())) nodes.push_back(v);
  }
  return nodes;
}

std::vector<Index> nodes_of_region(const fem::Problem& problem, Index region) {
  std::vector<Index> nodes;
  for (Index t = 0; t < problem.mesh.num_tets(); ++t) {
    if (problem.mesh.region(t) != region) continue;
    for (int k = 0; k < 4; ++k) nodes.push_back(problem.mesh.tets(t, k));
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

TEST(BuildProblem, TwoGeneratedBodies) {
  const fem::Problem problem = build(two_body_scene());
  ASSERT_EQ(problem.bodies.size(), 2u);
  const fem::BodyRange& slab = problem.bodies[0];
  const fem::BodyRange& plate = problem.bodies[1];
  EXPECT_EQ(slab.name, "slab");
  EXPECT_EQ(plate.name, "plate");
  EXPECT_EQ(slab.first_node, 0);
  EXPECT_EQ(slab.first_tet, 0);
  EXPECT_GT(slab.num_nodes, 0);
  EXPECT_GT(plate.num_tets, 0);
  EXPECT_EQ(plate.first_node, slab.num_nodes);
  EXPECT_EQ(plate.first_tet, slab.num_tets);
  EXPECT_EQ(problem.mesh.num_nodes(), slab.num_nodes + plate.num_nodes);
  EXPECT_EQ(problem.mesh.num_tets(), slab.num_tets + plate.num_tets);
  // Each body's tets use only its own nodes.
  for (const fem::BodyRange& body : problem.bodies) {
    for (Index t = body.first_tet; t < body.first_tet + body.num_tets; ++t) {
      for (int k = 0; k < 4; ++k) {
        EXPECT_GE(problem.mesh.tets(t, k), body.first_node);
        EXPECT_LT(problem.mesh.tets(t, k), body.first_node + body.num_nodes);
      }
      EXPECT_GT(mesh::signed_volume(problem.mesh.rest, problem.mesh.tets, t), 0);
    }
  }

  // Regions, materials, densities.
  ASSERT_EQ(problem.mesh.region_names.size(), 3u);
  ASSERT_EQ(problem.region_material.size(), 3u);
  ASSERT_EQ(problem.region_density.size(), 3u);
  const Index soft = region_index(problem, "slab/soft");
  const Index fibers = region_index(problem, "slab/fibers");
  const Index rigid = region_index(problem, "plate/plate");
  EXPECT_NE(problem.region_material[soft], nullptr);
  EXPECT_NE(problem.region_material[fibers], nullptr);
  EXPECT_EQ(problem.region_material[rigid], nullptr);
  EXPECT_STREQ(problem.region_material[soft]->name(), "neo-hookean");
  EXPECT_EQ(problem.region_density[soft], 2);
  EXPECT_EQ(problem.region_density[fibers], 3);
  EXPECT_EQ(problem.region_density[rigid], 7);
  // The fiber override: stretching along y engages the fibers, along x it does not.
  Matrix3 stretch_y = Matrix3::Identity(), stretch_x = Matrix3::Identity();
  stretch_y(1, 1) = 1.2;
  stretch_x(0, 0) = 1.2;
  EXPECT_GT(problem.region_material[fibers]->energy_density(stretch_y),
            problem.region_material[fibers]->energy_density(stretch_x) + 1e-6);

  // The rigid region is one rigid body holding all the plate's tets.
  ASSERT_EQ(problem.rigid_bodies.size(), 1u);
  const fem::RigidBody& body = problem.rigid_bodies[0];
  EXPECT_EQ(body.name, "plate/plate");
  EXPECT_EQ(body.kind, fem::RigidBody::Kind::Prescribed);
  EXPECT_EQ(body.motion.translation, Vector3(0, 0, 0.2));
  ASSERT_EQ(static_cast<Index>(body.tets.size()), plate.num_tets);
  EXPECT_EQ(body.tets.front(), plate.first_tet);
  EXPECT_EQ(body.tets.back(), plate.first_tet + plate.num_tets - 1);

  // The transform moved the plate down by 0.1.
  const auto plate_z = problem.mesh.rest.col(2).segment(plate.first_node, plate.num_nodes);
  EXPECT_NEAR(plate_z.minCoeff(), -0.6, 1e-9);
  EXPECT_NEAR(plate_z.maxCoeff(), -0.1, 1e-9);

  // Sets are renamed and renumbered.
  ASSERT_TRUE(problem.mesh.face_sets.count("plate/plate.surface"));
  const Triangles& plate_surface = problem.mesh.face_sets.at("plate/plate.surface");
  EXPECT_GE(plate_surface.minCoeff(), plate.first_node);

  // Selectors against brute force.
  ASSERT_EQ(problem.prescribed.size(), 2u);
  EXPECT_EQ(problem.prescribed[0].name, "left");
  EXPECT_TRUE(problem.prescribed[0].motion.is_identity());
  EXPECT_EQ(problem.prescribed[0].nodes,
            brute_force(problem, slab, [](const Vector3& X) { return std::abs(X.x()) <= 1e-9; }));
  EXPECT_FALSE(problem.prescribed[0].nodes.empty());
  EXPECT_EQ(problem.prescribed[1].name, "right");
  EXPECT_EQ(problem.prescribed[1].motion.translation, Vector3(0.1, 0, 0));
  EXPECT_EQ(problem.prescribed[1].nodes, brute_force(problem, slab, [](const Vector3& X) {
              return std::abs(X.x() - 1) <= 1e-9 && X.y() >= -1e-9 && X.y() <= 1 + 1e-9 && X.z() >= -1e-9 &&
                     X.z() <= 0.5 + 1e-9;
            }));
  EXPECT_FALSE(problem.prescribed[1].nodes.empty());
  ASSERT_EQ(problem.planar.size(), 1u);
  std::vector<Index> surface(problem.mesh.face_sets.at("slab/soft.surface").data(),
                             problem.mesh.face_sets.at("slab/soft.surface").data() +
                                 problem.mesh.face_sets.at("slab/soft.surface").size());
  std::sort(surface.begin(), surface.end());
  surface.erase(std::unique(surface.begin(), surface.end()), surface.end());
  EXPECT_EQ(problem.planar[0].nodes, surface);
  EXPECT_EQ(problem.planar[0].normal, Vector3(0, 0, 1));

  ASSERT_EQ(problem.forces.size(), 2u);
  std::vector<Index> all_plate(static_cast<std::size_t>(plate.num_nodes));
  std::iota(all_plate.begin(), all_plate.end(), plate.first_node);
  EXPECT_EQ(problem.forces[0].nodes, all_plate);
  EXPECT_EQ(problem.forces[0].total_force, Vector3(0, 0, 1));
  EXPECT_EQ(problem.forces[1].nodes, nodes_of_region(problem, fibers));
  EXPECT_EQ(problem.gravity, Vector3(0, 0, -9.81));
}

TEST(BuildProblem, RotationIsAppliedBeforeTranslation) {
  json scene = two_body_scene();
  scene["bodies"][1]["transform"] = {{"translate", {10, 0, 0}}, {"rotate", {{"axis", {0, 0, 1}}, {"angle_deg", 90}}}};
  const fem::Problem problem = build(scene);
  const fem::BodyRange& plate = problem.bodies[1];
  const auto rest = problem.mesh.rest.middleRows(plate.first_node, plate.num_nodes);
  // [0, 1] x [0, 1] rotated by 90 degrees about z is [-1, 0] x [0, 1]; then x += 10.
  EXPECT_NEAR(rest.col(0).minCoeff(), 9, 1e-9);
  EXPECT_NEAR(rest.col(0).maxCoeff(), 10, 1e-9);
  EXPECT_NEAR(rest.col(1).minCoeff(), 0, 1e-9);
  EXPECT_NEAR(rest.col(1).maxCoeff(), 1, 1e-9);
}

TEST(BuildProblem, MeshFileWithRigidRegions) {
  const fem::Problem problem = build_problem(parse_scene(json::parse(scene_example_json()), data_directory()));
  ASSERT_EQ(problem.bodies.size(), 2u);
  const fem::BodyRange& block = problem.bodies[0];
  EXPECT_EQ(block.num_nodes, 125);  // tests/scene/data/block.msh: 4 x 4 x 4 cells
  EXPECT_EQ(block.num_tets, 384);
  for (const char* name : {"block/flesh", "block/bone", "block/patella", "block/tibia", "block/muscle", "ball/ball",
                           "ball/core"}) {
    region_index(problem, name);
  }
  EXPECT_STREQ(problem.region_material[region_index(problem, "block/flesh")]->name(), "mooney-rivlin");
  EXPECT_STREQ(problem.region_material[region_index(problem, "ball/ball")]->name(), "neo-hookean");
  EXPECT_EQ(problem.region_material[region_index(problem, "block/bone")], nullptr);
  EXPECT_NE(problem.region_material[region_index(problem, "block/muscle")], nullptr);
  EXPECT_EQ(problem.region_density[region_index(problem, "block/flesh")], 1e-6);
  EXPECT_EQ(problem.region_density[region_index(problem, "block/patella")], 2e-6);

  ASSERT_EQ(problem.rigid_bodies.size(), 3u);
  std::map<std::string, fem::RigidBody::Kind> kinds;
  for (const fem::RigidBody& body : problem.rigid_bodies) {
    kinds[body.name] = body.kind;
    EXPECT_EQ(body.tets.size(), 6u);  // one cell each
  }
  EXPECT_EQ(kinds.at("block/bone"), fem::RigidBody::Kind::Fixed);
  EXPECT_EQ(kinds.at("block/patella"), fem::RigidBody::Kind::Free);
  EXPECT_EQ(kinds.at("block/tibia"), fem::RigidBody::Kind::Prescribed);

  ASSERT_EQ(problem.prescribed.size(), 2u);
  EXPECT_EQ(problem.prescribed[0].nodes.size(), 25u);  // x = 0 face
  EXPECT_EQ(problem.prescribed[1].nodes.size(), 25u);  // x = 1 face
  for (Index node : problem.prescribed[1].nodes) EXPECT_EQ(problem.mesh.rest(node, 0), 1.0);
  ASSERT_EQ(problem.planar.size(), 1u);
  EXPECT_EQ(problem.planar[0].nodes.size(), 25u);  // the "bottom" set
  for (Index node : problem.planar[0].nodes) EXPECT_EQ(problem.mesh.rest(node, 2), 0.0);
  ASSERT_EQ(problem.forces.size(), 1u);
  EXPECT_GE(problem.forces[0].nodes.front(), problem.bodies[1].first_node);
}

TEST(SelectNodes, EveryKindOnAHandMadeMesh) {
  mesh::TetMesh mesh;
  mesh.rest.resize(5, 3);
  mesh.rest << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1;
  mesh.tets.resize(2, 4);
  mesh.tets << 0, 1, 2, 3, 1, 2, 3, 4;
  mesh.region.resize(2);
  mesh.region << 0, 1;
  mesh.region_names = {"a", "b"};
  mesh.node_sets["corner"] = {4, 0, 4};
  mesh.face_sets["face"] = Triangles(1, 3);
  mesh.face_sets["face"] << 3, 1, 2;

  NodeSelector selector;
  selector.kind = NodeSelector::Kind::Set;
  selector.name = "corner";
  EXPECT_EQ(select_nodes(mesh, selector), (std::vector<Index>{0, 4}));
  selector.name = "face";  // no node set of that name: the face set's nodes
  EXPECT_EQ(select_nodes(mesh, selector), (std::vector<Index>{1, 2, 3}));
  selector.name = "fcae";
  try {
    select_nodes(mesh, selector);
    ADD_FAILURE() << "unknown set accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "the mesh has no node or face set \"fcae\"; did you mean \"face\"?; its sets: \"corner\", \"face\"");
  }
  selector.kind = NodeSelector::Kind::Region;
  selector.name = "b";
  EXPECT_EQ(select_nodes(mesh, selector), (std::vector<Index>{1, 2, 3, 4}));
  selector.kind = NodeSelector::Kind::Box;
  selector.box_min = Vector3(0.5, -1, -1);
  selector.box_max = Vector3(2, 2, 2);
  selector.tolerance = 0;
  EXPECT_EQ(select_nodes(mesh, selector), (std::vector<Index>{1, 4}));
  selector.box_min = Vector3(0, 0, 0);
  selector.box_max = Vector3(0, 0, 0);
  EXPECT_EQ(select_nodes(mesh, selector), (std::vector<Index>{0}));
  selector.kind = NodeSelector::Kind::Plane;
  selector.point = Vector3(0, 0, 0.5);
  selector.normal = Vector3(1, 1, 1);  // normalized on use: nodes 0-3 lie 0.5/sqrt(3) from the plane, node 4 farther
  selector.tolerance = 0.5 / std::sqrt(3.0) + 1e-12;
  EXPECT_EQ(select_nodes(mesh, selector), (std::vector<Index>{0, 1, 2, 3}));
  selector.kind = NodeSelector::Kind::All;
  EXPECT_EQ(select_nodes(mesh, selector), (std::vector<Index>{0, 1, 2, 3, 4}));
}

// ---------------------------------------------------------------- errors

TEST(BuildProblemErrors, NodePrescribedTwice) {
  json scene = two_body_scene();
  // "right" covers the lower half of x = 1; this one the whole x = 1 face.
  scene["boundary_conditions"].push_back(json::parse(
      R"({"name": "again", "type": "fixed", "nodes": {"body": "slab", "plane": {"point": [1, 0, 0], "normal": [1, 0, 0]}}})"));
  const std::string message = build_error(scene);
  EXPECT_THAT(message, ::testing::StartsWith("boundary_conditions[3].nodes: "));
  EXPECT_THAT(message, HasSubstr("are already prescribed by \"right\" (boundary_conditions[1])"));
}

TEST(BuildProblemErrors, PlanarOverlappingFixedIsAllowed) {
  json scene = two_body_scene();
  scene["boundary_conditions"][2]["nodes"] = json::parse(R"({"body": "slab", "all": true})");
  const fem::Problem problem = build(scene);
  EXPECT_EQ(problem.planar.at(0).nodes.size(), static_cast<std::size_t>(problem.bodies[0].num_nodes));
}

TEST(BuildProblemErrors, ConstrainedNodeOfARigidRegion) {
  json scene = two_body_scene();
  scene["boundary_conditions"].push_back(
      json::parse(R"({"name": "hold", "type": "fixed", "nodes": {"body": "plate", "plane": {"point": [0, 0, -0.1], "normal": [0, 0, 1]}}})"));
  scene["boundary_conditions"].push_back(
      json::parse(R"({"name": "glide", "type": "planar", "nodes": {"body": "plate", "all": true}, "normal": [0, 0, 1]})"));
  const std::string message = build_error(scene);
  EXPECT_THAT(message, HasSubstr("boundary_conditions[3].nodes: "));
  EXPECT_THAT(message, HasSubstr("boundary_conditions[4].nodes: "));
  EXPECT_THAT(message, HasSubstr("belong to rigid region \"plate/plate\"; the rigid body's motion rules them: "
                                 "prescribe the rigid region instead"));
}

TEST(BuildProblemErrors, RigidRegionsSharingNodes) {
  json scene = two_body_scene();
  scene["bodies"][0]["regions"] = json::parse(R"({"soft": {"rigid": "fixed"}, "fibers": {"rigid": "free"}})");
  scene["boundary_conditions"] = json::array();
  scene["loads"]["forces"] = json::array();
  EXPECT_THAT(build_error(scene),
              ::testing::StartsWith("bodies[0].regions.fibers: rigid region \"slab/fibers\" shares node(s) with rigid "
                                    "region \"slab/soft\", e.g. node "));
}

TEST(BuildProblemErrors, SelectorMatchingNoNode) {
  json scene = two_body_scene();
  scene["loads"]["forces"][0]["nodes"] = json::parse(R"({"body": "plate", "box": {"min": [5, 5, 5], "max": [6, 6, 6]}})");
  EXPECT_EQ(build_error(scene),
            "loads.forces[0].nodes: selects no node of body \"plate\" (box); positions are rest positions after the "
            "body's transform");
}

TEST(BuildProblemErrors, UnknownSetOrRegionInASelector) {
  json scene = two_body_scene();
  scene["boundary_conditions"][2]["nodes"]["set"] = "nowhere";
  scene["loads"]["forces"][1]["nodes"]["region"] = "fiber";
  const std::string message = build_error(scene);
  EXPECT_THAT(message, HasSubstr("boundary_conditions[2].nodes: the mesh has no node or face set \"nowhere\""));
  EXPECT_THAT(message, HasSubstr("loads.forces[1].nodes: the mesh has no region \"fiber\"; its regions: "));
}

TEST(BuildProblemErrors, RegionEntriesMustMatchTheMesh) {
  json scene = two_body_scene();
  scene["bodies"][0]["regions"]["fibres"] = scene["bodies"][0]["regions"]["fibers"];
  scene["bodies"][0]["regions"].erase("fibers");
  const std::string message = build_error(scene);
  EXPECT_THAT(message, HasSubstr("bodies[0].regions.fibres: the mesh has no region \"fibres\"; its regions: "));
  EXPECT_THAT(message, HasSubstr("\"fibers\""));
  EXPECT_THAT(message, HasSubstr("bodies[0].regions: mesh region \"fibers\" has no entry and there is no \"*\" entry"));
}

TEST(BuildProblemErrors, MeshErrorsCarryTheBodyPath) {
  json scene = two_body_scene();
  scene["bodies"][1]["mesh"] = {{"file", "full_example.json"}};  // exists, but is no mesh
  EXPECT_THAT(build_error(scene), ::testing::StartsWith("bodies[1].mesh: "));
}

}  // namespace
}  // namespace sinew::scene
