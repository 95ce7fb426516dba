#pragma once
/// @file solve_model.hpp
/// Runs a Model: load stepping for a static analysis, time stepping for a dynamic one, with
/// the same callbacks and the same result.

#include "sinew/model/checkpoint.hpp"
#include "sinew/model/model.hpp"
#include "sinew/solver/stepper.hpp"

namespace sinew::model {

/// Solves `model` from its rest state, or from `resume` (a snapshot of a run of the same model,
/// checked by check_snapshot_fits; not for explicit integration: InputError). StepRecord::t is
/// the load parameter lambda of a static analysis and the time of a dynamic one.
solver::StepperResult solve_model(Model& model, const solver::StepperCallbacks& callbacks = {},
                                  const RunSnapshot* resume = nullptr);

}  // namespace sinew::model
