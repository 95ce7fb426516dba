#include "sinew/model/solve_model.hpp"

#include <memory>

#include "sinew/model/contact_refinement.hpp"
#include "sinew/solver/load_stepping.hpp"
#include "sinew/solver/time_stepping.hpp"

namespace sinew::model {

solver::StepperResult solve_model(Model& model, const solver::StepperCallbacks& callbacks) {
  std::unique_ptr<ContactRefinement> refinement;
  if (model.contact && (model.contact_enforcement.method != contact::ContactEnforcement::Penalty || model.friction))
    refinement = std::make_unique<ContactRefinement>(
        *model.contact, model.contact_enforcement, model.friction.get(),
        FrictionRefresh{model.friction_max_updates, model.friction_tolerance});
  if (!model.dynamics)
    return solver::solve_static(*model.objective, model.solver, model.scales, callbacks, refinement.get());
  const Dynamics& d = *model.dynamics;
  solver::NewtonSetup scales = model.scales;
  scales.node_viscosity.resize(0);  // quasi-viscosity is a device of load stepping
  return solver::solve_dynamic(*model.objective, {d.inertia.get(), d.viscosity.get()}, d.options, model.solver, scales,
                               {.critical_time_step = d.critical_time_step}, callbacks, refinement.get());
}

}  // namespace sinew::model
