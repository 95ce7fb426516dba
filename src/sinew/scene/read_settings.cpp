/// @file read_settings.cpp
/// Scene JSON -> the solver and dynamics settings (solver::StaticSolverOptions, DynamicsConfig).

#include "sinew/scene/scene_reading.hpp"

namespace sinew::scene::reading {

DynamicsConfig read_dynamics(const json& j, ReadErrors& errors) {
  DynamicsConfig d;
  d.enabled = true;
  d.options.integrator = read_name<solver::DynamicOptions::Integrator>(j, "integrator", "dynamics", errors);
  d.options.end_time = j.at("end_time").get<double>();
  d.options.output_interval = j.at("output_interval").get<double>();
  if (j.contains("time_step")) d.options.time_step = j.at("time_step").get<double>();
  if (j.contains("max_time_step")) d.options.max_time_step = j.at("max_time_step").get<double>();
  if (j.contains("min_time_step")) d.options.min_time_step = j.at("min_time_step").get<double>();
  d.options.growth = j.at("growth").get<double>();
  d.options.easy_iterations = j.at("easy_iterations").get<int>();
  d.options.explicit_safety = j.at("explicit_safety").get<double>();
  d.mass = read_name<fem::MassKind>(j, "mass", "dynamics", errors);
  d.mass_damping = j.at("mass_damping").get<double>();
  d.stiffness_damping = j.at("stiffness_damping").get<double>();
  return d;
}

solver::StaticSolverOptions read_solver(const json& j, ReadErrors& errors) {
  solver::StaticSolverOptions options;
  options.stepping.increments = j.at("increments").get<int>();
  options.stepping.predictor = read_name<solver::LoadSteppingOptions::Predictor>(j, "predictor", "solver", errors);
  options.stepping.min_step = j.at("min_step").get<double>();
  options.stepping.growth = j.at("growth").get<double>();
  options.stepping.easy_iterations = j.at("easy_iterations").get<int>();
  options.stepping.snap_through_after_cuts = j.at("snap_through_after_cuts").get<int>();
  options.stepping.snap_through_iterations = j.at("snap_through_iterations").get<int>();
  options.stepping.stabilization = j.at("stabilization").get<double>();
  const json& newton = j.at("newton");
  options.newton.max_iterations = newton.at("max_iterations").get<int>();
  options.newton.residual_tolerance = newton.at("residual_tolerance").get<double>();
  options.newton.increment_tolerance = newton.at("increment_tolerance").get<double>();
  options.newton.line_search = read_name<solver::NewtonOptions::LineSearchRule>(newton, "line_search", "solver.newton", errors);
  options.newton.max_line_search_steps = newton.at("max_line_search_steps").get<int>();
  options.newton.quasi_viscosity = newton.at("quasi_viscosity").get<double>();
  options.newton.project_element_hessians = newton.at("project_hessians").get<bool>();
  options.newton.max_step_growth = newton.at("max_step_growth").get<double>();
  const json& linear = j.at("linear");
  options.linear.kind = read_name<solver::LinearSolverOptions::Kind>(linear, "solver", "solver.linear", errors);
  options.linear.tolerance = linear.at("tolerance").get<double>();
  options.linear.max_iterations = linear.at("max_iterations").get<int>();
  options.linear.gmres_restart = linear.at("gmres_restart").get<int>();
  options.linear.lagged_iterations = linear.at("lagged_iterations").get<int>();
  options.linear.lagged_tolerance = linear.at("lagged_tolerance").get<double>();
  return options;
}

}  // namespace sinew::scene::reading
