/// @file scene_schema_body.cpp
/// The scene schema of a body: its mesh, placement, regions and material depth.

#include "sinew/scene/scene_schema_parts.hpp"

#include "sinew/mesh/generate.hpp"
#include "sinew/scene/scene_config.hpp"
#include "sinew/scene/schema_bounds.hpp"
#include "sinew/scene/schema_builder.hpp"
#include "sinew/surface/repair_surface.hpp"
#include "sinew/surface/tetrahedralize.hpp"

namespace sinew::scene::schema_parts {

using namespace schema_builder;  // NOLINT(google-build-using-namespace)
using namespace schema_bounds;   // NOLINT(google-build-using-namespace)
using nlohmann::json;

namespace {

SchemaNode surfaces_mesh_schema() {
  const surface::TetrahedralizeOptions defaults;
  const surface::SizeZone zone_defaults;
  const surface::RepairOptions repair_defaults;
  return object(
      "surfaces",
      "mesh regions bounded by closed triangle surfaces (STL, OBJ, PLY, glTF/GLB) with CGAL Mesh_3: one "
      "conforming mesh, one region per part (docs/surface-input.md)",
      {
          number("element_size", "target tet edge length away from size zones (length)").required().min(kMinElementSize).max(kMaxLength),
          number("facet_distance",
                 "largest distance between a boundary triangle and the surface it approximates (length); 0 = "
                 "element_size / 20")
              .min(0)
              .max(kMaxLength)
              .fallback(defaults.facet_distance),
          number("min_dihedral_deg",
                 "fail when a tet's smallest dihedral angle stays below this after sliver removal (degrees); 0 = "
                 "report only")
              .min(0)
              .max(60)
              .fallback(defaults.min_dihedral_deg),
          map("surfaces", "surface name -> where it comes from",
              object("", "one mesh of a surface file, placed in the scene",
                     {
                         string("file",
                                "surface file; relative paths start at the scene's data_dir (or the scene file's "
                                "directory)")
                             .required()
                             .non_empty(),
                         string("mesh", "the named mesh of a file with several (glTF); omit for a file with one").non_empty(),
                         number("unit_scale", "file units -> scene units (1000 for a file in m and a scene in mm)")
                             .above(0)
                             .max(kMaxScale)
                             .fallback(1.0),
                         vec3("translate", "translation after the scale (length)").within(kMaxLength).fallback(vec3_json(Vector3::Zero())),
                         object("repair", "repair before use",
                                {
                                    boolean("drop_degenerate", "drop triangles of zero area").fallback(repair_defaults.drop_degenerate),
                                    boolean("drop_duplicates", "drop repeated triangles").fallback(repair_defaults.drop_duplicates),
                                    boolean("fill_holes", "close every hole with a refined patch").fallback(repair_defaults.fill_holes),
                                    number("remesh_edge_length",
                                           "> 0: remesh the triangles isotropically toward this edge length, after "
                                           "the holes are filled (fewer triangles make meshing faster); 0 keeps them (length)")
                                        .min(0)
                                        .max(kMaxLength)
                                        .fallback(repair_defaults.remesh_edge_length),
                                }),
                         string("source", "where a user gets the file, printed when it is missing").non_empty(),
                     }))
              .required()
              .items(1),
          array("parts",
                "named solids, each a region of one conforming mesh; where they overlap, the first listed wins; each "
                "region's boundary is also the face set \"<region>.surface\"",
                object("", "a named solid",
                       {
                           string("region", "region name of this part").required().non_empty(),
                           ref("solid", "its solid", "solid").required(),
                       }))
              .required()
              .items(1),
          array("size_zones",
                "finer elements near some surfaces or in a capsule: size + grading x distance, up to element_size",
                object("", "a size zone: surfaces, a capsule, or both",
                       {
                           array("surfaces", "surface names", string("", "a surface name").non_empty()).items(1),
                           object("capsule", "the points within radius of the segment a-b (distance 0 inside)",
                                  {
                                      vec3("a", "one end of the axis (length)").required().within(kMaxLength),
                                      vec3("b", "the other end (length)").required().within(kMaxLength),
                                      number("radius", "radius (length)").required().above(0).max(kMaxLength),
                                  }),
                           number("size", "element size on those surfaces and in the capsule (length)").required().min(kMinElementSize).max(kMaxLength),
                           number("grading", "growth of the size per unit distance (dimensionless)")
                               .min(0)
                               .max(100)
                               .fallback(zone_defaults.grading),
                       }))
              .fallback(json::array()),
      });
}

}  // namespace

SchemaNode body_schema() {
  using Rigid = fem::RigidBody::Kind;
  const MeshSourceConfig mesh_defaults;
  const mesh::GenerateOptions generate_defaults;
  const RegionConfig region_defaults;
  return object(
      "", "A solid body: its mesh, placement and what each mesh region is made of",
      {
          string("name", "unique body name; regions and sets are called \"<body>/<name>\" in outputs")
              .required()
              .non_empty(),
          one_of("mesh", "where the tetrahedral mesh comes from",
                 {
                     string("file", "Gmsh .msh file (format 2 or 4); relative paths start at the scene file's directory")
                         .non_empty(),
                     object("generate", "mesh primitive solids with Gmsh (OpenCASCADE)",
                            {
                                number("element_size", "target tet edge length (length)").required().min(kMinElementSize).max(kMaxLength),
                                integer("optimize_passes", "Gmsh tet optimization passes")
                                    .min(0)
                                    .max(100)
                                    .fallback(generate_defaults.optimize_passes),
                                number("elements_per_turn",
                                       "curved surfaces get at least this many elements per full turn, down to "
                                       "element_size / 10 (thin rods: lower it); 0 = element_size alone")
                                    .min(0)
                                    .max(1000)
                                    .fallback(generate_defaults.elements_per_turn),
                                array("parts",
                                      "named solids, each a region; fragmented into one conforming mesh (where they "
                                      "overlap, the first listed wins); each part's boundary is also the face set "
                                      "\"<region>.surface\"",
                                      object("", "a named solid",
                                             {
                                                 string("region", "region name of this part").required().non_empty(),
                                                 ref("shape", "its solid", "shape").required(),
                                             }))
                                    .required()
                                    .items(1),
                            }),
                     surfaces_mesh_schema(),
                 },
                 {"file", "generate", "surfaces"})
              .required(),
          object("transform", "rigid placement of the mesh: rotate about the origin, then translate",
                 {
                     vec3("translate", "translation (length)").within(kMaxLength).fallback(vec3_json(mesh_defaults.translate)),
                     object("rotate", "rotation about an axis through the origin",
                            {
                                vec3("axis", "rotation axis").nonzero().within(kMaxLength).fallback(vec3_json(mesh_defaults.rotate_axis)),
                                number("angle_deg", "angle (degrees, right-hand rule)").within(kMaxAngle).fallback(mesh_defaults.rotate_angle),
                            })
                         .fallback(json::object()),
                 })
              .fallback(json::object()),
          map("regions",
              "mesh region name -> what it is made of; the entry \"*\" applies to every mesh region without its own "
              "entry",
              object("", "a deformable region (\"material\") or a rigid one (\"rigid\")",
                     {
                         string("material", "name of a material (a key of \"materials\"); omit for rigid regions")
                             .non_empty(),
                         either("rigid",
                                "the region moves as one rigid body: \"fixed\" (stays in place), \"free\" (moved by "
                                "contact and loads) or {\"prescribed\": motion}",
                                {
                                    string("", "fixed or free").allowed({key_of(Rigid::Fixed), key_of(Rigid::Free)}),
                                    one_of("", "a prescribed rigid motion",
                                           {ref(key_of(Rigid::Prescribed), "the motion", "motion")},
                                           {key_of(Rigid::Prescribed)}),
                                }),
                         number("density", "mass per rest volume (mass / length^3)")
                             .max(kMaxPhysical)
                             .min(0)
                             .fallback(region_defaults.density),
                         vec3("fiber_direction", "overrides the material's fiber direction in this region").nonzero().within(kMaxLength),
                         array("fiber_path",
                               "fibers along a polyline instead (points, length): each element's fiber direction is "
                               "that of the path segment nearest its centroid, a per-element field that follows a "
                               "muscle's curved line of action",
                               vec3("", "a point of the path (length)").within(kMaxLength))
                             .items(2),
                         number("contact_penalty_scale",
                                "factor on the contact penalty where this region's surface or tets take part; two "
                                "parts in contact use the smaller of their factors, so stiff parts (e.g. two rigid "
                                "bones) can meet with a stiffer penalty than soft tissue against either")
                             .max(kMaxScale)
                             .above(0)
                             .fallback(region_defaults.contact_penalty_scale),
                     }))
              .required()
              .items(1),
          object("contact",
                 "how this body's material depth is defined (used when the scene has a \"contact\" section); by "
                 "default the depth of a node is its rest distance to the body's whole boundary",
                 {
                     string("depth_face_set",
                            "measure depth from this face set only (a mesh face set of the body, or "
                            "\"<region>.surface\" of a generated part)")
                         .non_empty(),
                     string("depth_region",
                            "measure depth from the boundary faces of the tets of this region only")
                         .non_empty(),
                     array("depth_nodes",
                           "measure depth from the boundary faces whose three nodes are all chosen by one of these "
                           "selectors (e.g. a plane: only the face that touches; symmetry planes and free sides then "
                           "do not count); a plane chooses only faces that lie in it (normal within 30 degrees of "
                           "the plane's)",
                           ref("", "a node selector (its \"body\" is this body)", "node_selector"))
                         .items(1),
                     array("exclude_faces",
                           "boundary faces whose three nodes are all chosen by one of these selectors are not a "
                           "surface of the real object, e.g. where the model was cut by a plane: they take no part in "
                           "contact (no contact integral over them) and are not zero-depth surface; the tets behind "
                           "them can still be penetrated; a plane chooses only faces that lie in it (normal within 30 "
                           "degrees of the plane's), not the side walls that meet it (docs/contact.md)",
                           ref("", "a node selector (its \"body\" is this body)", "node_selector"))
                         .items(1),
                     string("depth_file",
                            "nodal depths instead (text: one number per node of the body's mesh, in mesh order; "
                            "relative paths start at the scene file's directory)")
                         .non_empty(),
                     string("depth_field",
                            "nodal depths instead, from this node field of the body's mesh file (a Gmsh "
                            "$NodeData view of this name: one scalar per node, its first time step; every "
                            "node of the mesh needs a finite value >= 0)")
                         .non_empty(),
                 })
              .fallback(json::object()),
      });
}

}  // namespace sinew::scene::schema_parts
