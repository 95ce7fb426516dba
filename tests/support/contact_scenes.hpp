#pragma once
/// @file contact_scenes.hpp
/// Small contact scenes as JSON, shared by the scene and model tests.

#include <vector>

#include <nlohmann/json.hpp>

namespace sinew::testing {

/// A soft neo-Hookean box [0,1]^2 x [0,0.5] (mu 1, lambda 10; element size 0.25) and a fixed
/// rigid plate [-1,2]^2 x [-1,0] below it, with a default contact section. Units m, N, Pa.
inline nlohmann::json box_on_plate_scene() {
  return nlohmann::json::parse(R"({
    "units": "m, N, Pa",
    "materials": {"gel": {"law": "neo-hookean", "mu": 1.0, "lambda": 10.0}},
    "bodies": [
      {"name": "box",
       "mesh": {"generate": {"element_size": 0.25, "parts": [
         {"region": "gel", "shape": {"box": {"min": [0, 0, 0], "max": [1, 1, 0.5]}}}]}},
       "regions": {"gel": {"material": "gel"}}},
      {"name": "plate",
       "mesh": {"generate": {"element_size": 0.5, "parts": [
         {"region": "plate", "shape": {"box": {"min": [-1, -1, -1], "max": [2, 2, 0]}}}]}},
       "regions": {"plate": {"rigid": "fixed"}}}
    ],
    "contact": {}
  })");
}

/// box_on_plate_scene with the box's top pushed down by `push` on rollers (its x = 0 and y = 0
/// faces held in their planes): contact with the plate holds its bottom up.
inline nlohmann::json pressed_box_on_plate_scene(double push = 0.02) {
  nlohmann::json scene = box_on_plate_scene();
  auto plane = [](const char* name, std::vector<double> point, std::vector<double> normal, double displacement) {
    return nlohmann::json{{"name", name},
                          {"type", "planar"},
                          {"nodes", {{"body", "box"}, {"plane", {{"point", point}, {"normal", normal}, {"tolerance", 1e-6}}}}},
                          {"normal", normal},
                          {"displacement", displacement}};
  };
  scene["boundary_conditions"] = {plane("top", {0, 0, 0.5}, {0, 0, 1}, -push), plane("x0", {0, 0, 0}, {1, 0, 0}, 0),
                                  plane("y0", {0, 0, 0}, {0, 1, 0}, 0)};
  return scene;
}

}  // namespace sinew::testing
