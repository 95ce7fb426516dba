#pragma once
/// @file contact_energy.hpp
/// The material-depth contact energy (docs/theory.md, dissertation chapter 5) as one term of
/// the total potential:
///   Ec(x) = Σ over pairs (t, e) (ε_te / 2) ∫_{t ∩ e} g_e(y)² da(y)      (area method), or
///   Ec(x) = Σ over pairs (t, e) (ε_te / 2) Σ_{v of t in e} (A_t/3) g_e(x_v)²  (point method),
/// t a contact-surface triangle and e a tetrahedron of any body, the same body included
/// (self-contact); pairs that share a node are skipped. It sees only positions, connectivity,
/// nodal depths and penalties, never the finite element model.
///
/// ContactEnergy is a thin adapter of the Energy interface over a CollisionSet (the pairs, the
/// Hessian pattern union and its revision; collision_set.hpp) and the PairIntegrator of the
/// method (pair_integrator.hpp). Figures for output come from contact_report (contact_report.hpp),
/// which does not change the energy.
///
/// Units: lengths L, depths L, penalties ε in force / L³ (stress per length: a penetration g
/// meets a pressure of about ε g), energy in force × L, gradient in force.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "sinew/contact/collision_set.hpp"
#include "sinew/contact/contact_geometry.hpp"
#include "sinew/core/energy.hpp"

namespace sinew::contact {

/// Joins the pairs the parts of a run detected (CollisionShare::join).
using PairJoin = std::function<void(std::vector<ActivePair>& pairs, std::size_t& candidates)>;

class ContactEnergy final : public Energy {
 public:
  /// Throws InputError when sizes disagree, a depth is negative or not finite, a penalty is
  /// negative or not finite, or the penalty matrix is not #B x #B (validate_contact_geometry).
  ContactEnergy(ContactGeometry geometry, ContactOptions options);

  std::string_view name() const override { return "contact"; }
  /// Ec at x (force × L); +inf when the last update() overflowed (see is_valid).
  double value(const Positions& x) const override;
  /// False when the broad phase at x found more candidate pairs than ContactOptions::
  /// candidate_cap (by default 20 per tet, at least 100000): the bodies overlap far beyond
  /// anything contact can resolve, as in a wild Newton trial state. Such a state is rejected
  /// without building its pairs, which would take memory in proportion to the overlap.
  bool is_valid(const Positions& x) const override;
  /// grad (#V x 3) += dEc/dx (force). Throws Error at an overflowed configuration.
  void add_gradient(const Positions& x, NodalVectors& grad) const override;
  /// H += d²Ec/dx² (force / L) of the kind ContactOptions::hessian, into the blocks of
  /// hessian_pattern(); throws std::logic_error when a block is missing. With the exact kind, a
  /// pair whose triangle or tet is immovable (pair_unknowns) adds nothing to the rows and
  /// columns of that side's nodes, which no unknown moves.
  void add_hessian(const Positions& x, BlockSparseMatrix& H) const override;
  /// The union of the node blocks of every pair active since construction.
  void hessian_pattern(std::vector<std::pair<Index, Index>>& pairs) const override;
  /// Recomputes the pairs at x (#V x 3) unless x is the configuration of the last update.
  void update(const Positions& x) override;
  /// Rebuilds the tree at x (#V x 3), then recomputes the pairs.
  void begin_step(const Positions& x) override;
  std::uint64_t pattern_revision() const override { return collisions_.pattern_revision(); }

  /// Replaces the body-pair penalties (CollisionSet::set_penalty): the energy changes, the
  /// pairs and the Hessian pattern do not.
  void set_penalty(const MatrixX& penalty) { collisions_.set_penalty(penalty); }
  /// Sets the augmented Lagrangian nodal pressures (#V, force / L², or 0 rows for none;
  /// CollisionSet::set_pressure): each pair's energy gains ∫ p r(g) da, r the onset ramp.
  void set_pressure(VectorX pressure) { collisions_.set_pressure(std::move(pressure)); }
  const VectorX& pressure() const { return collisions_.pressure(); }
  /// The depth δ (L) over which the pressures ramp up (CollisionSet::set_pressure_onset).
  void set_pressure_onset(double onset) { collisions_.set_pressure_onset(onset); }

  /// The collision set at the last update() (pairs, pattern, times).
  const CollisionSet& collisions() const { return collisions_; }
  /// On several ranks (docs/mpi.md, "Who owns what"): value(), add_gradient() and add_hessian()
  /// take only the pairs whose tet `tet_owner` (#T of the geometry, a rank per tet) gives to
  /// `part`. With a `join` the parts also split the collision detection by the same owners
  /// (CollisionSet::set_share; every part must then set its share alike), and the join leaves
  /// every part with all the pairs; without one, detection runs whole on every part. Validity and
  /// the pattern are whole either way. Empty `tet_owner` (the default): all pairs, whole
  /// detection. Throws sinew::Error when `tet_owner` is neither empty nor one per tet.
  void set_share(std::vector<int> tet_owner, int part, PairJoin join = {});
  /// The active (triangle, tet) pairs at the last update(), in the broad phase's order.
  std::vector<std::pair<Index, Index>> active_pairs() const { return collisions_.pair_indices(); }
  const ContactGeometry& geometry() const { return collisions_.geometry(); }
  const CollisionTimes& last_update_times() const { return collisions_.times(); }
  const ContactOptions& options() const { return options_; }
  Index num_bodies() const { return static_cast<Index>(geometry().penalty.rows()); }
  /// ε of surface triangle f against tet t: the body pair's penalty times the smaller of the
  /// two penalty scales (force / L³).
  double pair_penalty(Index f, Index t) const { return contact::pair_penalty(geometry(), f, t); }

 private:
  /// Throws std::logic_error unless x is the configuration of the last update().
  void require_current(const Positions& x) const;
  /// The indices into the pair list of the pairs this share evaluates (all of them by default).
  std::vector<std::size_t> shared_pairs() const;

  ContactOptions options_;
  CollisionSet collisions_;
  std::vector<int> tet_owner_;  ///< #T or empty (every pair is this share's)
  int share_part_ = 0;
};

/// Ec (force × L) of the pairs of `collisions` at x (#V x 3), which must be the set's current
/// positions; +inf when the set overflowed. Pair energies are summed in the set's order.
/// `which`: the indices into the set's pair list of the pairs to sum (the overload without: all).
double contact_energy_value(const CollisionSet& collisions, const Positions& x, const std::vector<std::size_t>& which);
double contact_energy_value(const CollisionSet& collisions, const Positions& x);

/// The gradient (force) of one pair's energy (ε/2) I with respect to its 21 local variables
/// (pair_integral.hpp), at positions x (#V x 3).
PairVector pair_energy_gradient(const CollisionSet& collisions, const ActivePair& pair, const Positions& x);

}  // namespace sinew::contact
