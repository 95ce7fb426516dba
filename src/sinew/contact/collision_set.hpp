#pragma once
/// @file collision_set.hpp
/// The set of colliding (surface triangle, tet) pairs of a configuration, in the manner of
/// ipc-toolkit's collision sets: collision detection and its bookkeeping, no energy.
///
/// An AabbTree per body over its tets with a non-zero depth somewhere is built by rebuild() and
/// refit by update() at every new configuration; each surface triangle is queried against the
/// trees of the bodies its body has a positive penalty with (broad phase), and the candidates
/// are kept when their pair's penalty is not zero, not all seven nodes are immovable and the
/// method's PairIntegrator finds a support for them (narrow phase: clip polygon or collocation
/// points). Pairs that share a node never come out of the broad phase. A configuration whose
/// broad phase finds more candidates than the cap is "overflowed": no pairs are built.
///
/// The Hessian pattern is the union of the node blocks of every pair active since the set was
/// created; pattern_revision() grows exactly when new blocks appear (docs/theory.md,
/// "Material-depth contact energy"; dissertation chapter 5).
///
/// The set knows the ContactGeometry (shared, immutable plain arrays) and the method, never the
/// finite element model. Units: lengths L, penalties force / L³, times in wall-clock seconds.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <unordered_set>
#include <utility>
#include <vector>

#include "sinew/collision/aabb_tree.hpp"
#include "sinew/collision/broad_phase.hpp"
#include "sinew/contact/contact_geometry.hpp"
#include "sinew/contact/pair_integrator.hpp"

namespace sinew::contact {

/// Wall-clock seconds of the phases of the last update() that recomputed the pairs.
struct CollisionTimes {
  double refit = 0;  ///< tet boxes and tree refit (or build)
  double query = 0;  ///< triangle queries against the tree (broad phase)
  double clip = 0;   ///< triangle ∩ tet clipping of the candidates (narrow phase)
  Index candidates = 0;
};

/// One colliding pair: surface triangle `triangle` (row of ContactGeometry::surface) against tet
/// `tet` (row of ContactGeometry::tets), with its penalty ε (force / L³) and its support at the
/// configuration of the last update.
struct ActivePair {
  Index triangle = 0;
  Index tet = 0;
  double penalty = 0;
  PairSupport support;
};

/// How the parts of a run on several processes split the detection (docs/mpi.md, "Collision
/// detection split by tet"): each part queries the trees of the tets it detects only, and `join`
/// gathers the parts' pairs so that every part ends with all of them.
struct CollisionShare {
  /// Per tet of the geometry (#T): nonzero when this part detects the pairs of that tet.
  std::vector<char> detects_tet;
  /// Collective: every part calls it at every update that recomputes the pairs (an update to
  /// the positions of the last one recomputes nothing, on every part alike). On entry `pairs`
  /// holds this part's pairs and `candidates` its broad-phase candidates; on return every
  /// part's pairs in part order and the sum of the candidates, the same on every part.
  std::function<void(std::vector<ActivePair>& pairs, std::size_t& candidates)> join;
};

class CollisionSet {
 public:
  /// `candidate_cap`: most broad-phase candidates before the configuration is overflowed;
  /// 0 = automatic, max(100000, 20 x #tets). Throws InputError for an invalid geometry
  /// (validate_contact_geometry).
  CollisionSet(std::shared_ptr<const ContactGeometry> geometry, ContactMethod method, std::size_t candidate_cap = 0);
  CollisionSet(ContactGeometry geometry, ContactMethod method, std::size_t candidate_cap = 0);

  /// Splits the detection among parts (CollisionShare; every part of the split calls it). An
  /// empty `detects_tet` detects every tet alone again. The trees are built anew at the next
  /// update. Throws sinew::Error when `detects_tet` is neither empty nor one per tet, or has no
  /// join.
  void set_share(CollisionShare share);
  /// The split in force (an empty `detects_tet`: this set detects every tet).
  const CollisionShare& share() const { return share_; }

  /// Builds the tree anew at x (#V x 3) and recomputes the pairs (start of a load or time step).
  /// Throws std::invalid_argument when x does not have one row per node of the geometry.
  void rebuild(const Positions& x);
  /// Refits the tree to x (#V x 3; builds it the first time) and recomputes the pairs; does
  /// nothing when x equals the positions of the last update. Throws std::invalid_argument when
  /// x does not have one row per node of the geometry.
  void update(const Positions& x);
  /// True when the pairs are those of x (x equals the positions of the last update).
  bool is_current(const Positions& x) const;
  /// The positions of the last update (#V x 3; 0 rows before the first).
  const Positions& positions() const { return positions_; }

