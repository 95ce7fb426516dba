#pragma once
/// @file static_model.hpp
/// The pieces of a static analysis, assembled from a fem::Problem: DofMap, energy terms and
/// the objective Newton minimizes. A plain aggregate built by one free function; the solve and
/// the output live elsewhere.

#include <memory>
#include <optional>

#include "sinew/contact/contact_energy.hpp"
#include "sinew/fem/elastic_energy.hpp"
#include "sinew/fem/external_force_energy.hpp"
#include "sinew/fem/problem.hpp"
#include "sinew/fem/quadratic_energy.hpp"
#include "sinew/scene/scene_config.hpp"
#include "sinew/solver/static_solver.hpp"

namespace sinew::app {

struct StaticModel {
  std::unique_ptr<fem::DofMap> dofs;
  std::unique_ptr<fem::ElasticEnergy> elastic;
  std::unique_ptr<fem::ExternalForceEnergy> external;
  std::unique_ptr<contact::ContactEnergy> contact;  ///< null without contact
  std::vector<std::string> contact_body_names;      ///< body id of the contact geometry -> name
  std::unique_ptr<solver::Objective> objective;
  std::vector<material::MaterialPtr> tet_material;  ///< #T, nullptr for rigid tets
  solver::StaticSetup setup;                         ///< scales and quasi-viscosity
  // Dynamics (empty for a static analysis).
  std::unique_ptr<BlockSparseMatrix> mass;           ///< M (lumped or consistent), for kinetic energy
  std::unique_ptr<fem::QuadraticEnergy> inertia;     ///< implicit Euler and explicit
  std::unique_ptr<fem::QuadraticEnergy> viscosity;   ///< D = mass_damping M + stiffness_damping K0
  double critical_time_step = 0;                     ///< explicit: min of the elastic and contact bounds
  double contact_critical_time_step = 0;             ///< explicit with contact: 2 / omega of the stiffest penalty spring
};

/// The contact term's input, when the scene has contact.
struct ContactInput {
  contact::ContactGeometry geometry;
  contact::ContactOptions options;
  std::vector<std::string> body_names;
};

/// The contact input of a scene with contact enabled (material depths, penalties, options;
/// throws InputError on bad contact settings), none otherwise.
std::optional<ContactInput> make_contact_input(const scene::SceneConfig& scene, const fem::Problem& problem);

/// `problem` must outlive the model. With `contact`, a contact energy joins the total potential.
/// With `dynamics` (enabled), the inertia and viscosity terms of time integration join it too,
/// and gravity acts in full from t = 0.
StaticModel make_static_model(const fem::Problem& problem, const solver::StaticSolverOptions& options,
                              const ContactInput* contact = nullptr, const scene::DynamicsConfig* dynamics = nullptr);

}  // namespace sinew::app
