#pragma once
/// @file stable_time_step.hpp
/// Critical time step of explicit central differences (with the lumped mass), bounded per
/// element (Irons' element eigenvalue bound). Units: time = length sqrt(density / stress).

#include <vector>

#include "sinew/core/types.hpp"
#include "sinew/material/material.hpp"

namespace sinew::fem {

/// `dt` (time unit): 2 / omega_max; +infinity when there is no elastic tet (nothing limits the
/// step). `critical_tet`: the tet attaining omega_max (the lowest index on ties), -1 when none.
/// `omega_max` (radians per time unit): the bound on the highest angular eigenfrequency.
struct StableTimeStep {
  double dt = 0;
  Index critical_tet = -1;
  double omega_max = 0;
};

/// Critical time step of explicit central differences with the lumped mass, 2 / omega_max, with
/// omega_max^2 bounded above by the largest element eigenvalue max_e lambda_max(M_e^-1 K_e)
/// (Irons' bound; M_e the element's lumped mass rho V0/4 per node, K_e the element stiffness at
/// the rest state from the material's dP/dF at F = I). Tets with a null material (rigid) are skipped.
/// Elastic tets with zero density -> InputError (explicit integration needs mass).
///
/// `rest`: #V x 3; `tets`: #T x 4; `tet_material`: #T laws (nullptr = rigid); `tet_density`: #T
/// densities (mass per rest volume). The bound holds for the assembled lumped system with every
/// tet's mass, rigid ones included (extra mass only lowers the frequencies), and it is exact for a
/// single tet. Throws InputError for a degenerate rest tet and for an elastic tet whose density is
/// not finite and > 0; Error when the sizes disagree or a material's dP/dF(I) is not finite.
StableTimeStep critical_time_step(const Positions& rest, const Tets& tets,
                                  const std::vector<material::MaterialPtr>& tet_material,
                                  const VectorX& tet_density);

}  // namespace sinew::fem