  /// True when the last update's broad phase found more candidates than candidate_cap() (of all
  /// parts together, when shared); the pairs are then empty.
  bool overflowed() const { return overflowed_; }
  /// The colliding pairs at the last update, in the broad phase's order.
  const std::vector<ActivePair>& pairs() const { return active_; }
  /// The (triangle, tet) indices of pairs(), in the same order.
  std::vector<std::pair<Index, Index>> pair_indices() const;
  /// The effective candidate cap.
  std::size_t candidate_cap() const { return candidate_cap_; }
  const CollisionTimes& times() const { return times_; }

  /// Appends the node pairs (a, b), a < b, of every off-diagonal block in the pattern union
  /// (diagonal blocks are not listed: the objective has them anyway).
  void append_pattern(std::vector<std::pair<Index, Index>>& blocks) const;
  /// Number of off-diagonal blocks in the pattern union.
  std::size_t pattern_size() const { return pattern_.size(); }
  /// Grows by one at every update that added blocks to the pattern union; starts at 0.
  std::uint64_t pattern_revision() const { return revision_; }

  const ContactGeometry& geometry() const { return *geometry_; }
  const std::shared_ptr<const ContactGeometry>& shared_geometry() const { return geometry_; }
  ContactMethod method() const { return integrator_->method; }
  const PairIntegrator& integrator() const { return *integrator_; }
  /// The 7 global nodes of pair p (triangle's 3, then tet's 4).
  std::array<Index, 7> nodes(const ActivePair& p) const { return pair_nodes(*geometry_, p.triangle, p.tet); }
  /// The geometry of pair p at positions x (#V x 3), with the multipliers q = p / ε of its
  /// triangle's vertices when the set has contact pressures.
  PairGeometry pair_geometry_at(const Positions& x, const ActivePair& p) const {
    PairGeometry pg = pair_geometry(*geometry_, x, p.triangle, p.tet);
    if (pressure_.size() > 0 && p.penalty > 0)
      for (int k = 0; k < 3; ++k) pg.multiplier[k] = pressure_[geometry_->surface(p.triangle, k)] / p.penalty;
    pg.multiplier_onset = pressure_onset_;
    return pg;
  }

  /// Replaces the body-pair penalties (#B x #B, symmetric; an entry may change only between
  /// positive values, so the pairs that take part stay the same) and the penalties of the
  /// current pairs. Throws InputError for a matrix of the wrong size, a non-finite or
  /// non-positive entry where the geometry has a positive one, or a positive one where it has 0.
  void set_penalty(const MatrixX& penalty);
  /// The augmented Lagrangian contact pressure per node (#V, force / L², >= 0), interpolated
  /// linearly over each surface triangle; 0 rows = none (pure penalty). Throws InputError for
  /// a wrong size or a negative or non-finite entry.
  void set_pressure(VectorX pressure);
  const VectorX& pressure() const { return pressure_; }
  /// The depth δ (L, >= 0) over which the pressure ramps up from 0 at the surface to p
  /// (PairGeometry::multiplier_onset; 0 = no ramp). Throws InputError for a negative or
  /// non-finite δ.
  void set_pressure_onset(double onset);
  double pressure_onset() const { return pressure_onset_; }

 private:
  void check_size(const Positions& x, const char* caller) const;
  /// Fills trees_ (the tets with depth that this part detects, per body) and trees_of_body_.
  void assign_trees();
  /// Builds (rebuild) or refits every body's tree at x.
  void fit_trees(const Positions& x, bool rebuild);
  /// Narrow phase of the candidates at x into active_.
  void find_pairs(const Positions& x, const std::vector<std::pair<Index, Index>>& candidates);
  /// Adds the blocks of pairs never seen before to the pattern union.
  void grow_pattern();

  std::shared_ptr<const ContactGeometry> geometry_;
  const PairIntegrator* integrator_;
  std::size_t candidate_cap_;
  /// Per tet (#T): false when its four nodes all have zero depth (g ≡ 0, no energy; skipped).
  std::vector<char> tet_has_depth_;
  /// Per body: a tree over its tets that have depth (those without are never a pair).
  std::vector<collision::TetSubsetTree> trees_;
  CollisionShare share_;  ///< empty: this set detects every tet
  /// Per body of the surface triangles: the trees of the bodies it has a positive penalty with
  /// (the broad phase never tests a triangle against a body it cannot contact).
  std::vector<std::vector<int>> trees_of_body_;
  bool tree_built_ = false;
  Positions positions_;
  std::vector<ActivePair> active_;
  bool overflowed_ = false;
  CollisionTimes times_;
  /// Keys (min node, max node) of the off-diagonal blocks in the pattern union.
  std::unordered_set<std::uint64_t> pattern_;
  /// (triangle, tet) keys of every pair whose blocks are in pattern_.
  std::unordered_set<std::uint64_t> pairs_in_pattern_;
  std::uint64_t revision_ = 0;
  VectorX pressure_;  ///< #V augmented Lagrangian pressures, or empty
  double pressure_onset_ = 0;  ///< δ of the pressures' onset ramp (L)
};

}  // namespace sinew::contact
