#pragma once
/// @file build_surface_mesh.hpp
/// A body's mesh from closed surfaces: read, repair, check, tetrahedralize (docs/surface-input.md).

#include <string>

#include "sinew/mesh/tet_mesh.hpp"
#include "sinew/scene/scene_config.hpp"

namespace sinew::scene {

/// Where a surface file is: `file.file` as is when absolute, else under `directory` (when set).
std::string surface_file_path(const SurfaceFileConfig& file, const std::string& directory);

/// Reads every surface of `config` from `directory` (relative file names resolve there),
/// repairs the ones with a "repair" entry, checks that each is a closed, self-intersection-free
/// 2-manifold, and meshes the parts. Logs what repair changed and the mesh's size, quality and
/// region volumes. Throws InputError naming the surface, its file and mesh: a missing file
/// (with the surface's "source" text), an unreadable or malformed one, an open, non-manifold or
/// self-intersecting surface (with a location), or a mesher failure.
mesh::TetMesh build_surface_mesh(const SurfaceMeshConfig& config, const std::string& directory);

}  // namespace sinew::scene
