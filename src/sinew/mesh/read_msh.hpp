#pragma once
/// @file read_msh.hpp
/// Gmsh .msh files (format 2 and 4, ASCII or binary) through Gmsh's C++ API.

#include <string>

#include "sinew/mesh/tet_mesh.hpp"

namespace sinew::mesh {

/// Reads the linear tetrahedra of a .msh file. Dimension-3 physical groups become regions
/// (tets outside every group form region "default"); dimension-2 groups become face sets and
/// node sets; dimension-0/1 groups become node sets. Nodes not used by any tet are dropped and
/// the rest renumbered. Tets are oriented positively. Scalar `$NodeData` views with a value at
/// every node become node_fields (first time step with data), the others skipped_node_fields.
/// Throws InputError naming the file when it is missing, unreadable, holds no tetrahedra, or
/// fails validate().
TetMesh read_msh(const std::string& path);

}  // namespace sinew::mesh
