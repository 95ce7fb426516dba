#pragma once
/// @file surface_mesh.hpp
/// A triangle surface read from a surface file (docs/surface-input.md).

#include <string>

#include "sinew/core/types.hpp"

namespace sinew::surface {

/// One triangle surface. Vertices at exactly the same position are one vertex, so edges shared
/// by two triangles share their vertex indices (surface_topology counts on these indices).
struct SurfaceMesh {
  Positions vertices;   ///< #V x 3, in scene units (after unit scale, rotation and translation)
  Triangles triangles;  ///< #F x 3 indices into `vertices`, in the file's winding order
  std::string name;     ///< the mesh's name in the file (docs/surface-input.md: naming)
};

}  // namespace sinew::surface
