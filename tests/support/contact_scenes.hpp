#pragma once
/// @file contact_scenes.hpp
/// Small contact scenes as JSON, shared by the scene and model tests.

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

}  // namespace sinew::testing
