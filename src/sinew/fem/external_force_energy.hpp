#pragma once
/// @file external_force_energy.hpp
/// Potential of dead loads: E = -f(lambda) . x, with f = a_g(lambda) m g + sum of nodal forces
/// (each NodalForce spread over its nodes in equal or given shares).
/// Gravity uses the lumped nodal mass (mass unit).

#include <vector>

#include "sinew/fem/constraints_config.hpp"
#include "sinew/core/energy.hpp"

namespace sinew::fem {

/// Lumped nodal masses: each tet gives density * V0 / 4 to each of its nodes. #V.
VectorX lumped_masses(const Positions& rest, const Tets& tets, const IndexVector& region,
                      const std::vector<double>& region_density);

class ExternalForceEnergy final : public Energy {
 public:
  /// `nodal_mass`: #V; `gravity`: acceleration; gravity is scaled by `gravity_amplitude`.
  ExternalForceEnergy(VectorX nodal_mass, Vector3 gravity, Amplitude gravity_amplitude,
                      std::vector<NodalForce> forces, Index num_nodes);

  std::string_view name() const override { return "external"; }
  double value(const Positions& x) const override;
  void add_gradient(const Positions& x, NodalVectors& grad) const override;
  void add_hessian(const Positions&, BlockSparseMatrix&) const override {}
  void hessian_pattern(std::vector<std::pair<Index, Index>>&) const override {}
  void set_load_parameter(double lambda) override;
  bool has_hessian() const override { return false; }

  /// Current nodal forces (#V x 3).
  const NodalVectors& forces() const { return current_; }

 private:
  VectorX mass_;
  Vector3 gravity_;
  Amplitude gravity_amplitude_;
  std::vector<NodalForce> nodal_forces_;
  NodalVectors current_;
};

}  // namespace sinew::fem
