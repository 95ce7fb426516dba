#pragma once
/// @file mass_matrix.hpp
/// Mass matrix of linear tetrahedra (mass unit = density x length^3), lumped or consistent,
/// for the inertia terms of time integration.
///
/// The matrix is scalar over nodes: M is #V x #V and the 3x3 node block (a, b) of the full
/// 3#V x 3#V matrix (node-major degrees of freedom 3 a + k, as in a flattened Positions) is
/// M(a, b) I3. Per tet with rest volume V0 and density rho:
/// - consistent: M_e(a, b) = rho V0 / 20 (1 + delta_ab), the exact integral of rho N_a N_b;
/// - lumped: M_e(a, a) = rho V0 / 4 (the row sums of the consistent matrix), as lumped_masses().

#include <vector>

#include <Eigen/SparseCore>

#include "sinew/core/enum_names.hpp"
#include "sinew/core/types.hpp"

namespace sinew::fem {

enum class MassKind { Lumped, Consistent };

/// Scene names of MassKind.
inline constexpr NameTable<MassKind, 2> kMassKindNames{{
    {MassKind::Lumped, "lumped"},
    {MassKind::Consistent, "consistent"},
}};
constexpr const auto& enum_names(MassKind) { return kMassKindNames; }

/// #V x #V symmetric scalar mass matrix M (mass units); the 3x3 node block (a, b) of the full
/// 3#V x 3#V matrix is M(a, b) * I3. Consistent: per tet rho V0 / 20 * (1 + delta_ab);
/// Lumped: rho V0 / 4 on the diagonal (row sums of the consistent matrix). rho = region_density[region[t]].
///
/// `rest`: #V x 3 rest positions; `tets`: #T x 4; `region`: #T region ids indexing
/// `region_density` (mass per rest volume, >= 0). V0 = |det Dm| / 6, so an inverted rest tet
/// weighs as much as its mirror image (like lumped_masses()); a degenerate tet throws InputError.
/// A negative or non-finite density throws InputError. Every diagonal entry is stored (zero for
/// a node in no tet), so the pattern of M is a superset of the identity's.
Eigen::SparseMatrix<double> mass_matrix(const Positions& rest, const Tets& tets, const IndexVector& region,
                                        const std::vector<double>& region_density, MassKind kind);

}  // namespace sinew::fem
