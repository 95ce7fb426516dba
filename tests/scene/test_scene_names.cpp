/// @file test_scene_names.cpp
/// Names that would give a run's tables two columns of one name are refused when the scene is
/// loaded (validate used to pass what run then rejected: "CSV table ... has two columns named").

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_test_support.hpp"
#include "sinew/scene/build_problem.hpp"
#include "sinew/scene/load_scene.hpp"

namespace sinew::scene {
namespace {

using nlohmann::json;
using testing::data_directory;
using testing::minimal_scene;
using testing::parse_error;
using ::testing::HasSubstr;

json condition(const std::string& name) {
  return {{"name", name}, {"type", "fixed"}, {"nodes", {{"all", true}}}};
}

TEST(SceneNames, AConditionNamedLikeARigidRegion) {
  json scene = minimal_scene();
  scene["bodies"][0]["regions"] = {{"cube", {{"rigid", "fixed"}}}};
  scene["boundary_conditions"] = {condition("cube/cube")};
  EXPECT_EQ(parse_error(scene),
            "boundary_conditions[0].name: the boundary condition name \"cube/cube\" is also the name of the rigid "
            "region at bodies[0].regions.cube; their reaction columns (<name>.fx, ...) would clash: rename one");
}

TEST(SceneNames, ARigidRegionCoveredByTheStarEntryOfGeneratedParts) {
  json scene = minimal_scene();
  scene["bodies"][0]["regions"] = {{"*", {{"rigid", "free"}}}};
  scene["loads"]["forces"] = {{{"name", "cube/cube"}, {"nodes", {{"all", true}}}, {"total_force", {0, 0, 1}}}};
  EXPECT_THAT(parse_error(scene), HasSubstr("loads.forces[0].name: the force name \"cube/cube\" is also the name of "
                                            "the rigid region at bodies[0].regions[\"*\"]"));
}

TEST(SceneNames, AForceNamedLikeACondition) {
  json scene = minimal_scene();
  scene["boundary_conditions"] = {condition("base")};
  scene["loads"]["forces"] = {{{"name", "base"}, {"nodes", {{"all", true}}}, {"total_force", {0, 0, 1}}}};
  EXPECT_THAT(parse_error(scene), HasSubstr("loads.forces[0].name: the force name \"base\" is also the name of the "
                                            "boundary condition at boundary_conditions[0].name"));
}

json two_bodies(const std::string& a, const std::string& b) {
  json scene = minimal_scene();
  json second = scene["bodies"][0];
  scene["bodies"][0]["name"] = a;
  second["name"] = b;
  scene["bodies"].push_back(second);
  scene["contact"] = json::object();
  return scene;
}

TEST(SceneNames, AConditionNamedLikeContactColumns) {
  json scene = two_bodies("a", "b");
  scene["boundary_conditions"] = {{{"name", "contact.a.b"}, {"type", "fixed"}, {"nodes", {{"body", "a"}, {"all", true}}}}};
  EXPECT_THAT(parse_error(scene),
              HasSubstr("boundary_conditions[0].name: the boundary condition name \"contact.a.b\" gives reaction "
                        "columns \"contact.a.b.fx\", ... that are also the contact columns of bodies bodies[0].name "
                        "and bodies[1].name"));
  // Without contact there are no contact columns.
  scene.erase("contact");
  EXPECT_NO_THROW(parse_scene(scene, ""));
}

TEST(SceneNames, TwoPairsOfBodiesWithTheSameContactColumns) {
  json scene = two_bodies("a.b", "c");
  json more = two_bodies("a", "b.c")["bodies"];
  scene["bodies"].push_back(more[0]);
  scene["bodies"].push_back(more[1]);
  EXPECT_THAT(parse_error(scene), HasSubstr("bodies[3].name: the contact columns of bodies bodies[2].name and "
                                            "bodies[3].name (\"contact.a.b.c...\") are also those of bodies[0].name "
                                            "and bodies[1].name"));
}

TEST(SceneNames, ARigidRegionOfAMeshFileIsCheckedWhenTheProblemIsBuilt) {
  json scene = minimal_scene();
  scene["bodies"][0] = {{"name", "block"}, {"mesh", {{"file", "block.msh"}}}, {"regions", {{"*", {{"rigid", "fixed"}}}}}};
  scene["boundary_conditions"] = {condition("block/bone")};
  const SceneConfig config = parse_scene(scene, data_directory());  // the mesh's regions are not known yet
  try {
    build_problem(config);
    ADD_FAILURE() << "build_problem accepted a condition named like a rigid region";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("boundary_conditions[0].name: the boundary condition name \"block/bone\" is also "
                                    "the name of the rigid region at bodies[0].regions[\"*\"]"));
  }
}

}  // namespace
}  // namespace sinew::scene
