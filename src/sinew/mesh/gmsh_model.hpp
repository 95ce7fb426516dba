#pragma once
/// @file gmsh_model.hpp
/// Conversion of the mesh held by the current Gmsh model into a TetMesh. Needs a GmshSession;
/// Gmsh calls may throw std::string (run it inside GmshSession::run).

#include <string>
#include <vector>

#include "sinew/mesh/tet_mesh.hpp"

namespace sinew::mesh {

/// The linear tetrahedra (Gmsh element type 4) of the current model:
/// - regions: dimension-3 physical groups in ascending tag order (unnamed groups are named
///   "group_<tag>", groups sharing a name share a region); tets of volumes in no group form the
///   last region, "default";
/// - face sets: triangles (element type 2) of dimension-2 physical groups; those on the mesh
///   boundary are oriented outward, the others keep Gmsh's orientation;
/// - node sets: nodes of dimension-0, 1 and 2 physical groups;
/// - nodes not used by any tet are dropped (with the set entries that refer to them) and the
///   rest renumbered in ascending Gmsh node tag order;
/// - tets are oriented positively;
/// - node fields: every post-processing view (a .msh file's `$NodeData` blocks become views)
///   that holds one value per node for every kept node, in its first time step with data, by
///   view name; the other views go to skipped_node_fields with the reason.
/// Returns a mesh without tets when the model has none; does not call validate().
/// Throws InputError when a tet is inverted relative to a neighbour (see reject_folded_tets);
/// tets merely wound the other way are flipped to positive orientation.
TetMesh tet_mesh_from_gmsh_model();

/// Throws InputError naming the first pairs of face-sharing tets that lie on the same side of
/// their shared face (a fold: one of them is inverted).
void reject_folded_tets(const Positions& rest, const Tets& tets);

/// The names of the Gmsh element types of dimension `dim` (all dimensions when -1) present in
/// the current model's mesh, leaving out `excluded_types` (Gmsh type numbers), e.g.
/// "Triangle 3", "Hexahedron 8" (for messages).
std::vector<std::string> gmsh_element_type_names(int dim = -1,
                                                 const std::vector<int>& excluded_types = {});

/// Gmsh's type number of the linear tetrahedron.
inline constexpr int kGmshLinearTetrahedron = 4;

/// Face set triangles lying on the boundary of `tets` get the boundary's outward orientation;
/// the others are returned unchanged. #F x 3.
Triangles orient_like_boundary(const Tets& tets, const Triangles& triangles);

}  // namespace sinew::mesh
