#pragma once
/// @file tet_mesh.hpp
/// A linear tetrahedral mesh as plain Eigen matrices plus named regions and sets.

#include <map>
#include <string>
#include <vector>

#include "sinew/core/types.hpp"

namespace sinew::mesh {

struct TetMesh {
  Positions rest;                 ///< #V x 3 rest positions (length unit of the scene)
  Tets tets;                      ///< #T x 4, positively oriented (see types.hpp)
  IndexVector region;             ///< #T, region id of each tet, index into region_names
  std::vector<std::string> region_names;  ///< region id -> name ("default" when unnamed)
  /// Named node sets (Gmsh physical groups of dimension 0, 1 or 2 become node sets with
  /// the group's name; dimension-2 groups also become face sets).
  std::map<std::string, std::vector<Index>> node_sets;
  /// Named face sets: #F x 3 triangles (node indices), from Gmsh dimension-2 physical groups.
  std::map<std::string, Triangles> face_sets;
  /// Scalar fields per node from the mesh file, #V each, by view name: every Gmsh `$NodeData`
  /// view with one component and a value at every node (its first time step that holds data).
  /// Empty for generated meshes.
  std::map<std::string, VectorX> node_fields;
  /// The file's other `$NodeData` views, by view name -> why they are not in node_fields
  /// (e.g. "3 components per node, not 1", "no value at 2 of the mesh's 8 nodes, e.g. ..."), so that
  /// asking for one by name can say what is wrong with it.
  std::map<std::string, std::string> skipped_node_fields;

  Index num_nodes() const { return static_cast<Index>(rest.rows()); }
  Index num_tets() const { return static_cast<Index>(tets.rows()); }
  /// Region id of a name; throws InputError listing the known names when absent.
  Index region_id(const std::string& name) const;
};

/// Signed volume of tet t in configuration x (#V x 3): det[x1-x0, x2-x0, x3-x0] / 6.
double signed_volume(const Positions& x, const Tets& tets, Index t);

/// Boundary triangles (faces that belong to exactly one tet), oriented so that their normal
/// (x1-x0) x (x2-x0) points out of the tet they bound. #F x 3.
Triangles boundary_triangles(const Tets& tets);

/// Triangles on the interface between two regions (faces shared by a tet of region_a and a tet
/// of region_b), oriented outward from region_a. #F x 3.
Triangles interface_triangles(const TetMesh& mesh, Index region_a, Index region_b);

/// Node -> incident tets, as CSR: tets of node v are indices[offsets[v] .. offsets[v+1]).
struct NodeTetAdjacency {
  std::vector<Index> offsets;  ///< #V + 1
  std::vector<Index> indices;  ///< 4 #T
};
NodeTetAdjacency node_tet_adjacency(const Tets& tets, Index num_nodes);

/// Node -> neighbour nodes (sharing a tet), sorted, each list including the node itself. CSR.
struct NodeNodeAdjacency {
  std::vector<Index> offsets;
  std::vector<Index> indices;
};
NodeNodeAdjacency node_node_adjacency(const Tets& tets, Index num_nodes);

/// Nodes used by at least one tet, sorted.
std::vector<Index> referenced_nodes(const Tets& tets);

/// Quality checks run on every mesh before use. Throws InputError with the first few
/// offending element indices (1-based as Gmsh prints them and 0-based) when it finds:
/// - an index out of range, or a node field whose length is not #V;
/// - an inverted tet (negative volume) or a zero-volume one (|V| <= rel_volume_tolerance *
///   mean |V|);
/// - two tets with the same node set (duplicates);
/// - a non-manifold boundary (a face shared by more than two tets, or a boundary edge used
///   by a number of boundary triangles other than 2).
/// `what` names the mesh in messages (e.g. the file name or body name).
struct ValidationOptions {
  double rel_volume_tolerance = 1e-12;
  /// Check the boundary for edges not joining exactly two boundary triangles and for pinched
  /// nodes (faces shared by more than two tets are always refused). The surface mesher (CGAL
  /// Mesh_3) may leave such an edge where regions meet, which the solver handles: its meshes are
  /// not held to this when read back from the mesh cache.
  bool check_boundary_manifold = true;
};
void validate(const TetMesh& mesh, const std::string& what, const ValidationOptions& options = {});

/// Flips the orientation of negatively oriented tets (swaps two nodes). Used by readers of
/// files whose orientation convention differs; returns how many were flipped.
Index orient_positively(const Positions& rest, Tets& tets);

}  // namespace sinew::mesh
