#pragma once
/// @file rigid_body_modes.hpp
/// The six rigid-body motions of everything (three translations, three rotations) seen in Newton's
/// unknowns q: the near-null space of the unconstrained tangent, which smoothed-aggregation
/// multigrid (PETSc's GAMG) needs to coarsen elasticity well (docs/solver.md, "PETSc solvers").

#include <vector>

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

/// The fit of rigid_body_modes before it is made orthonormal, at the listed `unknowns` only:
/// #unknowns x 6, row i for unknown unknowns[i] (each in [0, #dofs)). On several MPI ranks each
/// takes the rows it holds; orthonormalizing_transform() then makes them one basis.
MatrixX rigid_body_motions(const DofMap& dofs, const State& state, const std::vector<Index>& unknowns);

/// An orthonormal basis of the span of `columns` (n x k, taken over), by a QR with column
/// pivoting: n x r, columns whose pivot falls below 1e-10 of the largest left out.
MatrixX orthonormal_basis(MatrixX columns);

/// For `gram` = Mᵀ M (k x k, summed over the ranks that hold M's rows), a k x r matrix T with
/// (M T)ᵀ (M T) = I: T = V Λ^-1/2 over the eigenpairs of `gram` above 1e-14 of its largest
/// eigenvalue (directions that M does not span to that accuracy are left out; none when `gram`
/// is not finite). Applied twice (a second Gram matrix of M T), the columns are orthonormal to
/// round-off.
MatrixX orthonormalizing_transform(const MatrixX& gram);

/// 3 when every unknown belongs to a group of 3 aligned unknowns (free nodes, free rigid bodies'
/// translation and rotation), 1 otherwise (planar nodes have 1 or 2): the block size a sparse
/// matrix of the q-space tangent can declare.
int unknowns_block_size(const DofMap& dofs, Index num_nodes);

}  // namespace sinew::fem
