#pragma once
/// @file static_model.hpp
/// The pieces of a static analysis, assembled from a fem::Problem: DofMap, energy terms and
/// the objective Newton minimizes. A plain aggregate built by one free function; the solve and
/// the output live elsewhere.

#include <memory>

#include "sinew/contact/contact_energy.hpp"
#include "sinew/fem/elastic_energy.hpp"
#include "sinew/fem/external_force_energy.hpp"
#include "sinew/fem/problem.hpp"
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
};

/// The contact term's input, when the scene has contact.
struct ContactInput {
  contact::ContactGeometry geometry;
  contact::ContactOptions options;
  std::vector<std::string> body_names;
};

/// `problem` must outlive the model. With `contact`, a contact energy joins the total potential.
StaticModel make_static_model(const fem::Problem& problem, const solver::StaticSolverOptions& options,
                              const ContactInput* contact = nullptr);

}  // namespace sinew::app
