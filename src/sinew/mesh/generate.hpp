#pragma once
/// @file generate.hpp
/// Meshes from primitive solids through Gmsh's OpenCASCADE kernel.

#include <memory>
#include <string>
#include <vector>

#include "sinew/core/enum_names.hpp"
#include "sinew/mesh/tet_mesh.hpp"

namespace sinew::mesh {

/// A constructive-solid-geometry tree. Lengths in the scene's unit, angles in degrees.
///
/// Every shape, primitive or boolean, may carry a rigid transform, applied to the shape after
/// it is built (for a boolean: after its children, with their own transforms, are combined):
/// first the rotation by `rotation_angle_deg` about the line through `rotation_center` along
/// `rotation_axis` (right-hand rule), then the translation by `translation`:
///
///     x' = R (x - rotation_center) + rotation_center + translation,
///     R = rotation by rotation_angle_deg about rotation_axis
///
/// Nested transforms compose from the inside out: a child's transform acts first, then its
/// parent's. The default (angle 0, translation 0) is the identity.
struct Shape {
  enum class Kind { Box, Cylinder, Sphere, Torus, Union, Difference, Intersection };
  Kind kind = Kind::Box;
  Vector3 min = Vector3::Zero();  ///< Box: lower corner
  Vector3 max = Vector3::Ones();  ///< Box: upper corner
  /// Sphere: center; Cylinder: center of the base disk; Torus: center (on its axis, in the
  /// plane of its centre circle)
  Vector3 center = Vector3::Zero();
  /// Cylinder: from base center to top center (length = height). Torus: normal of the plane
  /// of the centre circle (any non-zero length); the sweep turns about it by the right-hand rule.
  Vector3 axis = Vector3::UnitZ();
  double radius = 1;           ///< Sphere, Cylinder; Torus: major radius (centre circle)
  double minor_radius = 0.25;  ///< Torus: tube radius, 0 < minor_radius < radius
  /// Torus: swept angle in degrees, in (0, 360]; less than 360 gives a bent rod with flat
  /// (disk) ends, one end in the half-plane of `start_direction`, the other `angle_deg` further
  /// by the right-hand rule about `axis`.
  double angle_deg = 360;
  /// Torus: direction from `center` to the centre of the tube's first end (the reference of
  /// `angle_deg`); only its part perpendicular to `axis` counts, which must be non-zero. Zero
  /// (the default) means the default reference: +x projected onto the torus plane, or +y
  /// projected when `axis` is (within 0.06 degrees) along x.
  Vector3 start_direction = Vector3::Zero();
  /// Union: all children fused. Difference: children[0] minus the union of the others.
  /// Intersection: the region common to all children (at least two).
  std::vector<Shape> children;

  Vector3 rotation_axis = Vector3::UnitZ();   ///< rotation axis direction (non-zero when rotating)
  Vector3 rotation_center = Vector3::Zero();  ///< a point of the rotation axis (length)
  double rotation_angle_deg = 0;              ///< rotation angle (degrees, right-hand rule)
  Vector3 translation = Vector3::Zero();      ///< translation applied after the rotation (length)
};

/// Scene names of Shape::Kind (the keys of a shape object).
inline constexpr NameTable<Shape::Kind, 7> kShapeKindNames{{
    {Shape::Kind::Box, "box"},
    {Shape::Kind::Sphere, "sphere"},
    {Shape::Kind::Cylinder, "cylinder"},
    {Shape::Kind::Torus, "torus"},
    {Shape::Kind::Union, "union"},
    {Shape::Kind::Difference, "difference"},
    {Shape::Kind::Intersection, "intersection"},
}};
constexpr const auto& enum_names(Shape::Kind) { return kShapeKindNames; }

/// A named part: its shape becomes a region of the mesh. Parts are fragmented together so
/// their meshes are conforming (shared nodes) where they touch or overlap; where parts overlap,
/// the overlap belongs to the part listed first.
struct Part {
  std::string region;
  Shape shape;
};

struct GenerateOptions {
  double element_size = 0.1;  ///< target tet edge length (scene length unit), > 0
  int optimize_passes = 1;    ///< Gmsh's tet optimization passes (Netgen-free)
  /// Curved surfaces get at least this many elements per full turn (Gmsh's
  /// Mesh.MeshSizeFromCurvature), down to element_size / 10; 0 = element_size alone decides
  /// (thin rods: fewer elements around, far fewer tets).
  double elements_per_turn = 12;
  int threads = 1;            ///< Gmsh meshing threads
};

/// Meshes the parts into one conforming TetMesh with one region per part. The boundary
/// surface of every part is also stored as a face set named "<region>.surface". Throws
/// InputError with Gmsh's message when the geometry is invalid or meshing fails.
TetMesh generate_mesh(const std::vector<Part>& parts, const GenerateOptions& options);

}  // namespace sinew::mesh
