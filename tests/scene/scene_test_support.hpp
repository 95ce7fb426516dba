#pragma once
/// @file scene_test_support.hpp
/// Helpers shared by the scene tests: fixture paths, a minimal valid scene, error capture (and
/// TempDir, from support/temp_dir.hpp).

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "sinew/core/error.hpp"
#include "sinew/scene/load_scene.hpp"
#include "sinew/scene/scene_schema.hpp"
#include "support/temp_dir.hpp"

namespace sinew::scene::testing {

using sinew::testing::TempDir;

/// The scene schema's node at a dotted path of object keys ("solver.newton.max_iterations");
/// Map and Array steps are written "[]" ("bodies.[].regions.[].density"); variant keys are
/// searched too. Throws std::runtime_error for a path the schema does not have.
inline const SchemaNode& schema_node_at(const std::string& path) {
  const SchemaNode* node = &scene_schema().root;
  std::istringstream steps(path);
  std::string step;
  while (std::getline(steps, step, '.')) {
    while (node->type == SchemaType::Ref) node = &scene_schema().definitions.at(node->ref);
    if (step == "[]") {
      node = &node->items.at(0);
      continue;
    }
    const SchemaNode* next = nullptr;
    for (const SchemaNode& property : node->properties) {
      if (property.key == step) next = &property;
    }
    for (const SchemaVariant& variant : node->variants) {
      for (const SchemaNode& property : variant.properties) {
        if (property.key == step) next = &property;
      }
    }
    if (next == nullptr) throw std::runtime_error("no schema key " + path);
    node = next;
  }
  return *node;
}

inline std::string data_directory() { return std::string(SINEW_SOURCE_DIR) + "/tests/scene/data"; }

/// One body (a generated unit cube of neo-Hookean gel), nothing else: every other key defaults.
inline nlohmann::json minimal_scene() {
  return nlohmann::json::parse(R"({
    "units": "m, N, Pa, s",
    "materials": {"gel": {"law": "neo-hookean", "mu": 1.0, "lambda": 10.0}},
    "bodies": [{"name": "cube",
                "mesh": {"generate": {"element_size": 0.5,
                                      "parts": [{"region": "cube", "shape": {"box": {"min": [0, 0, 0], "max": [1, 1, 1]}}}]}},
                "regions": {"*": {"material": "gel"}}}]
  })");
}

/// The InputError message parse_scene throws for `scene`; an empty string (and a test failure)
/// when it does not throw.
inline std::string parse_error(const nlohmann::json& scene, const std::string& base_directory = data_directory()) {
  try {
    parse_scene(scene, base_directory);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "parse_scene accepted an invalid scene: " << scene.dump();
  return "";
}

/// The InputError message load_scene_file throws for the file `path`; an empty string (and a
/// test failure) when it does not throw.
inline std::string load_error(const std::string& path) {
  try {
    load_scene_file(path);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "load_scene_file accepted " << path;
  return "";
}

}  // namespace sinew::scene::testing
