#pragma once
/// @file solver_rig.hpp
/// A static problem wired to an Objective (elastic + external-force terms) and the uniaxial
/// Mooney-Rivlin tension test with its closed form, shared by the solver tests.

#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "sinew/fem/elastic_energy.hpp"
#include "sinew/fem/external_force_energy.hpp"
#include "sinew/solver/newton_solver.hpp"
#include "sinew/solver/objective.hpp"
#include "support/problem_builder.hpp"

namespace sinew::testing {

/// The rubber of the uniaxial rig in the solver tests: Mooney-Rivlin C1, C2 and the volume
/// term's a (force / length², unit cube).
inline constexpr double kC1 = 0.5, kC2 = 0.2, kA = 1.5;

/// Newton's scales for the unit cube under unit forces: its diagonal and 1 N.
inline const solver::NewtonSetup kUnitCube{.characteristic_length = std::sqrt(3.0), .reference_force = 1.0};

/// Closed form of uniaxial tension for the seed's Mooney-Rivlin law, F = diag(l, s, s):
/// the lateral stretch s zeroes the lateral nominal stress; returns (s, axial nominal stress).
inline std::pair<double, double> mooney_rivlin_uniaxial(double C1, double C2, double a, double l) {
  const double c = C1 + 2 * C2 + a;
  auto lateral = [&](double s) { return 2 * C1 * s + 2 * C2 * s * (l * l + s * s) + 2 * a * s * s * s * l * l - 2 * c / s; };
  double lo = 1e-3, hi = 10;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (lateral(mid) > 0 ? hi : lo) = mid;
  }
  const double s = 0.5 * (lo + hi);
  const double axial = 2 * C1 * l + 4 * C2 * l * s * s + 2 * a * l * s * s * s * s - 2 * c / l;
  return {s, axial};
}

/// The problem, its DofMap, the elastic and external-force terms and the Objective over both.
struct SolverRig {
  fem::Problem problem;
  std::unique_ptr<fem::DofMap> dofs;
  std::unique_ptr<fem::ElasticEnergy> elastic;
  std::unique_ptr<fem::ExternalForceEnergy> external;
  std::unique_ptr<solver::Objective> objective;

  /// `gravity_amplitude`: how gravity and nodal loads follow the load parameter (default: ramped).
  explicit SolverRig(fem::Problem p, fem::ElasticEnergyOptions options = {}, fem::Amplitude gravity_amplitude = {},
                     std::vector<Energy*> extra_terms = {})
      : problem(std::move(p)) {
    dofs = std::make_unique<fem::DofMap>(problem);
    elastic = std::make_unique<fem::ElasticEnergy>(problem.mesh.rest, problem.mesh.tets, tet_materials(problem),
                                                   options);
    external = std::make_unique<fem::ExternalForceEnergy>(
        fem::lumped_masses(problem.mesh.rest, problem.mesh.tets, problem.mesh.region, problem.region_density),
        problem.gravity, std::move(gravity_amplitude), problem.forces, problem.mesh.num_nodes());
    std::vector<Energy*> terms{elastic.get(), external.get()};
    terms.insert(terms.end(), extra_terms.begin(), extra_terms.end());
    objective = std::make_unique<solver::Objective>(*dofs, std::move(terms), problem.mesh.num_nodes());
  }
};

/// A unit cube (3 x 2 x 2 cells) of Mooney-Rivlin(C1, C2, a) on rollers at x = 0, y = 0, z = 0,
/// its x = 1 face pulled to x = stretch: homogeneous uniaxial tension F = diag(stretch, s, s).
inline fem::Problem uniaxial_problem(double stretch, double C1, double C2, double a) {
  auto p = box_problem(3, 2, 2, Vector3(0, 0, 0), Vector3(1, 1, 1), mooney_rivlin(C1, C2, a));
  p.planar.push_back({"x0", nodes_on_plane(p.mesh, 0, 0.0), Vector3::UnitX(), 0.0, {}});
  p.planar.push_back({"y0", nodes_on_plane(p.mesh, 1, 0.0), Vector3::UnitY(), 0.0, {}});
  p.planar.push_back({"z0", nodes_on_plane(p.mesh, 2, 0.0), Vector3::UnitZ(), 0.0, {}});
  p.planar.push_back({"pull", nodes_on_plane(p.mesh, 0, 1.0), Vector3::UnitX(), stretch - 1.0, {}});
  return p;
}

}  // namespace sinew::testing
