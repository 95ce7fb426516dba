/// @file scene_schema.cpp
/// The scene schema: every key of a scene file, its type, default, range and meaning,
/// assembled from its parts (scene_schema_parts.hpp).

#include "sinew/scene/scene_schema.hpp"

#include "sinew/scene/scene_schema_parts.hpp"
#include "sinew/scene/schema_builder.hpp"

namespace sinew::scene {

using nlohmann::json;

namespace {

using namespace schema_builder;  // NOLINT(google-build-using-namespace)
using namespace schema_parts;    // NOLINT(google-build-using-namespace)

Schema build_scene_schema() {
  Schema schema;
  schema.title = "sinew scene";
  schema.root = object("", "A scene: materials, bodies, boundary conditions, loads, solver and output settings",
                       {
                           string("name", "scene name, for logs and outputs").fallback(""),
                           string("description", "free text").free_text().fallback(""),
                           string("units",
                                  "the consistent unit system, e.g. \"mm, N, MPa, s\" (documentation only: sinew "
                                  "converts nothing)")
                               .required()
                               .non_empty(),
                           string("data_dir",
                                  "directory of surface files (relative: to the scene file's directory); the command "
                                  "line's --data-dir replaces it")
                               .non_empty(),
                           string("initial_state",
                                  "output directory (relative: to the scene file's directory) of a finished run of "
                                  "the same meshes this scene starts from: its final positions, rigid-body poses "
                                  "and, between dynamic runs with inertia, velocities; motions, planar constraints "
                                  "and fixed parts start from there, the rest state stays the meshes' "
                                  "(docs/stages.md)")
                               .non_empty(),
                           map("materials", "material name -> law and parameters", material_schema())
                               .fallback(json::object()),
                           array("bodies", "the solids", body_schema()).required().items(1),
                           array("boundary_conditions", "constraints on nodes", boundary_condition_schema())
                               .fallback(json::array()),
                           loads_schema(),
                           contact_schema(),
                           solver_schema(),
                           dynamics_schema(),
                           output_schema(),
                       });
  schema.definitions["node_selector"] = node_selector_definition();
  schema.definitions["motion"] = motion_definition();
  schema.definitions["amplitude"] = amplitude_definition();
  schema.definitions["shape"] = shape_definition();
  schema.definitions["solid"] = solid_definition();
  return schema;
}

}  // namespace

const Schema& scene_schema() {
  static const Schema schema = build_scene_schema();
  return schema;
}

json scene_json_schema() { return to_json_schema(scene_schema()); }

}  // namespace sinew::scene
