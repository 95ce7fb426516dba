/// @file test_traction.cpp
/// Traction loads (loads.forces[].traction): read from the scene, spread over the selected
/// boundary faces by tributary area (each node a third of each face it belongs to), and refused
/// with a clear message when the force gives both or neither of total_force and traction, or
/// when the selected nodes hold no whole boundary face.

#include <gtest/gtest.h>

#include <map>
#include <numeric>

#include "scene/scene_test_support.hpp"
#include "sinew/mesh/tet_mesh.hpp"
#include "sinew/scene/build_problem.hpp"

namespace sinew::scene {
namespace {

using nlohmann::json;
using testing::minimal_scene;
using testing::parse_error;

/// The unit cube of minimal_scene() (element size 0.5) with a traction on its top face z = 1.
json cube_with_top_traction(const json& traction) {
  json scene = minimal_scene();
  scene["loads"]["forces"] = {{{"name", "top"},
                               {"nodes", {{"plane", {{"point", {0, 0, 1}}, {"normal", {0, 0, 1}}}}}},
                               {"traction", traction},
                               {"amplitude", {{0, 0}, {0.5, 1}}}}};
  return scene;
}

TEST(Traction, IsReadAsAForcePerArea) {
  const SceneConfig scene = parse_scene(cube_with_top_traction({1, 0, -2}), "");
  ASSERT_EQ(scene.loads.forces.size(), 1u);
  ASSERT_TRUE(scene.loads.forces[0].traction.has_value());
  EXPECT_EQ(*scene.loads.forces[0].traction, Vector3(1, 0, -2));
  EXPECT_EQ(scene.loads.forces[0].amplitude(0.25), 0.5);
}

TEST(Traction, IsSpreadOverTheSelectedFacesByTributaryArea) {
  const fem::Problem problem = build_problem(parse_scene(cube_with_top_traction({1, 0, -2}), ""));
  ASSERT_EQ(problem.forces.size(), 1u);
  const fem::NodalForce& force = problem.forces[0];
  // The top face has area 1: the total force is the traction.
  EXPECT_NEAR((force.total_force - Vector3(1, 0, -2)).norm(), 0, 1e-12);
  ASSERT_EQ(force.shares.size(), force.nodes.size());
  EXPECT_NEAR(std::accumulate(force.shares.begin(), force.shares.end(), 0.0), 1, 1e-12);

  // Brute force: a third of the area of every boundary face with its three nodes on z = 1.
  const Positions& rest = problem.mesh.rest;
  std::map<Index, double> expected;
  const Triangles faces = mesh::boundary_triangles(problem.mesh.tets);
  for (Index f = 0; f < faces.rows(); ++f) {
    bool on_top = true;
    for (int k = 0; k < 3; ++k) on_top = on_top && std::abs(rest(faces(f, k), 2) - 1) < 1e-12;
    if (!on_top) continue;
    const Vector3 a = rest.row(faces(f, 0)), b = rest.row(faces(f, 1)), c = rest.row(faces(f, 2));
    for (int k = 0; k < 3; ++k) expected[faces(f, k)] += 0.5 * (b - a).cross(c - a).norm() / 3;
  }
  ASSERT_EQ(expected.size(), force.nodes.size());
  for (std::size_t i = 0; i < force.nodes.size(); ++i) {
    EXPECT_NEAR(force.shares[i], expected.at(force.nodes[i]), 1e-12) << "node " << force.nodes[i];
  }
  // A corner carries less than a node in the middle of the face: the shares are not equal.
  const auto [smallest, largest] = std::minmax_element(force.shares.begin(), force.shares.end());
  EXPECT_LT(*smallest, 0.5 * *largest);
}

TEST(TractionErrors, AForceGivesExactlyOneOfTotalForceAndTraction) {
  json scene = cube_with_top_traction({0, 0, -1});
  scene["loads"]["forces"][0]["total_force"] = {0, 0, -1};
  EXPECT_EQ(parse_error(scene), "loads.forces[0]: give either total_force (force, in equal nodal shares) or "
                                "traction (force per area on the selected boundary faces)");
  scene["loads"]["forces"][0].erase("total_force");
  scene["loads"]["forces"][0].erase("traction");
  EXPECT_EQ(parse_error(scene), "loads.forces[0]: give either total_force (force, in equal nodal shares) or "
                                "traction (force per area on the selected boundary faces)");
  scene["loads"]["forces"][0]["traction"] = {0, 0, "NaN"};
  EXPECT_EQ(parse_error(scene), "loads.forces[0].traction: must be an array of 3 numbers [x, y, z], got [0,0,\"NaN\"]");
}

TEST(TractionErrors, NodesThatHoldNoWholeBoundaryFaceAreRefused) {
  // One edge of the top face: its nodes hold no whole face.
  json scene = cube_with_top_traction({0, 0, -1});
  scene["loads"]["forces"][0]["nodes"] = {{"box", {{"min", {0, 0, 1}}, {"max", {1, 0, 1}}, {"padding", 1e-9}}}};
  const SceneConfig config = parse_scene(scene, "");
  try {
    build_problem(config);
    ADD_FAILURE() << "a traction on an edge was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "loads.forces[0].nodes: selects no whole boundary face: a traction acts on the boundary faces "
              "whose three nodes are all selected");
  }
}

}  // namespace
}  // namespace sinew::scene
