#pragma once
/// @file solve_model.hpp
/// Runs a Model: load stepping for a static analysis, time stepping for a dynamic one, with
/// the same callbacks and the same result.

#include "sinew/model/model.hpp"
#include "sinew/solver/stepper.hpp"

namespace sinew::model {

/// Solves `model` from its rest state. StepRecord::t is the load parameter lambda of a static
/// analysis and the time of a dynamic one.
solver::StepperResult solve_model(Model& model, const solver::StepperCallbacks& callbacks = {});

}  // namespace sinew::model
