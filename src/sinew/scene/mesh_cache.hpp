#pragma once
/// @file mesh_cache.hpp
/// A directory of the meshes sinew generated (from shapes or from surfaces), so that a scene run
/// again with the same mesh section, element size and surface files skips the meshing
/// (docs/mesh-cache.md). Each entry is one file, named by a hash of its key and holding the key
/// itself, so that two keys with the same hash never share a mesh. Entries are written
/// atomically (io/atomic_file.hpp): concurrent runs never see half an entry.

#include <optional>
#include <string>

#include "sinew/mesh/tet_mesh.hpp"
#include "sinew/scene/scene_config.hpp"

namespace sinew::scene {

/// What identifies a body's generated mesh: the completed JSON of its `generate` or `surfaces`
/// section (MeshSourceConfig::cache_key), the element size in force (the command line's
/// override included), the bytes of every surface file it reads (a hash and the size), and the
/// running executable (its path, size and modification time: a rebuilt sinew never reuses an
/// older build's meshes). `data_directory`: where the surface files are (relative paths resolve
/// there, as the mesher resolves them). nullopt when a surface file cannot be read: the mesher
/// then reports it with the file's name and where to get it.
std::optional<std::string> mesh_cache_key(const MeshSourceConfig& mesh, const std::string& data_directory);

/// The entry's file for `key` in `directory`: <directory>/<16 hex digits>.sinew-mesh.
std::string mesh_cache_file(const std::string& directory, const std::string& key);

/// The cached mesh of `key` in `file`, or nullopt: when there is no file (`problem` left empty),
/// or when it is unreadable, not a cache entry of this format, holds another key, or holds a
/// mesh that fails mesh::validate (`problem` says which, to be logged before meshing anew).
std::optional<mesh::TetMesh> read_cached_mesh(const std::string& file, const std::string& key, std::string& problem);

/// Stores `mesh` as the entry of `key` in `file` (atomically; creates the directory). Throws
/// OutputError naming the file when it cannot be written.
void write_cached_mesh(const std::string& file, const std::string& key, const mesh::TetMesh& mesh);

}  // namespace sinew::scene
