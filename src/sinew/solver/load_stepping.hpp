#pragma once
/// @file load_stepping.hpp
/// Adaptive incremental loading (paper section 3.2): the load parameter lambda goes from 0 to 1
/// in user-visible increments; each increment is reached in one or more load steps whose size
/// halves when Newton fails and grows after easy steps; each step starts from a predictor (the
/// seed's two-point extrapolation, or a tangent predictor). The steps are run_stepper's.

#include "sinew/fem/quadratic_energy.hpp"
#include "sinew/solver/stepper.hpp"

namespace sinew::solver {

/// Equilibrium at lambda = 0, then at the end of every increment, of `objective`.
/// `setup.transient_terms` must be empty. `stabilization`, when given, must be a term of the
/// objective, off (scale 0) until the stepping is stuck: then every later step sets it to
/// A = D (LoadSteppingOptions::stabilization), center the step's start and scale 1 / dlambda
/// (StepScheme::start_stabilizing); newton.csv's equilibrium_residual leaves it out.
StepperResult solve_static(Objective& objective, const StaticSolverOptions& options, const NewtonSetup& setup,
                           const StepperCallbacks& callbacks = {}, StepRefinement* refinement = nullptr,
                           const StepperSnapshot* resume = nullptr, fem::QuadraticEnergy* stabilization = nullptr);

}  // namespace sinew::solver
