#pragma once
/// @file problem.hpp
/// The discretized problem as plain data: all bodies' meshes concatenated into one node and
/// tet numbering, a material per region, constraints and loads resolved to node indices.
/// Built by the scene module; consumed by the energies and the solver. It owns nothing that
/// changes during a solve (state lives in solver::State).

#include <map>
#include <string>
#include <vector>

#include "sinew/fem/constraints_config.hpp"
#include "sinew/material/material.hpp"
#include "sinew/mesh/tet_mesh.hpp"

namespace sinew::fem {

/// Where one body lives in the global numbering: nodes [first_node, first_node + num_nodes),
/// tets [first_tet, first_tet + num_tets).
struct BodyRange {
  std::string name;
  Index first_node = 0, num_nodes = 0;
  Index first_tet = 0, num_tets = 0;
};

struct Problem {
  /// All bodies, concatenated. Region names are "<body>/<region>"; node and face sets are
  /// "<body>/<set>".
  mesh::TetMesh mesh;
  std::vector<BodyRange> bodies;
  /// Per region: the law (nullptr for rigid regions, which carry no elastic energy).
  std::vector<material::MaterialPtr> region_material;
  /// Tets whose law differs from their region's (a per-element fiber field: RegionConfig's
  /// fiber_path), by global tet index.
  std::map<Index, material::MaterialPtr> element_material;
  /// Per region: mass density (mass per rest volume), 0 allowed.
  std::vector<double> region_density;

  std::vector<RigidBody> rigid_bodies;
  std::vector<PrescribedNodes> prescribed;
  std::vector<PlanarNodes> planar;
  std::vector<NodalForce> forces;
  Vector3 gravity = Vector3::Zero();  ///< acceleration (length / time^2)
};

/// Whether tet `t` of `problem` carries no elastic energy: its region is rigid and it has no
/// law of its own.
inline bool is_rigid_tet(const Problem& problem, Index t) {
  return !problem.region_material[static_cast<std::size_t>(problem.mesh.region[t])] &&
         !problem.element_material.contains(t);
}

/// The law of every tet (#T): its own (element_material) or its region's; nullptr for a rigid
/// tet. A vector of #T shared pointers (16 bytes a tet): build it where it is used, not to keep.
inline std::vector<material::MaterialPtr> tet_laws(const Problem& problem) {
  std::vector<material::MaterialPtr> laws(static_cast<std::size_t>(problem.mesh.num_tets()));
  for (Index t = 0; t < problem.mesh.num_tets(); ++t)
    laws[static_cast<std::size_t>(t)] = problem.region_material[static_cast<std::size_t>(problem.mesh.region[t])];
  for (const auto& [t, law] : problem.element_material) laws[static_cast<std::size_t>(t)] = law;
  return laws;
}

}  // namespace sinew::fem
