#include "sinew/fem/external_force_energy.hpp"

#include "sinew/fem/tet_kinematics.hpp"

namespace sinew::fem {

VectorX lumped_masses(const Positions& rest, const Tets& tets, const IndexVector& region,
                      const std::vector<double>& region_density) {
  VectorX m = VectorX::Zero(rest.rows());
  const auto shapes = compute_rest_shapes(rest, tets);
  for (Index t = 0; t < tets.rows(); ++t) {
    const double rho = region_density[static_cast<std::size_t>(region[t])];
    for (int i = 0; i < 4; ++i) m[tets(t, i)] += rho * shapes[t].volume / 4.0;
  }
  return m;
}

ExternalForceEnergy::ExternalForceEnergy(VectorX nodal_mass, Vector3 gravity, Amplitude gravity_amplitude,
                                         std::vector<NodalForce> forces, Index num_nodes)
    : mass_(std::move(nodal_mass)),
      gravity_(gravity),
      gravity_amplitude_(std::move(gravity_amplitude)),
      nodal_forces_(std::move(forces)),
      current_(NodalVectors::Zero(num_nodes, 3)) {
  set_load_parameter(1.0);
}

void ExternalForceEnergy::set_load_parameter(double lambda) {
  current_.setZero();
  const Vector3 g = gravity_amplitude_(lambda) * gravity_;
  for (Index a = 0; a < current_.rows(); ++a) current_.row(a) = mass_[a] * g.transpose();
  for (const auto& f : nodal_forces_) {
    if (f.nodes.empty()) continue;
    const Vector3 force = f.amplitude(lambda) * f.total_force;
    const double equal_share = 1.0 / static_cast<double>(f.nodes.size());
    for (std::size_t i = 0; i < f.nodes.size(); ++i)
      current_.row(f.nodes[i]) += (f.shares.empty() ? equal_share : f.shares[i]) * force.transpose();
  }
}

double ExternalForceEnergy::value(const Positions& x) const { return -(current_.array() * x.array()).sum(); }

void ExternalForceEnergy::add_gradient(const Positions&, NodalVectors& grad) const { grad -= current_; }

}  // namespace sinew::fem
