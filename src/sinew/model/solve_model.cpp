#include "sinew/model/solve_model.hpp"

#include <memory>

#include "sinew/core/error.hpp"

#include "sinew/model/contact_refinement.hpp"
#include "sinew/solver/load_stepping.hpp"
#include "sinew/solver/time_stepping.hpp"

namespace sinew::model {

solver::StepperResult solve_model(Model& model, const solver::StepperCallbacks& callbacks,
                                  const RunSnapshot* resume) {
  if (resume) {
    if (model.is_dynamic() && model.dynamics->options.integrator == solver::DynamicOptions::Integrator::Explicit)
      throw InputError("a run with explicit integration cannot resume (it writes no checkpoints); run it again");
    // Penalties first: the refinement keeps what it finds, and clears the pressures.
    if (model.contact) model.contact->set_penalty(resume->contact_penalty);
  }
  std::unique_ptr<ContactRefinement> refinement;
  if (model.contact && (model.contact_enforcement.method != contact::ContactEnforcement::Penalty || model.friction))
    refinement = std::make_unique<ContactRefinement>(
        *model.contact, model.contact_enforcement, model.friction.get(),
        FrictionRefresh{model.friction_max_updates, model.friction_tolerance});
  if (resume && model.contact) {
    if (refinement)
      refinement->restore_pressure(resume->contact_pressure);
    else
      model.contact->set_pressure(resume->contact_pressure);
  }
  const solver::StepperSnapshot* stepper = resume ? &resume->stepper : nullptr;
  if (!model.dynamics)
    return solver::solve_static(*model.objective, model.solver, model.scales, callbacks, refinement.get(), stepper,
                                model.stabilization.get());
  const Dynamics& d = *model.dynamics;
  solver::NewtonSetup scales = model.scales;
  scales.node_viscosity.resize(0);  // quasi-viscosity is a device of load stepping
  return solver::solve_dynamic(*model.objective, {d.inertia.get(), d.viscosity.get()}, d.options, model.solver, scales,
                               {.critical_time_step = d.critical_time_step,
                                .initial_velocity = model.start_velocity,
                                .resume = stepper},
                               callbacks, refinement.get());
}

}  // namespace sinew::model
