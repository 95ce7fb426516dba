/// @file test_surface_mesh_scene.cpp
/// Bodies meshed from surface files ("mesh": {"surfaces": ...}): paths through data_dir, the
/// missing-file message with the surface's source, unknown names, open surfaces and repair.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "scene/scene_test_support.hpp"
#include "sinew/scene/build_problem.hpp"
#include "support/files.hpp"
#include "support/temp_dir.hpp"
#include "surface/surface_fixtures.hpp"

namespace sinew::scene {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

/// A body "block" from the unit cube file `cube.stl` scaled to 10 mm, with a capsule core first.
json cube_scene(const std::string& data_dir) {
  json scene = json::parse(R"({
    "units": "mm, mN, kPa",
    "materials": {"gel": {"law": "neo-hookean", "mu": 1.0, "lambda": 10.0}},
    "bodies": [{"name": "block",
      "mesh": {"surfaces": {"element_size": 2.5, "facet_distance": 0.2,
        "surfaces": {"cube": {"file": "cube.stl", "unit_scale": 10, "source": "the test writes it"}},
        "parts": [{"region": "core", "solid": {"capsule": {"a": [5, 5, 3], "b": [5, 5, 7], "radius": 2}}},
                  {"region": "box", "solid": {"surface": "cube"}}]}},
      "regions": {"*": {"material": "gel"}}}]
  })");
  scene["data_dir"] = data_dir;
  return scene;
}

std::string build_error(const json& scene, const std::string& base) {
  try {
    build_problem(parse_scene(scene, base));
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted " << scene.dump();
  return "";
}

TEST(SurfaceMeshScene, MeshesRegionsFromAFileInTheDataDirectory) {
  const sinew::testing::TempDir dir;
  sinew::testing::write_text(dir.path() / "cube.stl", sinew::testing::ascii_stl(sinew::testing::unit_cube()));
  const fem::Problem problem = build_problem(parse_scene(cube_scene(dir.path().string()), "/nonexistent"));
  ASSERT_EQ(problem.mesh.region_names.size(), 2u);
  EXPECT_EQ(problem.mesh.region_names[0], "block/core");
  EXPECT_EQ(problem.mesh.region_names[1], "block/box");
  double volume = 0;
  for (Index t = 0; t < problem.mesh.num_tets(); ++t) volume += mesh::signed_volume(problem.mesh.rest, problem.mesh.tets, t);
  EXPECT_NEAR(volume, 1000.0, 30.0);  // the cube's edges are rounded by about facet_distance
  EXPECT_GT(problem.mesh.num_tets(), 100);
}

TEST(SurfaceMeshScene, RelativeDataDirectoryStartsAtTheSceneDirectory) {
  const sinew::testing::TempDir dir;
  std::filesystem::create_directories(dir.path() / "data");
  sinew::testing::write_text(dir.path() / "data" / "cube.stl", sinew::testing::ascii_stl(sinew::testing::unit_cube()));
  const fem::Problem problem = build_problem(parse_scene(cube_scene("data"), dir.path().string()));
  EXPECT_EQ(problem.mesh.region_names.size(), 2u);
}

TEST(SurfaceMeshScene, MissingFileNamesTheSurfaceTheFileAndItsSource) {
  const sinew::testing::TempDir dir;
  const std::string message = build_error(cube_scene(dir.path().string()), dir.path().string());
  EXPECT_THAT(message, HasSubstr("bodies[0].mesh"));
  EXPECT_THAT(message, HasSubstr("surface \"cube\" (cube.stl)"));
  EXPECT_THAT(message, HasSubstr("file not found"));
  EXPECT_THAT(message, HasSubstr("get it from: the test writes it"));
  EXPECT_THAT(message, HasSubstr("--data-dir"));
}

TEST(SurfaceMeshScene, UnknownSurfaceNameIsAnInputError) {
  json scene = cube_scene("/tmp");
  scene["bodies"][0]["mesh"]["surfaces"]["parts"][1]["solid"] = {{"surface", "cub"}};
  try {
    parse_scene(scene, "/tmp");
    ADD_FAILURE() << "accepted an unknown surface";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("bodies[0].mesh.surfaces.parts[1].solid: unknown surface \"cub\""));
    EXPECT_THAT(e.what(), HasSubstr("\"cube\""));
  }
}

TEST(SurfaceMeshScene, SizeZoneTakesACapsuleAndNeedsSurfacesOrOne) {
  json scene = cube_scene("/nonexistent");
  scene["bodies"][0]["mesh"]["surfaces"]["size_zones"] =
      json::parse(R"([{"capsule": {"a": [5, 5, 3], "b": [5, 5, 7], "radius": 1}, "size": 1, "grading": 0.5}])");
  const SceneConfig config = parse_scene(scene, "/nonexistent");
  const auto& zones = config.bodies.at(0).mesh.surfaces->options.size_zones;
  ASSERT_EQ(zones.size(), 1u);
  ASSERT_TRUE(zones[0].capsule.has_value());
  EXPECT_EQ(zones[0].capsule->b, Vector3(5, 5, 7));
  EXPECT_EQ(zones[0].capsule->radius, 1);
  EXPECT_TRUE(zones[0].surfaces.empty());
  EXPECT_EQ(zones[0].grading, 0.5);
  scene["bodies"][0]["mesh"]["surfaces"]["size_zones"] = json::parse(R"([{"size": 1}])");
  try {
    parse_scene(scene, "/nonexistent");
    ADD_FAILURE() << "a zone without surfaces or capsule was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("bodies[0].mesh.surfaces.size_zones[0]: a size zone needs \"surfaces\" or a \"capsule\""));
  }
}

