#pragma once
/// @file contact_report.hpp
/// Contact figures of one configuration for logs and output: pair count, contact area,
/// penetration, energy, nodal forces and pressures, and the force each pair of bodies exerts
/// (docs/theory.md, "Material-depth contact energy"). Reporting never changes the energy the
/// solver uses.

#include <vector>

#include "sinew/contact/collision_set.hpp"
#include "sinew/contact/contact_energy.hpp"

namespace sinew::contact {

struct ContactReport {
  Index pairs = 0;               ///< intersecting (triangle, tet) pairs
  double area = 0;               ///< Σ polygon areas (L²); point method: Σ A_t/3 per inside vertex
  double max_penetration = 0;    ///< largest interpolated depth on any polygon (L)
  double mean_penetration = 0;   ///< ∫ g da / area (L), 0 without contact
  double energy = 0;             ///< Ec (force × L); +inf when the collision set overflowed
  Index num_bodies = 0;          ///< #B
  /// Force on body i from body j for i < j (the sum of the contact forces on body i's nodes
  /// from the pairs between i and j), indexed [i * #B + j]; zero for i >= j. Force unit.
  std::vector<Vector3> body_pair_force;
  /// Self-contact per body b (#B): half the sum over b's nodes of the magnitude of the nodal
  /// force from pairs within b (a magnitude: the vector sum of internal forces is zero). Force.
  VectorX self_contact_force_magnitude;
  /// Largest interpolated depth on the polygons between bodies i and j (self-contact when
  /// i == j), indexed [i * #B + j] for i <= j; zero for i > j (L).
  std::vector<double> body_pair_max_penetration;
  NodalVectors nodal_force;      ///< -dEc/dx, #V x 3 (force)
  VectorX nodal_pressure;        ///< |nodal force| / (1/3 of the adjacent surface area), #V (stress)

  /// Force on body i from body j, i < j (force).
  const Vector3& force_between(Index i, Index j) const {
    return body_pair_force[static_cast<std::size_t>(i * num_bodies + j)];
  }
  /// Largest penetration between bodies i and j, i <= j (L).
  double max_penetration_between(Index i, Index j) const {
    return body_pair_max_penetration[static_cast<std::size_t>(i * num_bodies + j)];
  }
};

/// Figures of the pairs of `collisions` at its current positions (CollisionSet::positions()).
ContactReport contact_report(const CollisionSet& collisions);

/// Figures at x (#V x 3): from energy.collisions() when its pairs are those of x, otherwise
/// from a local collision set updated to x. The energy is not changed.
ContactReport contact_report(const ContactEnergy& energy, const Positions& x);

}  // namespace sinew::contact
