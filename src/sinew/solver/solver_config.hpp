#pragma once
/// @file solver_config.hpp
/// Options of the static solver (paper section 3.2, dissertation Fig. 12).

#include "sinew/core/enum_names.hpp"

namespace sinew::solver {

struct LinearSolverOptions {
  enum class Kind { Cholmod, Gmres, ConjugateGradient, PetscGamg, PetscMumps };
  Kind kind = Kind::Cholmod;
  /// Relative residual at which iterative solvers stop (the seed's GMRES: 0.1).
  double tolerance = 0.1;
  int max_iterations = 200;  ///< iterative solvers
  int gmres_restart = 50;
  /// CHOLMOD only: conjugate-gradient iterations, preconditioned by the last Cholesky
  /// factorization, tried on a new matrix before it is factorized itself (0: factorize every
  /// matrix, the default: docs/solver.md says why). A factorization that still converges CG within
  /// this many iterations is kept.
  int lagged_iterations = 0;
  /// Relative residual |K x - b| / |b| at which that lagged CG stops.
  double lagged_tolerance = 1e-3;
};

struct NewtonOptions {
  enum class LineSearchRule { Energy, Residual };
  int max_iterations = 25;
  /// Converged when |residual| <= residual_tolerance * force scale (the largest of external
  /// loads, reaction forces, and the initial residual of the step) ...
  double residual_tolerance = 1e-6;
  /// ... and the largest node displacement of the last iteration <= increment_tolerance *
  /// characteristic length (bounding-box diagonal).
  double increment_tolerance = 1e-6;
  LineSearchRule line_search = LineSearchRule::Energy;
  int max_line_search_steps = 30;  ///< halvings before the iteration fails
  /// Quasi-viscosity K + D/dt with D_a = quasi_viscosity * (volume around node a)^(1/3)
  /// (stress unit, the seed's dt = 1). 0 disables it. At most 1e-3 x the smallest shear modulus (docs/solver.md).
  double quasi_viscosity = 0;
  /// Project each element's dP/dF onto the positive semi-definite cone before assembly.
  bool project_element_hessians = false;
  /// Energy rule only: when the full Newton step is accepted and the energy still falls steeply
  /// along the direction at its end (slope there below kExtrapolationSlopeRatio of the slope at
  /// the start), the step is doubled while the energy keeps falling, up to this factor. Newton on
  /// an exponential law that a predictor has overstretched (Veronda-Westmann, beta = 8) removes
  /// only about 1/beta of the overshoot per full step, dividing the residual by e each time;
  /// longer steps skip those iterations (docs/solver.md, "Extrapolated steps"). 1 = off, the
  /// default: on the Visible Human knee (18 mm) steps stretched along shifted directions led
  /// into indefinite regions and the run halved ten times by 35 degrees.
  double max_step_growth = 1;
  /// Lagged linear solves only (LinearSolverOptions::lagged_iterations > 0): an accepted step
  /// along an inexact direction that multiplies the residual by more than this is undone, and
  /// the iteration solves exactly. Such a step lowers the energy but drives an element nearly
  /// flat, where the forces explode (docs/solver.md, "Lagged factorizations"). +inf: never.
  double max_lagged_residual_growth = 10;
};

/// See NewtonOptions::max_step_growth.
inline constexpr double kExtrapolationSlopeRatio = 0.1;

struct LoadSteppingOptions {
  enum class Predictor { None, TwoPoint, Tangent };
  int increments = 10;          ///< user-visible load increments (outputs after each)
  double min_step = 1e-4;       ///< smallest load-parameter step, as a fraction of an increment
  double growth = 2.0;          ///< step growth after an easy step
  int easy_iterations = 4;      ///< Newton iterations at or below which a step counts as easy
  /// Snap-through: after this many failed attempts in a row the next attempt gets
  /// `snap_through_iterations` Newton iterations. Past a limit point (a buckle, a fold that
  /// snaps) no nearby equilibrium exists however small the step; Newton with the energy line
  /// search is a descent method and walks to the equilibrium on the new branch if allowed to.
  /// 0 disables it.
  int snap_through_after_cuts = 2;
  int snap_through_iterations = 200;  ///< Newton budget of that attempt
  /// Tangent (default): dq = -K^-1 dg/dlambda dlambda from the last factorization, measured to
  /// need 25-35 % fewer Newton iterations than the seed's two-point extrapolation on the examples.
  Predictor predictor = Predictor::Tangent;
  /// Viscous stabilization where the stepping is stuck (docs/solver.md, "Stabilization"): when a
  /// step fails at the smallest allowed size, the run goes on instead of stopping, with every
  /// later step adding the pseudo-viscous term (1 / (2 dlambda)) sum_a D_a |x_a - x_a^n|², x^n the
  /// step's start, D_a = stabilization x (smallest initial shear modulus of the deformable
  /// regions) x (rest volume of the tets around node a)^(1/3) (force / length). The energy it
  /// dissipates is reported; the states it reaches are equilibria up to those viscous forces.
  /// Dimensionless; 0: stop instead.
  double stabilization = 1e-3;
};

/// Scene names of LinearSolverOptions::Kind.
inline constexpr NameTable<LinearSolverOptions::Kind, 5> kLinearSolverNames{{
    {LinearSolverOptions::Kind::Cholmod, "cholmod"},
    {LinearSolverOptions::Kind::Gmres, "gmres"},
    {LinearSolverOptions::Kind::ConjugateGradient, "cg"},
    {LinearSolverOptions::Kind::PetscGamg, "petsc-gamg"},
    {LinearSolverOptions::Kind::PetscMumps, "petsc-mumps"},
}};
constexpr const auto& enum_names(LinearSolverOptions::Kind) { return kLinearSolverNames; }

/// Scene names of NewtonOptions::LineSearchRule.
inline constexpr NameTable<NewtonOptions::LineSearchRule, 2> kLineSearchNames{{
    {NewtonOptions::LineSearchRule::Energy, "energy"},
    {NewtonOptions::LineSearchRule::Residual, "residual"},
}};
constexpr const auto& enum_names(NewtonOptions::LineSearchRule) { return kLineSearchNames; }

/// Scene names of LoadSteppingOptions::Predictor.
inline constexpr NameTable<LoadSteppingOptions::Predictor, 3> kPredictorNames{{
    {LoadSteppingOptions::Predictor::None, "none"},
    {LoadSteppingOptions::Predictor::TwoPoint, "two-point"},
    {LoadSteppingOptions::Predictor::Tangent, "tangent"},
}};
constexpr const auto& enum_names(LoadSteppingOptions::Predictor) { return kPredictorNames; }

struct StaticSolverOptions {
  LinearSolverOptions linear;
  NewtonOptions newton;
  LoadSteppingOptions stepping;
};

}  // namespace sinew::solver

