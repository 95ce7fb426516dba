/// @file scene_schema_solver.cpp
/// The scene schema of the solver, dynamics and output settings; defaults from the option structs.

#include "sinew/scene/scene_schema_parts.hpp"

#include "sinew/scene/scene_config.hpp"
#include "sinew/solver/solver_config.hpp"
#include "sinew/scene/schema_bounds.hpp"
#include "sinew/scene/schema_builder.hpp"

namespace sinew::scene::schema_parts {

using namespace schema_builder;  // NOLINT(google-build-using-namespace)
using namespace schema_bounds;   // NOLINT(google-build-using-namespace)
using nlohmann::json;

SchemaNode solver_schema() {
  const solver::StaticSolverOptions defaults;
  const auto& stepping = defaults.stepping;
  const auto& newton = defaults.newton;
  const auto& linear = defaults.linear;
  return object(
             "solver", "static solver: adaptive load stepping, Newton, line search, linear solver",
             {
                 integer("increments", "load increments (an output after each)").min(1).max(kMaxIncrements).fallback(stepping.increments),
                 choice("predictor", "initial guess of each step: tangent (linearized response from the last factorization), two-point (the seed's extrapolation of the last two states) or none",
                        stepping.predictor),
                 number("min_step", "smallest load step when halving, as a fraction of an increment")
                     .min(kMinStep)
                     .max(1)
                     .fallback(stepping.min_step),
                 number("growth", "step growth factor after an easy step").min(1).max(kMaxGrowth).fallback(stepping.growth),
                 integer("easy_iterations", "Newton iterations at or below which a step counts as easy")
                     .max(kMaxIterations)
                     .min(0)
                     .fallback(stepping.easy_iterations),
                 integer("snap_through_after_cuts", "after this many failed attempts in a row, the next attempt gets snap_through_iterations Newton iterations (passes limit points: a buckle or a fold snapping through, where no smaller step helps); 0 = off")
                     .max(kMaxCuts)
                     .min(0)
                     .fallback(stepping.snap_through_after_cuts),
                 integer("snap_through_iterations", "Newton iterations of that attempt")
                     .max(kMaxIterations)
                     .min(1)
                     .fallback(stepping.snap_through_iterations),
                 number("stabilization",
                        "when a load step fails at the smallest allowed size, go on instead of stopping, with every "
                        "later step damped by the viscous term (1 / (2 dlambda)) sum_a D_a |x_a - x_a(step start)|^2, "
                        "D_a = this x (smallest initial shear modulus) x (rest volume around node a)^(1/3) "
                        "(dimensionless); the energy it dissipates is in summary.json (docs/solver.md); 0 = stop")
                     .min(0)
                     .max(1)
                     .fallback(stepping.stabilization),
                 object("newton", "Newton iterations of one load step",
                        {
                            integer("max_iterations", "iterations before the step fails and is halved")
                                .max(kMaxIterations)
                                .min(1)
                                .fallback(newton.max_iterations),
                            number("residual_tolerance", "converged when |residual| <= this * force scale")
                                .min(kMinTolerance)
                                .fallback(newton.residual_tolerance),
                            number("increment_tolerance",
                                   "... and the largest node displacement of the last iteration <= this * bounding-box "
                                   "diagonal")
                                .min(kMinTolerance)
                                .fallback(newton.increment_tolerance),
                            choice("line_search", "accept a step when the energy decreases, or when the residual does",
                                   newton.line_search),
                            integer("max_line_search_steps", "step halvings before the iteration fails")
                                .max(kMaxHalvings)
                                .min(0)
                                .fallback(newton.max_line_search_steps),
                            number("quasi_viscosity",
                                   "Newton matrix K + D with D_a = this * (volume around node a)^(1/3), the seed's "
                                   "quasi-viscosity with dt = 1 (stress unit); 0 = off. It changes the matrix, not the "
                                   "equilibrium, and slows Newton: keep it at most 1e-3 x the smallest initial shear "
                                   "modulus (1e-2 doubles the Newton iterations, 0.1 multiplies them 10-150 times; "
                                   "docs/solver.md)")
                                .max(kMaxPhysical)
                                .min(0)
                                .fallback(newton.quasi_viscosity),
                            number("max_step_growth",
                                   "after an accepted full Newton step along which the energy still falls steeply "
                                   "(the slope at its end below 0.1 of the slope at its start), double the step while "
                                   "the energy keeps falling, up to this factor: fewer iterations on exponential laws "
                                   "that the predictor overstretched (docs/solver.md); 1 = off")
                                .min(1)
                                .max(1024)
                                .fallback(newton.max_step_growth),
                            boolean("project_hessians",
                                    "project each element's dP/dF onto the positive semi-definite cone")
                                .fallback(newton.project_element_hessians),
                        })
                     .fallback(json::object()),
                 object("linear", "linear solver of each Newton iteration",
                        {
                            choice("solver",
                                   "sparse Cholesky (CHOLMOD), GMRES, conjugate gradients, PETSc's conjugate gradients "
                                   "with algebraic multigrid given the rigid-body modes (petsc-gamg; set tolerance to "
                                   "1e-6 or below for Newton's quadratic convergence) or PETSc's MUMPS LDL^T",
                                   linear.kind),
                            number("tolerance", "relative residual at which iterative solvers stop")
                                .min(kMinTolerance)
                                .below(1)
                                .fallback(linear.tolerance),
                            integer("max_iterations", "iterative solvers' iteration limit")
                                .max(kMaxLinearIterations)
                                .min(1)
                                .fallback(linear.max_iterations),
                            integer("gmres_restart", "GMRES restart length").min(1).max(kMaxRestart).fallback(linear.gmres_restart),
                            integer("lagged_iterations",
                                    "cholmod only: CG iterations, preconditioned by the last Cholesky factorization, "
                                    "tried on each new Newton matrix before it is factorized itself; 0 = factorize "
                                    "every matrix (the default; 20 is 2.1-2.8x faster on a compressed block and 1.24x on the VH "
                                    "knee's first 45 degrees, slower on the generated knee: docs/solver.md)")
                                .min(0)
                                .max(kMaxLinearIterations)
                                .fallback(linear.lagged_iterations),
                            number("lagged_tolerance", "relative residual at which that lagged CG stops")
                                .min(kMinTolerance)
                                .below(1)
                                .fallback(linear.lagged_tolerance),
                        })
                     .fallback(json::object()),
             })
      .fallback(json::object());
}

SchemaNode dynamics_schema() {
  const DynamicsConfig defaults;
  const auto& o = defaults.options;
  return object("dynamics",
                "time integration instead of load stepping (paper section 4): implicit Euler with inertia and "
                "viscosity (the seed's), quasistatic (viscosity, no inertia) or explicit central differences. "
                "Prescribed motions follow lambda = t / end_time; gravity and loads act in full from t = 0. The "
                "solver section's newton and linear settings apply to every implicit step.",
                {
                    choice("integrator", "implicit-euler, quasistatic or explicit", o.integrator),
                    number("end_time", "simulated time (time)").required().above(0).max(kMaxTime),
                    number("output_interval", "VTU/PVD output every this much simulated time (time)")
                        .required()
                        .above(0)
                        .max(kMaxTime),
                    number("time_step", "first step of the implicit integrators (time); default output_interval / 10")
                        .min(kMinTime)
                        .max(kMaxTime),
                    number("max_time_step", "upper bound of the adaptive step (time); default output_interval")
                        .min(kMinTime)
                        .max(kMaxTime),
                    number("min_time_step",
                           "a step halved below this fails the run (time); default 1e-6 of the first step")
                        .min(kMinTime)
                        .max(kMaxTime),
                    number("growth", "step growth after an easy step").min(1).max(kMaxGrowth).fallback(o.growth),
                    integer("easy_iterations", "Newton iterations at or below which a step counts as easy")
                        .max(kMaxIterations)
                        .min(0)
                        .fallback(o.easy_iterations),
                    choice("mass", "lumped (rho V / 4 per node) or consistent mass matrix (implicit only)", defaults.mass),
                    number("mass_damping", "Rayleigh viscosity D = mass_damping M + stiffness_damping K0: 1/time")
                        .max(kMaxPhysical)
                        .min(0)
                        .fallback(defaults.mass_damping),
                    number("stiffness_damping", "... and time (K0: elastic stiffness at rest)")
                        .max(kMaxPhysical)
                        .min(0)
                        .fallback(defaults.stiffness_damping),
                    number("explicit_safety", "explicit step as a fraction of the critical step 2 / omega_max")
                        .above(0)
                        .max(1)
                        .fallback(o.explicit_safety),
                });
}

SchemaNode output_schema() {
  const OutputConfig defaults;
  return object("output", "what is written",
                {
                    boolean("vtu", "write a .vtu per output step and a .pvd series").fallback(defaults.vtu),
                    integer("every", "write every n-th increment (the last one always)").min(1).max(kMaxIncrements).fallback(defaults.every),
                    integer("checkpoint_every",
                            "write checkpoint.cbor (for sinew run --resume) after every n-th accepted load step, or "
                            "output interval in dynamics, and at the end; 0: only at the end and on an interrupt")
                        .min(0)
                        .max(kMaxIncrements)
                        .fallback(defaults.checkpoint_every),
                })
      .fallback(json::object());
}

}  // namespace sinew::scene::schema_parts
