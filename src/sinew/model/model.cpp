#include "sinew/model/model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "sinew/contact/body_overlap.hpp"
#include "sinew/contact/contact_enforcement.hpp"
#include "sinew/contact/pair_exchange.hpp"
#include "sinew/contact/contact_time_step.hpp"
#include "sinew/core/error.hpp"
#include "sinew/core/log.hpp"
#include "sinew/fem/hessian_reduction.hpp"
#include "sinew/fem/mass_matrix.hpp"
#include "sinew/fem/stable_time_step.hpp"
#include "sinew/mesh/tet_mesh.hpp"
#include "sinew/model/stage_start.hpp"
#include "sinew/parallel/partition.hpp"
#include "sinew/parallel/ranks.hpp"
#include "sinew/scene/build_problem.hpp"

namespace sinew::model {
namespace {

using Integrator = solver::DynamicOptions::Integrator;

/// Rest volume of the tets around each node (#V, volume).
VectorX rest_volume_around_nodes(const mesh::TetMesh& mesh) {
  VectorX volume = VectorX::Zero(mesh.num_nodes());
  for (Index t = 0; t < mesh.num_tets(); ++t) {
    const double v = std::abs(mesh::signed_volume(mesh.rest, mesh.tets, t));
    for (int i = 0; i < 4; ++i) volume[mesh.tets(t, i)] += v;
  }
  return volume;
}

/// Length and force scales of Newton's convergence test, and the quasi-viscosity per node.
solver::NewtonSetup newton_scales(const fem::Problem& problem, const solver::NewtonOptions& newton) {
  const auto& mesh = problem.mesh;
  solver::NewtonSetup scales;
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
  scales.characteristic_length = length;
  scales.reference_force = (modulus > 0 ? modulus : 1.0) * length * length;
  if (newton.quasi_viscosity > 0) {
    // D_a = eta * (volume of the tets around node a)^(1/3): proportional to the local element size.
    const VectorX volume = rest_volume_around_nodes(mesh);
    scales.node_viscosity = newton.quasi_viscosity * volume.unaryExpr([](double v) { return std::cbrt(v); });
  }
  return scales;
}

/// Mass, inertia and Rayleigh viscosity of a dynamic analysis, and the elements' critical step.
Dynamics make_dynamics(const scene::DynamicsConfig& config, const fem::Problem& problem,
                       const std::vector<material::MaterialPtr>& tet_material, fem::ElasticEnergy& elastic) {
  const auto& mesh = problem.mesh;
  Dynamics d;
  d.options = config.options;
  const Integrator integrator = config.options.integrator;
  const fem::MassKind kind = integrator == Integrator::Explicit ? fem::MassKind::Lumped : config.mass;
  d.mass = std::make_unique<BlockSparseMatrix>(
      fem::block_mass_matrix(fem::mass_matrix(mesh.rest, mesh.tets, mesh.region, problem.region_density, kind)));
  if (integrator != Integrator::Quasistatic) d.inertia = std::make_unique<fem::QuadraticEnergy>("inertia", *d.mass);
  if (config.mass_damping > 0 || config.stiffness_damping > 0) {
    // K0: the elastic stiffness at rest. On several ranks `elastic` evaluates this rank's tets
    // only: their parts, on the whole pattern, are summed, so every rank has all of K0.
    std::vector<std::pair<Index, Index>> pairs;
    elastic.whole_hessian_pattern(pairs);
    BlockSparseMatrix K0;
    K0.set_pattern(mesh.num_nodes(), std::move(pairs));
    elastic.bind_pattern(K0);
    elastic.add_hessian(mesh.rest, K0);
    if (parallel::size() > 1 && !K0.values().empty()) parallel::sum(K0.values().front().data(), 9 * K0.values().size());
    d.viscosity = std::make_unique<fem::QuadraticEnergy>(
        "viscosity", fem::linear_combination(config.mass_damping, *d.mass, config.stiffness_damping, K0));
  }
  if (integrator == Integrator::Explicit) {
    VectorX tet_density(mesh.num_tets());
    for (Index t = 0; t < mesh.num_tets(); ++t)
      tet_density[t] = problem.region_density[static_cast<std::size_t>(mesh.region[t])];
    d.elastic_critical_time_step = fem::critical_time_step(mesh.rest, mesh.tets, tet_material, tet_density).dt;
    d.critical_time_step = d.elastic_critical_time_step;
  }
  return d;
}

/// The static stepping's stabilization (solver::LoadSteppingOptions::stabilization): D_a = eta x
/// mu_min x (rest volume of the tets around a)^(1/3) on every node with unknowns (0 on fixed and
/// prescribed nodes and on members of fixed or prescribed rigid bodies: their motion is given, and
/// would count as dissipation), mu_min the smallest initial shear modulus of the deformable regions. Null when
/// eta = 0 or no region deforms.
std::unique_ptr<fem::QuadraticEnergy> make_stabilization(const fem::Problem& problem, const fem::DofMap& dofs,
                                                         double eta) {
  double shear = std::numeric_limits<double>::infinity();
  for (const auto& law : problem.region_material)
    if (law) shear = std::min(shear, law->initial_shear_modulus());
  if (!(eta > 0) || !std::isfinite(shear) || !(shear > 0)) return nullptr;
  const auto& mesh = problem.mesh;
  const VectorX volume = rest_volume_around_nodes(mesh);
  BlockSparseMatrix D;
  D.set_pattern(mesh.num_nodes(), {});  // the diagonal blocks
  for (Index a = 0; a < mesh.num_nodes(); ++a) {
    if (dofs.num_node_dofs(a) == 0) continue;
    D.add(D.find(a, a), eta * shear * std::cbrt(volume[a]) * Matrix3::Identity());
  }
  return std::make_unique<fem::QuadraticEnergy>("stabilization", std::move(D));
}

/// Explicit integration divides by the reduced mass M_q = Jᵀ M J: every unknown needs mass.
void check_explicit_mass(const Model& model) {
  fem::HessianReduction reduction(*model.dofs);
  const BlockSparseMatrix& M = *model.dynamics->mass;
  reduction.bind(M);
  fem::SparseMatrix Mq;
  const fem::State rest = model.dofs->initial_state(0.0);
  reduction.reduce(rest, M, NodalVectors::Zero(M.num_nodes(), 3), VectorX(), Mq);
  if (Mq.rows() > 0 && !(Mq.diagonal().minCoeff() > 0))
    throw InputError(
        "dynamics: explicit integration: a moving part has no mass (a region or rigid body of density 0?): give every "
        "part that is not fixed or prescribed a density > 0");
}

/// Gathers the contact pairs each rank detected among its tets onto every rank, in rank order,
/// and sums their candidates (docs/mpi.md, "Collision detection split by tet").
contact::PairJoin rank_pair_join(const contact::ContactEnergy& contact) {
  const contact::ContactMethod method = contact.options().method;
  return [method](std::vector<contact::ActivePair>& pairs, std::size_t& candidates) {
    std::vector<char> bytes;
    contact::pack_pairs(pairs, method, bytes);
    pairs = contact::unpack_pairs(parallel::gather_all(bytes), method);
    candidates = static_cast<std::size_t>(parallel::sum(static_cast<double>(candidates)));
  };
}

/// The objective over the current terms (elastic, external, contact, inertia, viscosity).
void rebuild_objective(Model& model) {
  std::vector<Energy*> terms{model.elastic.get(), model.external.get()};
  if (model.contact) terms.push_back(model.contact.get());
  if (model.friction) terms.push_back(model.friction.get());
  if (model.stabilization) terms.push_back(model.stabilization.get());
  if (model.dynamics) {
    if (model.dynamics->inertia) terms.push_back(model.dynamics->inertia.get());
    if (model.dynamics->viscosity) terms.push_back(model.dynamics->viscosity.get());
  }
  model.objective = std::make_unique<solver::Objective>(*model.dofs, terms, model.problem->mesh.num_nodes());
  if (parallel::size() > 1) {
    // Several ranks (docs/mpi.md): each evaluates the tets it owns and the contact pairs whose tet
    // it owns (the contact geometry's tets are the mesh's); the other terms are rank 0's.
    if (model.contact) model.contact->set_share(model.tet_owner, parallel::rank(), rank_pair_join(*model.contact));
    std::vector<bool> shared(terms.size(), false);
    for (std::size_t i = 0; i < terms.size(); ++i)
      shared[i] = terms[i] == model.elastic.get() || (model.contact && terms[i] == model.contact.get());
    model.objective->share_terms(std::move(shared));
  }
}

/// On several ranks, the tets this rank evaluates: those Model::tet_owner gives it (docs/mpi.md);
/// empty (every tet) on one rank.
std::vector<bool> own_tets(const Model& model) {
  std::vector<bool> own(model.tet_owner.size());
  for (std::size_t t = 0; t < own.size(); ++t) own[t] = model.tet_owner[t] == parallel::rank();
  return own;
}

/// On several ranks: the rank that owns each tet (parallel::partition_tets, compact parts of
/// balanced work); empty on one rank. A deformable tet weighs kDeformableTetWeight, a rigid one 1:
/// a rigid tet has no element work, only the contact pairs and the output cells it may carry.
std::vector<int> partition_among_ranks(const mesh::TetMesh& mesh, const std::vector<material::MaterialPtr>& tet_material) {
  if (parallel::size() <= 1) return {};
  constexpr int kDeformableTetWeight = 8;
  std::vector<int> weights(tet_material.size(), 1);
  for (std::size_t t = 0; t < tet_material.size(); ++t)
    if (tet_material[t]) weights[t] = kDeformableTetWeight;
  return parallel::partition_tets(mesh.tets, weights, parallel::size());
}

/// The friction coefficient of every pair of contact bodies: the pair's own or the scene's.
MatrixX friction_coefficients(const scene::ContactConfig& config, const std::vector<std::string>& body_names) {
  const auto bodies = static_cast<Index>(body_names.size());
  MatrixX mu = MatrixX::Constant(bodies, bodies, config.friction.coefficient);
  auto id = [&](const std::string& name) {
    return static_cast<Index>(std::find(body_names.begin(), body_names.end(), name) - body_names.begin());
  };
  for (const scene::ContactPairConfig& pair : config.pairs) {
    if (!pair.friction) continue;
    const Index a = id(pair.body_a), b = id(pair.body_b);
    if (a < bodies && b < bodies) mu(a, b) = mu(b, a) = *pair.friction;
  }
  return mu;
}

/// Contact energy from `geometry` (and the friction term on it, when the model has friction);
/// explicit integration's critical step follows its springs.
void attach_contact(Model& model, contact::ContactGeometry geometry, const contact::ContactOptions& options) {
  model.friction.reset();
  model.contact = std::make_unique<contact::ContactEnergy>(std::move(geometry), options);
  if (model.friction_options) model.friction = std::make_unique<contact::FrictionEnergy>(*model.contact, *model.friction_options);
  if (model.dynamics && model.dynamics->options.integrator == Integrator::Explicit) {
    // The penalty springs of contact are stiffer than the elements when h is small.
    const auto& mesh = model.problem->mesh;
    VectorX movable_mass = fem::lumped_masses(mesh.rest, mesh.tets, mesh.region, model.problem->region_density);
    for (Index a = 0; a < mesh.num_nodes(); ++a) {
      const auto kind = model.dofs->kind(a);
      if (kind == fem::DofMap::NodeKind::Prescribed || kind == fem::DofMap::NodeKind::RigidMember) movable_mass[a] = 0;
    }
    Dynamics& d = *model.dynamics;
    d.contact_critical_time_step =
        contact::contact_critical_time_step(model.contact->geometry(), mesh.rest, movable_mass).dt;
    d.critical_time_step = std::min(d.elastic_critical_time_step, d.contact_critical_time_step);
  }
}

/// 1 for every node no unknown moves (#V): fixed or prescribed, or a member of a fixed or prescribed
/// rigid body (contact leaves pairs of such nodes out, ContactGeometry::node_immovable).
std::vector<std::uint8_t> immovable_nodes(const fem::DofMap& dofs, Index nodes) {
  std::vector<std::uint8_t> immovable(static_cast<std::size_t>(nodes), 0);
  for (Index a = 0; a < nodes; ++a) immovable[static_cast<std::size_t>(a)] = dofs.num_node_dofs(a) == 0;
  return immovable;
}

/// Overlaps shallower than this fraction of the mean contact-surface edge are not reported.
constexpr double kReportedStartOverlap = 1e-3;
/// At most this many overlaps are named one by one (the deepest); one line counts the rest.
constexpr std::size_t kNamedStartOverlaps = 10;

/// Warns about every pair of bodies that overlaps at the start state (docs/contact.md, "Parts
/// that overlap at the start"): where the parts can move, contact pushes them apart in the
/// first step; where neither can, the pairs are left out of contact.
void warn_about_start_overlaps(const Model& model) {
  if (!parallel::is_root()) return;  // the other ranks log nothing (docs/mpi.md): no collision pass for them
  const contact::ContactGeometry& g = model.contact->geometry();
  const Positions x = model.dofs->initial_state(0.0).x;
  const double h = contact::mean_surface_edge(g, x);
  const auto& names = model.contact_setup->body_names;
  const std::vector<contact::BodyOverlap> overlaps =
      contact::body_overlaps(g, x, model.contact_setup->options.method, kReportedStartOverlap * h);
  if (overlaps.size() > kNamedStartOverlaps)
    logger().warn("contact at the start: {} overlaps of pairs of bodies; the {} deepest follow", overlaps.size(),
                  kNamedStartOverlaps);
  for (std::size_t k = 0; k < std::min(overlaps.size(), kNamedStartOverlaps); ++k) {
    const contact::BodyOverlap& o = overlaps[k];
    const std::string& a = names[static_cast<std::size_t>(o.body_a)];
    const std::string& b = names[static_cast<std::size_t>(o.body_b)];
    const std::string parts =
        o.body_a == o.body_b ? fmt::format("body \"{}\" overlaps itself", a) : fmt::format("\"{}\" and \"{}\" overlap", a, b);
    const std::string where = fmt::format("by up to {:.4g} ({:.2g} of the mean contact-surface edge) near ({:.4g}, "
                                          "{:.4g}, {:.4g}), in {} triangle-tet pairs",
                                          o.max_depth, o.max_depth / h, o.place.x(), o.place.y(), o.place.z(), o.pairs);
    if (o.immovable)
      logger().warn("contact at the start: {} {} where neither side can move (fixed or prescribed); those pairs "
                    "are left out of contact",
                    parts, where);
    else
      logger().warn("contact at the start: {} {}; contact pushes them apart in the first step (move the parts "
                    "apart if they are not meant to overlap)",
                    parts, where);
  }
}

void detach_contact(Model& model) {
  model.friction.reset();
  model.contact.reset();
  if (model.dynamics) {
    model.dynamics->contact_critical_time_step = 0;
    model.dynamics->critical_time_step = model.dynamics->elastic_critical_time_step;
  }
}

}  // namespace

const std::vector<std::string>& Model::contact_body_names() const {
  static const std::vector<std::string> none;
  return contact_setup ? contact_setup->body_names : none;
}

Model build_model(const scene::SceneConfig& scene) {
  Model model;
  model.name = scene.name;
  model.problem = std::make_unique<const fem::Problem>(scene::build_problem(scene));
  const fem::Problem& problem = *model.problem;
  if (scene.contact.enabled) model.contact_setup = scene::build_contact(scene, problem);
  model.solver = scene.solver;

  const auto& mesh = problem.mesh;
  // Not kept in the model: 16 bytes a tet, on every MPI rank (docs/mpi.md).
  std::vector<material::MaterialPtr> tet_material = fem::tet_laws(problem);
  model.dofs = std::make_unique<fem::DofMap>(problem);
  model.tet_owner = partition_among_ranks(mesh, tet_material);
  model.elastic = std::make_unique<fem::ElasticEnergy>(
      mesh.rest, mesh.tets, tet_material,
      fem::ElasticEnergyOptions{.project_hessians = scene.solver.newton.project_element_hessians,
                                .evaluated_tets = own_tets(model)});
  const bool dynamic = scene.dynamics.enabled;
  // Dynamics: gravity and loads act in full from t = 0.
  model.external = std::make_unique<fem::ExternalForceEnergy>(
      fem::lumped_masses(mesh.rest, mesh.tets, mesh.region, problem.region_density), problem.gravity,
      dynamic ? fem::Amplitude{{{0.0, 1.0}}} : fem::Amplitude{}, problem.forces, mesh.num_nodes());
  if (dynamic)
    model.dynamics = make_dynamics(scene.dynamics, problem, tet_material, *model.elastic);
  else
    model.stabilization = make_stabilization(problem, *model.dofs, scene.solver.stepping.stabilization);
  if (!scene.initial_state.empty()) start_from_run(model, scene.initial_state);
  if (model.contact_setup) {
    const MatrixX mu = friction_coefficients(scene.contact, model.contact_setup->body_names);
    if (mu.size() > 0 && mu.maxCoeff() > 0) {
      const scene::FrictionConfig& f = scene.contact.friction;
      model.friction_options = contact::FrictionOptions{
          mu, f.slip_threshold.value_or(1e-3 * contact::mean_surface_edge(model.contact_setup->geometry, mesh.rest)),
          f.slip_velocity_threshold.value_or(0)};
      model.friction_max_updates = f.max_updates;
      model.friction_tolerance = f.tolerance;
    }
    model.contact_setup->geometry.node_immovable = immovable_nodes(*model.dofs, mesh.num_nodes());
    attach_contact(model, model.contact_setup->geometry, model.contact_setup->options);
    warn_about_start_overlaps(model);
    model.contact_enforcement = scene.contact.enforcement;
    if (scene.contact.relative_penetration_tolerance)
      model.contact_enforcement.penetration_tolerance =
          *scene.contact.relative_penetration_tolerance * contact::mean_surface_edge(model.contact_setup->geometry, mesh.rest);
  }
  rebuild_objective(model);
  model.scales = newton_scales(problem, scene.solver.newton);
  if (!model.tet_owner.empty()) model.scales.node_owner = parallel::node_owners(mesh.tets, model.tet_owner, mesh.num_nodes());
  if (dynamic && scene.dynamics.options.integrator == Integrator::Explicit) check_explicit_mass(model);
  return model;
}

contact::ContactGeometry geometry_with_penalty(const scene::ContactSetup& setup, double penalty) {
  if (!(penalty > 0) || !std::isfinite(penalty))
    throw InputError(fmt::format("contact penalty {} must be finite and > 0", penalty));
  contact::ContactGeometry geometry = setup.geometry;
  for (Index a = 0; a < geometry.penalty.rows(); ++a)
    for (Index b = 0; b < geometry.penalty.cols(); ++b)
      if (geometry.penalty(a, b) > 0) geometry.penalty(a, b) = penalty;
  scene::check_penalty_bounds(setup, geometry.penalty);
  return geometry;
}

void set_contact(Model& model, const ContactChange& change) {
  if (!model.contact_setup) throw InputError(fmt::format("scene \"{}\" has no contact section", model.name));
  if (!(change.penalty >= 0) || !std::isfinite(change.penalty))
    throw InputError(fmt::format("contact penalty {} must be finite and >= 0", change.penalty));
  if (change.penalty == 0) {
    detach_contact(model);
    rebuild_objective(model);
    return;
  }
  const scene::ContactSetup& setup = *model.contact_setup;
  contact::ContactGeometry geometry = geometry_with_penalty(setup, change.penalty);
  contact::ContactOptions options = setup.options;
  options.method = change.method;
  attach_contact(model, std::move(geometry), options);
  rebuild_objective(model);
}

}  // namespace sinew::model
