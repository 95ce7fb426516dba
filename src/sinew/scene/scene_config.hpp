#pragma once
/// @file scene_config.hpp
/// A scene as plain config structs, the result of parsing and validating a JSON scene
/// (see docs/scene-reference.md, generated from the schema in scene_schema.cpp).

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sinew/contact/contact_energy.hpp"
#include "sinew/contact/contact_enforcement.hpp"
#include "sinew/fem/constraints_config.hpp"
#include "sinew/material/material_spec.hpp"
#include "sinew/mesh/generate.hpp"
#include "sinew/fem/mass_matrix.hpp"
#include "sinew/solver/solver_config.hpp"
#include "sinew/surface/repair_surface.hpp"
#include "sinew/surface/tetrahedralize.hpp"

namespace sinew::scene {

/// One mesh of a surface file, placed in the scene: x = unit_scale x_file + translate.
struct SurfaceFileConfig {
  std::string file;        ///< as written: relative paths resolve against SceneConfig::data_directory
  std::string mesh_name;   ///< empty = the file's only mesh
  double unit_scale = 1;
  Vector3 translate = Vector3::Zero();
  std::optional<surface::RepairOptions> repair;  ///< none = used as read
  std::string source;      ///< where a user gets the file (for the missing-file message)
};

/// A mesh of regions bounded by closed surfaces (docs/surface-input.md).
struct SurfaceMeshConfig {
  std::map<std::string, SurfaceFileConfig> surfaces;  ///< by name
  std::vector<surface::SolidPart> parts;
  surface::TetrahedralizeOptions options;
};

/// A body's mesh: a Gmsh file, generated parts or surface parts, then an optional rigid placement.
struct MeshSourceConfig {
  std::string file;                 ///< absolute, or resolved against the scene's directory
  std::vector<mesh::Part> parts;    ///< when file is empty
  mesh::GenerateOptions generate;
  std::optional<SurfaceMeshConfig> surfaces;  ///< when set, the mesh is made from surfaces
  Vector3 translate = Vector3::Zero();  ///< applied after rotate
  Vector3 rotate_axis = Vector3::UnitZ();
  double rotate_angle = 0;              ///< radians, about rotate_axis through the origin
  /// The completed JSON of the `generate` or `surfaces` section (keys sorted): what, with the
  /// element size in force and the surface files' bytes, identifies a generated mesh in the
  /// mesh cache (mesh_cache.hpp). Empty for a mesh file.
  std::string cache_key;
};

/// What a region of a body is made of.
struct RegionConfig {
  std::string material;   ///< key into SceneConfig::materials; empty when rigid
  bool rigid = false;
  fem::RigidBody::Kind rigid_kind = fem::RigidBody::Kind::Fixed;
  fem::RigidMotion rigid_motion;          ///< when rigid_kind == Prescribed
  double density = 0;                      ///< mass per volume
  std::optional<Vector3> fiber_direction;  ///< overrides the material's fiber direction
  /// Fibers along a polyline (>= 2 points, length): each tet's fiber direction is that of the
  /// path segment nearest its rest centroid, a per-element field. Empty = none.
  std::vector<Vector3> fiber_path;
  /// Factor on the contact penalty of this region's surface and tets; a pair of parts uses the
  /// smaller of their two factors (see contact::ContactGeometry).
  double contact_penalty_scale = 1;
};

/// Chooses nodes of one body.
struct NodeSelector {
  enum class Kind { Set, Region, Box, Plane, All };
  Kind kind = Kind::All;
  std::string body;   ///< body name (may be omitted in JSON when the scene has one body)
  std::string name;   ///< Set: node/face set name; Region: region name
  Vector3 box_min = Vector3::Zero(), box_max = Vector3::Zero();  ///< Box, inclusive
  Vector3 point = Vector3::Zero(), normal = Vector3::UnitZ();    ///< Plane
  double tolerance = 1e-9;  ///< Plane: |n.(X-p)| <= tolerance; Box: padding (length)
};

/// Scene names of NodeSelector::Kind (the keys of a node selector).
inline constexpr NameTable<NodeSelector::Kind, 5> kNodeSelectorKindNames{{
    {NodeSelector::Kind::Set, "set"},
    {NodeSelector::Kind::Region, "region"},
    {NodeSelector::Kind::Box, "box"},
    {NodeSelector::Kind::Plane, "plane"},
    {NodeSelector::Kind::All, "all"},
}};
constexpr const auto& enum_names(NodeSelector::Kind) { return kNodeSelectorKindNames; }

/// How a body takes part in contact.
struct BodyContactConfig {
  /// Which boundary faces are the zero-depth surface from which material depth is measured.
  enum class DepthSurface { Boundary, FaceSet, Region, Nodes };
  DepthSurface depth_surface = DepthSurface::Boundary;
  std::string depth_surface_name;  ///< FaceSet: face set name; Region: region name
  /// Nodes: boundary faces whose three nodes are all chosen by one of these selectors.
  std::vector<NodeSelector> depth_nodes;
  std::string depth_file;          ///< nodal depths (one per node of the body's mesh), overrides the above
  /// Nodal depths from this node field of the body's mesh file (TetMesh::node_fields), overrides
  /// the surface options above; at most one of depth_file and depth_field is set.
  std::string depth_field;
  /// Boundary faces whose three nodes are all chosen by one of these selectors are not a surface
  /// of the real object (e.g. where the model was cut by a plane): they are left out of the
  /// contact surface (no contact integral over them) and out of the zero-depth surface. The
  /// body's tets behind them can still be penetrated.
  std::vector<NodeSelector> exclude_faces;
};

struct BodyConfig {
  std::string name;
  MeshSourceConfig mesh;
  BodyContactConfig contact;
  /// Region name -> config. A mesh region without an entry uses the entry named "*" if any.
  std::map<std::string, RegionConfig> regions;
};

struct BoundaryConditionConfig {
  enum class Kind { Fixed, Prescribed, Planar };
  std::string name;
  Kind kind = Kind::Fixed;
  NodeSelector nodes;
  fem::RigidMotion motion;            ///< Prescribed
  Vector3 normal = Vector3::UnitZ();   ///< Planar
  double displacement = 0;            ///< Planar: final normal displacement
  fem::Amplitude amplitude;           ///< Planar
};

/// Scene names of BoundaryConditionConfig::Kind (the "type" of a boundary condition).
inline constexpr NameTable<BoundaryConditionConfig::Kind, 3> kBoundaryConditionKindNames{{
    {BoundaryConditionConfig::Kind::Fixed, "fixed"},
    {BoundaryConditionConfig::Kind::Prescribed, "prescribed"},
    {BoundaryConditionConfig::Kind::Planar, "planar"},
}};
constexpr const auto& enum_names(BoundaryConditionConfig::Kind) { return kBoundaryConditionKindNames; }

/// A dead load on a node set: a total force in equal nodal shares, or a traction (force per
/// rest area) over the boundary faces whose three nodes are all selected.
struct ForceConfig {
  std::string name;
  NodeSelector nodes;
  Vector3 total_force = Vector3::Zero();  ///< force; unused when `traction` is given
  std::optional<Vector3> traction;        ///< force / length^2 on the rest area
  fem::Amplitude amplitude;
};

struct LoadsConfig {
  Vector3 gravity = Vector3::Zero();
  std::vector<ForceConfig> forces;
};

/// Penalty between two named bodies (or of one body with itself).
struct ContactPairConfig {
  std::string body_a, body_b;
  std::optional<double> penalty;  ///< force / length^3; absent: the automatic default
  std::optional<double> friction;  ///< Coulomb coefficient of this pair; absent: ContactConfig's
  bool enabled = true;
};

/// Coulomb friction on the contact (contact/friction.hpp).
struct FrictionConfig {
  double coefficient = 0;                 ///< μ of every pair without its own (0: frictionless)
  std::optional<double> slip_threshold;   ///< length; absent: 1e-3 of the mean contact-surface edge
  /// length / time, dynamics only: the slip threshold of each time step is this times its size
  /// (excludes slip_threshold).
  std::optional<double> slip_velocity_threshold;
  int max_updates = 5;                    ///< lag refreshes per step at most
  double tolerance = 0.01;                ///< relative change of the total normal force that ends them
};

/// Material-depth contact between all bodies (docs/theory.md).
struct ContactConfig {
  bool enabled = false;  ///< true when the scene has a "contact" section
  contact::ContactMethod method = contact::ContactMethod::Area;
  contact::PairHessian hessian = contact::ContactOptions{}.hessian;
  std::optional<double> penalty;  ///< global penalty (force / length^3); absent: automatic
  /// Automatic penalty: penalty_scale * E / h, E the smaller initial Young's modulus of the two
  /// bodies, h the smaller mean surface edge length (a 10 % strain then penetrates ~h/100·10/scale).
  double penalty_scale = 10;
  bool self_contact = true;
  std::vector<ContactPairConfig> pairs;
  /// Penetration control beyond the plain penalty (contact_enforcement.hpp). Its
  /// penetration_tolerance is absolute (length) when given as such; a relative tolerance is
  /// kept in relative_penetration_tolerance and resolved against the mean contact-surface edge
  /// when the model is built.
  contact::ContactEnforcementOptions enforcement;
  std::optional<double> relative_penetration_tolerance;  ///< fraction of the mean surface edge
  FrictionConfig friction;
};

/// Time integration instead of load stepping (absent: a static analysis).
struct DynamicsConfig {
  bool enabled = false;
  solver::DynamicOptions options;
  fem::MassKind mass = fem::MassKind::Lumped;  ///< explicit always uses the lumped mass
  /// Rayleigh viscosity D = mass_damping M + stiffness_damping K0 (K0 the elastic stiffness at
  /// rest): mass_damping in 1/time, stiffness_damping in time.
  double mass_damping = 0;
  double stiffness_damping = 0;
};

struct OutputConfig {
  bool vtu = true;        ///< write a .vtu per output step and a .pvd series
  int every = 1;          ///< write every n-th increment (the last one always)
  /// Write checkpoint.cbor after every n-th accepted load step (static) or output interval
  /// (dynamic, implicit), and at the end; 0: only at the end and on an interrupt.
  int checkpoint_every = 1;
};

/// Limits on what a scene may ask of the machine. Not read from the scene file: the command line
/// sets them (a scene cannot lift its own limits).
struct ResourceLimits {
  /// Largest estimated tet count of one generated body (resource_estimate.hpp): about 6 GB of
  /// memory at the default; the examples need at most ~1e5 (knee at 9 mm: ~37k tets).
  double max_tets = 3e6;
};

struct SceneConfig {
  std::string name;
  std::string description;
  std::string units;            ///< free text, e.g. "mm, N, MPa, s" (documentation only)
  std::string base_directory;   ///< directory of the scene file (relative paths resolve here)
  /// Directory of surface files: the scene's data_dir resolved against base_directory (or the
  /// command line's --data-dir); empty = base_directory.
  std::string data_directory;
  /// Output directory of the finished run this scene starts from (docs/stages.md), resolved
  /// against base_directory; empty = the rest state.
  std::string initial_state;
  std::map<std::string, material::MaterialSpec> materials;
  std::vector<BodyConfig> bodies;
  std::vector<BoundaryConditionConfig> boundary_conditions;
  LoadsConfig loads;
  ContactConfig contact;
  solver::StaticSolverOptions solver;
  DynamicsConfig dynamics;
  OutputConfig output;
  ResourceLimits limits;  ///< set by the command line, not the scene file
  /// Directory of the mesh cache (mesh_cache.hpp, docs/mesh-cache.md); empty = no cache. Set by
  /// the command line, not the scene file.
  std::string mesh_cache_directory;
};

}  // namespace sinew::scene
