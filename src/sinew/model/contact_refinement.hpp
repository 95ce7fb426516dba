#pragma once
/// @file contact_refinement.hpp
/// The stepper's outer iteration for contact (docs/contact.md, "Penetration control" and
/// "Friction"): augmented Lagrangian multiplier updates within a step, penalty growth between
/// steps, and the refresh of friction's lagged normal forces after each converged solve.

#include "sinew/contact/contact_energy.hpp"
#include "sinew/contact/contact_enforcement.hpp"
#include "sinew/contact/friction.hpp"
#include "sinew/solver/stepper.hpp"

namespace sinew::model {

/// How often friction's lag is refreshed within a step.
struct FrictionRefresh {
  int max_updates = 5;      ///< refreshes per step that may ask for a re-solve
  double tolerance = 0.01;  ///< relative change of the total normal force that asks for one
};

class ContactRefinement final : public solver::StepRefinement {
 public:
  /// The augmented Lagrangian's pressure onset δ (ContactEnergy::set_pressure_onset) as a
  /// fraction of the penetration tolerance: a point carrying its whole pressure through the
  /// multiplier rests less than δ deep, so the updates can end below the tolerance.
  static constexpr double kPressureOnsetFraction = 0.5;
  /// `contact` (and `friction`, when not null) must outlive the refinement. Unless there is
  /// friction, options.method must not be Penalty; a method other than Penalty needs
  /// penetration_tolerance > 0 (std::invalid_argument otherwise). Clears the contact's pressures
  /// (a run starts from the plain penalty); penalties grown by an earlier run stay.
  ContactRefinement(contact::ContactEnergy& contact, contact::ContactEnforcementOptions options,
                    contact::FrictionEnergy* friction = nullptr, FrictionRefresh refresh = {});

  /// Augmented Lagrangian: when the largest penetration at `converged` exceeds the tolerance
  /// and the step has had fewer than max_updates updates, updates the nodal pressures. Friction:
  /// lags the normal forces and tangents again at `converged`. True when either changed enough
  /// to solve the step again (the pressures were updated, or the total normal force changed by
  /// more than the refresh tolerance and the step has had fewer than max_updates refreshes).
  bool refine(const fem::State& converged) override;
  /// The re-solve after the last refine() failed. Augmented Lagrangian: halves the last update of
  /// the pressures (at most three times: 1/2, 1/4, 1/8 of it) and returns true; then restores the
  /// pressures before it, ends the refinement of this step (refine() returns false until the
  /// next step), logs a warning with the penetration left, and returns false. Friction refreshes
  /// alone are not halved: false at once.
  bool retry_softer() override;
  /// Keeps the pressures for the next step; adaptive penalty: grows the penalties of the body
  /// pairs that penetrate more than the tolerance at `state`.
  void accept(const fem::State& state) override;
  /// Restores the pressures of the last accepted step.
  void reject() override;
  /// Continues a run whose last accepted step ended with these nodal pressures (#V or empty).
  void restore_pressure(const VectorX& pressure);

  /// Largest penetration (L) at the last state refine() or accept() looked at.
  double last_max_penetration() const { return last_max_penetration_; }

 private:
  contact::ContactEnergy& contact_;
  contact::ContactEnforcementOptions options_;
  contact::FrictionEnergy* friction_;
  FrictionRefresh refresh_;
  int updates_ = 0;           ///< multiplier updates in the current step
  bool exhausted_ = false;    ///< a re-solve failed and nothing smaller is left: no more updates this step
  bool updated_ = false;      ///< the last refine() updated the pressures
  VectorX previous_pressure_;  ///< before the last update
  VectorX updated_pressure_;   ///< the last update's full pressures
  double update_fraction_ = 1;  ///< of the last update, now in the objective
  int friction_updates_ = 0;  ///< friction refreshes that asked for a re-solve in the current step
  VectorX accepted_pressure_;
  double last_max_penetration_ = 0;
};

}  // namespace sinew::model
