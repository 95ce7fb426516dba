#pragma once
/// @file generate.hpp
/// Meshes from primitive solids through Gmsh's OpenCASCADE kernel.

#include <memory>
#include <string>
#include <vector>

#include "sinew/mesh/tet_mesh.hpp"

namespace sinew::mesh {

/// A constructive-solid-geometry tree. Lengths in the scene's unit.
struct Shape {
  enum class Kind { Box, Cylinder, Sphere, Union, Difference };
  Kind kind = Kind::Box;
  Vector3 min = Vector3::Zero();     ///< Box: lower corner
  Vector3 max = Vector3::Ones();     ///< Box: upper corner
  Vector3 center = Vector3::Zero();  ///< Sphere: center; Cylinder: center of the base disk
  Vector3 axis = Vector3::UnitZ();   ///< Cylinder: from base center to top center (length = height)
  double radius = 1;                 ///< Sphere, Cylinder
  /// Union: all children fused. Difference: children[0] minus the union of the others.
  std::vector<Shape> children;
};

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
  int threads = 1;            ///< Gmsh meshing threads
};

/// Meshes the parts into one conforming TetMesh with one region per part. The boundary
/// surface of every part is also stored as a face set named "<region>.surface". Throws
/// InputError with Gmsh's message when the geometry is invalid or meshing fails.
TetMesh generate_mesh(const std::vector<Part>& parts, const GenerateOptions& options);

}  // namespace sinew::mesh