namespace sinew::solver {

/// Time integration (paper section 4, dissertation sections 4.8 and 8.2). Times in the scene's
/// time unit. Prescribed motions follow the load parameter lambda = t / end_time; gravity and
/// nodal loads act in full from t = 0.
struct DynamicOptions {
  enum class Integrator {
    ImplicitEuler,  ///< inertia + viscosity + potential, one Newton solve per step (the seed's)
    Quasistatic,    ///< viscosity + potential, no inertia
    Explicit        ///< central differences with the lumped mass, automatic stable step
  };
  Integrator integrator = Integrator::ImplicitEuler;
  double end_time = 1;           ///< simulated time (> 0)
  double output_interval = 0.1;  ///< VTU/PVD output every this much simulated time (> 0)
  double time_step = 0;          ///< first step of the implicit integrators; 0: output_interval / 10
  double max_time_step = 0;      ///< upper bound of adaptive steps; 0: output_interval
  double min_time_step = 0;      ///< a step cut below this fails the run; 0: 1e-6 x time_step
  double growth = 1.5;           ///< step growth after an easy step (implicit)
  int easy_iterations = 4;       ///< Newton iterations at or below which a step counts as easy
  double explicit_safety = 0.5;  ///< explicit step = this fraction of the critical step (0, 1]
  int explicit_rebuild_every = 20;  ///< explicit: contact BVH rebuilt every this many steps
};

/// Scene names of DynamicOptions::Integrator.
inline constexpr NameTable<DynamicOptions::Integrator, 3> kIntegratorNames{{
    {DynamicOptions::Integrator::ImplicitEuler, "implicit-euler"},
    {DynamicOptions::Integrator::Quasistatic, "quasistatic"},
    {DynamicOptions::Integrator::Explicit, "explicit"},
}};
constexpr const auto& enum_names(DynamicOptions::Integrator) { return kIntegratorNames; }

}  // namespace sinew::solver
