#pragma once
/// @file solver_config.hpp
/// Options of the static solver (paper section 3.2, dissertation Fig. 12).

namespace sinew::solver {

struct LinearSolverOptions {
  enum class Kind { Cholmod, Gmres, ConjugateGradient };
  Kind kind = Kind::Cholmod;
  /// Relative residual at which iterative solvers stop (the seed's GMRES: 0.1).
  double tolerance = 0.1;
  int max_iterations = 200;  ///< iterative solvers
  int gmres_restart = 50;
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
  /// (stress unit times length). 0 disables it.
  double quasi_viscosity = 0;
  /// Project each element's dP/dF onto the positive semi-definite cone before assembly.
  bool project_element_hessians = false;
};

struct LoadSteppingOptions {
  enum class Predictor { None, TwoPoint, Tangent };
  int increments = 10;          ///< user-visible load increments (outputs after each)
  double min_step = 1e-4;       ///< smallest load-parameter step, as a fraction of an increment
  double growth = 2.0;          ///< step growth after an easy step
  int easy_iterations = 4;      ///< Newton iterations at or below which a step counts as easy
  /// Tangent (default): dq = -K^-1 dg/dlambda dlambda from the last factorization, measured to
  /// need 25-35 % fewer Newton iterations than the seed's two-point extrapolation on the examples.
  Predictor predictor = Predictor::Tangent;
};

struct StaticSolverOptions {
  LinearSolverOptions linear;
  NewtonOptions newton;
  LoadSteppingOptions stepping;
};

}  // namespace sinew::solver
