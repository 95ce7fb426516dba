/// @file scene_schema_definitions.cpp
/// The shared definitions of the scene schema: amplitudes, rigid motions, node selectors and shapes.

#include "sinew/scene/scene_schema_parts.hpp"

#include "sinew/fem/motion.hpp"
#include "sinew/mesh/generate.hpp"
#include "sinew/scene/scene_config.hpp"
#include "sinew/scene/schema_bounds.hpp"
#include "sinew/scene/schema_builder.hpp"
#include "sinew/surface/solid.hpp"

namespace sinew::scene::schema_parts {

using namespace schema_builder;  // NOLINT(google-build-using-namespace)
using namespace schema_bounds;   // NOLINT(google-build-using-namespace)
using nlohmann::json;

SchemaNode amplitude_definition() {
  SchemaNode pair = array("", "[lambda, factor]", number("", "lambda or factor").within(kMaxFactor)).items(2, 2);
  return array("", "Piecewise-linear factor through [lambda, factor] points, lambda strictly increasing, held "
                   "constant outside them; when omitted the factor ramps as a(lambda) = lambda",
               pair)
      .items(1);
}

SchemaNode motion_definition() {
  const fem::RigidMotion defaults;
  return object("",
                "A rigid motion reached at the end of the load (lambda = 1), scaled by its amplitude: "
                "x = R(a angle) (X - point) + point + a translation",
                {
                    vec3("translation", "final translation (length)").within(kMaxLength).fallback(vec3_json(defaults.translation)),
                    object("rotation", "final rotation about an axis through a point (none when omitted)",
                           {
                               vec3("axis", "rotation axis direction, normalized on use").required().nonzero().within(kMaxLength),
                               vec3("point", "a point on the axis (length)").within(kMaxLength).fallback(vec3_json(defaults.axis_point)),
                               number("angle_deg", "final angle (degrees, right-hand rule)").required().within(kMaxAngle),
                           }),
                    ref("amplitude", "factor a(lambda) applied to angle and translation", "amplitude"),
                    array("keyframes",
                          "poses at given load parameters or times, instead of translation, rotation and amplitude: "
                          "x = R (X - pivot) + pivot + translation, with the translation interpolated linearly and "
                          "the rotation by slerp (along the shorter arc: keep consecutive keyframes less than 180 "
                          "degrees apart); held before the first and after the last",
                          object("", "a keyframe: its place (lambda or time) and its pose",
                                 {
                                     number("lambda", "load parameter of the keyframe (static; strictly increasing)")
                                         .within(kMaxFactor),
                                     number("time", "time of the keyframe (dynamics: lambda = time / end_time)")
                                         .within(kMaxTime),
                                     vec3("translation", "translation at the keyframe (length)")
                                         .within(kMaxLength)
                                         .fallback(vec3_json(Vector3::Zero())),
                                     object("rotation", "rotation about the motion's pivot at the keyframe (none when omitted)",
                                            {
                                                vec3("axis", "rotation axis direction, normalized on use").required().nonzero().within(kMaxLength),
                                                number("angle_deg", "angle (degrees, right-hand rule)").required().within(kMaxAngle),
                                            }),
                                 }))
                        .items(1),
                    vec3("pivot", "keyframes: the point their rotations turn about (length)")
                        .within(kMaxLength)
                        .fallback(vec3_json(defaults.pivot)),
                });
}

SchemaNode node_selector_definition() {
  using Selector = NodeSelector::Kind;
  const NodeSelector defaults;
  return one_of(
      "", "Chooses nodes of one body by rest position (after the body's transform), set or region",
      {
          string("body", "body name; may be omitted when the scene has exactly one body").non_empty(),
          string(key_of(Selector::Set), "a node set of the mesh, or the nodes of the face set of that name").non_empty(),
          string(key_of(Selector::Region), "the nodes of the tets of this mesh region").non_empty(),
          object(key_of(Selector::Box), "nodes with min - padding <= X <= max + padding, componentwise",
                 {
                     vec3("min", "lower corner (length)").required().within(kMaxLength),
                     vec3("max", "upper corner (length)").required().within(kMaxLength),
                     number("padding", "tolerance added on every side (length)").min(0).max(kMaxLength).fallback(defaults.tolerance),
                 }),
          object(key_of(Selector::Plane), "nodes with |n . (X - point)| <= tolerance",
                 {
                     vec3("point", "a point of the plane (length)").required().within(kMaxLength),
                     vec3("normal", "plane normal n, normalized on use").required().nonzero().within(kMaxLength),
                     number("tolerance", "distance tolerance (length)").min(0).max(kMaxLength).fallback(defaults.tolerance),
                 }),
          boolean(key_of(Selector::All), "every node of the body").allowed({true}),
      },
      names_of<Selector>());
}

SchemaNode shape_definition() {
  using Shape = mesh::Shape::Kind;
  const mesh::Shape defaults;
  return one_of("",
                "A solid for mesh generation: a primitive or a boolean combination, optionally moved by a rigid "
                "transform",
                {
                    object(key_of(Shape::Box), "box, axis-aligned before the shape's transform",
                           {
                               vec3("min", "lower corner (length)").required().within(kMaxLength),
                               vec3("max", "upper corner, > min componentwise (length)").required().within(kMaxLength),
                           }),
                    object(key_of(Shape::Sphere), "ball",
                           {
                               vec3("center", "center (length)").required().within(kMaxLength),
                               number("radius", "radius (length)").required().above(0).max(kMaxLength),
                           }),
                    object(key_of(Shape::Cylinder), "solid cylinder",
                           {
                               vec3("base", "center of the base disk (length)").required().within(kMaxLength),
                               vec3("axis", "from the base center to the top center; its length is the height (length)")
                                   .within(kMaxLength)
                                   .required()
                                   .nonzero(),
                               number("radius", "radius (length)").required().above(0).max(kMaxLength),
                           }),
                    object(key_of(Shape::Torus),
                           "solid torus, or the segment of one swept through angle_deg (a bent rod with flat "
                           "disk ends)",
                           {
                               vec3("center", "center of the torus, on its axis (length)").required().within(kMaxLength),
                               vec3("axis",
                                    "normal of the plane of the centre circle; the sweep turns about it by the "
                                    "right-hand rule")
                                   .within(kMaxLength)
                                   .required()
                                   .nonzero(),
                               number("radius", "major radius: of the circle through the tube centres (length)")
                                   .max(kMaxLength)
                                   .required()
                                   .above(0),
                               number("minor_radius", "tube radius, < radius (length)").required().above(0).max(kMaxLength),
                               number("angle_deg", "swept angle (degrees), from start_direction about axis")
                                   .above(0)
                                   .max(360)
                                   .fallback(defaults.angle_deg),
                               vec3("start_direction",
                                    "direction from the center to the centre of the tube's first end (its part "
                                    "perpendicular to axis counts); default: +x projected onto the torus plane, or +y "
                                    "projected when the axis is along x")
                                   .within(kMaxLength)
                                   .nonzero(),
                           }),
                    array(key_of(Shape::Union), "all shapes fused", ref("", "", "shape")).items(1),
                    array(key_of(Shape::Difference), "the first shape minus all the others", ref("", "", "shape")).items(2),
                    array(key_of(Shape::Intersection), "the region common to all the shapes", ref("", "", "shape")).items(2),
                    object("transform",
                           "rigid transform of this shape, applied after it is built (and after its children's own "
                           "transforms): first rotate, then translate",
                           {
                               object("rotate", "rotation about an axis through a point (none when omitted)",
                                      {
                                          vec3("axis", "rotation axis direction, normalized on use")
                                              .within(kMaxLength)
                                              .required()
                                              .nonzero(),
                                          number("angle_deg", "angle (degrees, right-hand rule)").required().within(kMaxAngle),
                                          vec3("center", "a point on the axis (length)")
                                              .within(kMaxLength)
                                              .fallback(vec3_json(defaults.rotation_center)),
                                      }),
                               vec3("translate", "translation, applied after the rotation (length)")
                                   .within(kMaxLength)
                                   .fallback(vec3_json(defaults.translation)),
                           }),
                },
                names_of<Shape>());
}

SchemaNode solid_definition() {
  using Solid = surface::Solid::Kind;
  const surface::Solid defaults;
  SchemaNode surface_names = array("surfaces", "names of closed surfaces (keys of \"surfaces\")",
                                   string("", "a surface name").non_empty())
                                 .required()
                                 .items(1);
  return one_of(
      "",
      "A solid of a mesh made from surfaces: a closed surface, a primitive, an offset or a boolean; a point set, so "
      "crops (intersection with a half_space) and booleans are exact and the mesher makes the caps",
      {
          string(key_of(Solid::Surface), "the inside of a closed surface (a key of \"surfaces\")").non_empty(),
          object(key_of(Solid::Offset),
                 "the points within distance of the union of surfaces or inside it (distance > 0: a hull around "
                 "parts; < 0: the inside shrunk by -distance, e.g. under a skin layer)",
                 {
                     surface_names,
                     number("distance", "offset (length)").required().within(kMaxLength),
                 }),
          object(key_of(Solid::Box), "axis-aligned box",
                 {
                     vec3("min", "lower corner (length)").required().within(kMaxLength),
                     vec3("max", "upper corner, > min componentwise (length)").required().within(kMaxLength),
                 }),
          object(key_of(Solid::Capsule), "the points within radius of the segment a-b (a rod with round ends)",
                 {
                     vec3("a", "one end of the axis (length)").required().within(kMaxLength),
                     vec3("b", "the other end (length)").required().within(kMaxLength),
                     number("radius", "radius (length)").required().above(0).max(kMaxLength),
                 }),
          object(key_of(Solid::Ellipsoid), "ellipsoid with semi-axes along axis_u, axis_v and axis_u x axis_v",
                 {
                     vec3("center", "centre (length)").required().within(kMaxLength),
                     vec3("semi_axes", "semi-axis lengths (length)").required().within(kMaxLength),
                     vec3("axis_u", "first axis").nonzero().within(kMaxLength).fallback(vec3_json(defaults.axis_u)),
                     vec3("axis_v", "second axis (made orthogonal to axis_u)").nonzero().within(kMaxLength).fallback(vec3_json(defaults.axis_v)),
                 }),
          object(key_of(Solid::HalfSpace), "the points x with (x - point) . normal <= 0: intersect with it to crop",
                 {
                     vec3("point", "a point of the plane (length)").required().within(kMaxLength),
                     vec3("normal", "outward normal of the kept side").required().nonzero().within(kMaxLength),
                 }),
          array(key_of(Solid::Union), "in any of the solids", ref("", "", "solid")).items(1),
          array(key_of(Solid::Difference), "in the first solid and in none of the others", ref("", "", "solid")).items(2),
          array(key_of(Solid::Intersection), "in all of the solids", ref("", "", "solid")).items(2),
      },
      names_of<Solid>());
}

}  // namespace sinew::scene::schema_parts
