#pragma once
/// @file build_problem.hpp
/// SceneConfig -> fem::Problem: meshes read or generated, placed, concatenated into one
/// numbering; a material per region; rigid bodies; node selectors resolved to node indices.

#include <vector>

#include "sinew/fem/problem.hpp"
#include "sinew/scene/scene_config.hpp"

namespace sinew::scene {

/// Builds the discretized problem. Bodies are concatenated in scene order (fem::BodyRange per
/// body); region names become "<body>/<region>", node and face sets "<body>/<set>", node fields
/// (and skipped ones) "<body>/<field>", each spanning all nodes with NaN at other bodies' nodes.
/// Throws InputError listing every error, each starting with the path of the config entry
/// (e.g. "boundary_conditions[1].nodes: selects no node ..."):
/// - a selector that matches no node, or names a set or region the body does not have;
/// - a `regions` entry naming a region the mesh lacks (the mesh's regions are listed), or a
///   mesh region with neither its own entry nor a "*" entry;
/// - a node prescribed by two fixed/prescribed boundary conditions;
/// - a prescribed or planar node that belongs to a rigid region (prescribe the rigid region);
/// - two rigid regions that share nodes (a node can follow only one rigid body);
/// - a generated body whose estimated tet count exceeds scene.limits.max_tets (checked before
///   any meshing; resource_estimate.hpp);
/// - a condition or force named like a rigid region of a mesh file (scene_names.hpp);
/// and the mesh readers' and material factory's errors.
fem::Problem build_problem(const SceneConfig& scene);

/// The nodes of `mesh` a selector chooses (its `body` field is ignored), sorted, 0-based in
/// `mesh`'s numbering. Throws InputError (without a path) when a named set or region is absent.
std::vector<Index> select_nodes(const mesh::TetMesh& mesh, const NodeSelector& selector);

/// Places a body's mesh: X <- R(angle, axis) X + translate (rotation about the origin first).
void apply_transform(mesh::TetMesh& mesh, const MeshSourceConfig& source);

}  // namespace sinew::scene
