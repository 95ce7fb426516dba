#pragma once
/// @file clip_triangle_tet.hpp
/// The intersection of a triangle with a tetrahedron (the integration domain of the contact
/// energy, docs/theory.md): the triangle clipped by the four face half-spaces of the tet
/// (Sutherland-Hodgman on the triangle's plane). Every polygon vertex carries its provenance
/// (a triangle vertex, a triangle edge crossing a tet face plane, or a tet edge crossing the
/// triangle's plane), from which the exact derivatives of the contact energy are built, and its
/// barycentric coordinates in the tet. Fixed capacity, no heap.
///
/// Conventions: tet face f is the face opposite tet vertex f, i.e. the plane xi_f = 0, and its
/// inside half-space is xi_f >= 0 (xi = barycentric coordinates in the tet). Points within about
/// kClipSnap (relative) of a face plane are treated as exactly on it; the face's plane is computed
/// from its vertices in a fixed (lexicographic) order, so two tets sharing a face agree bitwise on
/// which points lie on it, and on which side the others lie.
///
/// Half-open rule (docs/contact.md): a triangle lying in the plane of face f belongs to the tet
/// only if the tet is on the side of the triangle's outward normal (away from the triangle's own
/// body, for an outward-oriented surface); it is then clipped by the other faces only. Of two tets
/// sharing that face exactly one takes it; a triangle resting on a boundary face of another body
/// (touching, zero gap) belongs to that body's tet, and one lying beside another body's face in
/// the same plane, both bodies on the same side (a common cut plane), to none. A collocation
/// point on a face plane belongs to the tet if the perturbation x + δ n + δ² d1 + δ³ d2 + δ⁴ d3
/// (δ -> 0+) moves it into the tet, n the triangle's outward normal and d1..d3
/// tie_break_directions(): in a conforming mesh exactly one of the tets around a shared face, edge or node gets it. Other points on face
/// planes only bound the clip polygon and make no difference to its area.
/// Lengths are in the caller's unit; barycentric coordinates are dimensionless.

#include <array>
#include <cstdint>

#include "sinew/core/types.hpp"

namespace sinew::collision {

/// A triangle clipped by 4 planes has at most 3 + 4 vertices.
inline constexpr int kMaxClipVertices = 7;

/// Barycentric values with |xi| <= kClipSnap are taken as exactly 0 when classifying against a
/// face plane (dimensionless, hence independent of the length unit).
inline constexpr double kClipSnap = 1e-14;

/// What a clip-polygon vertex is, in terms of the raw node positions.
enum class ClipVertexKind : std::uint8_t {
  TriangleVertex,       ///< triangle vertex `a`
  TriangleEdgeTetFace,  ///< triangle edge (a, b) crossing the plane of tet face `face`
  TetEdgeTrianglePlane  ///< tet edge (a, b) crossing the plane of the triangle
};

/// Provenance of one polygon vertex. Indices are local: triangle vertices 0..2, tet vertices
/// (and faces) 0..3. For the two edge kinds a < b. Unused fields are -1.
struct ClipVertexProvenance {
  ClipVertexKind kind = ClipVertexKind::TriangleVertex;
  std::int8_t a = -1;     ///< triangle vertex, or first vertex of the triangle/tet edge
  std::int8_t b = -1;     ///< second vertex of the triangle edge or of the tet edge
  std::int8_t face = -1;  ///< TriangleEdgeTetFace only: the tet face (= opposite tet vertex)

  friend bool operator==(const ClipVertexProvenance&, const ClipVertexProvenance&) = default;
};

/// The convex polygon triangle ∩ tet, vertices in order around the polygon (same turning sense
/// as the triangle's vertex order). `count` is 0 when the intersection is empty or has fewer
/// than 3 vertices; a degenerate (zero-area) polygon may still have count >= 3.
struct ClipPolygon {
  int count = 0;
  std::array<Vector3, kMaxClipVertices> vertices;                  ///< positions (length unit)
  /// Barycentric coordinates in the tet, clamped to [0, 1] and summing to 1.
  std::array<Eigen::Vector4d, kMaxClipVertices> barycentric;
  std::array<ClipVertexProvenance, kMaxClipVertices> provenance;

  bool empty() const { return count == 0; }
};

/// The fixed directions d1, d2, d3 (spanning space) of the half-open rule, after the triangle's
/// outward normal: (1, √2, √3), then x, then y.
const std::array<Vector3, 3>& tie_break_directions();

/// Clips `triangle` (3x3, one vertex per row) by the tet `tet` (4x3, one vertex per row,
/// either orientation), with the half-open rule for a triangle in a face plane. Exits early
/// when the triangle lies strictly outside one face plane.
/// A degenerate (zero-volume) tet gives an empty polygon. Never produces NaN for finite input.
ClipPolygon clip_triangle_tet(const Matrix3& triangle, const Eigen::Matrix<double, 4, 3>& tet);

/// Barycentric coordinates of point `x` in `tet` (4x3, rows = vertices), computed per face as
/// xi_f = n_f.(x - p) / n_f.(P_f - p) with n_f the normal of face f and p a vertex on it.
/// The four values sum to 1 up to round-off; NaN/inf only for a zero-volume tet.
Eigen::Vector4d tet_barycentric(const Vector3& x, const Eigen::Matrix<double, 4, 3>& tet);

/// Point-collocation baseline (dissertation §5.3.5): the triangle vertices that lie in the tet
/// (barycentric coordinates >= 0 after snapping, the half-open rule on face planes), in increasing order, with their
/// barycentric coordinates (clamped to [0, 1], summing to 1). The caller applies weight A/3 each.
struct CollocationPoints {
  int count = 0;
  std::array<std::int8_t, 3> vertex{{-1, -1, -1}};  ///< local triangle vertex indices
  std::array<Eigen::Vector4d, 3> barycentric;
};

CollocationPoints triangle_vertices_in_tet(const Matrix3& triangle,
                                           const Eigen::Matrix<double, 4, 3>& tet);

}  // namespace sinew::collision
