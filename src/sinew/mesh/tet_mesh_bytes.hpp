#pragma once
/// @file tet_mesh_bytes.hpp
/// A TetMesh as one string of bytes and back, exactly (the doubles and indices as stored), for
/// sending a mesh between the processes of one run: rank 0 meshes a body and the other MPI ranks
/// receive it (docs/mpi.md). Not a file format: the bytes hold no version and are read only by
/// the same program that wrote them.

#include <string>
#include <string_view>

#include "sinew/mesh/tet_mesh.hpp"

namespace sinew::mesh {

/// Every member of `mesh`: the positions, tets and regions, the region names, node and face
/// sets and node fields (about 24 bytes per node and 20 per tet besides the sets).
std::string tet_mesh_bytes(const TetMesh& mesh);

/// The mesh that tet_mesh_bytes wrote. Throws sinew::Error when `bytes` end early, hold more, or
/// hold a count that cannot be.
TetMesh tet_mesh_from_bytes(std::string_view bytes);

}  // namespace sinew::mesh
