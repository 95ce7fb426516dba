#pragma once
/// @file friction.hpp
/// Coulomb friction on material-depth contact as a lagged dissipative potential (docs/contact.md,
/// "Friction"; dissertation §10.1.5), in the manner of IPC's lagged friction:
///
///   D(x) = Σ over friction points k of μ_k N_k f0(|u_k(x)|),
///   u_k = T_kᵀ [ Σ_a β_ka (x_a - x̂_a) - Σ_b ξ_kb (x_b - x̂_b) ],
///
/// x̂ the positions at the start of the load or time step. The points are the quadrature points
/// of the contact supports at a lag state: per clip polygon the centroids of its fan triangles
/// (weight: their area), per collocation point the triangle vertex (weight A_t/3). Each carries
/// the triangle's shape functions β_k (3) and the tet's barycentric coordinates ξ_k (4) of the
/// same material point, the normal force N_k = weight × (ε g + p) |∇g| at the lag state (p the
/// augmented Lagrangian pressure; (ε g + p) ∇g is the force density the pair exerts there), and a tangent basis T_k (3 x 2) orthogonal to the triangle's
/// normal (the sliding surface; the depth gradient of a coarse tet points toward the body's
/// middle, not across the surface). μ_k is the friction coefficient of the two bodies. f0 is C¹ with a
/// slip threshold ε_u (length):
///   f0(s) = s² / ε_u - s³ / (3 ε_u²) + ε_u / 3 for s < ε_u, s beyond (force μN once sliding).
/// With these lagged, D is a smooth function of x and Newton minimizes E + D; the stepper
/// refreshes the lag after a converged solve until the normal forces stop changing.
/// Units: lengths L, forces F, D in F × L.

#include <cstdint>
#include <unordered_set>
#include <utility>
#include <vector>

#include "sinew/contact/contact_energy.hpp"
#include "sinew/core/energy.hpp"

namespace sinew::contact {

/// One lagged friction point.
struct FrictionPoint {
  Index triangle = 0;             ///< row of ContactGeometry::surface
  Index tet = 0;                  ///< row of ContactGeometry::tets
  Vector3 triangle_weights;       ///< β: the triangle's shape functions at the point
  Eigen::Vector4d tet_weights;    ///< ξ: barycentric coordinates in the tet
  Eigen::Matrix<double, 3, 2> basis;  ///< T: orthonormal tangent directions (columns)
  double normal_force = 0;        ///< N (force)
  double mu = 0;                  ///< friction coefficient
};

struct FrictionOptions {
  MatrixX mu;                     ///< #B x #B symmetric friction coefficients (>= 0)
  double slip_threshold = 0;      ///< ε_u (L, > 0): below this tangential slip per step, f0 is quadratic
  /// ε_v (L / T, >= 0): when > 0, time stepping sets ε_u = ε_v h for every step of size h
  /// (set_time_step), so that what sticks creeps slower than ε_v whatever the step; slip_threshold
  /// is then only the value before the first step.
  double slip_velocity_threshold = 0;
};

/// The lagged friction points of the pairs of `contact` at its current configuration (the
/// positions of its last update), for the body pairs with μ > 0.
std::vector<FrictionPoint> friction_points(const ContactEnergy& contact, const MatrixX& mu);

/// f0(s), f1(s) = f0'(s) and f1(s) / s of the smoothed Coulomb law with threshold eps (> 0).
double friction_f0(double s, double eps);
double friction_f1_over_s(double s, double eps);

class FrictionEnergy final : public Energy {
 public:
  /// Throws InputError for a μ matrix of the wrong size, not symmetric, negative or not finite,
  /// or a slip threshold that is not finite and > 0. `contact` must outlive the energy.
  FrictionEnergy(ContactEnergy& contact, FrictionOptions options);

  std::string_view name() const override { return "friction"; }
  double value(const Positions& x) const override;
  void add_gradient(const Positions& x, NodalVectors& grad) const override;
  void add_hessian(const Positions& x, BlockSparseMatrix& H) const override;
  void hessian_pattern(std::vector<std::pair<Index, Index>>& pairs) const override;
  /// A step starts from x: x̂ = x and the points are lagged at x (the contact term, listed
  /// before this one in the objective, has its pairs at x).
  void begin_step(const Positions& x) override;
  /// With a slip velocity threshold ε_v: ε_u = ε_v h for the step of size h (time) that follows.
  void set_time_step(double h) override;
  std::uint64_t pattern_revision() const override { return revision_; }

  /// Lags the points again at x (a converged state of the current step), keeping x̂. Returns
  /// the relative change of the total normal force, |ΣN_new - ΣN_old| / max(ΣN_new, ΣN_old),
  /// 0 when both are 0.
  double refresh(const Positions& x);

  const std::vector<FrictionPoint>& points() const { return points_; }
  const Positions& step_start() const { return start_; }
  const FrictionOptions& options() const { return options_; }
  /// The tangential slip u_k (L) of every point at x, as a 2-vector per point.
  std::vector<Eigen::Vector2d> slips(const Positions& x) const;
  /// The friction force on body i from body j at x, for i < j, indexed [i * #B + j]; zero for
  /// i >= j (force).
  std::vector<Vector3> body_pair_forces(const Positions& x) const;
  /// Per node (#V): the largest |u_k| / ε_u of the points on the node's triangles at x; 1 or
  /// more where the surface slides, below 1 where it sticks, 0 off contact.
  VectorX slip_ratio(const Positions& x) const;

 private:
  void lag(const Positions& x);
  std::array<Index, 7> nodes(const FrictionPoint& p) const;

  ContactEnergy& contact_;
  FrictionOptions options_;
  Positions start_;
  std::vector<FrictionPoint> points_;
  std::unordered_set<std::uint64_t> pattern_;
  std::uint64_t revision_ = 0;
};

}  // namespace sinew::contact
