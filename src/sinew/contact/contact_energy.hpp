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
/// Collision detection: an AabbTree over the tets is built by begin_step() and refit by
/// update() at every new configuration; each surface triangle is queried against it, the
/// candidates clipped (triangle ∩ tet) and the non-empty ones kept as the active pairs.
/// The Hessian pattern is the union of the node blocks of every pair active since the term
/// was created; pattern_revision() grows when new blocks appear.
///
/// Units: lengths L, depths L, penalties ε in force / L³ (stress per length: a penetration g
/// meets a pressure of about ε g), energy in force × L.

#include <algorithm>
#include <cstdint>
#include <unordered_set>
#include <utility>
#include <vector>

#include "sinew/collision/aabb_tree.hpp"
#include "sinew/collision/clip_triangle_tet.hpp"
#include "sinew/contact/pair_integral.hpp"
#include "sinew/core/energy.hpp"
#include "sinew/core/enum_names.hpp"

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
};

struct ContactOptions {
  ContactMethod method = ContactMethod::Area;
  PairHessian hessian = PairHessian::Exact;
  /// Most (triangle, tet) candidates of the broad phase a configuration may have before it is
  /// declared invalid (see ContactEnergy::is_valid); 0 = automatic, max(100000, 20 x #tets).
  std::size_t candidate_cap = 0;
};

/// Per-configuration contact figures (for logs and output).
struct ContactStatistics {
  Index pairs = 0;                ///< intersecting (triangle, tet) pairs
  double area = 0;                ///< Σ polygon areas (L²); point method: Σ A_t/3 per inside vertex
  double max_penetration = 0;     ///< largest interpolated depth on any polygon (L)
  double mean_penetration = 0;    ///< ∫ g da / area (L), 0 without contact
  double energy = 0;              ///< Ec (force × L)
  /// Force on body i from body j (i < j), and for self-contact (i == i) half the sum of the
  /// nodal force magnitudes. Indexed [i * #B + j]. Force unit.
  std::vector<Vector3> body_pair_force;
  NodalVectors nodal_force;       ///< -dEc/dx, #V x 3 (force)
  VectorX nodal_pressure;         ///< |nodal force| / (1/3 of the adjacent surface area), #V (stress)
};

/// Wall-clock seconds of the phases of the last update() that recomputed the pairs.
struct CollisionTimes {
  double refit = 0;  ///< tet boxes and tree refit (or build)
  double query = 0;  ///< triangle queries against the tree (broad phase)
  double clip = 0;   ///< triangle ∩ tet clipping of the candidates (narrow phase)
  Index candidates = 0;
};

class ContactEnergy final : public Energy {
 public:
  /// Throws InputError when sizes disagree, a depth is negative or not finite, a penalty is
  /// negative or not finite, or the penalty matrix is not #B x #B.
  ContactEnergy(ContactGeometry geometry, ContactOptions options);

  std::string_view name() const override { return "contact"; }
  /// +inf when the last update() overflowed (see is_valid).
  double value(const Positions& x) const override;
  /// False when the broad phase at x found more candidate pairs than ContactOptions::
  /// candidate_cap (by default 20 per tet, at least 100000): the bodies overlap far beyond anything contact can resolve, as in a wild
  /// Newton trial state. Such a state is rejected without building its pairs, which would take
  /// memory in proportion to the overlap.
  bool is_valid(const Positions& x) const override;
  void add_gradient(const Positions& x, NodalVectors& grad) const override;
  void add_hessian(const Positions& x, BlockSparseMatrix& H) const override;
  void hessian_pattern(std::vector<std::pair<Index, Index>>& pairs) const override;
  void update(const Positions& x) override;
  void begin_step(const Positions& x) override;
  std::uint64_t pattern_revision() const override { return revision_; }

  /// Figures at x (calls update(x) first).
  ContactStatistics statistics(const Positions& x);

  /// The active (triangle, tet) pairs at the last update(), sorted.
  std::vector<std::pair<Index, Index>> active_pairs() const;
  const ContactGeometry& geometry() const { return geometry_; }
  const CollisionTimes& last_update_times() const { return times_; }
  const ContactOptions& options() const { return options_; }
  Index num_bodies() const { return static_cast<Index>(geometry_.penalty.rows()); }
  /// ε of surface triangle f against tet t: the body pair's penalty times the smaller of the
  /// two penalty scales (force / L³).
  double pair_penalty(Index f, Index t) const {
    double e = geometry_.penalty(geometry_.surface_body[f], geometry_.tet_body[t]);
    if (geometry_.surface_penalty_scale.size() > 0 || geometry_.tet_penalty_scale.size() > 0) {
      const double sf = geometry_.surface_penalty_scale.size() > 0 ? geometry_.surface_penalty_scale[f] : 1.0;
      const double st = geometry_.tet_penalty_scale.size() > 0 ? geometry_.tet_penalty_scale[t] : 1.0;
      e *= std::min(sf, st);
    }
    return e;
  }

 private:
  struct ActivePair {
    Index triangle = 0;
    Index tet = 0;
    double penalty = 0;
    collision::ClipPolygon polygon;          ///< area method
    collision::CollocationPoints points;     ///< point method
  };
  PairGeometry pair_geometry(const Positions& x, const ActivePair& p) const;
  /// The 7 global nodes of a pair in local variable order.
  std::array<Index, 7> pair_nodes(const ActivePair& p) const;
  void require_current(const Positions& x) const;

  ContactGeometry geometry_;
  ContactOptions options_;
  collision::AabbTree tree_;
  bool tree_built_ = false;
  Positions current_x_;
  std::vector<ActivePair> active_;
  std::unordered_set<std::uint64_t> pattern_;
  /// (triangle, tet) keys of every pair whose blocks are in pattern_.
  std::unordered_set<std::uint64_t> pairs_in_pattern_;
  std::uint64_t revision_ = 0;
  CollisionTimes times_;
  bool overflowed_ = false;  ///< the last update() found more candidates than the cap
  /// Tets whose four nodes all have zero depth carry no energy (g ≡ 0) and are skipped.
  std::vector<char> tet_has_depth_;
};

}  // namespace sinew::contact
