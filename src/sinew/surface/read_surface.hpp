#pragma once
/// @file read_surface.hpp
/// Triangle surfaces from STL (ASCII, binary), OBJ, PLY and glTF/GLB files, placed in the scene
/// by a unit scale and a rigid body transform (docs/surface-input.md).

#include <string>
#include <vector>

#include "sinew/core/types.hpp"
#include "sinew/surface/surface_mesh.hpp"

namespace sinew::surface {

/// How a surface file's mesh is chosen and placed: x_scene = rotation (unit_scale x_file) + translation,
/// where x_file already carries the file's own node transforms (glTF nodes).
struct SurfaceReadOptions {
  /// Which named mesh; empty = the file's only mesh (an error when the file has several).
  std::string mesh_name;
  /// File units -> scene units, > 0 and finite (1000 for a file in m and a scene in mm).
  double unit_scale = 1;
  /// A proper rotation (orthonormal, det +1, tolerance 1e-9), applied after the scale.
  Matrix3 rotation = Matrix3::Identity();
  /// In scene units, applied last.
  Vector3 translation = Vector3::Zero();
};

/// Reads one mesh of a surface file: triangulated, vertices at exactly the same position joined
/// into one (vertices no triangle uses are dropped), placed by `options`. Throws InputError
/// naming the file (and the mesh) for every bad input: see docs/surface-input.md for the list.
SurfaceMesh read_surface(const std::string& path, const SurfaceReadOptions& options = {});

/// The names of the meshes of a surface file, in file order (a glTF file's named meshes;
/// "mesh<i>" for a mesh without a name). Throws InputError like read_surface.
std::vector<std::string> surface_mesh_names(const std::string& path);

}  // namespace sinew::surface
