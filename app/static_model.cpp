#include "static_model.hpp"

#include <cmath>

#include "sinew/mesh/tet_mesh.hpp"

namespace sinew::app {

StaticModel make_static_model(const fem::Problem& problem, const solver::StaticSolverOptions& options,
                              const ContactInput* contact) {
  StaticModel model;
  const auto& mesh = problem.mesh;
  model.tet_material.resize(static_cast<std::size_t>(mesh.num_tets()));
  for (Index t = 0; t < mesh.num_tets(); ++t) model.tet_material[t] = problem.region_material[mesh.region[t]];

  model.dofs = std::make_unique<fem::DofMap>(problem);
  model.elastic = std::make_unique<fem::ElasticEnergy>(
      mesh.rest, mesh.tets, model.tet_material,
      fem::ElasticEnergyOptions{.project_hessians = options.newton.project_element_hessians});
  model.external = std::make_unique<fem::ExternalForceEnergy>(
      fem::lumped_masses(mesh.rest, mesh.tets, mesh.region, problem.region_density), problem.gravity,
      fem::Amplitude{}, problem.forces, mesh.num_nodes());
  std::vector<Energy*> terms{model.elastic.get(), model.external.get()};
  if (contact) {
    model.contact = std::make_unique<contact::ContactEnergy>(contact->geometry, contact->options);
    model.contact_body_names = contact->body_names;
    terms.push_back(model.contact.get());
  }
  model.objective = std::make_unique<solver::Objective>(*model.dofs, std::move(terms), mesh.num_nodes());

  const Vector3 extent = mesh.rest.colwise().maxCoeff() - mesh.rest.colwise().minCoeff();
  const double length = std::max(extent.norm(), 1e-300);
  double shear_modulus = 0;
  for (const auto& law : problem.region_material)
    if (law) shear_modulus = std::max(shear_modulus, law->initial_shear_modulus());
  model.setup.characteristic_length = length;
  model.setup.reference_force = (shear_modulus > 0 ? shear_modulus : 1.0) * length * length;

  if (options.newton.quasi_viscosity > 0) {
    // D_a = eta * (volume of the tets around node a)^(1/3): proportional to the local element size.
    VectorX volume = VectorX::Zero(mesh.num_nodes());
    for (Index t = 0; t < mesh.num_tets(); ++t) {
      const double v = std::abs(mesh::signed_volume(mesh.rest, mesh.tets, t));
      for (int i = 0; i < 4; ++i) volume[mesh.tets(t, i)] += v;
    }
    model.setup.node_viscosity = options.newton.quasi_viscosity * volume.unaryExpr([](double v) { return std::cbrt(v); });
  }
  return model;
}

}  // namespace sinew::app