TEST(SurfaceMeshScene, OpenSurfaceIsRefusedUnlessRepaired) {
  const sinew::testing::TempDir dir;
  sinew::testing::Shape open = sinew::testing::unit_cube();
  open.triangles.pop_back();
  sinew::testing::write_text(dir.path() / "cube.stl", sinew::testing::ascii_stl(open));
  json scene = cube_scene(dir.path().string());
  const std::string message = build_error(scene, dir.path().string());
  EXPECT_THAT(message, HasSubstr("the surface is open"));
  EXPECT_THAT(message, HasSubstr("fill_holes"));
  scene["bodies"][0]["mesh"]["surfaces"]["surfaces"]["cube"]["repair"] = {{"fill_holes", true}};
  const fem::Problem problem = build_problem(parse_scene(scene, dir.path().string()));
  EXPECT_EQ(problem.mesh.region_names.size(), 2u);
}

TEST(SurfaceMeshScene, PartHiddenByAnEarlierOneIsReported) {
  const sinew::testing::TempDir dir;
  sinew::testing::write_text(dir.path() / "cube.stl", sinew::testing::ascii_stl(sinew::testing::unit_cube()));
  json scene = cube_scene(dir.path().string());
  const json core = scene["bodies"][0]["mesh"]["surfaces"]["parts"][0];
  const json box = scene["bodies"][0]["mesh"]["surfaces"]["parts"][1];
  scene["bodies"][0]["mesh"]["surfaces"]["parts"] = json::array({box, core});  // nothing is left for the core
  const std::string message = build_error(scene, dir.path().string());
  EXPECT_THAT(message, HasSubstr("part \"core\" got no elements"));
}

TEST(SurfaceMeshScene, RemeshedSurfaceMeshesTheSameRegions) {
  const sinew::testing::TempDir dir;
  sinew::testing::write_text(dir.path() / "cube.stl", sinew::testing::ascii_stl(sinew::testing::unit_cube()));
  json scene = cube_scene(dir.path().string());
  scene["bodies"][0]["mesh"]["surfaces"]["surfaces"]["cube"]["repair"] = {{"remesh_edge_length", 2.0}};
  const fem::Problem problem = build_problem(parse_scene(scene, dir.path().string()));
  ASSERT_EQ(problem.mesh.region_names.size(), 2u);
  double volume = 0;
  for (Index t = 0; t < problem.mesh.num_tets(); ++t) volume += mesh::signed_volume(problem.mesh.rest, problem.mesh.tets, t);
  // Remeshing moves vertices in the cube's faces and keeps its sharp edges only roughly.
  EXPECT_NEAR(volume, 1000.0, 60.0);
}

TEST(SurfaceMeshScene, RemeshEdgeLengthThatWouldMakeTooManyTrianglesIsRefused) {
  const sinew::testing::TempDir dir;
  sinew::testing::write_text(dir.path() / "cube.stl", sinew::testing::ascii_stl(sinew::testing::unit_cube()));
  json scene = cube_scene(dir.path().string());
  // 600 mm^2 of surface in triangles of edge 1e-3: about 1.4e9 of them.
  scene["bodies"][0]["mesh"]["surfaces"]["surfaces"]["cube"]["repair"] = {{"remesh_edge_length", 1e-3}};
  const std::string message = build_error(scene, dir.path().string());
  EXPECT_THAT(message, HasSubstr("surface \"cube\" (cube.stl)"));
  EXPECT_THAT(message, HasSubstr("\"remesh_edge_length\" 0.001 would make about 1.39e+09 triangles"));
  EXPECT_THAT(message, HasSubstr("choose a longer edge"));
  scene["bodies"][0]["mesh"]["surfaces"]["surfaces"]["cube"]["repair"] = {{"remesh_edge_length", -1.0}};
  EXPECT_THAT(build_error(scene, dir.path().string()), HasSubstr("remesh_edge_length"));
}

TEST(SurfaceMeshScene, RemeshEdgeLengthThatCollapsesTheSurfaceIsRefused) {
  // Edges of 20 on a 10 mm cube: CGAL collapses it to a small polyhedron (about 5 % of its volume).
  const sinew::testing::TempDir dir;
  sinew::testing::write_text(dir.path() / "cube.stl", sinew::testing::ascii_stl(sinew::testing::unit_cube()));
  json scene = cube_scene(dir.path().string());
  scene["bodies"][0]["mesh"]["surfaces"]["surfaces"]["cube"]["repair"] = {{"remesh_edge_length", 20.0}};
  const std::string message = build_error(scene, dir.path().string());
  EXPECT_THAT(message, HasSubstr("surface \"cube\" (cube.stl): remeshing to edges of 20 changed the enclosed volume "
                                 "from 1000 to"));
  EXPECT_THAT(message, HasSubstr("choose a shorter \"remesh_edge_length\""));
}

TEST(SurfaceMeshScene, TooFineAMeshIsRefusedBeforeMeshing) {
  const sinew::testing::TempDir dir;
  sinew::testing::write_text(dir.path() / "cube.stl", sinew::testing::ascii_stl(sinew::testing::unit_cube()));
  json scene = cube_scene(dir.path().string());
  scene["bodies"][0]["mesh"]["surfaces"]["element_size"] = 0.01;  // ~1e7 tets in a 10 mm cube
  const std::string message = build_error(scene, dir.path().string());
  EXPECT_THAT(message, HasSubstr("exceed the limit of 3e+06 tets"));
  EXPECT_THAT(message, HasSubstr("--max-tets"));
}

}  // namespace
}  // namespace sinew::scene
