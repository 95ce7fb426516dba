#pragma once
/// @file assimp_import.hpp
/// The one place that talks to Assimp: a checked SurfaceFile in, plain triangle meshes out,
/// with the scene graph's node transforms applied (docs/surface-input.md).

#include <string>
#include <vector>

#include "sinew/core/types.hpp"
#include "sinew/surface/surface_file.hpp"

namespace sinew::surface {

/// One named mesh of a file, every instance placed by its node transforms.
struct ImportedMesh {
  std::string name;     ///< the file's mesh name; "mesh<i>" when the file gives none
  Positions vertices;   ///< #V x 3, file units, node transforms applied, not yet welded
  Triangles triangles;  ///< #F x 3; point and line primitives are dropped
};

/// Imports every mesh of `file` through Assimp (aiProcess_Triangulate |
/// aiProcess_JoinIdenticalVertices only). Meshes of the same name (a glTF mesh's primitives)
/// form one ImportedMesh; a mesh referenced by several nodes gets every instance, one referenced
/// by none is taken as it is. Only `file.bytes` is read: any other file the format refers to is
/// refused (a .gltf's external buffer: an error; an .obj's material library: read without it).
/// Throws InputError naming the file on a parse failure (with Assimp's message), an external
/// reference, or a file without meshes; names the mesh for a non-finite coordinate or an index
/// out of range.
std::vector<ImportedMesh> import_meshes(const SurfaceFile& file);

}  // namespace sinew::surface
