#pragma once
/// @file pair_integrator.hpp
/// The per-pair part of the contact energy that depends on the method, chosen once per method
/// (docs/theory.md, "Material-depth contact energy"):
///   area method:  the support of a (triangle, tet) pair is the clip polygon triangle ∩ tet and
///                 I = ∫ g² da over it;
///   point method: the support is the set of triangle vertices inside the tet and
///                 I = Σ (A_t / 3) g² over them (the dissertation's collocation, chapter 5).
/// Everything else (collision detection, scaling by ε/2, assembly, reporting) is the same for
/// both methods and never asks which one it has.

#include "sinew/collision/clip_triangle_tet.hpp"
#include "sinew/contact/contact_geometry.hpp"
#include "sinew/contact/pair_integral.hpp"

namespace sinew::contact {

/// Where a pair's integrand is evaluated; the integrator of the method uses one member.
struct PairSupport {
  collision::ClipPolygon polygon;       ///< area method: triangle ∩ tet (barycentric vertices)
  collision::CollocationPoints points;  ///< point method: the triangle's vertices inside the tet
};

/// The method-specific operations on one pair. Each takes the pair's current geometry
/// (PairGeometry: positions in L, depths in L) and its support from find_support() at the same
/// geometry; integrals I are in L⁴, gradients dI/d(21 local variables) in L³, Hessians in L².
struct PairIntegrator {
  ContactMethod method;
  /// Narrow phase: fills `support` and returns true when the pair has contact (a polygon with
  /// area, or at least one triangle vertex inside the tet); `support` is unspecified otherwise.
  bool (*find_support)(const PairGeometry& pair, PairSupport& support);
  /// I.
  double (*integral)(const PairGeometry& pair, const PairSupport& support);
  /// I; writes dI/dx into `gradient`.
  double (*integral_gradient)(const PairGeometry& pair, const PairSupport& support, PairVector& gradient);
  /// I; writes the gradient and the 21 x 21 Hessian of kind `kind` with respect to `unknowns`.
  double (*integral_hessian)(const PairGeometry& pair, const PairSupport& support, PairHessian kind,
                             PairUnknowns unknowns, PairVector& gradient, PairMatrix& hessian);
  /// Area (L²), ∫ g da (L³) and largest g (L) of the support (point method: A_t/3 per vertex).
  PolygonMoments (*moments)(const PairGeometry& pair, const PairSupport& support);
};

/// The integrator of `method` (a static table: the reference stays valid).
const PairIntegrator& pair_integrator(ContactMethod method);

/// False when the tet lies on one side of the triangle's plane (touching it at most along an edge
/// within round-off), so triangle ∩ tet has no area: the pair can be rejected before clipping.
/// A tet with a face in the plane is kept (its intersection with the triangle can have area).
bool tet_crosses_triangle_plane(const PairGeometry& pair);

/// False when the tet lies wholly beyond one of the triangle's edges: every tet vertex on the far
/// side of the plane through that edge perpendicular to the triangle, by more than 1e-9 of the
/// pair's coordinate scale, so triangle ∩ tet is empty. A separating-axis test (the axes n × e of
/// the triangle's normal n and edges e) that costs a fraction of a clip; near-touching and
/// degenerate pairs are kept for the clip to decide.
bool tet_within_triangle_edges(const PairGeometry& pair);

}  // namespace sinew::contact
