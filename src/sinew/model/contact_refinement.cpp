#include "sinew/model/contact_refinement.hpp"

#include <stdexcept>

#include "sinew/contact/contact_report.hpp"
#include "sinew/core/log.hpp"

namespace sinew::model {

ContactRefinement::ContactRefinement(contact::ContactEnergy& contact, contact::ContactEnforcementOptions options,
                                     contact::FrictionEnergy* friction, FrictionRefresh refresh)
    : contact_(contact), options_(options), friction_(friction), refresh_(refresh) {
  contact_.set_pressure(VectorX());  // a run starts from the plain penalty
  const bool penalty = options_.method == contact::ContactEnforcement::Penalty;
  if (penalty && !friction_) throw std::invalid_argument("ContactRefinement: the plain penalty needs no refinement");
  if (!penalty && !(options_.penetration_tolerance > 0))
    throw std::invalid_argument("ContactRefinement: the penetration tolerance must be > 0");
  // Under full pressure a point then rests at most δ deep, half the tolerance (docs/contact.md,
  // "Augmented Lagrangian").
  if (options_.method == contact::ContactEnforcement::AugmentedLagrangian)
    contact_.set_pressure_onset(kPressureOnsetFraction * options_.penetration_tolerance);
}

bool ContactRefinement::refine(const fem::State& converged) {
  if (exhausted_) return false;
  bool again = false;
  updated_ = false;
  if (options_.method == contact::ContactEnforcement::AugmentedLagrangian) {
    contact_.update(converged.x);
    last_max_penetration_ = contact::contact_report(contact_.collisions()).max_penetration;
    if (last_max_penetration_ > options_.penetration_tolerance && updates_ < options_.max_updates) {
      previous_pressure_ = contact_.pressure();
      updated_pressure_ = contact::updated_contact_pressure(contact_.collisions());
      update_fraction_ = 1;
      contact_.set_pressure(updated_pressure_);
      ++updates_;
      logger().info("contact: multiplier update {}: largest penetration {:.3g} (tolerance {:.3g}), largest pressure {:.3g}",
                    updates_, last_max_penetration_, options_.penetration_tolerance, updated_pressure_.maxCoeff());
      updated_ = true;
      again = true;
    }
  }
  if (friction_ && friction_updates_ < refresh_.max_updates) {
    // Lagged at the converged state (with the new pressures): solve again if the normal forces moved.
    const double change = friction_->refresh(converged.x);
    if (change > refresh_.tolerance) {
      ++friction_updates_;
      again = true;
    }
  }
  return again;
}

bool ContactRefinement::retry_softer() {
  constexpr double kSmallestFraction = 1.0 / 8;
  if (updated_ && update_fraction_ > kSmallestFraction) {
    update_fraction_ /= 2;
    // Pressures of nodes that left contact (0 in the update) are blended too: the update is a
    // vector of nodal values over all nodes.
    const VectorX previous =
        previous_pressure_.size() == updated_pressure_.size() ? previous_pressure_ : VectorX::Zero(updated_pressure_.size());
    contact_.set_pressure(previous + update_fraction_ * (updated_pressure_ - previous));
    logger().info("contact: no convergence after the multiplier update {}: trying {} of it", updates_, update_fraction_);
    return true;
  }
  if (updated_) contact_.set_pressure(previous_pressure_);
  exhausted_ = true;
  if (updated_) {
    logger().warn("contact: no convergence after the multiplier update of this step; the step keeps its last converged "
                  "state (largest penetration {:.3g}, tolerance {:.3g})",
                  last_max_penetration_, options_.penetration_tolerance);
  } else {
    // A friction refresh: its normal forces and slip bases stay those of the last converged state.
    logger().warn("contact: no convergence after the friction refresh of this step; the step keeps its last converged "
                  "state, solved with the friction's previous lag");
  }
  return false;
}

void ContactRefinement::accept(const fem::State& state) {
  updates_ = 0;
  friction_updates_ = 0;
  exhausted_ = false;
  updated_ = false;
  accepted_pressure_ = contact_.pressure();
  if (options_.method != contact::ContactEnforcement::AdaptivePenalty) return;
  const contact::ContactReport report = contact::contact_report(contact_, state.x);
  last_max_penetration_ = report.max_penetration;
  const MatrixX& penalty = contact_.geometry().penalty;
  const MatrixX grown =
      contact::grown_penalty(penalty, report, options_.penetration_tolerance, options_.max_growth);
  if (grown != penalty) {
    logger().info("contact: penetration {:.3g} above the tolerance {:.3g}: penalty grown (largest {:.3g} -> {:.3g})",
              report.max_penetration, options_.penetration_tolerance, penalty.maxCoeff(), grown.maxCoeff());
    contact_.set_penalty(grown);
  }
}

void ContactRefinement::restore_pressure(const VectorX& pressure) {
  contact_.set_pressure(pressure);
  accepted_pressure_ = pressure;
}

void ContactRefinement::reject() {
  updates_ = 0;
  friction_updates_ = 0;
  exhausted_ = false;
  updated_ = false;
  contact_.set_pressure(accepted_pressure_);
}

}  // namespace sinew::model
