/// @file scene_schema_loads.cpp
/// The scene schema of boundary conditions and loads.

#include "sinew/scene/scene_schema_parts.hpp"

#include "sinew/scene/scene_config.hpp"
#include "sinew/scene/schema_bounds.hpp"
#include "sinew/scene/schema_builder.hpp"

namespace sinew::scene::schema_parts {

using namespace schema_builder;  // NOLINT(google-build-using-namespace)
using namespace schema_bounds;   // NOLINT(google-build-using-namespace)
using nlohmann::json;

SchemaNode boundary_condition_schema() {
  using Kind = BoundaryConditionConfig::Kind;
  const BoundaryConditionConfig defaults;
  Key bc = object("", "Constrains the motion of nodes",
                  {
                      string("name", "unique name, used in logs and reaction-force outputs").required().non_empty(),
                      string("type", "kind of constraint").required().allowed(allowed_names<Kind>()),
                      ref("nodes", "the constrained nodes", "node_selector").required(),
                  });
  bc.node.tag_key = "type";
  bc.node.variants = {
      {key_of(Kind::Fixed), "the nodes stay at their rest positions", {}},
      {key_of(Kind::Prescribed), "the nodes follow a rigid motion", {ref("motion", "the prescribed motion", "motion").required()}},
      {key_of(Kind::Planar),
       "the nodes move only in a plane: n . (x - X) = displacement * amplitude(lambda)",
       {
           vec3("normal", "plane normal n, normalized on use").required().nonzero().within(kMaxLength),
           number("displacement", "final displacement along n (length)").within(kMaxLength).fallback(defaults.displacement),
           ref("amplitude", "factor applied to the displacement", "amplitude"),
       }},
  };
  return bc;
}

SchemaNode loads_schema() {
  const LoadsConfig defaults;
  return object("loads", "external loads",
                {
                    vec3("gravity", "gravitational acceleration (length / time^2)").within(kMaxPhysical).fallback(vec3_json(defaults.gravity)),
                    array("forces", "dead loads: a total force spread equally over a node set, or a traction over the boundary faces it covers",
                          object("", "a force",
                                 {
                                     string("name", "name, used in logs").required().non_empty(),
                                     ref("nodes", "the loaded nodes", "node_selector").required(),
                                     vec3("total_force", "total force over all selected nodes, in equal shares (force); give this or traction").within(kMaxPhysical),
                                     vec3("traction", "force per rest area on the boundary faces whose three nodes are all selected, each node taking a third of each face's force (force / length^2); give this or total_force").within(kMaxPhysical),
                                     ref("amplitude", "factor applied to the force", "amplitude"),
                                 }))
                        .fallback(json::array()),
                })
      .fallback(json::object());
}

}  // namespace sinew::scene::schema_parts
