#pragma once
/// @file contact_geometry.hpp
/// What takes part in contact, as plain arrays over the global node numbering, and the options
/// of the contact term (docs/theory.md, "Material-depth contact energy"; dissertation chapter 5).
/// Nothing here knows the finite element model.
///
/// Units: lengths L, depths L, penalties ε in force / L³ (stress per length: a penetration g
/// meets a pressure of about ε g).

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sinew/contact/pair_integral.hpp"
#include "sinew/core/enum_names.hpp"
#include "sinew/core/types.hpp"

namespace sinew::contact {

enum class ContactMethod {
  Area,  ///< exact integral over triangle ∩ tet (the default; continuous forces)
  Point  ///< the dissertation's point collocation at triangle vertices (baseline)
};

/// Scene and command-line names of ContactMethod.
inline constexpr NameTable<ContactMethod, 2> kContactMethodNames{{
    {ContactMethod::Area, "area"},
    {ContactMethod::Point, "point"},
}};
constexpr const auto& enum_names(ContactMethod) { return kContactMethodNames; }

/// What takes part in contact, as plain arrays over the global node numbering.
struct ContactGeometry {
  Triangles surface;          ///< #F x 3 contact-surface triangles, outward-oriented, every body
  IndexVector surface_body;   ///< #F: body of each surface triangle (0 .. #B-1)
  Tets tets;                  ///< #T x 4 tets that can be penetrated, every body
  IndexVector tet_body;       ///< #T: body of each tet
  VectorX depth;              ///< #V: material depth per node (L), >= 0
  MatrixX penalty;            ///< #B x #B symmetric: ε per pair of bodies (force / L³); 0 = off
  /// Optional factors on the pair penalty, per surface triangle (#F) and per tet (#T), > 0;
  /// empty means 1. A (triangle, tet) pair uses penalty(bodies) x min(triangle's, tet's): the
  /// softer part governs, so e.g. two rigid parts can meet stiffly while soft tissue against
  /// either keeps the body pair's penalty.
  VectorX surface_penalty_scale;
  VectorX tet_penalty_scale;
  /// Optional, #V or empty (none): 1 marks a node no unknown moves (fixed, prescribed, or a
  /// member of a fixed or prescribed rigid body). A (triangle, tet) pair whose 7 nodes are all
  /// immovable is left out of contact: its energy depends on no unknown, so it cannot change
  /// the solution, yet an overlap of two immovable parts would add its forces to the scale of
  /// Newton's convergence test and its depth to every penetration figure (docs/contact.md,
  /// "Parts that overlap at the start").
  std::vector<std::uint8_t> node_immovable;
};

struct ContactOptions {
  ContactMethod method = ContactMethod::Area;
  PairHessian hessian = PairHessian::Exact;
  /// Most (triangle, tet) candidates of the broad phase a configuration may have before it is
  /// declared invalid (see ContactEnergy::is_valid); 0 = automatic, max(100000, 20 x #tets).
  std::size_t candidate_cap = 0;
};

/// Throws InputError when sizes disagree (node_immovable included, unless empty), a depth is
/// negative or not finite, a penalty or a penalty scale is negative or not finite, the penalty
/// matrix is not #B x #B symmetric, or a triangle or tet refers to a body or node that does not
/// exist.
void validate_contact_geometry(const ContactGeometry& geometry);

/// ε of surface triangle f against tet t: the body pair's penalty times the smaller of the two
/// penalty scales (force / L³).
inline double pair_penalty(const ContactGeometry& geometry, Index f, Index t);

/// The 7 global nodes of the pair (surface triangle f, tet t) in the local variable order of
/// pair_integral.hpp: the triangle's 3 nodes, then the tet's 4.
inline std::array<Index, 7> pair_nodes(const ContactGeometry& geometry, Index f, Index t);

/// The current positions x (#V x 3, L) of the pair (f, t) and the material depths (L) at the
/// tet's nodes.
inline PairGeometry pair_geometry(const ContactGeometry& geometry, const Positions& x, Index f, Index t);

/// True when geometry.node_immovable marks all 7 nodes of the pair (surface triangle f, tet t).
inline bool pair_is_immovable(const ContactGeometry& geometry, Index f, Index t);

/// The nodes of the pair whose Hessian rows are wanted (pair_integral.hpp): Tet when the
/// triangle's three nodes are all immovable, Triangle when the tet's four are, All otherwise
/// (also for a pair immovable on both sides, which the pair search leaves out).
inline PairUnknowns pair_unknowns(const ContactGeometry& geometry, Index f, Index t);

inline double pair_penalty(const ContactGeometry& g, Index f, Index t) {
  double e = g.penalty(g.surface_body[f], g.tet_body[t]);
  if (g.surface_penalty_scale.size() > 0 || g.tet_penalty_scale.size() > 0) {
    const double sf = g.surface_penalty_scale.size() > 0 ? g.surface_penalty_scale[f] : 1.0;
    const double st = g.tet_penalty_scale.size() > 0 ? g.tet_penalty_scale[t] : 1.0;
    e *= std::min(sf, st);
  }
  return e;
}

inline std::array<Index, 7> pair_nodes(const ContactGeometry& g, Index f, Index t) {
  const auto& F = g.surface;
  const auto& T = g.tets;
  return {F(f, 0), F(f, 1), F(f, 2), T(t, 0), T(t, 1), T(t, 2), T(t, 3)};
}

inline PairGeometry pair_geometry(const ContactGeometry& g, const Positions& x, Index f, Index t) {
  PairGeometry pg;
  for (int k = 0; k < 3; ++k) pg.triangle.row(k) = x.row(g.surface(f, k));
  for (int k = 0; k < 4; ++k) {
    const Index a = g.tets(t, k);
    pg.tet.row(k) = x.row(a);
    pg.depth[k] = g.depth[a];
  }
  return pg;
}

inline bool pair_is_immovable(const ContactGeometry& g, Index f, Index t) {
  if (g.node_immovable.empty()) return false;
  for (const Index a : pair_nodes(g, f, t))
    if (!g.node_immovable[static_cast<std::size_t>(a)]) return false;
  return true;
}

inline PairUnknowns pair_unknowns(const ContactGeometry& g, Index f, Index t) {
  if (g.node_immovable.empty()) return PairUnknowns::All;
  const auto immovable = [&g](Index a) { return g.node_immovable[static_cast<std::size_t>(a)] != 0; };
  const bool triangle_held = immovable(g.surface(f, 0)) && immovable(g.surface(f, 1)) && immovable(g.surface(f, 2));
  const bool tet_held =
      immovable(g.tets(t, 0)) && immovable(g.tets(t, 1)) && immovable(g.tets(t, 2)) && immovable(g.tets(t, 3));
  if (triangle_held == tet_held) return PairUnknowns::All;
  return triangle_held ? PairUnknowns::Tet : PairUnknowns::Triangle;
}

}  // namespace sinew::contact
