/// @file test_coplanar_solve.cpp
/// Newton on coplanar contact faces (docs/contact.md, "Faces in one plane"): two slabs side by
/// side whose ends lie in one cut plane, pressed into each other, with the cut faces kept out of
/// contact (exclude_faces); and the same with the cut faces as contact and zero-depth surface
/// (the default). Both converge in every load step.

#include <gtest/gtest.h>

#include <iostream>

#include "sinew/model/solve_model.hpp"
#include "sinew/scene/load_scene.hpp"

namespace sinew::model {
namespace {

using nlohmann::json;

/// Slabs [-1, 0] and [0, 1] in x, [0, 1] in y, [-1, 0] in z: touching face to face at x = 0 with
/// zero gap, both ending in the cut plane z = 0 (held there by a planar condition, free in x and
/// y); the left slab's far side is pushed 0.05 to the right, the right one's held.
json side_by_side_scene(bool exclude_cut) {
  json scene = json::parse(R"({
    "name": "coplanar-slabs", "description": "two slabs side by side, cut by the plane z = 0", "units": "mm, N, MPa",
    "materials": {"soft": {"law": "neo-hookean", "mu": 0.4, "lambda": 0.6}},
    "bodies": [
      {"name": "left", "mesh": {"generate": {"element_size": 0.4,
         "parts": [{"region": "left", "shape": {"box": {"min": [-1, 0, -1], "max": [0, 1, 0]}}}]}},
       "regions": {"left": {"material": "soft"}}},
      {"name": "right", "mesh": {"generate": {"element_size": 0.3,
         "parts": [{"region": "right", "shape": {"box": {"min": [0, 0, -1], "max": [1, 1, 0]}}}]}},
       "regions": {"right": {"material": "soft"}}}
    ],
    "boundary_conditions": [
      {"name": "push", "type": "planar", "nodes": {"body": "left", "plane": {"point": [-1, 0, 0], "normal": [1, 0, 0]}},
       "normal": [1, 0, 0], "displacement": 0.05},
      {"name": "hold", "type": "planar", "nodes": {"body": "right", "plane": {"point": [1, 0, 0], "normal": [1, 0, 0]}},
       "normal": [1, 0, 0], "displacement": 0},
      {"name": "left_cut", "type": "planar", "nodes": {"body": "left", "plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}},
       "normal": [0, 0, 1], "displacement": 0},
      {"name": "right_cut", "type": "planar", "nodes": {"body": "right", "plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}},
       "normal": [0, 0, 1], "displacement": 0},
      {"name": "left_y", "type": "planar", "nodes": {"body": "left", "plane": {"point": [0, 0, 0], "normal": [0, 1, 0]}},
       "normal": [0, 1, 0], "displacement": 0},
      {"name": "right_y", "type": "planar", "nodes": {"body": "right", "plane": {"point": [0, 0, 0], "normal": [0, 1, 0]}},
       "normal": [0, 1, 0], "displacement": 0}
    ],
    "contact": {},
    "solver": {"increments": 2},
    "output": {"vtu": false}
  })");
  if (exclude_cut)
    for (auto& body : scene["bodies"])
      body["contact"] = json::parse(R"({"exclude_faces": [{"plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}}]})");
  return scene;
}

TEST(CoplanarSolve, SlabsSideBySideInOneCutPlaneConverge) {
  for (const bool exclude : {true, false}) {
    SCOPED_TRACE(exclude ? "cut faces excluded" : "cut faces in contact");
    Model model = build_model(scene::parse_scene(side_by_side_scene(exclude), ""));
    const solver::StepperResult result = solve_model(model);
    std::cout << "[coplanar slabs] " << (exclude ? "cut excluded" : "cut in contact") << ": " << result.steps
              << " steps, " << result.newton_iterations << " Newton iterations, " << result.cuts << " cuts\n";
    EXPECT_TRUE(result.success) << result.message;
    EXPECT_EQ(result.cuts, 0);
    EXPECT_LE(result.newton_iterations, 40);
  }
}

}  // namespace
}  // namespace sinew::model
