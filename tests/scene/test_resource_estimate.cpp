/// @file test_resource_estimate.cpp
/// Generated meshes are sized before meshing: a body whose estimated tet count exceeds the limit
/// fails at once (a box 1e5 on a side at element_size 1 would need ~1e16 tets).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>
#include <string>

#include "scene/scene_test_support.hpp"
#include "sinew/scene/build_problem.hpp"
#include "sinew/scene/load_scene.hpp"
#include "sinew/scene/resource_estimate.hpp"

namespace sinew::scene {
namespace {

using nlohmann::json;
using testing::minimal_scene;
using ::testing::HasSubstr;

using std::numbers::pi;

std::string build_error(const SceneConfig& config) {
  try {
    build_problem(config);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "build_problem accepted the scene";
  return "";
}

TEST(ResourceEstimate, AHugeBoxIsRefusedBeforeMeshing) {
  json scene = minimal_scene();
  scene["bodies"][0]["mesh"]["generate"]["element_size"] = 1.0;
  scene["bodies"][0]["mesh"]["generate"]["parts"][0]["shape"]["box"]["max"] = {1e5, 1e5, 1e5};
  const SceneConfig config = parse_scene(scene, "");
  EXPECT_NEAR(estimated_tets(config.bodies[0]), kTetsPerEdgeCubed * 1e15, 1e3);
  // Meshing it would take hours and all memory: the message comes before any Gmsh call.
  EXPECT_EQ(build_error(config),
            "bodies[0].mesh.generate: an estimated 8.5e+15 tets (about 1.7e+10 GB) at element_size 1 exceed the "
            "limit of 3e+06 tets (raise it with --max-tets); or raise element_size");
}

TEST(ResourceEstimate, TheLimitComesFromTheConfig) {
  SceneConfig config = parse_scene(minimal_scene(), "");  // a unit cube at element_size 0.5
  config.bodies[0].mesh.generate.element_size = 0.1;       // ~8.5e3 tets estimated
  config.limits.max_tets = 1000;
  EXPECT_THAT(build_error(config), HasSubstr("exceed the limit of 1e+03 tets"));
  config.limits.max_tets = 1e5;
  EXPECT_NO_THROW(build_problem(config));
}

TEST(ResourceEstimate, VolumeBoundsOfShapes) {
  mesh::Shape box;
  box.min = Vector3(0, 0, 0);
  box.max = Vector3(1, 2, 3);
  EXPECT_DOUBLE_EQ(shape_volume_bound(box), 6);
  mesh::Shape sphere;
  sphere.kind = mesh::Shape::Kind::Sphere;
  sphere.radius = 2;
  EXPECT_DOUBLE_EQ(shape_volume_bound(sphere), 32 * pi / 3);
  mesh::Shape cylinder;
  cylinder.kind = mesh::Shape::Kind::Cylinder;
  cylinder.radius = 1;
  cylinder.axis = Vector3(0, 0, 4);
  EXPECT_DOUBLE_EQ(shape_volume_bound(cylinder), 4 * pi);
  mesh::Shape torus;
  torus.kind = mesh::Shape::Kind::Torus;
  torus.radius = 2;
  torus.minor_radius = 0.5;
  torus.angle_deg = 180;
  EXPECT_DOUBLE_EQ(shape_volume_bound(torus), pi * 0.25 * pi * 2);  // half of 2 pi^2 R r^2
  mesh::Shape combined;
  combined.children = {box, sphere};
  combined.kind = mesh::Shape::Kind::Union;
  EXPECT_DOUBLE_EQ(shape_volume_bound(combined), 6 + 32 * pi / 3);
  combined.kind = mesh::Shape::Kind::Difference;
  EXPECT_DOUBLE_EQ(shape_volume_bound(combined), 6);
  combined.kind = mesh::Shape::Kind::Intersection;
  EXPECT_DOUBLE_EQ(shape_volume_bound(combined), 6);
}

TEST(ResourceEstimate, CurvedSurfacesAddTheirRefinedLayer) {
  mesh::Part ball{"ball", {}};
  ball.shape.kind = mesh::Shape::Kind::Sphere;
  ball.shape.radius = 1;
  mesh::GenerateOptions options;
  options.element_size = 1;
  options.elements_per_turn = 0;  // element_size alone
  const double plain = estimated_tets({ball}, options);
  EXPECT_DOUBLE_EQ(plain, kTetsPerEdgeCubed * 4 * pi / 3);
  options.elements_per_turn = 12;  // surface size 2 pi / 12 ~ 0.52
  const double s = 2 * pi / 12;
  EXPECT_DOUBLE_EQ(estimated_tets({ball}, options), plain + kTetsPerEdgeCubed * 4 * pi / (s * s));
}

TEST(ResourceEstimate, EveryExampleIsWellUnderTheDefaultLimit) {
  const ResourceLimits limits;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(SINEW_SOURCE_DIR) + "/examples")) {
    if (entry.path().extension() != ".json") continue;
    const SceneConfig config = load_scene_file(entry.path().string());
    for (const BodyConfig& body : config.bodies) {
      EXPECT_LT(estimated_tets(body), limits.max_tets / 10) << entry.path() << " " << body.name;
    }
  }
  // The knee's leg at 9 mm meshes into ~30k tets; the estimate is of that order.
  const SceneConfig knee = load_scene_file(std::string(SINEW_SOURCE_DIR) + "/examples/knee-flexion.json");
  EXPECT_EQ(knee.bodies[1].name, "leg");
  EXPECT_GT(estimated_tets(knee.bodies[1]), 3e4);
  EXPECT_LT(estimated_tets(knee.bodies[1]), 3e5);
}

}  // namespace
}  // namespace sinew::scene
