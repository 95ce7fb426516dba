#pragma once
/// @file pair_integral.hpp
/// The contact integral of one (boundary triangle, tetrahedron) pair and its exact derivatives
/// (docs/theory.md):
///   area method:  I = ∫_{t ∩ e} g_e(y)² da(y), integrated exactly over the clip polygon,
///   point method: I = Σ over triangle vertices v inside e of (A_t / 3) g_e(x_v)²,
/// with g_e the linear interpolation of the nodal material depths over the tet, all in the
/// current configuration. The pair's energy is (ε/2) I.
///
/// With augmented Lagrangian multipliers (docs/contact.md, "Augmented Lagrangian"; dissertation
/// §10.1.2) the integrand g² becomes g² + 2 q r(g), q the contact pressure p interpolated linearly
/// over the triangle from its vertices and divided by the pair's penalty (q = p / ε, a length):
/// the pair's energy (ε/2) I is then (ε/2) ∫ g² + ∫ p r(g). r is the multiplier's onset ramp of
/// width δ (PairGeometry::multiplier_onset): r(g) = g² / (2δ) for g < δ, g − δ/2 beyond, so the
/// pressure p r'(g) grows from 0 at the surface to p at depth δ and the energy stays C¹ where a
/// point leaves the body (with δ = 0, r(g) = g and the force jumps from 0 to p there).
///
/// Local variables (21): the three triangle vertices, then the four tet vertices, x y z each:
/// variable 3 k + c is coordinate c of local node k (k = 0..2 triangle, 3..6 tet vertex k - 3).
/// The polygon's combinatorics (which edges cross which planes) comes from the clip; every
/// polygon vertex is then recomputed as a smooth function of the 21 variables, so the gradient
/// is the exact gradient of I, including the motion of the polygon's edges and the change of
/// its area. Units: lengths L, depths L, I in L^4.

#include "sinew/collision/clip_triangle_tet.hpp"
#include "sinew/core/enum_names.hpp"
#include "sinew/core/types.hpp"

namespace sinew::contact {

inline constexpr int kPairVariables = 21;
using PairVector = Eigen::Matrix<double, kPairVariables, 1>;
using PairMatrix = Eigen::Matrix<double, kPairVariables, kPairVariables>;
using TetVertices = Eigen::Matrix<double, 4, 3>;

/// Current positions of one pair and the material depths at the tet's nodes.
struct PairGeometry {
  Matrix3 triangle;       ///< rows: triangle vertices (L)
  TetVertices tet;        ///< rows: tet vertices (L)
  Eigen::Vector4d depth;  ///< material depth at the tet vertices (L)
  /// q = p / ε at the triangle vertices (L): the augmented Lagrangian pressure over the pair's
  /// penalty; zero without multipliers.
  Vector3 multiplier = Vector3::Zero();
  /// δ (L, >= 0): the depth over which the multiplier's pressure ramps up from 0 to p (see
  /// above); 0 = no ramp.
  double multiplier_onset = 0;
};

/// How the Hessian of a pair is formed.
enum class PairHessian {
  Exact,       ///< the exact second derivative (indefinite in general)
  GaussNewton,  ///< Σ w ∇g ∇gᵀ over the quadrature of g² with frozen areas: positive semi-definite
  Projected     ///< the exact second derivative projected onto the PSD cone (negative eigenvalues -> 0)
};

/// Scene names of PairHessian.
inline constexpr NameTable<PairHessian, 3> kPairHessianNames{{
    {PairHessian::Exact, "exact"},
    {PairHessian::Projected, "projected"},
    {PairHessian::GaussNewton, "gauss-newton"},
}};
constexpr const auto& enum_names(PairHessian) { return kPairHessianNames; }

/// Which of a pair's nodes its Hessian is wanted for. A side whose nodes no unknown moves (fixed,
/// prescribed, members of a fixed or prescribed rigid body) needs no rows: its nodes are held
/// constant, the derivatives are taken with respect to the other side's 9 or 12 coordinates
/// only (a third to a half of the work), and the held side's rows and columns of the Hessian,
/// and its entries of the gradient, come out zero. The other entries are the same numbers as
/// with All. Only PairHessian::Exact uses it: Projected (which projects the whole 21 x 21 matrix)
/// and GaussNewton always give all rows.
enum class PairUnknowns {
  All,       ///< all seven nodes
  Triangle,  ///< the triangle's three nodes (the tet's are held)
  Tet,       ///< the tet's four nodes (the triangle's are held)
};

/// ∫ g² da over the clip polygon `polygon` (from clip_triangle_tet of the same geometry).
/// Zero for an empty polygon.
double area_integral(const PairGeometry& pair, const collision::ClipPolygon& polygon);
/// Same value; also writes dI/d(21 variables) into `gradient`.
double area_integral_gradient(const PairGeometry& pair, const collision::ClipPolygon& polygon,
                              PairVector& gradient);
/// Same value and gradient; also writes the Hessian (21 x 21) of the chosen kind, with respect to
/// `unknowns` (the gradient too).
double area_integral_hessian(const PairGeometry& pair, const collision::ClipPolygon& polygon, PairHessian kind,
                             PairVector& gradient, PairMatrix& hessian, PairUnknowns unknowns = PairUnknowns::All);

/// Polygon statistics: area (L²), ∫ g da (L³) and the largest g on the polygon (L); and per
/// triangle vertex k, with N_k its linear shape function on the triangle, ∫ N_k da (L²) and
/// ∫ N_k g da (L³), which the augmented Lagrangian update of the vertex pressures uses.
struct PolygonMoments {
  double area = 0;
  double depth_integral = 0;
  double max_depth = 0;
  Vector3 vertex_area = Vector3::Zero();
  Vector3 vertex_depth_integral = Vector3::Zero();
};
PolygonMoments area_moments(const PairGeometry& pair, const collision::ClipPolygon& polygon);

/// r'(g) = min(1, g / δ) of the multipliers' onset ramp (1 for δ = 0): the fraction of the
/// pressure p a point at depth g (L) carries.
double onset_ramp_slope(double g, double onset);

/// The gradient of the tet's affine depth field ∇g_e (dimensionless; zero for a flat tet).
Vector3 depth_gradient(const PairGeometry& pair);
/// The triangle's linear shape functions (N0, N1, N2) at a point y of its plane.
Vector3 triangle_shape_functions(const PairGeometry& pair, const Vector3& y);

/// Point collocation: Σ over `points` (the triangle vertices inside the tet) of (A_t/3) g².
double point_integral(const PairGeometry& pair, const collision::CollocationPoints& points);
double point_integral_gradient(const PairGeometry& pair, const collision::CollocationPoints& points,
                               PairVector& gradient);
double point_integral_hessian(const PairGeometry& pair, const collision::CollocationPoints& points,
                              PairHessian kind, PairVector& gradient, PairMatrix& hessian,
                              PairUnknowns unknowns = PairUnknowns::All);
PolygonMoments point_moments(const PairGeometry& pair, const collision::CollocationPoints& points);

}  // namespace sinew::contact
