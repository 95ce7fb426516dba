#include "static_model.hpp"

#include <cmath>

#include "sinew/contact/contact_time_step.hpp"
#include "sinew/fem/mass_matrix.hpp"
#include "sinew/fem/stable_time_step.hpp"
#include "sinew/mesh/tet_mesh.hpp"
#include "sinew/scene/build_contact.hpp"

namespace sinew::app {

std::optional<ContactInput> make_contact_input(const scene::SceneConfig& scene, const fem::Problem& problem) {
  if (!scene.contact.enabled) return std::nullopt;
  scene::ContactSetup setup = scene::build_contact(scene, problem);
  return ContactInput{std::move(setup.geometry), setup.options, std::move(setup.body_names)};
}

StaticModel make_static_model(const fem::Problem& problem, const solver::StaticSolverOptions& options,
                              const ContactInput* contact, const scene::DynamicsConfig* dynamics) {
  if (dynamics && !dynamics->enabled) dynamics = nullptr;
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
      dynamics ? fem::Amplitude{{{0.0, 1.0}}} : fem::Amplitude{}, problem.forces, mesh.num_nodes());
  std::vector<Energy*> terms{model.elastic.get(), model.external.get()};
  if (contact) {
    model.contact = std::make_unique<contact::ContactEnergy>(contact->geometry, contact->options);
    model.contact_body_names = contact->body_names;
    terms.push_back(model.contact.get());
  }
  if (dynamics) {
    using Integrator = solver::DynamicOptions::Integrator;
    const Integrator integrator = dynamics->options.integrator;
    const fem::MassKind kind = integrator == Integrator::Explicit ? fem::MassKind::Lumped : dynamics->mass;
    model.mass = std::make_unique<BlockSparseMatrix>(
        fem::block_mass_matrix(fem::mass_matrix(mesh.rest, mesh.tets, mesh.region, problem.region_density, kind)));
    if (integrator != Integrator::Quasistatic) {
      model.inertia = std::make_unique<fem::QuadraticEnergy>("inertia", *model.mass);
      terms.push_back(model.inertia.get());
    }
    if (dynamics->mass_damping > 0 || dynamics->stiffness_damping > 0) {
      // K0: the elastic stiffness at rest.
      std::vector<std::pair<Index, Index>> pairs;
      model.elastic->hessian_pattern(pairs);
      BlockSparseMatrix K0;
      K0.set_pattern(mesh.num_nodes(), std::move(pairs));
      model.elastic->bind_pattern(K0);
      model.elastic->add_hessian(mesh.rest, K0);
      model.viscosity = std::make_unique<fem::QuadraticEnergy>(
          "viscosity", fem::linear_combination(dynamics->mass_damping, *model.mass, dynamics->stiffness_damping, K0));
      terms.push_back(model.viscosity.get());
    }
    if (integrator == Integrator::Explicit) {
      VectorX tet_density(mesh.num_tets());
      for (Index t = 0; t < mesh.num_tets(); ++t) tet_density[t] = problem.region_density[static_cast<std::size_t>(mesh.region[t])];
      model.critical_time_step = fem::critical_time_step(mesh.rest, mesh.tets, model.tet_material, tet_density).dt;
      if (model.contact) {
        // The penalty springs of contact are stiffer than the elements when h is small.
        VectorX movable_mass = fem::lumped_masses(mesh.rest, mesh.tets, mesh.region, problem.region_density);
        for (Index a = 0; a < mesh.num_nodes(); ++a) {
          const auto kind = model.dofs->kind(a);
          if (kind == fem::DofMap::NodeKind::Prescribed || kind == fem::DofMap::NodeKind::RigidMember) movable_mass[a] = 0;
        }
        model.contact_critical_time_step =
            contact::contact_critical_time_step(model.contact->geometry(), mesh.rest, movable_mass).dt;
        model.critical_time_step = std::min(model.critical_time_step, model.contact_critical_time_step);
      }
    }
  }
  model.objective = std::make_unique<solver::Objective>(*model.dofs, std::move(terms), mesh.num_nodes());

  const Vector3 extent = mesh.rest.colwise().maxCoeff() - mesh.rest.colwise().minCoeff();
  const double length = std::max(extent.norm(), 1e-300);
  // The reference force sets the round-off floor of Newton's residual. Round-off in the elastic
  // forces scales with the stiffest modulus, the bulk modulus of a nearly incompressible law
  // (a = 1e6 against C1 = 0.2): scaled by the shear modulus alone, the floor lay below the
  // round-off of a stress-free rest state, which then failed as "the initial state has no
  // equilibrium" (Newton could not reduce a residual that is pure round-off).
  double modulus = 0;
  for (const auto& law : problem.region_material)
    if (law) modulus = std::max({modulus, law->initial_shear_modulus(), law->initial_bulk_modulus()});
  model.setup.characteristic_length = length;
  model.setup.reference_force = (modulus > 0 ? modulus : 1.0) * length * length;

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
