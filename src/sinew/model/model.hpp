#pragma once
/// @file model.hpp
/// The runnable model of a scene: the problem (meshes, materials, constraints, loads), the
/// DofMap, the energy terms, the objective Newton minimizes, the scales of the convergence
/// test, and the dynamics part of a time-dependent analysis. Built by build_model from a
/// SceneConfig; the command, the studies, the benchmarks and the tests all run it through
/// solve_model (solve_model.hpp). See docs/architecture.md for the data flow.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sinew/contact/contact_enforcement.hpp"
#include "sinew/contact/contact_energy.hpp"
#include "sinew/contact/friction.hpp"
#include "sinew/fem/elastic_energy.hpp"
#include "sinew/fem/external_force_energy.hpp"
#include "sinew/fem/problem.hpp"
#include "sinew/fem/quadratic_energy.hpp"
#include "sinew/scene/build_contact.hpp"
#include "sinew/scene/scene_config.hpp"
#include "sinew/solver/objective.hpp"
#include "sinew/solver/newton_solver.hpp"
#include "sinew/solver/solver_config.hpp"

namespace sinew::model {

/// The time-integration part of a dynamic analysis.
struct Dynamics {
  solver::DynamicOptions options;
  std::unique_ptr<BlockSparseMatrix> mass;          ///< M (lumped or consistent), #V node blocks (mass)
  std::unique_ptr<fem::QuadraticEnergy> inertia;    ///< A = M; null for quasistatic
  std::unique_ptr<fem::QuadraticEnergy> viscosity;  ///< A = D = mass_damping M + stiffness_damping K0; null without damping
  double elastic_critical_time_step = 0;            ///< explicit: 2 / ω_max of the elements (time)
  double contact_critical_time_step = 0;            ///< explicit with contact: of the stiffest penalty spring (time)
  double critical_time_step = 0;                    ///< explicit: the smaller of the two (time)
};

struct Model {
  std::string name;  ///< the scene's name
  /// Owned on the heap: the energies and the DofMap refer to its arrays, so a Model can move.
  std::unique_ptr<const fem::Problem> problem;
  std::unique_ptr<fem::DofMap> dofs;
  /// On several MPI ranks: the rank that owns each tet (#T; compact parts of the mesh, docs/mpi.md
  /// "Who owns what"), which evaluates its element and contact work and writes it out; empty on
  /// one rank.
  std::vector<int> tet_owner;
  /// The elastic energy of the deformable tets; on several MPI ranks, of the deformable tets this
  /// rank owns only (its share, docs/mpi.md): its value is then this rank's part of the sum.
  std::unique_ptr<fem::ElasticEnergy> elastic;
  std::unique_ptr<fem::ExternalForceEnergy> external;
  /// The scene's contact input (depths, penalties, body names), kept so that set_contact
  /// changes the method and penalties without re-meshing or recomputing the depth; none
  /// without a contact section.
  std::optional<scene::ContactSetup> contact_setup;
  std::unique_ptr<contact::ContactEnergy> contact;  ///< null without contact (or with penalty 0)
  /// Penetration control of the contact term, its tolerance resolved to a length
  /// (contact_enforcement.hpp); solve_model applies it through a ContactRefinement.
  contact::ContactEnforcementOptions contact_enforcement;
  /// Coulomb friction on the contact (contact/friction.hpp): null without contact or when every
  /// coefficient is 0. Listed after the contact in the objective (it reads its pairs).
  std::unique_ptr<contact::FrictionEnergy> friction;
  /// The coefficients and slip threshold the friction term is (re)built with; none without friction.
  std::optional<contact::FrictionOptions> friction_options;
  /// Lag refreshes per step and the relative change of the total normal force that ends them.
  int friction_max_updates = 5;
  double friction_tolerance = 0.01;
  std::optional<Dynamics> dynamics;                 ///< none for a static analysis
  /// Static analysis: the pseudo-viscous term load stepping switches on when it is stuck, A = D
  /// (solver::LoadSteppingOptions::stabilization, node blocks D_a I, force / length); off (scale
  /// 0) until then. Null for dynamics, with stabilization 0, or without deformable regions.
  std::unique_ptr<fem::QuadraticEnergy> stabilization;
  /// Nodal velocities (#V x 3, length / time) a dynamic stage with inertia starts with, taken
  /// from the dynamic run it starts from (stage_start.hpp); 0 rows: it starts at rest.
  NodalVectors start_velocity;
  /// Output directory of the run this model starts from (stage_start.hpp); empty: from rest.
  std::string started_from;
  std::unique_ptr<solver::Objective> objective;     ///< Σ of the terms above, seen through the DofMap
  solver::StaticSolverOptions solver;               ///< the scene's linear solver, Newton and load stepping
  /// Characteristic length, reference force and quasi-viscosity per node (solver/newton_solver.hpp).
  solver::NewtonSetup scales;

  bool is_dynamic() const { return dynamics.has_value(); }
  /// Names of the contact bodies by their id in the contact geometry (empty without contact).
  const std::vector<std::string>& contact_body_names() const;
};

/// Builds the problem (meshing, material depth) and the model of `scene`. Throws InputError
/// (with the scene path of the culprit) for anything a run would refuse, so `sinew validate`
/// catches exactly what `sinew run` would: bad meshes, constraints, contact settings, and for
/// explicit integration a moving part without mass.
Model build_model(const scene::SceneConfig& scene);

/// A change of the contact settings that keeps the meshes and the material depth.
struct ContactChange {
  contact::ContactMethod method = contact::ContactMethod::Area;
  /// Penalty of every body pair with contact (force / length³); 0 removes the contact term.
  double penalty = 0;
};

/// The scene's contact geometry with `penalty` (> 0) on every body pair that has contact.
/// Throws InputError as set_contact does.
contact::ContactGeometry geometry_with_penalty(const scene::ContactSetup& setup, double penalty);

/// Replaces the contact term by one with `change` (the pairs the scene has contact on keep it;
/// explicit integration's critical step is recomputed). Requires a scene with a contact section.
/// Throws InputError for a negative or non-finite penalty, or one above
/// scene::kMaxPenaltyOverAutomatic times a pair's automatic penalty.
void set_contact(Model& model, const ContactChange& change);

}  // namespace sinew::model
