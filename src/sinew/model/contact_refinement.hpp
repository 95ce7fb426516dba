#pragma once
/// @file contact_refinement.hpp
/// The stepper's outer iteration for contact penetration control (contact_enforcement.hpp,
/// docs/contact.md "Penetration control"): augmented Lagrangian multiplier updates within a
/// step, or penalty growth between steps.

#include "sinew/contact/contact_energy.hpp"
#include "sinew/contact/contact_enforcement.hpp"
#include "sinew/solver/stepper.hpp"

namespace sinew::model {

class ContactRefinement final : public solver::StepRefinement {
 public:
  /// `contact` must outlive the refinement; options.method must not be Penalty and its
  /// penetration_tolerance must be > 0 (std::invalid_argument otherwise). Clears the contact's
  /// pressures (a run starts from the plain penalty); penalties grown by an earlier run stay.
  ContactRefinement(contact::ContactEnergy& contact, contact::ContactEnforcementOptions options);

  /// Augmented Lagrangian: when the largest penetration at `converged` exceeds the tolerance
  /// and the step has had fewer than max_updates updates, updates the nodal pressures and
  /// returns true. Adaptive penalty: false.
  bool refine(const fem::State& converged) override;
  /// Keeps the pressures for the next step; adaptive penalty: grows the penalties of the body
  /// pairs that penetrate more than the tolerance at `state`.
  void accept(const fem::State& state) override;
  /// Restores the pressures of the last accepted step.
  void reject() override;

  /// Largest penetration (L) at the last state refine() or accept() looked at.
  double last_max_penetration() const { return last_max_penetration_; }

 private:
  contact::ContactEnergy& contact_;
  contact::ContactEnforcementOptions options_;
  int updates_ = 0;  ///< multiplier updates in the current step
  VectorX accepted_pressure_;
  double last_max_penetration_ = 0;
};

}  // namespace sinew::model
