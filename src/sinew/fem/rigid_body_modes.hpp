#pragma once
/// @file rigid_body_modes.hpp
/// The six rigid-body motions of everything (three translations, three rotations) seen in Newton's
/// unknowns q: the near-null space of the unconstrained tangent, which smoothed-aggregation
/// multigrid (PETSc's GAMG) needs to coarsen elasticity well (docs/solver.md, "PETSc solvers").

#include "sinew/core/types.hpp"
#include "sinew/fem/dof_map.hpp"
#include "sinew/fem/state.hpp"

namespace sinew::fem {

/// #dofs x 6, orthonormal columns spanning the q-space images of the translations along x, y, z
/// and the rotations about x, y, z (about the centroid of the current positions) at `state`. A
/// node's unknowns take the least-squares fit of the motion through DofMap::node_jacobian (exact
/// for free nodes and free rigid bodies, the in-plane part for planar nodes). Columns that
/// vanish in q (a translation every unknown is constrained against) are left out, so the
/// result may have fewer than 6 columns.
MatrixX rigid_body_modes(const DofMap& dofs, const State& state);

/// 3 when every unknown belongs to a group of 3 aligned unknowns (free nodes, free rigid bodies'
/// translation and rotation), 1 otherwise (planar nodes have 1 or 2): the block size a sparse
/// matrix of the q-space tangent can declare.
int unknowns_block_size(const DofMap& dofs, Index num_nodes);

}  // namespace sinew::fem
